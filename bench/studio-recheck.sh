#!/usr/bin/env bash
# Re-check in a warm studio: a BLOCKS-block program (bench/gen_program.py, default 2000) is sent to a running
# `gcnc studio` (POST /api/check, as the page does after each edit) WARM times, then one block is edited and
# the program re-checked RUNS times; prints the median, 90th percentile and worst round trip (HTTP and JSON
# included, as the page waits for it), and the same for POST /api/simulate (path + DMC), each also as the studio's own time (its Server-Timing
# header). Target: check < 50 ms. Also prints the machine's load: on a shared machine the figures are its.
# DRILL=1: the program drills and bores the part first (bench/gen_program.py --drill: a centre drill, a drill
# and a boring bar, on the tools of bench/drill.machine), as most real parts are.
# usage: bench/studio-recheck.sh JAR [BLOCKS]    (WARM=40, RUNS=60 by default)
set -eu
cd "$(dirname "$0")/.."
jar=$1; blocks=${2:-2000}
dir=bench/out/studio
mkdir -p "$dir"
if [ -n "${DRILL:-}" ]; then
    python3 bench/gen_program.py "$blocks" "$dir/long.nc" --drill
    machine=(--machine bench/drill.machine)
else
    python3 bench/gen_program.py "$blocks" "$dir/long.nc"
    machine=()
fi
java ${STUDIO_JAVA_OPTS:-} -jar "$jar" studio "$dir" --lang en "${machine[@]}" > "$dir/studio.out" 2>&1 &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
for _ in $(seq 50); do grep -q 'token=' "$dir/studio.out" 2>/dev/null && break; sleep 0.2; done
url=$(grep -o 'http://[^ ]*token=[0-9a-f]*' "$dir/studio.out")
uptime
python3 - "$url" "$dir/long.nc" "${WARM:-40}" "${RUNS:-60}" <<'PY'
import json, statistics, sys, time, urllib.request, urllib.parse
url, path, warm, runs = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
base = url.split("/?")[0]
token = urllib.parse.parse_qs(urllib.parse.urlparse(url).query)["token"][0]
lines = open(path).read().split("\n")
def post(endpoint, text):
    req = urllib.request.Request(base + "/api/" + endpoint, json.dumps({"name": "long.nc", "text": text}).encode(),
                                 {"X-Gcnc-Token": token, "Content-Type": "application/json"})
    t = time.perf_counter()
    with urllib.request.urlopen(req) as r:
        body = json.load(r)
        server = float(r.headers["Server-Timing"].split("dur=")[1])
    return (time.perf_counter() - t) * 1000, server, body
def edited(i):
    # one edit: a feed value in the middle of the program, a different one each run
    l = list(lines); k = len(l) // 2
    while "F" not in l[k]: k += 1
    l[k] = l[k].split(" F")[0] + f" F{100 + i % 50}."
    return "\n".join(l)
for endpoint in ("check", "simulate"):
    for i in range(warm):
        post(endpoint, edited(i))
    trips, inside = [], []
    for i in range(runs):
        ms, server, body = post(endpoint, edited(warm + i))
        doc = body if endpoint == "check" else body["diagnostics"]
        assert doc["errors"] == 0, doc["diagnostics"][:3]
        trips.append(ms); inside.append(server)
    for what, times in (("round trip", trips), ("in the studio", inside)):
        times.sort()
        print(f"{endpoint:8} {len(lines) - 1} lines, {what:13}: median {statistics.median(times):6.1f} ms, "
              f"p90 {times[int(0.9 * len(times)) - 1]:6.1f} ms, worst {times[-1]:6.1f} ms over {runs} edits (after {warm} warm-up)")
PY
