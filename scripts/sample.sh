#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The main job on the built-in sample dataset: install what is missing, build, generate a
# CF-NetCDF sample (4 time steps, 8 variables), convert it to a brick store, verify it,
# and describe it. Set DIMS (default 286x312x60, a fifth of the paper's grid per axis
# horizontally) to change the size, e.g. DIMS=1429x1556x150 for one full paper grid.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
# The three end-user tools only (the viewer for the figure command in the README), not
# the tests and the benchmarks: scripts/test.sh builds everything.
scripts/build.sh strielad-sample strielad-convert strielad-serve strielad-view
convert=build/cmd/strielad-convert/strielad-convert
sample=build/cmd/strielad-sample/strielad-sample
dims=${DIMS:-286x312x60}
out=${OUT:-sample-data}
rm -rf "$out/store"
"$sample" -o "$out/netcdf" --dims "$dims" --steps 4 --terrain 1024 --tracks 3000
# The DEM is not an input of the conversion: next to the store, not among the .nc inputs.
mv "$out/netcdf/sample_terrain.nc" "$out/sample_terrain.nc"
"$convert" "$out"/netcdf/*.nc -o "$out/store"
"$convert" verify "$out/store"
"$convert" info "$out/store"
"$convert" export-vdb "$out/store" --var clw --time 0 --level 0 -o "$out/clw-t0.vdb"
echo "store written to $out/store; clw at step 0 exported to $out/clw-t0.vdb"
