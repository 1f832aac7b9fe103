#!/usr/bin/env bash
# Two jars side by side on the benchmark program: alternating runs, so that this machine's drift
# from minute to minute hits both alike; prints the median (min-max) wall seconds, the median CPU
# seconds (user + system, every thread: steadier than wall time on a loaded machine) and the peak RSS
# of check and compile, on every core and pinned to one.
# usage: bench/side-by-side.sh BEFORE.jar AFTER.jar [RUNS] [BLOCKS]
#   e.g. git worktree add /tmp/base 86b4b37 && (cd /tmp/base && gradle -q assemble)
#        bash bench/side-by-side.sh /tmp/base/build/libs/gcnc.jar build/libs/gcnc.jar
set -eu
cd "$(dirname "$0")/.."
before=$1; after=$2; runs=${3:-5}; blocks=${4:-1000000}
prog=bench/out/turning-$blocks.nc
mkdir -p bench/out
[ -f "$prog" ] || python3 bench/gen_program.py "$blocks" "$prog"
log=bench/out/side-by-side.txt
: > "$log"
for i in $(seq "$runs"); do
  for jar in "$before" "$after"; do
    for pin in "" "taskset -c 0"; do
      cores=$([ -z "$pin" ] && echo "2-cores" || echo "1-core")
      for cmd in check compile; do
        args=("$prog"); [ "$cmd" = compile ] && args+=(-o bench/out/side-by-side.dmc)
        /usr/bin/time -f "%e %M %U %S" -o bench/out/time.txt $pin java -Xms64m -Xmx64m -XX:+UseSerialGC -jar "$jar" \
            "$cmd" "${args[@]}" >/dev/null 2>&1 || true
        echo "$jar $cmd $cores $(cat bench/out/time.txt)" >> "$log"
      done
    done
  done
done
python3 - "$log" "$before" "$after" <<'PY'
import collections, statistics, sys
runs = collections.defaultdict(list)
for line in open(sys.argv[1]):
    jar, cmd, cores, secs, kib, user, system = line.split()
    runs[(cmd, cores, jar)].append((float(secs), int(kib), float(user) + float(system)))
for cmd in ("compile", "check"):
    for cores in ("2-cores", "1-core"):
        row = [f"{cmd:8s} {cores:8s}"]
        for jar in sys.argv[2:]:
            v = sorted(s for s, _, _ in runs[(cmd, cores, jar)])
            rss = statistics.median(k for _, k, _ in runs[(cmd, cores, jar)]) / 1024
            cpu = statistics.median(c for _, _, c in runs[(cmd, cores, jar)])
            row.append(f"{statistics.median(v):.2f} s ({v[0]:.2f}-{v[-1]:.2f}), CPU {cpu:.2f} s, {rss:.0f} MiB")
        print(" | ".join(row))
PY
