#!/usr/bin/env python3
"""Writes a shop's library of small part programs for bench/library.sh: folders of PER programs for
the Haas profile, and in each folder SUBS subprogram files (O9001.nc, ...) that every CALL-th program
calls with M98 (the file beside it, as a control's memory holds it; gcnc.flow.Library).

usage: gen_library.py PROGRAMS OUT_DIR [--per 100] [--subs 4] [--call 10]

Each part program faces a bar and turns a diameter, about 16 blocks; the diameters and lengths vary
with its number so that no two programs are the same. A called file is clean on its own too (a
retract), apart from E139 (M99 in a main program), a warning.
"""
import os, sys

def option(name, default):
    return int(sys.argv[sys.argv.index(name) + 1]) if name in sys.argv else default

def main():
    programs, out = int(sys.argv[1]), sys.argv[2]
    per, subs, call = option("--per", 100), option("--subs", 4), option("--call", 10)
    for k in range(programs):
        folder = os.path.join(out, "src/main/gcode", f"cell{k // per:03d}")
        if k % per == 0:
            os.makedirs(folder, exist_ok=True)
            for s in range(subs):
                with open(os.path.join(folder, f"O{9001 + s}.nc"), "w") as f:
                    f.write(f"O{9001 + s} (RETRACT CLEAR OF THE PART, CELL {k // per})\n"
                            f"G21 G54 G00 X{46 + s}. Z{5 + s}.\nM99\n")
        number = 10000 + k
        d = 20 + (k % 17)            # finished diameter
        z = 10 + (k % 23)            # length turned
        lines = [f"O{number} (PART {number}: FACE AND TURN D{d})", "G21 G18 G40 G99", "G28 U0. W0.", "T101",
                 "G50 S3000", "G96 S200 M03", f"G54 G00 X{d + 6}. Z2. M08", "G01 Z0. F0.2", "X-1.6",
                 f"G00 X{d}. Z2.", f"G01 Z-{z}. F0.25", f"X{d + 6}.", "G00 Z2."]
        if k % call == 0:
            lines.append(f"M98 P{9001 + (k // call) % subs}")
        lines += ["M09", "G28 U0. W0.", "M05", "M30"]
        with open(os.path.join(folder, f"o{number}.nc"), "w") as f:
            f.write("\n".join(lines) + "\n")

main()
