#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# A curvilinear grid placed only by 2-D latitude/longitude through the tools as a user runs
# them: the curvilinear sample (a rotated pole written as lat(y, x), lon(y, x), a file per
# step) converts into a version-5 store with index axes and a GEOMETRY file that info
# shows and verify checks, and extracts in the axis frame (index coordinates) and, placed
# by those coordinates, in the lonlat, metric and ecef frames and with a geographic box; a folded
# grid is refused naming the cell; NCL's Eta file, whose coordinates attribute names
# variables it lacks, stays refused.
# Usage: curvilinear_cli_test.sh STRIELAD_CONVERT WORK_DIR
set -uo pipefail
convert=$1
work=$2
tools="$(dirname "$convert")/.."
serve="$tools/strielad-serve/strielad-serve"
sample="$tools/strielad-sample/strielad-sample"
rm -rf "$work" && mkdir -p "$work"
# shellcheck source=../support/expect_cli_error.sh
source "$(dirname "$0")/../support/expect_cli_error.sh"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
expect_convert() { expect_cli_error "$convert" "$work" "$@"; }

"$sample" -o "$work/in" --model curvilinear --dims 40x36x12 --steps 2 -q || fail "curvilinear sample"
ncdump -h "$work/in/curvilinear_t000.nc" 2>/dev/null | grep -Eq "rlon|rlat|grid_mapping" &&
  fail "the curvilinear sample has rotated axes or a grid mapping"
if "$convert" "$work/in"/*.nc -o "$work/store" -q; then
  "$convert" info "$work/store" >"$work/info" || fail "info"
  grep -Eq "^ +x +40 \(index, no units\): 0 \.\. 39" "$work/info" || fail "info: x is not an index axis"
  grep -q "^placed     by 2-D longitude 'lon' and latitude 'lat'" "$work/info" ||
    fail "info does not say the 2-D coordinates place the grid"
  grep -q "^geometry   curvilinear 40 x 36 from lon/lat" "$work/info" || fail "info shows no curvilinear geometry"
  "$convert" info "$work/store" --json >"$work/info.json" || fail "info --json"
  grep -q '"format_version": 5' "$work/info.json" || fail "the store is not version 5"
  grep -q '"curvilinear"' "$work/info.json" || fail "info --json has no curvilinear geometry"
  [[ -s $work/store/GEOMETRY ]] || fail "the store has no GEOMETRY file"
  "$convert" verify "$work/store" >"$work/verify" || fail "verify"
  echo '{"subvolumes": [{"id": 1, "limits": [{"var": "temp", "max": 265}]}]}' >"$work/scene.json"
  if "$serve" extract --store "$work/store" --scene "$work/scene.json" -o "$work/axis.vtp" \
    --frame axis --json >"$work/axis.json" 2>"$work/axis.err"; then
    [[ -s $work/axis.vtp ]] || fail "no axis.vtp"
    grep -q '"triangles": [1-9]' "$work/axis.json" || fail "axis extract: no triangles"
  else
    fail "extract --frame axis"
    cat "$work/axis.err"
  fi
  # Placed by the GEOMETRY coordinates in every other frame.
  for frame in lonlat metric ecef; do
    if "$serve" extract --store "$work/store" --scene "$work/scene.json" -o "$work/$frame.vtp" \
      --frame "$frame" --json >"$work/$frame.json" 2>"$work/$frame.err"; then
      grep -q '"triangles": [1-9]' "$work/$frame.json" || fail "$frame extract: no triangles"
      grep -q "\"frame\": \"$frame\"" "$work/$frame.json" || fail "$frame extract: frame not recorded"
    else
      fail "extract --frame $frame"
      cat "$work/$frame.err"
    fi
  done
  # A geographic box is evaluated on the stored coordinates.
  echo '{"format_version": 3, "subvolumes": [{"id": 1, "limits": [{"var": "temp", "max": 265}],
         "geographic": {"lat": [-90, 50]}}]}' >"$work/box.json"
  if "$serve" extract --store "$work/store" --scene "$work/box.json" -o "$work/box.vtp" \
    --frame lonlat --json >"$work/box.out" 2>"$work/box.err"; then
    grep -q '"triangles": [1-9]' "$work/box.out" || fail "geographic box: no triangles"
  else
    fail "extract with a geographic box"
    cat "$work/box.err"
  fi
else
  fail "conversion of the curvilinear sample"
fi

# A grid whose third column turns back west folds: refused with the cell at fault.
if command -v ncgen >/dev/null; then
  {
    echo 'netcdf fold { dimensions: lev = 2 ; y = 2 ; x = 3 ; variables:'
    echo ' double lev(lev) ; lev:units = "hPa" ;'
    echo ' double lat(y, x) ; lat:units = "degrees_north" ;'
    echo ' double lon(y, x) ; lon:units = "degrees_east" ;'
    echo ' float ta(lev, y, x) ; ta:units = "K" ; ta:coordinates = "lon lat" ;'
    echo 'data: lev = 1000, 500 ; lat = 0, 0, 0, 1, 1, 1 ; lon = 0, 1, 0.5, 0, 1, 0.5 ;'
    echo " ta = $(seq -s ', ' 201 212) ; }"
  } >"$work/fold.cdl"
  ncgen -o "$work/fold.nc" "$work/fold.cdl" || fail "ncgen of the folded grid"
  expect_convert 4 "the grid folds: the cell from (i 1, j 0) to (i 2, j 1)" -- "$work/fold.nc" \
    -o "$work/fold"
fi

# NCL's Eta file names gridlat_6 gridlon_6 in its coordinates attribute but lacks them.
eta=/usr/share/ncarg/data/cdf/ced1.lf00.t00z.eta.nc
if [[ -f $eta ]]; then
  expect_convert 5 "which the file does not contain" -- "$eta" -o "$work/eta"
fi

if [[ $failures -ne 0 ]]; then
  echo "$failures failure(s)"
  exit 1
fi
rm -rf "$work"
