#!/usr/bin/env bash
# Allocation per check: the MB the checking thread allocates to check the benchmark program
# (a deterministic measure, unlike time on this machine). Uses only gcnc's public library API.
# usage: bench/alloc.sh JAR [BLOCKS]     (default 1000000 blocks)
set -eu
cd "$(dirname "$0")/.."
jar=$1; blocks=${2:-1000000}
prog=bench/out/turning-$blocks.nc
mkdir -p bench/out/alloc
[ -f "$prog" ] || python3 bench/gen_program.py "$blocks" "$prog"
javac -d bench/out/alloc -cp "$jar" bench/alloc/Alloc.java
java -Xmx256m -cp "$jar:bench/out/alloc" Alloc "$prog"
