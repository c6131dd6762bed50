(bad-alarms.nc: compile-time alarms of fanuc-m with the FANUC numbers. Each block is rejected on its)
(own and leaves the state as it was, so one run reports them all.)
G90 G00 X0 Y0 Z0
G01 X10.
G02 X10. Y10. I3. J0 F100.
G27 X5.
G14 X1.
G00 B5.
G00 X1. Q2.
M3.5
G04 P1.5
M30
