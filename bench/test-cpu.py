#!/usr/bin/env python3
"""The CPU of a whole test run, every process counted (the test JVMs, the JVMs and browsers they start).

    python3 bench/test-cpu.py [gradle arguments]     # default: cleanJunitPlatformTest junitPlatformTest

Runs `gradle --console=plain ARGS` from the checkout and samples /proc every 0.5 s: each process's
user+system time (a process that was already running counts from the first sample), grouped by what
it is. Prints the wall time, the CPU of each group and the total. A process that lives less than one
sample interval is missed: the total is a lower bound. Quote a figure with this command and the load.
"""
import os
import subprocess
import sys
import threading
import time

HZ = os.sysconf("SC_CLK_TCK")


def sample(stop, seen):
    first = {}
    initial = True
    while not stop.is_set():
        for p in os.listdir("/proc"):
            if not p.isdigit():
                continue
            try:
                with open(f"/proc/{p}/stat") as f:
                    st = f.read()
                with open(f"/proc/{p}/cmdline", "rb") as f:
                    cmd = f.read().replace(b"\0", b" ").decode(errors="replace")
            except OSError:
                continue
            fields = st[st.rindex(")") + 2:].split()
            cpu = (int(fields[11]) + int(fields[12])) / HZ
            first.setdefault(p, cpu if initial else 0)
            old = seen.get(p, (0, ""))
            seen[p] = (max(old[0], cpu - first[p]), cmd or old[1])
        initial = False
        time.sleep(0.5)


def group(cmd):
    exe = os.path.basename(cmd.split(" ", 1)[0])
    if exe.startswith("chrom"):
        return "chromium and chromedriver (the studio's browser tests)"
    if "ConsoleLauncher" in cmd:
        return "test JVMs (the lanes)"
    if "gradle-launcher" in cmd or "GradleDaemon" in cmd or "GradleWorkerMain" in cmd:
        return "gradle (this build, and ShopProjectTest's builds)"
    if "DaemonServer" in cmd:
        return "gcnc daemon (the resident checker's tests)"
    if " lsp" in cmd or "pytest" in cmd or "nvim" in cmd:
        return "language server and its clients"
    if "java" in cmd:
        return "other JVMs the tests start (gcnc runs)"
    return "other"


def main():
    args = sys.argv[1:] or ["cleanJunitPlatformTest", "junitPlatformTest"]
    load = os.getloadavg()[0]
    seen = {}
    stop = threading.Event()
    t = threading.Thread(target=sample, args=(stop, seen), daemon=True)
    t.start()
    start = time.time()
    status = subprocess.call(["gradle", "--console=plain"] + args, stdout=subprocess.DEVNULL,
                             stderr=subprocess.STDOUT, cwd=os.path.dirname(os.path.abspath(__file__)) + "/..")
    wall = time.time() - start
    stop.set()
    t.join()
    me = str(os.getpid())
    groups = {}
    for p, (cpu, cmd) in seen.items():
        if p != me:
            g = group(cmd)
            groups[g] = groups.get(g, 0) + cpu
    print(f"gradle {' '.join(args)}: exit {status}, {wall:.0f} s wall, load before: {load:.1f}")
    for g, cpu in sorted(groups.items(), key=lambda x: -x[1]):
        print(f"  {cpu:7.1f} s  {g}")
    print(f"  {sum(groups.values()):7.1f} s  CPU in all")
    sys.exit(status)


if __name__ == "__main__":
    main()
