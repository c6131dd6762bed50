(bad-alarms.nc: compile-time alarms of fanuc-m with the FANUC numbers. Each block is rejected on its)
(own; what it would have changed is unknown afterwards, so G00 X0 Y0 fixes X/Y before G27.)
G90 G00 X0 Y0 Z0
G01 Z-1.
G02 X10. Y10. I3. J0 F100.
G00 X0 Y0
G27 X5.
G14 X1.
G00 B5.
G00 X1. Q2.
M3.5
G04 P1.5
M30
