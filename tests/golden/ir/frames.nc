(frames.nc: each block's frame, kept beside work-space targets by lower and added to them by)
(work-to-machine: a G10 work offset, tool length, G52 local and G92 shifts, an arc centre.)
N10 G90 G17 G21 G10 L2 P1 X100. Y50. Z-10.
N20 G54 G00 X10. Y10. Z5. S800 M03
N30 G10 L10 P1 R25.
N40 G43 H1 Z5.
N50 G01 Z-2. F300.
N60 G52 X5. Y5.
N70 G02 X15. Y5. R10.
N80 G52 X0 Y0
N90 G92 X0 Y0
N100 G01 X10. F200.
N110 G92.1 X0 Y0
N120 G49 G00 Z50.
N130 M05 M30
