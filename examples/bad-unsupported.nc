(bad-unsupported.nc: a mirror image, a coordinate rotation, an impossible R arc, two codes of)
(one group and an offset number out of range. fanuc-m, each block is rejected on its own.)
(The arc comes first: after a rejected block a move that depends on it is not judged.)
G90 G00 X0 Y0
G02 X100. R40. F100.
G51.1 X10.
G68 X0 Y0 R45.
G90 G91 X1.
G43 Z1. H999
M30
