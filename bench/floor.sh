#!/usr/bin/env bash
# Start-up against the JVM's own floor (issue 35): the installed gcnc command (cold: GCNC_DAEMON=off,
# its launcher's options and class-data archive) beside `java -version` with the same class-data
# sharing, collector and C1-only JIT, alternating RUNS rounds so that this shared machine's drift hits
# all alike. Prints the median (min) wall and CPU seconds of each (user + system of that process and
# its children alone, from its rusage), the machine's load before and after, and the ratios to the floor.
# usage: bench/floor.sh [RUNS] [BLOCKS]     (default 15 rounds, a 2,000-block check)
set -eu
cd "$(dirname "$0")/.."
runs=${1:-15}; blocks=${2:-2000}
mkdir -p bench/out
prefix=bench/out/prefix
bash scripts/install.sh --prefix "$prefix" >/dev/null
nc=bench/out/turning-$blocks.nc
[ -f "$nc" ] || python3 bench/gen_program.py "$blocks" "$nc"
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
GCNC_DAEMON=off python3 - "$runs" "$prefix/bin/gcnc" "$nc" <<'PY'
import os, statistics, subprocess, sys, time
runs, gcnc, nc = int(sys.argv[1]), sys.argv[2], sys.argv[3]
kinds = {
    "java -version": ["java", "-Xshare:auto", "-XX:+UseSerialGC", "-XX:TieredStopAtLevel=1", "-version"],
    "gcnc --version": [gcnc, "--version"],
    "gcnc check": [gcnc, "check", nc],
}
got = {k: [] for k in kinds}
for _ in range(runs):
    for k, cmd in kinds.items():
        t = time.perf_counter()
        p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        _, _, ru = os.wait4(p.pid, 0)
        got[k].append((time.perf_counter() - t, ru.ru_utime + ru.ru_stime))
floor = got["java -version"]
for k, r in got.items():
    w = [x[0] for x in r]; c = [x[1] for x in r]
    row = f"{k:15s} wall {statistics.median(w):.3f} s ({min(w):.3f})  CPU {statistics.median(c):.3f} s ({min(c):.3f})"
    if k != "java -version":
        row += (f"  | x floor: wall {statistics.median(a[0] / b[0] for a, b in zip(r, floor)):.2f},"
                f" CPU {statistics.median(a[1] / b[1] for a, b in zip(r, floor)):.2f}")
    print(row)
PY
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
