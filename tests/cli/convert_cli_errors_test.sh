#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# strielad-convert turns bad input into one line on stderr naming what is wrong and the
# documented exit status, and leaves nothing half-written behind.
# Usage: convert_cli_errors_test.sh STRIELAD_CONVERT WORK_DIR
set -uo pipefail
convert=$1
work=$2
rm -rf "$work" && mkdir -p "$work"

# shellcheck source=../support/expect_cli_error.sh
source "$(dirname "$0")/../support/expect_cli_error.sh"
# expect STATUS "SUBSTRING" -- ARGS...
expect() { expect_cli_error "$convert" "$work" "$@"; }

"$convert" sample -o "$work/data" --dims 12x10x5 --steps 2 --vars clw,ta -q
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
for s in s1 s3 s4 s5 s6; do
  [[ ! -e "$work/$s/MANIFEST" ]] || { echo "FAIL: $s has a MANIFEST after a failed run"; failures=$((failures + 1)); }
done

if [[ $failures -eq 0 ]]; then echo "PASS"; exit 0; fi
echo "$failures FAILED"; exit 1
