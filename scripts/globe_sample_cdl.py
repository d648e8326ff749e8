#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Writes a synthetic global 2.5-degree forecast as CDL on stdout (docs/view.md "The globe"):
#   python3 scripts/globe_sample_cdl.py > globe.cdl && ncgen -k nc4 -o globe.nc globe.cdl
import math, sys
nx, ny, nz = 144, 73, 16
lon = [2.5 * i for i in range(nx)]
lat = [-90 + 2.5 * j for j in range(ny)]
hgt = [1000.0 * k for k in range(nz)]
out = sys.stdout
out.write("netcdf globe {\ndimensions:\n time = UNLIMITED ;\n height = %d ;\n lat = %d ;\n lon = %d ;\n" % (nz, ny, nx))
out.write("variables:\n double time(time) ;\n  time:standard_name = \"time\" ;\n  time:units = \"seconds since 2024-06-21 12:00:00\" ;\n")
out.write(" double height(height) ;\n  height:standard_name = \"height\" ;\n  height:units = \"m\" ;\n  height:positive = \"up\" ;\n")
out.write(" double lat(lat) ;\n  lat:standard_name = \"latitude\" ;\n  lat:units = \"degrees_north\" ;\n")
out.write(" double lon(lon) ;\n  lon:standard_name = \"longitude\" ;\n  lon:units = \"degrees_east\" ;\n")
out.write(" float clw(time, height, lat, lon) ;\n  clw:units = \"kg kg-1\" ;\n")
out.write(" float orog(time, height, lat, lon) ;\n  orog:units = \"km\" ;\n")
out.write("data:\n time = 0 ;\n height = %s ;\n lat = %s ;\n lon = %s ;\n" % (
    ", ".join("%g" % v for v in hgt), ", ".join("%g" % v for v in lat), ", ".join("%g" % v for v in lon)))
def clw(i, j, k):
    lo, la, h = math.radians(lon[i]), lat[j], hgt[k]
    itcz = math.exp(-((la - 7) / 7.0) ** 2) * (0.6 + 0.4 * math.sin(3 * lo + 1.0))
    storms = math.exp(-((abs(la) - 50) / 9.0) ** 2) * max(0.0, math.sin(6 * lo + 0.08 * la)) ** 2
    level = math.exp(-((h - 5000) / 2800.0) ** 2)
    return 1e-4 * (itcz + storms) * level
vals = []
for k in range(nz):
    for j in range(ny):
        for i in range(nx):
            vals.append("%.4g" % clw(i, j, k))
out.write(" clw = " + ", ".join(vals) + " ;\n")
vals = []
for k in range(nz):
    for j in range(ny):
        for i in range(nx):
            vals.append("%g" % (hgt[k] / 1000.0))
out.write(" orog = " + ", ".join(vals) + " ;\n}\n")
