#!/usr/bin/env bash
# The checking thread's CPU per check, warm: RUNS checks of the benchmark program in one JVM, one
# core, the launcher's heap options; prints each run's milliseconds (the first ones include the JIT).
# usage: bench/warm.sh JAR [RUNS] [BLOCKS]     (default 6 runs, 1000000 blocks)
set -eu
cd "$(dirname "$0")/.."
jar=$1; runs=${2:-6}; blocks=${3:-1000000}
prog=bench/out/turning-$blocks.nc
mkdir -p bench/out/alloc
[ -f "$prog" ] || python3 bench/gen_program.py "$blocks" "$prog"
javac -d bench/out/alloc -cp "$jar" bench/alloc/Warm.java
taskset -c 0 java -XX:+UseSerialGC -Xmn48m -Xms64m -Xmx512m -cp "$jar:bench/out/alloc" Warm "$prog" "$runs"
