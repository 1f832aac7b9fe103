#!/usr/bin/env bash
# The simulator's cost against the number of moves that reach into the blank: a Haas program of
# N rapids, every one E305 and each leaving its notch in an ever more ragged stock
# (bench/gen_rapids.py), compiled for N = 500 .. 4000. Prints wall and CPU seconds and the peak
# resident memory of each run; a near-linear simulator doubles its CPU time with N.
# usage: bench/sim-cost.sh JAR [N ...]     (default 500 1000 2000 4000)
set -eu
cd "$(dirname "$0")/.."
jar=$1; shift
sizes=("$@"); [ ${#sizes[@]} -gt 0 ] || sizes=(500 1000 2000 4000)
mkdir -p bench/out
printf '%6s  %8s  %8s  %8s  %s\n' moves wall_s cpu_s rss_MiB findings
for n in "${sizes[@]}"; do
  prog=bench/out/rapids-$n.nc
  [ -f "$prog" ] || python3 bench/gen_rapids.py "$n" "$prog"
  /usr/bin/time -f '%e %U %S %M' -o bench/out/sim-cost.time \
    java -Xmx256m -jar "$jar" compile "$prog" --machine haas -o bench/out/sim-cost.dmc \
    >/dev/null 2>bench/out/sim-cost.err || true
  read -r wall user sys rss < <(tail -1 bench/out/sim-cost.time)
  found=$(grep -c 'error\[E305\]' bench/out/sim-cost.err || true)
  printf '%6d  %8.2f  %8.2f  %8d  %s\n' "$n" "$wall" "$(echo "$user + $sys" | bc -l)" $((rss / 1024)) "$found"
done
