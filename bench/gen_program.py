#!/usr/bin/env python3
"""Writes a long, valid turning program for the generic profile: roughing passes with arcs.

usage: gen_program.py BLOCKS OUT.nc [--rs274] [--drill]   (BLOCKS counts every block, header and footer included)

--drill first drills and bores the part, as most real parts are: a centre drill (T02), a 20 mm drill
in pecks (T03) and a boring bar (T04) opening the hole to 24 mm, 14 mm deep (tools as
bench/drill.machine describes them); the roughing passes then stop at 30 mm, outside the bore.

--rs274 writes the same geometry for LinuxCNC's standalone interpreter `rs274` (bench/versus-rs274.sh):
the same passes, diameters, feeds and arcs, block for block, with LinuxCNC's own words for the header
(G18 G7: the XZ plane in diameter mode, G94 for the Fanuc lathe's G98, a tool change by T1 M6, M9 for
the chuck's M11) and a comment for the program number. Both files have the same number of blocks.
"""
import sys

def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    rs274 = "--rs274" in sys.argv[1:]
    drill = "--drill" in sys.argv[1:]
    blocks, out = int(args[0]), args[1]
    if rs274:
        first = "(O2000)"
        header = ["G18 G7 G21 G90 G94", "G64", "M9", "T1 M6", "S1200 M3", "G00 X52. Z2."]
        footer = ["G00 X60. Z5.", "M5", "M30"]
    else:
        first = "O2000"
        header = ["G21 G90 G98", "G50 S2500", "M11", "T0101", "S1200 M03", "G00 X52. Z2."]
        footer = ["G00 X60. Z5.", "M05", "M30"]
    if drill:
        holes = ["T0202", "G00 X0. Z2.", "G01 Z-4. F60.", "G00 Z2.", "T0303", "G00 X0. Z2."]
        for depth in (-5, -10, -15, -18):
            holes += [f"G01 Z{depth}. F80.", "G00 Z2."]
        holes += ["T0404", "G00 X20. Z2."]
        for bore in (21, 22, 23, 24):
            holes += [f"G00 X{bore}.", "G01 Z-14. F100.", f"G00 X{bore - 1}.", "G00 Z2."]
        holes += ["T0101", "G00 X52. Z2."]
        header = header[:-3] + [header[-2]] + holes
    body = blocks - len(header) - len(footer)
    n = 10
    with open(out, "w") as f:
        f.write(first + "\n")
        body -= 1
        for b in header:
            f.write(f"N{n} {b}\n"); n += 1
        written = 0
        d = 50.0
        while written < body:
            pass_blocks = [
                f"G00 X{d:.3f} Z2.",
                f"G01 Z-40.5 F120.",
                f"G02 X{d + 2:.3f} Z-41.5 R1.",
                f"G01 X{d + 4:.3f}",
                "G00 Z2.",
            ]
            for b in pass_blocks[: body - written]:
                f.write(f"N{n} {b}\n"); n += 1
            written += len(pass_blocks)
            d = d - 0.25 if d > (30 if drill else 21) else 50.0
        for b in footer:
            f.write(f"N{n} {b}\n"); n += 1

if __name__ == "__main__":
    main()
