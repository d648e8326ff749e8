#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Real model output through the tools as a new user runs it (libncarg-data): a rotated-pole
# EURO-CORDEX file is placed by its grid mapping (info shows the corners where cs2cs puts
# them), a global forecast on integer pressure levels extracts a longitude range across
# its seam into every output frame (the standard atmosphere named as the vertical), and
# NCEP's Lambert GRIB 2 forecast is placed where NCEP's grid table puts it, and grids that
# cannot be placed, or flags that make no sense, fail with one clear line.
# Usage: georeference_cli_test.sh STRIELAD_CONVERT WORK_DIR
set -uo pipefail
convert=$1
work=$2
serve="$(dirname "$convert")/../strielad-serve/strielad-serve"
data=/usr/share/ncarg/data
[[ -d $data ]] || { echo "libncarg-data not installed"; exit 77; }
rm -rf "$work" && mkdir -p "$work"
# shellcheck source=../support/expect_cli_error.sh
source "$(dirname "$0")/../support/expect_cli_error.sh"
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# Rotated pole: the grid's first sample lies at 10.06 W 21.99 N (cs2cs), not 28.4 W 23.4 S.
"$convert" "$data/nug/tas_rotated_grid_EUR11.nc" -o "$work/eur11" -q || fail "EUR-11 conversion"
"$convert" info "$work/eur11" >"$work/info" || fail "info"
grep -q "placed     by grid mapping 'rotated_pole' (rotated_latitude_longitude)" "$work/info" ||
  fail "info does not show the mapping"
grep -q "(-28.375, -23.375) at lon -10.063880, lat 21.987829" "$work/info" ||
  fail "info places the first sample elsewhere: $(grep 'first x, first y' "$work/info")"
grep -q "rlon .*projection_x" "$work/info" || fail "rlon is not a projection axis"
"$convert" info "$work/eur11" --json >"$work/info.json" || fail "info --json"
grep -q '"grid_mapping_name": "rotated_latitude_longitude"' "$work/info.json" ||
  fail "info --json lacks the mapping"

# A global 2.8125-degree forecast on integer hPa levels: periodic, a range across the seam.
"$convert" "$data/cdf/nc4uvt.nc" -o "$work/global" --vars T --brick 8 -q || fail "nc4uvt conversion"
"$convert" info "$work/global" | grep -q "periodic (round the Earth)" || fail "nc4uvt not periodic"
echo '{"subvolumes": [{"id": 1, "limits": [{"var": "T", "min": -40}],
  "domain": {"lon": [150, 210], "lev": [300, 850]}}]}' >"$work/seam.json"
for frame in axis lonlat metric ecef; do
  "$serve" extract --store "$work/global" --scene "$work/seam.json" -o "$work/$frame.vtp" \
    --seamless --frame "$frame" --json >"$work/$frame.json" 2>"$work/$frame.err" ||
    { fail "extract --frame $frame"; cat "$work/$frame.err"; continue; }
  grep -q "\"frame\": \"$frame\"" "$work/$frame.json" || fail "--json lacks the frame $frame"
  [[ -s $work/$frame.vtp ]] || fail "no $frame.vtp"
done
grep -q "ICAO standard atmosphere of pressure axis 'lev'" "$work/ecef.json" ||
  fail "the ecef output does not say how heights were found"

expect() { expect_cli_error "$serve" "$work" "$@"; }
echo '{"subvolumes": [{"id": 1, "domain": {"lon": [40, 50]}}]}' >"$work/nowhere.json"
"$convert" "$data/cdf/contour.cdf" -o "$work/contour" --vars T -q || fail "contour.cdf conversion"
expect 2 "--height-var" -- extract --store "$work/global" --scene "$work/seam.json" \
  -o "$work/x.vtp" --height-var T
expect 4 "selects no longitude" -- extract --store "$work/contour" --scene "$work/nowhere.json" \
  -o "$work/x.vtp"

expect_convert() { expect_cli_error "$convert" "$work" "$@"; }
expect_convert 5 "curvilinear grid" -- "$data/cdf/ced1.lf00.t00z.eta.nc" -o "$work/eta"
grep -q "gridlat_6 gridlon_6" "$work/err" || fail "the curvilinear error does not name the coordinates"
expect_convert 5 "unstructured grid" -- "$data/nug/triangular_grid_ICON.nc" -o "$work/icon"
for store in eta icon; do [[ -e $work/$store ]] && fail "a refused conversion left $store behind"; done

# GRIB 2, NCEP's AWIPS grid 211 (Lambert): placed where NCEP's grid table puts its corners
# (first point 12.190 N 133.459 W, last 57.290 N 49.385 W), extracted into true positions.
"$convert" "$data/grb/fh.0012_tl.press_gr.awp211.grb2" -o "$work/awp211" -q || fail "GRIB conversion"
"$convert" info "$work/awp211" >"$work/grib.info" || fail "GRIB info"
grep -q "(lambert_conformal_conic)" "$work/grib.info" || fail "GRIB info lacks the Lambert mapping"
grep -q "at lon -133.459000, lat 12.190000" "$work/grib.info" || fail "GRIB first point misplaced"
grep -q "at lon -49.3850.., lat 57.2894" "$work/grib.info" || fail "GRIB last point misplaced"
echo '{"subvolumes": [{"id": 1, "limits": [{"var": "t", "max": 250}]}]}' >"$work/cold.json"
"$serve" extract --store "$work/awp211" --scene "$work/cold.json" -o "$work/cold.vtp" \
  --frame lonlat --json >"$work/cold.json.out" || fail "GRIB extract"
grep -q "height from variable 'gh'" "$work/cold.json.out" || fail "GRIB heights not from gh"
expect_convert 4 "GRIB message 1" -- "$data/grb/ced1.lf00.t00z.eta.grb" -o "$work/eta-grib"
expect_convert 5 "cdo setgridtype,regular" -- "$data/grb/wafsgfs_L_t06z_intdsk60.grib2" -o "$work/wafs"

# Gaussian T42 with coordinates named unlike their dimensions: paired, converted.
"$convert" "$data/cdf/ex01B1_uv300.hs.nc" -o "$work/t42" 2>"$work/t42.err" || fail "ex01B1 conversion"
grep -q "dimension 'longitude' has no coordinate variable of its name; using 'lon'" "$work/t42.err" ||
  fail "the pairing is not logged"

if [[ $failures -ne 0 ]]; then
  echo "$failures failure(s)"
  exit 1
fi
rm -rf "$work"
