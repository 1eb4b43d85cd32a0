#!/usr/bin/python3
# Writes illumA.dat: CIE illuminant A, 380-780 nm at 5 nm, as a Radiance 1-D data file
#   S_A(l) = 100 (560/l)^5 (exp(1.435e7/(2848*560)) - 1)/(exp(1.435e7/(2848 l)) - 1)
import math
c2 = 1.435e7
with open("illumA.dat", "w") as f:
    f.write("# CIE illuminant A (100 at 560 nm), 380 to 780 nm in 5 nm steps\n")
    f.write("1\n380 780 81\n")
    for i in range(81):
        l = 380 + 5 * i
        s = 100 * (560 / l) ** 5 * (math.exp(c2 / (2848 * 560)) - 1) / (math.exp(c2 / (2848 * l)) - 1)
        f.write("%.6f\n" % s)
