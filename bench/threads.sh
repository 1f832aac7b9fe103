#!/usr/bin/env bash
# CPU seconds of each thread of one gcnc run (the checking thread is "java", then the simulator's,
# the JIT compilers C1/C2 and the VM thread, i.e. the garbage collector), read from
# /proc/PID/task/*/stat while it runs: where the CPU of a run goes, which wall time on two cores follows.
# usage: bench/threads.sh JAR check|compile [BLOCKS]     (default 1000000 blocks)
set -eu
cd "$(dirname "$0")/.."
jar=$1; cmd=$2; blocks=${3:-1000000}
prog=bench/out/turning-$blocks.nc
mkdir -p bench/out
[ -f "$prog" ] || python3 bench/gen_program.py "$blocks" "$prog"
args=("$prog"); [ "$cmd" = compile ] && args+=(-o bench/out/threads.dmc)
java -Xms64m -Xmx64m -XX:+UseSerialGC -jar "$jar" "$cmd" "${args[@]}" >/dev/null 2>&1 &
pid=$!
declare -A ticks
while kill -0 "$pid" 2>/dev/null; do
  for t in /proc/$pid/task/*; do
    name=$(cat "$t/comm" 2>/dev/null) || continue
    stat=$(sed 's/.*) //' "$t/stat" 2>/dev/null) || continue
    read -r -a f <<< "$stat"
    [ -n "${f[11]:-}" ] && ticks["$name#${t##*/}"]=$(( f[11] + f[12] ))
  done
  sleep 0.02
done
hz=$(getconf CLK_TCK)
for k in "${!ticks[@]}"; do
  [ "${ticks[$k]}" -gt 0 ] && printf '%6.2f s  %s\n' "$(echo "${ticks[$k]} / $hz" | bc -l)" "${k%#*}"
done | sort -rn
