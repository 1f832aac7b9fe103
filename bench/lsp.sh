#!/usr/bin/env bash
# Diagnostics as you type, on a warm language server: a BLOCKS-block program (bench/gen_program.py, default
# 2000) is opened in `gcnc lsp`, edited WARM times (one block changed each time, each edit waited for), then
# RUNS more times; prints the median, 90th percentile and worst time from sending textDocument/didChange to
# receiving the publishDiagnostics of that version (the check's findings: simulateAfterMs -1, as in an editor
# while typing; the server's own debounce, checkDelayMs, is DELAY ms, default 10 as shipped). Target: < 50 ms.
# Also prints the machine's load: on a shared machine the figures are its.
# usage: bench/lsp.sh JAR [BLOCKS]    (WARM=60, RUNS=60, DELAY=10 by default; LSP_JAVA_OPTS for the server's JVM)
set -eu
cd "$(dirname "$0")/.."
jar=$1; blocks=${2:-2000}
dir=bench/out/lsp
mkdir -p "$dir"
python3 bench/gen_program.py "$blocks" "$dir/long.nc"
uptime
python3 - "$jar" "$dir/long.nc" "${WARM:-60}" "${RUNS:-60}" "${DELAY:-10}" "${LSP_JAVA_OPTS:--XX:+UseSerialGC}" <<'PY'
import json, pathlib, shlex, statistics, subprocess, sys, time
jar, path, warm, runs, delay, opts = sys.argv[1], pathlib.Path(sys.argv[2]).resolve(), int(sys.argv[3]), int(sys.argv[4]), int(sys.argv[5]), sys.argv[6]
p = subprocess.Popen(["java", *shlex.split(opts), "-jar", jar, "lsp"], stdin=subprocess.PIPE, stdout=subprocess.PIPE)

def send(m):
    b = json.dumps(m).encode()
    p.stdin.write(b"Content-Length: %d\r\n\r\n" % len(b) + b)
    p.stdin.flush()

def frame():
    h = b""
    while not h.endswith(b"\r\n\r\n"):
        h += p.stdout.read(1)
    n = int([l for l in h.decode().split("\r\n") if l.lower().startswith("content-length")][0].split(":")[1])
    return json.loads(p.stdout.read(n))

send({"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {"capabilities": {}, "rootUri": path.parent.as_uri(),
      "initializationOptions": {"simulateAfterMs": -1, "checkDelayMs": delay}}})
while frame().get("id") != 1:
    pass
send({"jsonrpc": "2.0", "method": "initialized", "params": {}})
uri = path.as_uri()
lines = path.read_text().split("\n")
send({"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {"textDocument": {
      "uri": uri, "languageId": "gcode", "version": 1, "text": "\n".join(lines)}}})
version = 1
count = None

def edit():
    global version, count
    version += 1
    k = 10 + version % (len(lines) - 20)  # a block in the body, a feed changed
    changed = list(lines)
    changed[k] = changed[k] + " F%d." % (100 + version % 50) if changed[k].startswith("G01") else changed[k]
    text = "\n".join(changed)
    t = time.perf_counter()
    send({"jsonrpc": "2.0", "method": "textDocument/didChange", "params": {"textDocument": {"uri": uri, "version": version},
          "contentChanges": [{"text": text}]}})
    while True:
        m = frame()
        if m.get("method") == "textDocument/publishDiagnostics" and m["params"].get("version") == version:
            count = len(m["params"]["diagnostics"])
            return (time.perf_counter() - t) * 1000

for _ in range(warm):
    edit()
times = sorted(edit() for _ in range(runs))
print("gcnc lsp, %d lines (%d diagnostics), %d warm edits then %d: didChange -> publishDiagnostics median %.1f ms, p90 %.1f ms, worst %.1f ms (checkDelayMs %d)"
      % (len(lines), count, warm, runs, statistics.median(times), times[int(len(times) * 0.9) - 1], times[-1], delay))
send({"jsonrpc": "2.0", "id": 2, "method": "shutdown"})
while frame().get("id") != 2:
    pass
send({"jsonrpc": "2.0", "method": "exit"})
p.wait(10)
PY
uptime
