#!/usr/bin/env bash
# Benchmark: gcnc on a generated 1,000,000-block turning program.
# Reports blocks/second (end to end, JVM start included) and peak resident memory for
#   gcnc check      (parse + all checks)
#   gcnc compile    (check + Galil code generation + simulation, output written)
# first on every core (the simulator has a thread of its own; the JIT compiler uses a core too),
# then pinned to one core with taskset, the JIT compiler included.
# usage: bench/run.sh [BLOCKS]      (default 1000000; needs build/libs/gcnc.jar: gradle assemble)
set -eu
cd "$(dirname "$0")/.."
blocks=${1:-1000000}
jar=build/libs/gcnc.jar
[ -f "$jar" ] || gradle -q assemble
mkdir -p bench/out
prog=bench/out/turning-$blocks.nc
[ -f "$prog" ] || python3 bench/gen_program.py "$blocks" "$prog"
# A small, fixed heap: the checker streams, so it needs no more; the GC then keeps RSS flat.
jvm=(java -Xms64m -Xmx64m -XX:+UseSerialGC -jar "$jar")
run() {
    local name=$1; shift
    /usr/bin/time -f "%e %M" -o bench/out/time.txt $pin "${jvm[@]}" "$@" >/dev/null
    read -r secs kib < bench/out/time.txt
    python3 -c "import sys; b,s,k=$blocks,$secs,$kib; print(f'{sys.argv[1]:8s} {b} blocks in {s:.2f} s = {b/s:,.0f} blocks/s, peak RSS {k/1024:.0f} MiB')" "$name"
}
echo "gcnc benchmark: $(nproc) cores, $(java -version 2>&1 | head -1)"
pin=""
run check check "$prog"
run compile compile "$prog" -o bench/out/turning.dmc
if command -v taskset >/dev/null; then
    echo "one core (taskset -c 0):"
    pin="taskset -c 0"
    run check check "$prog"
    run compile compile "$prog" -o bench/out/turning.dmc
fi
