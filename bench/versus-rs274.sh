#!/usr/bin/env bash
# gcnc against LinuxCNC's standalone interpreter rs274 (Debian: apt install linuxcnc-uspace) on the
# same turning geometry, paired: every round runs rs274, then gcnc check and compile cold (the
# installed command with GCNC_DAEMON=off: a JVM of its own, the class-data archive, C1 alone for a
# small file), then the same through the resident checker (gcnc daemon start), so that this shared
# machine's drift from minute to minute hits all alike. Two sizes: SMALL blocks (a usual program) and
# LARGE blocks. bench/gen_program.py writes both programs (--rs274: the same passes, arcs and feeds in
# LinuxCNC's words, the same number of blocks); both tools' standard output goes to /dev/null.
#
# Prints, per size and per run kind, the median (min-max) wall seconds, the median CPU seconds (user +
# system of every thread of that process alone, from its own rusage; for a resident run the client's
# plus what the daemon's JVM spent on the request, its JIT and GC tail after the answer included:
# /proc/PID/stat read once the daemon is idle again) and peak RSS (a resident run: the daemon's, VmHWM), then the median
# of the paired ratios gcnc / rs274 of wall and CPU time, each beside its target (issues 23 and 35).
# Wall time on this 2-core machine moves with the other work on it; CPU time is the steadier figure.
#
# usage: bench/versus-rs274.sh [SMALL_RUNS] [LARGE_RUNS] [SMALL] [LARGE]
#        (default 7 rounds of 2,000 blocks, 3 rounds of 1,000,000; LARGE_RUNS=0 skips the large size)
set -eu
cd "$(dirname "$0")/.."
small_runs=${1:-7}; large_runs=${2:-3}; small=${3:-2000}; large=${4:-1000000}
command -v rs274 >/dev/null || { echo "versus-rs274: no rs274 on PATH (apt install linuxcnc-uspace)" >&2; exit 2; }
mkdir -p bench/out
prefix=bench/out/prefix
bash scripts/install.sh --prefix "$prefix" >/dev/null
gcnc="$prefix/bin/gcnc"
export GCNC_DAEMON_DIR="$PWD/bench/out/daemon-state"
"$gcnc" daemon stop >/dev/null 2>&1 || true
"$gcnc" daemon start
pid=$(sed -n 's/^pid=//p' "$GCNC_DAEMON_DIR/daemon.state")
trap '"$gcnc" daemon stop >/dev/null 2>&1 || true' EXIT
hz=$(getconf CLK_TCK)
ticks() { awk '{print $14 + $15}' "/proc/$pid/stat"; }
# wait until the daemon's CPU stands still for 0.2 s (at most 5 s): its compiler threads finish the
# work a request left them, so that none of it lands on the next run. Before 2026-12 the daemon's
# ticks were added to every run, rs274's and the cold runs' included: rs274 showed 0.28 s of CPU for
# its own 0.05 s, and the ratios were off by that much.
settle() {
    local last now i
    last=$(ticks)
    for i in $(seq 25); do
        sleep 0.2
        now=$(ticks)
        [ "$now" = "$last" ] && return 0
        last=$now
    done
}
log=bench/out/versus-rs274.txt
: > "$log"
# one measured run: KIND SIZE then the command; appends "SIZE KIND wall user sys rss daemon-ticks".
# Wall and CPU to the tenth of a millisecond (os.wait4's rusage, a monotonic clock): rs274 reads
# 2,000 blocks in about 20 ms, where /usr/bin/time's hundredths made a ratio jump by half.
measure() {
    local kind=$1 size=$2; shift 2
    local before after
    settle
    before=$(ticks)
    python3 - "$@" > bench/out/time.txt <<'PY'
import os, subprocess, sys, time
t = time.perf_counter()
p = subprocess.Popen(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
_, _, ru = os.wait4(p.pid, 0)
print(f"{time.perf_counter() - t:.4f} {ru.ru_utime:.4f} {ru.ru_stime:.4f} {ru.ru_maxrss}")
PY
    case "$kind" in
        *resident) settle; after=$(ticks) ;;
        *) after=$before ;; # not the daemon's run: none of its CPU is this run's (it was idle, settle)
    esac
    echo "$size $kind $(cat bench/out/time.txt) $(( after - before ))" >> "$log"
}
rounds() {
    local blocks=$1 runs=$2
    local nc=bench/out/turning-$blocks.nc ngc=bench/out/turning-$blocks.ngc
    [ -f "$nc" ] || python3 bench/gen_program.py "$blocks" "$nc"
    [ -f "$ngc" ] || python3 bench/gen_program.py "$blocks" "$ngc" --rs274
    # a resident checker runs for hours: a few runs first, unmeasured, so that the JIT's warm-up
    # is not charged to the first measured ones (the cold runs have none to pay, by definition)
    for i in 1 2 3; do
        "$gcnc" check "$nc" >/dev/null 2>&1 || true
        "$gcnc" compile "$nc" -o bench/out/versus.dmc >/dev/null 2>&1 || true
        [ "$blocks" -gt 100000 ] && break
    done
    for i in $(seq "$runs"); do
        measure rs274 "$blocks" rs274 -g "$ngc"
        measure check-cold "$blocks" env GCNC_DAEMON=off "$gcnc" check "$nc"
        measure compile-cold "$blocks" env GCNC_DAEMON=off "$gcnc" compile "$nc" -o bench/out/versus.dmc
        measure check-resident "$blocks" "$gcnc" check "$nc"
        measure compile-resident "$blocks" "$gcnc" compile "$nc" -o bench/out/versus.dmc
    done
}
rounds "$small" "$small_runs"
[ "$large_runs" -gt 0 ] && rounds "$large" "$large_runs"
daemon_rss=$(awk '/VmHWM/ {print $2}' "/proc/$pid/status")
echo "gcnc against rs274: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg), $(java -version 2>&1 | head -1)"
python3 - "$log" "$hz" "$daemon_rss" "$small" "$large" <<'PY'
import collections, statistics, sys
hz, daemon_rss, small = int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
runs = collections.defaultdict(list)
for line in open(sys.argv[1]):
    size, kind, wall, user, system, rss, daemon = line.split()
    resident = kind.endswith("resident")
    runs[(int(size), kind)].append((float(wall), float(user) + float(system) + int(daemon) / hz,
                                    daemon_rss if resident else int(rss)))
