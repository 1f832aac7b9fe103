#!/usr/bin/env python3
"""The resident checker's client: runs `gcnc check|compile|simulate ...` in the warm JVM of
`gcnc daemon start` instead of starting one (docs/command-line.md, "Resident checker").

usage: gcnc-client.py JAR ARG...   (scripts/gcnc calls it; JAR is the jar it would run)

It sends the arguments, the working directory, the environment, whether standard input and output
are a terminal, which file standard output is and, when an argument is `-`, standard input; it
writes what the daemon sends to its own standard output and error and exits with the run's status.
Exit status 75 and nothing printed: the daemon is absent, stale (another jar), busy, serves another
folder, or the request is one a warm JVM cannot run as a cold one would; the launcher then runs
gcnc cold. Python and not bash's /dev/tcp: the frames carry any byte (NUL included), which a shell
cannot hold in a variable, and standard input must be sent while the output comes back.
"""
import os
import socket
import struct
import sys
import threading

COLD = 75
CHUNK = 1 << 16


def state_folder():
    env = os.environ
    if env.get("GCNC_DAEMON_DIR"):
        return env["GCNC_DAEMON_DIR"]
    if env.get("XDG_RUNTIME_DIR"):
        return os.path.join(env["XDG_RUNTIME_DIR"], "gcnc")
    return os.path.join(os.path.expanduser("~"), ".cache", "gcnc")


def read_state():
    state = {}
    with open(os.path.join(state_folder(), "daemon.state"), encoding="utf-8") as f:
        for line in f:
            key, _, value = line.rstrip("\n").partition("=")
            state[key] = value
    return int(state["port"]), state["token"], int(state["pid"])


def forget_dead(pid):
    """A state file whose daemon is gone (a reboot, a kill): removed, so that later runs skip Python."""
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        try:
            os.remove(os.path.join(state_folder(), "daemon.state"))
        except OSError:
            pass
    except OSError:
        pass


def frame(kind, data):
    if isinstance(data, str):
        data = os.fsencode(data)
    return kind.encode() + struct.pack(">i", len(data)) + data


def read_exactly(sock, n):
    parts = []
    while n > 0:
        b = sock.recv(min(n, CHUNK))
        if not b:
            raise EOFError("the daemon closed the connection")
        parts.append(b)
        n -= len(b)
    return b"".join(parts)


def read_frame(sock):
    head = read_exactly(sock, 5)
    length = struct.unpack(">i", head[1:])[0]
    return chr(head[0]), read_exactly(sock, length)


def reads_stdin(args):
    """An argument `-` that is a program, not the value of -o or --svg (those write standard output)."""
    for i, a in enumerate(args):
        if a == "-" and not (i > 0 and args[i - 1] in ("-o", "--output", "--svg")):
            return True
    return False


def stdout_identity():
    try:
        st = os.fstat(1)
        return "%d:%d" % (st.st_dev, st.st_ino)
    except OSError:
        return None


def pump_stdin(sock):
    try:
        fd = sys.stdin.fileno()
        while True:
            b = os.read(fd, CHUNK)
            if not b:
                break
            sock.sendall(frame("i", b))
        sock.sendall(frame("z", b""))
    except OSError:
        pass  # the run ended without reading all of it, as a cold one would


def main():
    jar, args = sys.argv[1], sys.argv[2:]
    try:
        port, token, pid = read_state()
        try:
            sock = socket.create_connection(("127.0.0.1", port), timeout=2)
        except ConnectionRefusedError:
            forget_dead(pid)
            return COLD
        sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        stdin = reads_stdin(args)
        request = [frame("T", token), frame("R", b""), frame("J", os.path.abspath(jar)), frame("C", os.getcwd())]
        request += [frame("E", os.fsencode(k) + b"=" + os.fsencode(v)) for k, v in os.environb.items()] \
            if hasattr(os, "environb") else [frame("E", k + "=" + v) for k, v in os.environ.items()]
        request += [frame("A", a) for a in args]
        request.append(frame("O", "1" if os.isatty(0) and os.isatty(1) else "0"))
        ident = stdout_identity()
        if ident:
            request.append(frame("S", ident))
        if stdin:
            request.append(frame("I", b""))
        request.append(frame("G", b""))
        sock.sendall(b"".join(request))
        kind, data = read_frame(sock)
        if kind != "Y":
            return COLD  # K: cold (stale, busy, another folder...), N: refused
        sock.settimeout(None)
    except (OSError, EOFError, ValueError, KeyError, struct.error):
        return COLD
    if stdin:
        threading.Thread(target=pump_stdin, args=(sock,), daemon=True).start()
    out, err = sys.stdout.buffer, sys.stderr.buffer
    printed = False
    try:
        while True:
            kind, data = read_frame(sock)
            if kind == "1":
                out.write(data)
                out.flush()
                printed = True
            elif kind == "2":
                err.write(data)
                err.flush()
                printed = True
            elif kind == "K" and not printed:
                return COLD  # the run failed inside gcnc before any output: a cold JVM runs it again
            elif kind == "X":
                return int(data)
    except (OSError, EOFError, ValueError) as e:
        try:
            out.flush()
        finally:
            err.write(("gcnc: the resident checker stopped during this run (%s); run it again with GCNC_DAEMON=off\n"
                       % e).encode())
        return 2


if __name__ == "__main__":
    sys.exit(main())
