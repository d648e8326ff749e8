#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# strielad-convert turns bad input into one line on stderr naming what is wrong and the
# documented exit status, and leaves nothing half-written behind.
# Usage: convert_cli_errors_test.sh STRIELAD_CONVERT WORK_DIR
set -uo pipefail
convert=$1
sample="$(dirname "$convert")/../strielad-sample/strielad-sample"
work=$2
rm -rf "$work" && mkdir -p "$work"

# shellcheck source=../support/expect_cli_error.sh
source "$(dirname "$0")/../support/expect_cli_error.sh"
# expect STATUS "SUBSTRING" -- ARGS...
expect() { expect_cli_error "$convert" "$work" "$@"; }

"$sample" -o "$work/data" --dims 12x10x5 --steps 2 --vars clw,ta -q
"$convert" "$work"/data/*.nc -o "$work/store" --brick 4 -q

expect 3 "no-such-file.nc" -- "$work/no-such-file.nc" -o "$work/s1"
expect 3 "'nope'" -- "$work"/data/*.nc -o "$work/s2" --vars nope
expect 2 "codec 'gzip'" -- "$work"/data/*.nc -o "$work/s3" --codec gzip
expect 2 "--time" -- "$work"/data/*.nc -o "$work/s4" --time 3:1
expect 5 "of memory to convert" -- "$work"/data/*.nc -o "$work/s5" --memory-limit 0.000001
expect 2 "-o STORE is required" -- "$work"/data/*.nc
expect 8 "different inputs or options" -- "$work"/data/*.nc -o "$work/store" --brick 8
head -c 1000 "$work/data/sample_t000.nc" > "$work/truncated.nc"
expect 4 "truncated.nc" -- "$work/truncated.nc" -o "$work/s5"
echo "not netcdf" > "$work/text.nc"
expect 4 "text.nc" -- "$work/text.nc" -o "$work/s6"
# Only a classic magic, or one followed by bytes netCDF-C answers with EINVAL: invalid
# input (4), not an I/O error (7).
printf 'CDF\001' > "$work/magic.nc"
expect 4 "magic.nc" -- "$work/magic.nc" -o "$work/s7"
printf 'CDF\001\377\377\377\377\377\377\377\377\377\377\377\377' > "$work/damaged-header.nc"
expect 4 "damaged-header.nc: not a readable netCDF file" -- "$work/damaged-header.nc" -o "$work/s8"
# Attributes that would change every value: refused before anything is written.
cat > "$work/attrs.cdl" <<'CDL'
netcdf attrs {
dimensions:
  lev = 2 ; lat = 3 ; lon = 4 ;
variables:
  double lev(lev) ; lev:units = "hPa" ; lev:positive = "down" ; lev:axis = "Z" ;
  double lat(lat) ; lat:units = "degrees_north" ; lat:standard_name = "latitude" ;
  double lon(lon) ; lon:units = "degrees_east" ; lon:standard_name = "longitude" ;
  short packed(lev, lat, lon) ; packed:scale_factor = 0.f ; packed:add_offset = 280.f ;
  float ranged(lev, lat, lon) ; ranged:valid_range = 10.f, 0.f ;
data:
  lev = 1000, 850 ; lat = -10, 0, 10 ; lon = 0, 10, 20, 30 ;
  packed = 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23 ;
  ranged = 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23 ;
}
CDL
ncgen -o "$work/attrs.nc" "$work/attrs.cdl"
expect 4 "variable 'packed': scale_factor is 0" -- "$work/attrs.nc" -o "$work/s9" --vars packed
expect 4 "variable 'ranged': valid_range [10, 0] is inverted" -- "$work/attrs.nc" -o "$work/s10" --vars ranged
expect 3 "not a STRIELAD store" -- info "$work/nowhere"
expect 3 "variable 'nope'" -- export-vdb "$work/store" --var nope -o "$work/x.vdb"

# A bit flip in a chunk: verify names the node and exits 6.
cp -r "$work/store" "$work/damaged"
step="$work/damaged/steps/step-000001.bricks"
printf '\xff\xff\xff\xff' | dd of="$step" bs=1 seek=200 conv=notrunc status=none
"$convert" verify "$work/damaged" >"$work/verify.out" 2>&1
status=$?
if [[ $status -ne 6 ]] || ! grep -q "PROBLEM: .*step-000001.bricks.*node" "$work/verify.out"; then
  echo "FAIL: verify of a damaged store: status $status"; cat "$work/verify.out"; failures=$((failures + 1))
else
  echo "ok: verify found $(grep -c PROBLEM "$work/verify.out") problem(s), status 6"
fi
"$convert" verify "$work/store" >/dev/null 2>&1 || { echo "FAIL: clean store does not verify"; failures=$((failures + 1)); }

# No temporaries or stores left behind by failed runs.
leftovers=$(find "$work" -name '*.tmp.*' | wc -l)
[[ $leftovers -eq 0 ]] || { echo "FAIL: $leftovers temporary files left"; failures=$((failures + 1)); }
for s in s1 s3 s4 s5 s6 s7 s8 s9 s10; do
  [[ ! -e "$work/$s/MANIFEST" ]] || { echo "FAIL: $s has a MANIFEST after a failed run"; failures=$((failures + 1)); }
done

if [[ $failures -eq 0 ]]; then echo "PASS"; exit 0; fi
echo "$failures FAILED"; exit 1
