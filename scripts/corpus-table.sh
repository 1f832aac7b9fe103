#!/usr/bin/env bash
# The corpus table of docs/guide.md: gcnc over the real programs of ../shared/corpus (read where they
# are, never copied), each on the machine it was written for and simulated from a blank that fits it.
#   haas:  every file but the three written for a Fanuc (0100.nc, O1000_with_G02.nc, t24.gcode)
#   blank: the profile's 2 in bar, except
#     mark-brannan/*  0.375 in bar ("material is .375 SS round stock"), 160 mm long, 150 mm out
#                     (the haas profile's work zero is 150 mm from the jaws)
#     weld_pin        1.5 in bar: its G71 roughs from X1.5 and its finish faces the shoulder up to X1.5
#     0100.nc         none: op 2 of a 350 mm flange, a shape no bar describes (the stock checks are skipped)
#   verdicts: cadekiely/O58214.nc is clean since issue 17 (its G70's U and D, which the control
#     ignores, are two warnings E642, not error E161); CorpusTest pins the same verdicts
# usage: scripts/corpus-table.sh [CORPUS]     (needs build/libs/gcnc.jar: gradle assemble)
set -eu
cd "$(dirname "$0")/.."
corpus=${1:-../shared/corpus}
exec python3 scripts/check-folder.py "$corpus" --machine haas \
    --machine-for '*0100.nc=fanuc' --machine-for '*O1000*=fanuc' --machine-for '*t24*=fanuc' \
    --simulate \
    --stock-for 'mark-brannan/*=9.525,160,150' \
    --stock-for '*weld_pin.nc=38.1,160,150' \
    --stock-for '*0100.nc=none'
