#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Writes a synthetic global 2.5-degree forecast as CDL on stdout (docs/view.md "The globe"):
#   python3 scripts/globe_sample_cdl.py > globe.cdl && ncgen -k nc4 -o globe.nc globe.cdl
# --wind: two steps 6 hours apart (0 and 6 UTC after 2024-06-21 12:00) with wind ua, va,
# wa (m/s) for advection (docs/advection.md): easterly trades, westerlies peaking at
# 45 degrees of latitude, no meridional or vertical wind.
# --grid NXxNYxNZ: another grid (longitudes every 360/NX degrees, latitudes -90..90,
# heights every 15/(NZ-1) km), e.g. 48x25x8 for tests.
import argparse, math, sys
parser = argparse.ArgumentParser()
parser.add_argument("--wind", action="store_true")
parser.add_argument("--grid", default="144x73x16")
args = parser.parse_args()
nx, ny, nz = (int(v) for v in args.grid.split("x"))
lon = [360.0 / nx * i for i in range(nx)]
lat = [-90 + 180.0 / (ny - 1) * j for j in range(ny)]
hgt = [15000.0 / (nz - 1) * k for k in range(nz)]
times = [0, 21600] if args.wind else [0]
out = sys.stdout
out.write("netcdf globe {\ndimensions:\n time = UNLIMITED ;\n height = %d ;\n lat = %d ;\n lon = %d ;\n" % (nz, ny, nx))
out.write("variables:\n double time(time) ;\n  time:standard_name = \"time\" ;\n  time:units = \"seconds since 2024-06-21 12:00:00\" ;\n")
out.write(" double height(height) ;\n  height:standard_name = \"height\" ;\n  height:units = \"m\" ;\n  height:positive = \"up\" ;\n")
out.write(" double lat(lat) ;\n  lat:standard_name = \"latitude\" ;\n  lat:units = \"degrees_north\" ;\n")
out.write(" double lon(lon) ;\n  lon:standard_name = \"longitude\" ;\n  lon:units = \"degrees_east\" ;\n")
out.write(" float clw(time, height, lat, lon) ;\n  clw:units = \"kg kg-1\" ;\n")
out.write(" float orog(time, height, lat, lon) ;\n  orog:units = \"km\" ;\n")
if args.wind:
    for name in ("ua", "va", "wa"):
        out.write(" float %s(time, height, lat, lon) ;\n  %s:units = \"m s-1\" ;\n" % (name, name))
out.write("data:\n time = %s ;\n height = %s ;\n lat = %s ;\n lon = %s ;\n" % (
    ", ".join("%g" % t for t in times), ", ".join("%g" % v for v in hgt),
    ", ".join("%g" % v for v in lat), ", ".join("%g" % v for v in lon)))
def clw(i, j, k):
    lo, la, h = math.radians(lon[i]), lat[j], hgt[k]
    itcz = math.exp(-((la - 7) / 7.0) ** 2) * (0.6 + 0.4 * math.sin(3 * lo + 1.0))
    storms = math.exp(-((abs(la) - 50) / 9.0) ** 2) * max(0.0, math.sin(6 * lo + 0.08 * la)) ** 2
    level = math.exp(-((h - 5000) / 2800.0) ** 2)
    return 1e-4 * (itcz + storms) * level
def ua(i, j, k):
    la, h = lat[j], hgt[k]
    westerlies = 30.0 * math.exp(-((abs(la) - 45) / 12.0) ** 2) * (0.5 + h / 15000.0)
    trades = -6.0 * math.exp(-(la / 15.0) ** 2)
    return (westerlies + trades) * math.cos(math.radians(la))
def field(f, fmt):
    vals = []
    for _ in times:
        for k in range(nz):
            for j in range(ny):
                for i in range(nx):
                    vals.append(fmt % f(i, j, k))
    return ", ".join(vals)
out.write(" clw = " + field(clw, "%.4g") + " ;\n")
out.write(" orog = " + field(lambda i, j, k: hgt[k] / 1000.0, "%g") + " ;\n")
if args.wind:
    out.write(" ua = " + field(ua, "%.4g") + " ;\n")
    out.write(" va = " + field(lambda i, j, k: 0.0, "%g") + " ;\n")
    out.write(" wa = " + field(lambda i, j, k: 0.0, "%g") + " ;\n")
out.write("}\n")
