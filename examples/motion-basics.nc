(motion-basics.nc: G00, G01, G02/G03 with I/J/K and signed R, a full circle, a helix,)
(G18/G19 arcs, incremental arcs, G04 dwell in X and P, G95 feed per revolution, G20 inch.)
(fanuc-m on the default machine: X Y Z, G54-G59 at zero, standard decimal point, IS-B.)
N10 G21 G17 G90 G94 G00 X0 Y0 Z5. S1000 M03
N20 G01 Z-1. F200.
N30 X20. F300.
N40 G03 X30. Y10. J10.
N50 G02 X40. Y20. R10.
N60 G02 X50. Y10. R-10.
N70 G02 J-10.
N80 G91 G03 X-10. Y-10. I-10. Z-2.
N90 G90 G18 G02 X30. Z-13. I-10.
N100 G19 G03 Y10. Z-3. K10.
N110 G17 G04 X1.5
N120 G04 P250
N130 G95 G01 X40. F20
N140 G94 G20 G01 X2. Y1. F10.
N150 G21 G00 Z5.
N160 X0 Y0
N170 M05 M30
