(machine-functions.nc: T and M06 tool change, S with M03/M04/M05, M08/M09 coolant, M19 orient,)
(M00/M01 stops the run goes through, an M code passed through as a machine function, G10 L12/L13)
(cutter-radius registers. fanuc-m on the default machine. The moves golden shows the motion; the)
(disassembly golden shows every machine function in program order.)
O1000
N10 T1 M06
N20 S1200 M03
N30 M08
N40 G00 X10. Y10.
N50 M01
N60 M04 S800
N70 M00
N80 G01 X20. F150.
N90 M05
N100 M19
N110 M09 M50
N120 G10 L12 P3 R5.
N130 G10 L13 P3 R-0.1
N140 M30
