#!/usr/bin/env bash
# The 2,000-block benchmark, cold and resident: the installed command (scripts/install.sh into
# bench/out/prefix: launcher, jar, class-data archive) checks and compiles a BLOCKS-block turning
# program (bench/gen_program.py) RUNS times, alternating a cold run (GCNC_DAEMON=off: a JVM of its
# own) and a run through the resident checker (gcnc daemon start, in this folder, with its state in
# bench/out/daemon-state). Prints the median (min-max) wall seconds and the median CPU seconds of
# each: for a resident run, the client's (Python) plus what the daemon's JVM spent on the request,
# read from /proc/PID/stat before and after it.
# usage: bench/resident.sh [BLOCKS] [RUNS]      (default 2000 blocks, 7 runs)
set -eu
cd "$(dirname "$0")/.."
blocks=${1:-2000}; runs=${2:-7}
mkdir -p bench/out
prog=bench/out/turning-$blocks.nc
[ -f "$prog" ] || python3 bench/gen_program.py "$blocks" "$prog"
prefix=bench/out/prefix
bash scripts/install.sh --prefix "$prefix" >/dev/null
gcnc="$prefix/bin/gcnc"
export GCNC_DAEMON_DIR="$PWD/bench/out/daemon-state"
"$gcnc" daemon start
pid=$(sed -n 's/^pid=//p' "$GCNC_DAEMON_DIR/daemon.state")
# A resident checker runs for hours: three runs of each command first, unmeasured, so that the C2
# compiles the warm-up queued are not charged to the first measured runs.
for i in 1 2 3; do
  "$gcnc" check "$prog" >/dev/null 2>&1 || true
  "$gcnc" compile "$prog" -o bench/out/resident.dmc >/dev/null 2>&1 || true
done
hz=$(getconf CLK_TCK)
ticks() { awk '{print $14 + $15}' "/proc/$pid/stat"; }
log=bench/out/resident.txt
: > "$log"
for i in $(seq "$runs"); do
  for mode in cold resident; do
    for cmd in check compile; do
      args=("$prog"); [ "$cmd" = compile ] && args+=(-o bench/out/resident.dmc)
      before=$(ticks)
      if [ "$mode" = cold ]; then
        GCNC_DAEMON=off /usr/bin/time -f "%e %U %S" -o bench/out/time.txt "$gcnc" "$cmd" "${args[@]}" >/dev/null 2>&1 || true
      else
        /usr/bin/time -f "%e %U %S" -o bench/out/time.txt "$gcnc" "$cmd" "${args[@]}" >/dev/null 2>&1 || true
      fi
      after=$(ticks)
      echo "$mode $cmd $(cat bench/out/time.txt) $(( after - before ))" >> "$log"
    done
  done
done
"$gcnc" daemon stop
python3 - "$log" "$hz" "$blocks" <<'PY'
import collections, statistics, sys
hz = int(sys.argv[2])
runs = collections.defaultdict(list)
for line in open(sys.argv[1]):
    mode, cmd, wall, user, system, daemon = line.split()
    runs[(cmd, mode)].append((float(wall), float(user) + float(system) + int(daemon) / hz))
print(f"{sys.argv[3]} blocks, installed command | cold: own JVM | resident: gcnc daemon")
for cmd in ("check", "compile"):
    row = [f"{cmd:8s}"]
    for mode in ("cold", "resident"):
        w = sorted(x for x, _ in runs[(cmd, mode)])
        cpu = statistics.median(c for _, c in runs[(cmd, mode)])
        row.append(f"{mode} {statistics.median(w):.2f} s ({w[0]:.2f}-{w[-1]:.2f}), CPU {cpu:.2f} s")
    print(" | ".join(row))
PY
