(mazak-reference-returns.nc, mazak-m with mazak-reference-returns.toml: G54 at X10 Y20 Z-50, linear G00,)
(block skip on; G91 G28 and G90 G30 P3 through the intermediate point, G27 check, G10 L20 then G54.1 P5.)
N1 G90 G54 G00 X10. Y10. Z5.
/N2 G01 X100. F100.
N3 G91 G28 Z10.
N4 G90 G30 P3 X0 Y0
N5 G00 X0 Y0 Z0
N6 G27 X-10. Y-20. Z50.
N7 G10 L20 P5 X100. Y100. Z-100.
N8 G54.1 P5 G00 X1. Y2. Z3.
N9 M30
