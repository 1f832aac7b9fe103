#!/usr/bin/env python3
"""Writes a Haas program of MOVES rapids that all enter the blank (bench/sim-cost.sh).

usage: gen_rapids.py MOVES OUT.nc

Each rapid plunges the 60 deg threading insert (T0303) 0.03 mm further toward the chuck and
0.004 mm deeper than the last: every one reaches into material not yet cut (E305) and leaves its
notch in the stock, which grows more ragged with every move.
"""
import sys

def main():
    moves, out = int(sys.argv[1]), sys.argv[2]
    with open(out, "w") as f:
        f.write("%\nO1002\nG21 G18 G40 G54 G80 G99\nT0303\nG97 S1000 M03\nG00 X60. Z2.\n")
        for i in range(moves):
            f.write(f"G00 Z{-5.0 - i * 0.03:.3f}\nX{50.0 - i * 0.004:.3f}\nX60.\n")
        f.write("G00 Z5.\nM30\n%\n")

if __name__ == "__main__":
    main()
