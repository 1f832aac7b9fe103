#!/usr/bin/env bash
# Start-up: the median wall time of RUNS compiles of a 15-block program (samples/turning.nc), JVM
# start included, for each jar given, alternating so that the machine's drift hits all alike.
# usage: bench/startup.sh JAR [JAR...]   (RUNS=20 by default)
set -eu
cd "$(dirname "$0")/.."
mkdir -p bench/out
python3 - "${RUNS:-20}" "$@" <<'PY'
import statistics, subprocess, sys, time
runs, jars = int(sys.argv[1]), sys.argv[2:]
times = {j: [] for j in jars}
for _ in range(runs):
    for j in jars:
        t = time.time()
        subprocess.run(["java", "-Xms64m", "-Xmx64m", "-XX:+UseSerialGC", "-jar", j, "compile",
                        "samples/turning.nc", "-o", "bench/out/startup.dmc"], capture_output=True)
        times[j].append(time.time() - t)
for j in jars:
    print(f"{j}: median {statistics.median(times[j]):.3f} s, min {min(times[j]):.3f} s over {runs} runs")
PY
