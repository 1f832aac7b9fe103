(A part program with five mistakes, for trying gcnc: gcnc check docs/examples/mistakes.nc)
O1003
N10 G21 G90 G98
N20 G50 S2500
N30 M11
N40 T0101
N50 G00 X42. Z2.
N60 G01 X40. F120.
N70 S3000 M03
N80 G01 Z-30.
N90 G01 X44. Z-31. $
N100 G02 X50. Z-60. R3.
N110 G00 X300. Z5.
N120 M05
N130 M30
