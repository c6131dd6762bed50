(siemens-iso-feeds.nc, siemens-iso-m with siemens-iso-feeds.toml: G54 P2 extended work offset,)
(G95 feed per revolution, G04 in spindle revolutions under G95 - MD20734 bit2 = 1 -, G04 P in ms, G20 inch)
N10 G90 G54 P2 G00 X0 Y0 Z10.  ; G54 P2 = (50, 25, -100)
N20 G01 Z-5. F200.
N30 S1000 M03
N40 G95 G01 X20. F0.1          ; 0.1 mm per revolution
N50 G04 X2.                    ; two spindle revolutions in G95
N55 G94                        ; a dwell block holds nothing but G04 (§3.3.1)
N60 G04 P500                   ; 500 ms
N70 G20 G01 X1. F10.           ; inch input: 25.4 mm at 254 mm/min
N80 G21 G00 Z10.
N90 M30
