"""Bad input: malformed JSON-RPC, a message past the input limit, a 50 MB buffer, a binary file, a client
that never reads. Each is one logged line (stderr, window/logMessage) and the server goes on; its
standard output carries nothing but well-formed frames, and no stack trace appears anywhere."""
import json
import os
import queue
import subprocess
import threading

from conftest import SERVER


class Raw:
    """A client written by hand, to send what no library would."""

    def __init__(self, *options):
        self.p = subprocess.Popen(SERVER + list(options), stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                  stderr=subprocess.PIPE)
        self.errors = queue.Queue()
        self.stderr = []
        threading.Thread(target=self._stderr, daemon=True).start()

    def _stderr(self):
        for line in self.p.stderr:
            text = line.decode("utf-8", "replace")
            self.stderr.append(text)
            self.errors.put(text)

    def send_bytes(self, b):
        self.p.stdin.write(b)
        self.p.stdin.flush()

    def send(self, message):
        body = json.dumps(message).encode()
        self.send_bytes(b"Content-Length: %d\r\n\r\n" % len(body) + body)

    def frame(self):
        header = b""
        while not header.endswith(b"\r\n\r\n"):
            c = self.p.stdout.read(1)
            assert c, "the server closed its output"
            header += c
        lines = header.decode("ascii").split("\r\n")
        length = int(next(l for l in lines if l.lower().startswith("content-length:")).split(":")[1])
        return json.loads(self.p.stdout.read(length))  # a frame that is not JSON fails here

    def answer(self, id):
        while True:
            m = self.frame()
            if m.get("id") == id and "method" not in m:
                return m

    def notification(self, method):
        while True:
            m = self.frame()
            if m.get("method") == method:
                return m

    def initialize(self):
        self.send({"jsonrpc": "2.0", "id": 1, "method": "initialize",
                   "params": {"capabilities": {}, "initializationOptions": {"simulateAfterMs": -1}}})
        assert "capabilities" in self.answer(1)["result"]
        self.send({"jsonrpc": "2.0", "method": "initialized", "params": {}})

    def open(self, uri, text, version=1):
        self.send({"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {"textDocument": {
            "uri": uri, "languageId": "gcode", "version": version, "text": text}}})

    def hover(self, id, uri, line=0, character=0):
        self.send({"jsonrpc": "2.0", "id": id, "method": "textDocument/hover", "params": {
            "textDocument": {"uri": uri}, "position": {"line": line, "character": character}}})
        return self.answer(id)

    def wait_stderr(self, part, timeout=20):
        while True:
            line = self.errors.get(timeout=timeout)
            if part in line:
                return line

    def close(self):
        self.send({"jsonrpc": "2.0", "id": 999, "method": "shutdown"})
        self.answer(999)
        self.send({"jsonrpc": "2.0", "method": "exit"})
        assert self.p.wait(20) == 0
        assert not any("\tat " in l or "Exception in thread" in l for l in self.stderr), self.stderr


GOOD = "G21 G40 G99\nG50 S2000\nT0101\nG97 S500 M03\nG00 X50. Z2.\nM30\n"


def test_malformed_json_rpc_is_logged_and_the_server_goes_on():
    c = Raw()
    c.initialize()
    for body in (b"{not json", b'{"jsonrpc":"2.0","id":[]}', b'{"jsonrpc":"2.0","method":"textDocument/didOpen","params":7}'):
        c.send_bytes(b"Content-Length: %d\r\n\r\n" % len(body) + body)
    c.send_bytes(b"X-Nonsense: 1\r\n\r\n")  # a header without Content-Length
    c.send({"jsonrpc": "2.0", "id": 7, "method": "no/such/method", "params": {}})
    assert c.answer(7)["error"]["code"] == -32601
    c.open("file:///tmp/good.nc", GOOD)
    assert c.notification("textDocument/publishDiagnostics")["params"]["diagnostics"] == []
    assert "G21" in c.hover(8, "file:///tmp/good.nc")["result"]["contents"]["value"]
    assert any("gcnc lsp:" in l for l in c.stderr)
    c.close()


def test_a_message_past_the_input_limit_is_skipped_unread():
    c = Raw("--input-limit", "100000")
    c.initialize()
    c.open("file:///tmp/big.nc", "G00 X1.\n" * 50_000)  # 400 kB of text
    assert "is more than the 100000 this server reads: skipped" in c.wait_stderr("skipped")
    c.open("file:///tmp/good.nc", GOOD)
    assert c.notification("textDocument/publishDiagnostics")["params"]["uri"] == "file:///tmp/good.nc"
    c.close()


def test_a_50_mb_buffer_is_refused_with_e504_and_a_log_line():
    c = Raw()
    c.initialize()
    c.open("file:///tmp/huge.nc", ("G01 X1. Z2. F0.1 (" + "x" * 100 + ")\n") * 400_000)  # ~50 MB
    m = c.notification("textDocument/publishDiagnostics")["params"]
    assert [(d["code"], d["range"]["start"]) for d in m["diagnostics"]] == [("E504", {"line": 0, "character": 0})]
    assert "characters, more than the 16777216" in c.wait_stderr("more than the")
    assert c.hover(9, "file:///tmp/huge.nc") == {"jsonrpc": "2.0", "id": 9, "result": None}
    c.close()


def test_a_binary_file_gets_located_findings():
    c = Raw()
    c.initialize()
    data = bytes(range(256)) * 40 + os.urandom(4096)
    c.open("file:///tmp/binary.nc", data.decode("latin-1"))
    diags = c.notification("textDocument/publishDiagnostics")["params"]["diagnostics"]
    assert diags and all(d["source"] == "gcnc" and d["code"].startswith("E") for d in diags)
    c.close()


def test_a_client_that_does_not_read_does_not_stop_the_server():
    c = Raw("--output-limit", "200000")
    c.initialize()
    c.open("file:///tmp/good.nc", GOOD)
    line = None
    sent = 0
    while line is None:  # hovers answered into a pipe nobody reads: until the server says it drops them
        for _ in range(100):
            sent += 1
            c.send({"jsonrpc": "2.0", "id": 1000 + sent, "method": "textDocument/hover", "params": {
                "textDocument": {"uri": "file:///tmp/good.nc"}, "position": {"line": 4, "character": 1}}})
        try:
            line = c.wait_stderr("has not read", timeout=1)
        except queue.Empty:
            assert sent < 20_000 and c.p.poll() is None
    assert "dropped" in line
    # the client reads again: what was kept arrives, and the server answers what it is asked now
    assert "G00" in c.hover(10, "file:///tmp/good.nc", 4, 1)["result"]["contents"]["value"]
    c.close()
