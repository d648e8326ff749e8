#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Terrain-following model output through the tools as a user runs them: the ICON-like,
# CF hybrid-height, hybrid sigma-pressure and WRF-like (a file per step, Lambert, PH+PHB)
# samples convert into stores that record their
# grid geometry (info, info --json, verify), extract into every output frame with heights
# from the geometry, cut a height band by the geometry's field, export it as a .vdb; NCAR's
# CCM hybrid file (libncarg-data vinth2p.nc) is refused without P0 and converts with it;
# --height-var is refused where the geometry places heights.
# Usage: terrain_following_cli_test.sh STRIELAD_CONVERT WORK_DIR
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

declare -A limit=([icon]='"var": "temp", "max": 265' [icon-cf]='"var": "temp", "max": 265'
  [sigma-pressure]='"var": "t", "max": 265' [wrf]='"var": "QCLOUD", "min": 1e-5')
declare -A placed_by=([icon]="variable z_ifc" [icon-cf]="atmosphere_hybrid_height_coordinate"
  [sigma-pressure]="atmosphere_hybrid_sigma_pressure_coordinate" [wrf]="variable PH + PHB")
for model in icon icon-cf sigma-pressure wrf; do
  # WRF writes a file per step (wrfout_d01_<date>); the others one file.
  "$sample" -o "$work/in-$model" --model "$model" --dims 40x36x16 --steps 2 \
    $([[ $model == wrf ]] || echo --single-file) -q || fail "$model sample"
  "$convert" "$work/in-$model"/* -o "$work/$model" -q || { fail "$model conversion"; continue; }
  "$convert" info "$work/$model" >"$work/$model.info" || fail "$model info"
  grep -q "^geometry " "$work/$model.info" || fail "$model info shows no geometry"
  [[ $model != wrf ]] || grep -q "(lambert_conformal_conic)" "$work/$model.info" ||
    fail "the WRF store is not placed by its Lambert projection"
  "$convert" info "$work/$model" --json >"$work/$model.info.json" || fail "$model info --json"
  grep -q '"geometry"' "$work/$model.info.json" || fail "$model info --json has no geometry"
  grep -q '"format_version": 5' "$work/$model.info.json" || fail "$model store is not version 5"
  "$convert" verify "$work/$model" >"$work/$model.verify" || fail "$model verify"
  echo "{\"subvolumes\": [{\"id\": 1, \"limits\": [{${limit[$model]}}]}]}" >"$work/$model.scene.json"
  for frame in axis lonlat metric ecef; do
    "$serve" extract --store "$work/$model" --scene "$work/$model.scene.json" \
      -o "$work/$model.$frame.vtp" --frame "$frame" --json >"$work/$model.$frame.json" \
      2>"$work/$model.$frame.err" || { fail "$model extract --frame $frame"; cat "$work/$model.$frame.err"; continue; }
    [[ -s $work/$model.$frame.vtp ]] || fail "$model: no $frame.vtp"
    grep -q '"triangles": [1-9]' "$work/$model.$frame.json" || fail "$model $frame: no triangles"
  done
  grep -q "grid geometry: .* from ${placed_by[$model]}" "$work/$model.lonlat.json" ||
    fail "$model lonlat output does not say the geometry placed it"
done

# WRF's T is stored as the potential temperature theta = T + 300 K, in T's place.
grep -Eq "^ +theta +float32 +K +.*potential temperature \(T \+ 300 K\)" "$work/wrf.info" ||
  fail "the WRF store has no theta"
grep -Eq "^ +T +float32" "$work/wrf.info" && fail "the WRF store converted T by default"

# CF atmosphere_ln_pressure_coordinate: a plain pressure axis (p0 * exp(-lev), in Pa).
if command -v ncgen >/dev/null; then
  {
    echo 'netcdf ln { dimensions: lev = 4 ; lat = 3 ; lon = 4 ; variables:'
    echo ' double lev(lev) ; lev:axis = "Z" ;'
    echo '  lev:standard_name = "atmosphere_ln_pressure_coordinate" ;'
    echo '  lev:formula_terms = "p0: p0 lev: lev" ;'
    echo ' double p0 ; p0:units = "hPa" ;'
    echo ' double lat(lat) ; lat:units = "degrees_north" ;'
    echo ' double lon(lon) ; lon:units = "degrees_east" ;'
    echo ' float ta(lev, lat, lon) ; ta:units = "K" ;'
    echo "data: lev = 0, 0.5, 1, 2 ; p0 = 1000 ; lat = 0, 10, 20 ; lon = 0, 10, 20, 30 ;"
    echo " ta = $(seq -s ', ' 201 248) ; }"
  } >"$work/ln.cdl"
  ncgen -o "$work/ln.nc" "$work/ln.cdl" || fail "ncgen of the ln-pressure file"
  "$convert" "$work/ln.nc" -o "$work/ln" -q || fail "ln-pressure conversion"
  "$convert" info "$work/ln" >"$work/ln.info" || fail "ln-pressure info"
  grep -Eq "^ +lev +4 \(pressure, Pa\): 100000 \.\. 13533\.5" "$work/ln.info" ||
    fail "the ln-pressure store has no pressure axis p0 * exp(-lev)"
  grep -q "^geometry " "$work/ln.info" && fail "the ln-pressure store has a geometry"
  sed -i 's/p0 = 1000/p0 = -1000/' "$work/ln.cdl"
  ncgen -o "$work/ln-negative.nc" "$work/ln.cdl" || fail "ncgen of the negative p0 file"
  expect_cli_error "$convert" "$work" 4 "p0 is -100000 Pa" -- "$work/ln-negative.nc" \
    -o "$work/ln-negative"
fi

# ICON's absolute time axis has dates now.
grep -q "2013-04-26T12:00:00Z" "$work/icon.info" || fail "the ICON store has no dates"
# A height band: everything below 3000 m above sea level, by the geometry's own field.
echo '{"subvolumes": [{"id": 1, "limits": [{"var": "geometry_height", "max": 3000}]}]}' \
  >"$work/band.json"
"$serve" extract --store "$work/icon" --scene "$work/band.json" -o "$work/band.vtp" \
  --frame lonlat --json >"$work/band.json.out" || fail "height band extraction"
grep -q '"triangles": [1-9]' "$work/band.json.out" || fail "the height band has no triangles"
"$convert" export-vdb "$work/icon" --var geometry_height -o "$work/heights.vdb" --json \
  >"$work/vdb.json" || fail "export-vdb of the geometry"
grep -q '"active_voxels": 23040' "$work/vdb.json" || fail "the geometry grid is not whole (40x36x16)"

expect() { expect_cli_error "$serve" "$work" "$@"; }
expect 2 "--height-var zg: the store's grid geometry places" -- extract --store "$work/icon" \
  --scene "$work/icon.scene.json" -o "$work/x.vtp" --frame lonlat --height-var zg

# NCAR's CCM hybrid sigma-pressure file names P0_var = "P0" but has no P0.
data=/usr/share/ncarg/data
if [[ -f $data/cdf/vinth2p.nc ]]; then
  expect_convert() { expect_cli_error "$convert" "$work" "$@"; }
  expect_convert 4 "P0_var" -- "$data/cdf/vinth2p.nc" -o "$work/vinth2p-no-p0"
  grep -q -- "--formula-term P0=100000" "$work/err" || fail "the P0 refusal does not say what to do"
  "$convert" "$data/cdf/vinth2p.nc" -o "$work/vinth2p" --formula-term P0=100000 -q ||
    fail "vinth2p with P0"
  "$convert" info "$work/vinth2p" | grep -q "pressure.*hybrid_sigma_pressure" ||
    fail "vinth2p info does not show the pressure geometry"
  expect_convert 2 "--formula-term 'P0'" -- "$data/cdf/vinth2p.nc" -o "$work/x" --formula-term P0
fi

if [[ $failures -ne 0 ]]; then
  echo "$failures failure(s)"
  exit 1
fi
rm -rf "$work"
