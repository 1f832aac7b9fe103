#!/usr/bin/env bash
# Streaming (issue 33): how many segments a second `gcnc run` in the stream form keeps the vector buffer
# fed with over the loopback link, and so the smallest chord at which a feed stays blended. A virtual
# Galil (`gcnc controller --virtual`, its own JVM, loopback TCP, a trace) runs a finishing contour of
# chords of length L at feed F in one sequence fed while it runs; the host sends one command at a time
# and polls _LMS every POLL ms. For each L, from long to short, the demanded rate is SPEED x F / L
# segments a second; the run either keeps up (exit 0, the trace ends the sequence with `# end`, no
# `# underrun`) or the buffer runs dry (E890 at its segment). Prints the machine's load first: on a
# shared machine the figures are its.
# usage: bench/stream.sh [FEED_MM_MIN] [SECONDS]   (default 240 mm/min = F0.2 mm/rev at 1200 r/min; each
#        run about SECONDS of motion, default 3; SPEED=1 controller time as real time, POLL=10 ms,
#        CHORDS_UM="50 20 10 5" the chord lengths in micrometres; needs build/libs/gcnc.jar)
set -eu
cd "$(dirname "$0")/.."
feed=${1:-240}; seconds=${2:-3}
speed=${SPEED:-1}; poll=${POLL:-10}; chords=${CHORDS_UM:-50 20 10 5}
jar=$PWD/build/libs/gcnc.jar
[ -f "$jar" ] || gradle -q assemble
dir=bench/out/stream
mkdir -p "$dir"
echo "gcnc stream benchmark: $(nproc) cores, $(java -version 2>&1 | head -1); load: $(uptime | sed 's/.*load average: //')"
echo "feed $feed mm/min, controller speed x$speed, poll $poll ms"
python3 - "$jar" "$dir" "$feed" "$seconds" "$speed" "$poll" $chords <<'PY'
import math, os, re, socket, subprocess, sys, time
jar, d, feed, seconds, speed, poll = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4]), sys.argv[5], sys.argv[6]
gcnc = ["java", "-XX:+UseSerialGC", "-jar", jar]

def program(um):
    l = um / 1000.0
    n = max(600, int(seconds * feed / 60.0 / l))  # chords: about SECONDS of motion, more than a buffer
    rpm = 1200
    lines = ["%", "O3302 (STREAM BENCH)", "G21 G18 G40 G98", "T0101", f"G97 S{rpm} M03", "G00 X48. Z1.", f"G01 Z0. F{feed:g}"]
    for k in range(1, n + 1):
        z = -k * l
        lines.append(f"X{46 + 0.5 * math.sin(z / 2):.4f} Z{z:.4f}")
    lines += ["G00 X60.", "Z5.", "M05", "M30", "%"]
    path = os.path.join(d, f"chords-{um}um.nc")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return path, n

def tell(port, cmd):
    with socket.create_connection(("127.0.0.1", port), timeout=5) as s:
        s.sendall((cmd + "\r").encode())
        b = b""
        while not (b.endswith(b":") or b.endswith(b"?")):
            b += s.recv(256)
        return b.decode()

for um in [int(c) for c in sys.argv[7:]]:
    nc, n = program(um)
    trace = os.path.join(d, f"chords-{um}um.trace")
    vc = subprocess.Popen(gcnc + ["controller", "--virtual", "--tcp", "0", "--speed", speed, "--trace", trace],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    try:
        port = int(re.search(r"127\.0\.0\.1:(\d+)", vc.stdout.readline()).group(1))
        # home: where the program was verified from (the refusal names the counts; nothing moves)
        r = subprocess.run(gcnc + ["run", nc, "--machine", "haas", "--form", "stream", "--tcp", f"127.0.0.1:{port}"],
                           capture_output=True, text=True)
        home = re.search(r"verified from home at .*?\(Galil counts (-?\d+),(-?\d+)\)", r.stdout + r.stderr)
        if home:
            tell(port, f"DP {home.group(1)},{home.group(2)}")
        t0 = time.monotonic()
        r = subprocess.run(gcnc + ["run", nc, "--machine", "haas", "--form", "stream", "--tcp", f"127.0.0.1:{port}",
                                   "--poll", poll, "--quiet"], capture_output=True, text=True)
        wall = time.monotonic() - t0
    finally:
        vc.terminate()
        vc.wait()
    events = [l for l in open(trace) if l.startswith("# ")]
    per = {}
    for l in open(trace):
        if l[:1].isdigit():
            per[l.split()[0]] = per.get(l.split()[0], 0) + 1
    longest = max(per.values()) if per else 0
    rate = float(speed) * feed / 60.0 / (um / 1000.0)
    dry = re.search(r"E890\]: the vector buffer ran dry before VE at segment (\d+)", r.stdout + r.stderr)
    if r.returncode == 0 and not any(l.startswith("# underrun") for l in events):
        outcome = f"blended: the chords one sequence of {longest} segments, no underrun"
    elif dry:
        outcome = f"ran dry at segment {dry.group(1)} of {n + 1} (E890)"
    else:
        outcome = f"exit {r.returncode}: " + (r.stdout + r.stderr).strip().splitlines()[-1][:120]
    print(f"chord {um / 1000:.3f} mm, {n} chords: {rate:,.0f} segments/s demanded, run {wall:.1f} s: {outcome}")
PY
