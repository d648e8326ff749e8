#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# strielad-convert --lossy: bad requests are one line on stderr naming the flag (exit 2)
# and leave no store; a lossy store reports its zfp and fallback bricks (--json), info
# shows the bound per variable, and verify passes.
# Usage: lossy_cli_test.sh STRIELAD_CONVERT WORK_DIR
set -uo pipefail
convert=$1
sample="$(dirname "$convert")/../strielad-sample/strielad-sample"
work=$2
rm -rf "$work" && mkdir -p "$work"

# shellcheck source=../support/expect_cli_error.sh
source "$(dirname "$0")/../support/expect_cli_error.sh"
expect() { expect_cli_error "$convert" "$work" "$@"; }

"$sample" -o "$work/data" --dims 24x20x10 --steps 2 --vars clw,ta -q

expect 2 "--lossy 'ta=abs:-0.1': tolerance -0.1 must be positive" -- "$work"/data/*.nc -o "$work/s1" --lossy ta=abs:-0.1
expect 2 "--lossy 'ta=abs:nan'" -- "$work"/data/*.nc -o "$work/s2" --lossy ta=abs:nan
expect 2 "--lossy 'ta=0.1'" -- "$work"/data/*.nc -o "$work/s3" --lossy ta=0.1
expect 2 "--lossy names variable 'nope'" -- "$work"/data/*.nc -o "$work/s4" --lossy nope=abs:1
expect 2 "--lossy and --fpzip both name variable 'ta'" -- "$work"/data/*.nc -o "$work/s5" --lossy ta=abs:0.1 --fpzip ta
for s in s1 s2 s3 s4 s5; do
  [[ ! -e "$work/$s/MANIFEST" ]] || { echo "FAIL: $s has a MANIFEST after a failed run"; failures=$((failures + 1)); }
done

if ! "$convert" "$work"/data/*.nc -o "$work/lossy" --brick 8 --lossy ta=abs:0.05,clw=rel:0.001 --json -q \
    >"$work/convert.json" 2>"$work/convert.err"; then
  echo "FAIL: lossy conversion"; cat "$work/convert.err"; failures=$((failures + 1))
elif ! grep -q '"zfp_bricks"' "$work/convert.json" || ! grep -q '"fallback_bricks": 0' "$work/convert.json"; then
  echo "FAIL: --json lacks the lossy brick counts"; cat "$work/convert.json"; failures=$((failures + 1))
else
  echo "ok: lossy conversion reports $(grep -o '"zfp_bricks": [0-9]*' "$work/convert.json")"
fi
"$convert" info "$work/lossy" >"$work/info.out" 2>&1
if ! grep -q "ta .*LOSSY zfp within 0.05 (abs)" "$work/info.out" || ! grep -q "format version 6" "$work/info.out" ||
   ! grep -q "clw .*LOSSY zfp within .* (rel 0.001 of the range)" "$work/info.out"; then
  echo "FAIL: info does not show the lossy bounds"; cat "$work/info.out"; failures=$((failures + 1))
else
  echo "ok: info shows the lossy bounds"
fi
"$convert" verify "$work/lossy" >/dev/null 2>&1 || { echo "FAIL: the lossy store does not verify"; failures=$((failures + 1)); }

if [[ $failures -eq 0 ]]; then echo "PASS"; exit 0; fi
echo "$failures FAILED"; exit 1