# the largest ratio gcnc / rs274 allowed, end to end: the small size's are issue 23's (wall time);
# the large size's issue 35's (cold check 5x faster, compile 2x faster, in wall and in CPU time both)
targets = {(True, "check-cold"): 6, (True, "compile-cold"): 10, (True, "check-resident"): 1,
           (True, "compile-resident"): 2, (False, "check-cold"): 1 / 5, (False, "compile-cold"): 1 / 2}
for size in sorted({s for s, _ in runs}):
    print(f"{size:,} blocks ({len(runs[(size, 'rs274')])} paired rounds)")
    base = runs[(size, "rs274")]
    for kind in ("rs274", "check-cold", "compile-cold", "check-resident", "compile-resident"):
        r = runs[(size, kind)]
        w = sorted(x[0] for x in r)
        cpu = statistics.median(x[1] for x in r)
        rss = statistics.median(x[2] for x in r) / 1024
        row = f"  {kind:17s} wall {statistics.median(w):6.3f} s ({w[0]:.3f}-{w[-1]:.3f})  CPU {cpu:6.3f} s  RSS {rss:4.0f} MiB"
        if kind != "rs274":
            wr = statistics.median(a[0] / b[0] for a, b in zip(r, base))
            cr = statistics.median(a[1] / max(b[1], 0.001) for a, b in zip(r, base))
            row += f"  | x rs274: wall {wr:5.2f}, CPU {cr:5.2f}"
            t = targets.get((size <= small, kind))
            if t is not None:
                met = wr <= t and (size <= small or cr <= t)
                row += f"  target <= {t:.2f}{'' if size <= small else ' (wall and CPU)'}: {'met' if met else 'NOT met'}"
            if rss > 160:
                row += "  (RSS over 160 MiB)"
        print(row)
print("(resident RSS: the daemon's peak over the whole benchmark)")
PY
