%
O0310 (a G70 with the allowances the post writes in every cycle)
G21 G40 G99
G50 S2000
T0101
G97 S500 M03
G00 X50. Z2.
G71 U2. R0.5
G71 P10 Q20 U0.4 W0.1 F0.25
N10 G00 X46.
N20 G01 Z-15.
(GCNC ALLOW E642: our post writes U and W in every G70; the control ignores them)
G70 P10 Q20 U0.4
G00 X100. Z50.
M30
%
