#!/usr/bin/env python3
"""Runs `gcnc check` on every part program in a folder and prints a Markdown table: the file, the
machine it was checked on, its errors by code (with lines), its warnings, and the verdict.

usage: scripts/check-folder.py FOLDER [--machine NAME] [--machine-for GLOB=NAME ...] [--jar JAR]

  --machine NAME          machine profile for every file (default: haas)
  --machine-for GLOB=NAME another profile for the files whose name matches GLOB, e.g. '*0100.nc=fanuc'
  --jar JAR               gcnc's jar (default: build/libs/gcnc.jar; build it with gradle assemble)

The verdict: "clean" (no error), "not supported yet" (only E110/E111: functions gcnc cannot follow
yet), or "errors" (at least one other error: a real mistake, or gcnc's own fault).
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


def main():
    ap = argparse.ArgumentParser(description="gcnc check over a folder, as a table")
    ap.add_argument("folder")
    ap.add_argument("--machine", default="haas")
    ap.add_argument("--machine-for", action="append", default=[])
    ap.add_argument("--jar", default="build/libs/gcnc.jar")
    a = ap.parse_args()
    if not os.path.isfile(a.jar):
        sys.exit(f"check-folder: {a.jar} not found (gradle assemble)")
    overrides = []
    for spec in a.machine_for:
        glob, _, machine = spec.partition("=")
        if not machine:
            sys.exit(f"check-folder: --machine-for takes GLOB=NAME, not '{spec}'")
        overrides.append((glob, machine))
    files = sorted(os.path.join(d, f) for d, _, fs in os.walk(a.folder) for f in fs
                   if f.lower().endswith(PROGRAMS) and not f.lower().startswith("readme"))
    print("| file | machine | errors | warnings | verdict |")
    print("|---|---|---|---|---|")
    for path in files:
        name = os.path.relpath(path, a.folder)
        machine = next((m for g, m in overrides if fnmatch.fnmatch(name, g)), a.machine)
        r = subprocess.run(["java", "-jar", a.jar, "check", path, "--machine", machine],
                           capture_output=True, text=True)
        if r.returncode not in (0, 1):
            sys.exit(f"check-folder: gcnc failed on {path}:\n{r.stderr}")
        errors, warnings = {}, {}
        for line in r.stderr.splitlines():
            m = LINE.match(line)
            if not m or m.group("sev") == "note":
                continue
            bucket = errors if m.group("sev") == "error" else warnings
            bucket.setdefault(m.group("code"), []).append(m.group("line"))
        if not errors:
            verdict = "clean"
        elif set(errors) <= NOT_YET:
            verdict = "not supported yet"
        else:
            verdict = "errors"
        print(f"| {name} | {machine} | {summary(errors)} | {summary(warnings)} | {verdict} |")


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
