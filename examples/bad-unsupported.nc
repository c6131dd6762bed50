(bad-unsupported.nc: 3-D cutter compensation, thread cutting, an impossible R arc, two codes of)
(one group and an offset number out of range. fanuc-m, each block is rejected on its own.)
(The arc comes first: after a rejected block a move that depends on it is not judged.)
G90 G00 X0 Y0
G02 X100. R40. F100.
G41.2 X10. D1
G33 Z-10. F1.5
G90 G91 X1.
G43 Z1. H999
M30
