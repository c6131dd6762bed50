(Hole cycles on one row: G81 drilling, G83 peck drilling, G76 fine boring)
(docs/cycles.md draws each with ncc plot --from/--to)
G90 G54 G17 G00 X0 Y0 Z50.
T1 M06
S1000 M03
G98 G81 X10. Y10. R3. Z-10. F100.
G99 G83 X30. Y10. R3. Z-12. Q5. F100.
G98 G76 X50. Y10. R3. Z-8. Q1. P500 F80.
G80 G00 Z50.
M30
