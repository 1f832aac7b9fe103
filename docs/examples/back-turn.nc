(A part program with a cut the insert cannot make, for trying gcnc: gcnc simulate docs/examples/back-turn.nc)
(Blank 44 mm, generic lathe. T01 is an 80-degree CNMG insert on a 95-degree holder: it cuts toward)
(the chuck and faces down, but it cannot turn back toward the tailstock deeper than its trailing edge.)
O1004
N10 G21 G90 G98
N20 G50 S2500
N30 M11
N40 T0101
N50 S1000 M03
N60 G00 X46. Z2.
N70 G00 X40.
N80 G01 Z-30. F120.
N90 G01 X30.
N100 G01 Z-20.
N110 G00 X46.
N120 G00 Z2.
N130 M05
N140 M30
