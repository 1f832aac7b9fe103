#!/usr/bin/env python3
"""Runs gcnc over every part program in a folder and prints a Markdown table: the file, the machine
it was checked on, its errors by code (with lines), its warnings, the verdict of `gcnc check`, and
with --simulate the verdict of `gcnc simulate` (compile, then replay on the machine's model) on the
blank given for the file.

usage: scripts/check-folder.py FOLDER [--machine NAME] [--machine-for GLOB=NAME ...]
                               [--simulate] [--stock-for GLOB=DIA,LENGTH,STICKOUT|none ...] [--jar JAR]

  --machine NAME          machine profile for every file (default: haas)
  --machine-for GLOB=NAME another profile for the files whose name matches GLOB, e.g. '*0100.nc=fanuc'
  --simulate              also simulate each file that checks clean (the column "simulation")
  --stock-for GLOB=STOCK  the blank to simulate the files matching GLOB from: gcnc's --stock value
                          (mm: diameter,length,stick-out; or none for a part no bar describes);
                          without one, the program's stock header or the profile's blank
  --jar JAR               gcnc's jar (default: build/libs/gcnc.jar; build it with gradle assemble)

The verdict: "clean" (no error), "not supported yet" (only E110/E111: functions gcnc cannot follow
yet), or "errors" (at least one other error: a real mistake, or gcnc's own fault). The simulation:
"clean", the findings by code with lines, or "-" when the file does not check clean.
Exit status 0 whatever the programs hold; 2 when gcnc itself cannot run.
"""
import argparse
import fnmatch
import os
import re
import subprocess
import sys

PROGRAMS = (".nc", ".ngc", ".tap", ".gcode", ".txt")
LINE = re.compile(r"^(?P<file>.+?):(?P<line>\d+):(?P<col>\d+): (?P<sev>error|warning|note)\[(?P<code>E\d+)\]")
NOT_YET = {"E110", "E111"}


def pairs(specs, what):
    out = []
    for spec in specs:
        glob, _, value = spec.partition("=")
        if not value:
            sys.exit(f"check-folder: {what} takes GLOB=VALUE, not '{spec}'")
        out.append((glob, value))
    return out


def gcnc(jar, args):
    r = subprocess.run(["java", "-jar", jar] + args, capture_output=True, text=True)
    if r.returncode not in (0, 1):
        sys.exit(f"check-folder: gcnc {' '.join(args)} failed:\n{r.stderr}")
    errors, warnings = {}, {}
    for line in r.stderr.splitlines():
        m = LINE.match(line)
        if not m or m.group("sev") == "note":
            continue
        bucket = errors if m.group("sev") == "error" else warnings
        bucket.setdefault(m.group("code"), []).append(m.group("line"))
    return errors, warnings


def main():
    ap = argparse.ArgumentParser(description="gcnc over a folder, as a table")
    ap.add_argument("folder")
    ap.add_argument("--machine", default="haas")
    ap.add_argument("--machine-for", action="append", default=[])
    ap.add_argument("--simulate", action="store_true")
    ap.add_argument("--stock-for", action="append", default=[])
    ap.add_argument("--jar", default="build/libs/gcnc.jar")
    a = ap.parse_args()
    if not os.path.isfile(a.jar):
        sys.exit(f"check-folder: {a.jar} not found (gradle assemble)")
    machines = pairs(a.machine_for, "--machine-for")
    stocks = pairs(a.stock_for, "--stock-for")
    files = sorted(os.path.join(d, f) for d, _, fs in os.walk(a.folder) for f in fs
                   if f.lower().endswith(PROGRAMS) and not f.lower().startswith("readme"))
    head = "| file | machine | errors | warnings | verdict |"
    print(head + (" blank | simulation |" if a.simulate else ""))
    print("|---|---|---|---|---|" + ("---|---|" if a.simulate else ""))
    for path in files:
        name = os.path.relpath(path, a.folder)
        machine = next((m for g, m in machines if fnmatch.fnmatch(name, g)), a.machine)
        errors, warnings = gcnc(a.jar, ["check", path, "--machine", machine])
        if not errors:
            verdict = "clean"
        elif set(errors) <= NOT_YET:
            verdict = "not supported yet"
        else:
            verdict = "errors"
        row = f"| {name} | {machine} | {summary(errors)} | {summary(warnings)} | {verdict} |"
        if a.simulate:
            stock = next((s for g, s in stocks if fnmatch.fnmatch(name, g)), None)
            blank = f"`--stock {stock}`" if stock else "header or profile"
            if errors:
                row += f" {blank} | - |"
            else:
                found, _ = gcnc(a.jar, ["simulate", path, "--machine", machine]
                                + (["--stock", stock] if stock else []))
                row += f" {blank} | {summary(found) if found else 'clean'} |"
        print(row)


def summary(by_code):
    if not by_code:
        return "-"
    parts = []
    for code in sorted(by_code):
        lines = by_code[code]
        shown = ", ".join(lines[:6]) + (", ..." if len(lines) > 6 else "")
        parts.append(f"{code} ×{len(lines)} (line {shown})" if len(lines) > 1 else f"{code} (line {shown})")
    return "; ".join(parts)


if __name__ == "__main__":
    main()
