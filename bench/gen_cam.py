#!/usr/bin/env python3
"""A CAM-style finishing program in a Haas shop's words: passes of 399 short chords along a wavy
profile, each pass a rapid approach, a feed along the chords and a rapid retract, until BLOCKS
blocks are written. The program the stream form's figures come from (docs/galil.md, "Two forms";
docs/run.md; RunStreamTest -PlongRun writes the same one).
usage: bench/gen_cam.py [BLOCKS] [OUT]   (default 100000 blocks, standard output)"""
import math
import sys

blocks = int(sys.argv[1]) if len(sys.argv) > 1 else 100000
lines = ["%", "O1234 (LONG CAM FINISH)", "G21 G18 G40 G99", "G28 U0. W0.", "T0101", "G97 S1200 M03",
         "G00 X52. Z2. M08"]
n = 0
p = 0
while n < blocks:
    d = 50 - (p % 10) * 0.5
    lines.append(f"G00 X{d:.3f} Z1.")
    lines.append("G01 Z0. F0.2")
    for k in range(1, 400):
        lines.append(f"X{d - 2 + math.sin(k / 40.0):.3f} Z{-k * 0.05:.3f}")
    lines.append(f"G00 X{d + 2:.3f}")
    lines.append("Z1.")
    n += 403
    p += 1
lines += ["G00 X60. Z5. M09", "G28 U0. W0. M05", "M30", "%"]
text = "\n".join(lines) + "\n"
if len(sys.argv) > 2:
    with open(sys.argv[2], "w") as f:
        f.write(text)
else:
    sys.stdout.write(text)
