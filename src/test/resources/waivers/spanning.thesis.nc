N10 G21 G90
(GCNC ALLOW E642 FILE:
  nothing of the kind here)
N20 M30
