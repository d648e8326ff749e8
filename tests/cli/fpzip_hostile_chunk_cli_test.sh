#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# A store whose fpzip chunk holds a crafted stream, with every checksum recomputed, makes
# verify, extract and export-vdb fail with status 6 (corrupt) and one line naming the
# step file, variable and node; none of them crashes (before the stream check, fpzip's
# decoder died with SIGSEGV, status 139, on this chunk).
# Usage: fpzip_hostile_chunk_cli_test.sh STRIELAD_CONVERT WORK_DIR (strielad-serve is
# found next to strielad-convert in the build tree).
set -uo pipefail
convert=$1
sample="$(dirname "$convert")/../strielad-sample/strielad-sample"
work=$2
serve="$(dirname "$convert")/../strielad-serve/strielad-serve"
here="$(dirname "$0")"
rm -rf "$work" && mkdir -p "$work"

# shellcheck source=../support/expect_cli_error.sh
source "$here/../support/expect_cli_error.sh"

"$sample" -o "$work/data" --dims 12x10x5 --steps 1 --vars clw,ta -q
"$convert" "$work"/data/*.nc -o "$work/store" --brick 4 --fpzip all -q
cp -r "$work/store" "$work/forged"
forged=$(python3 "$here/../support/forge_fpzip_chunk.py" "$work/forged" \
  "$here/../fuzz/regressions/brick_chunk_decoder/fpzip-table-overrun-float32-5x5x5-1") ||
  { echo "FAIL: could not forge a chunk"; exit 1; }
read -r step_file var node _ <<<"$forged"
echo "forged: $forged"
needle="$step_file: step 0 variable '$var' node $node"

expect_cli_error "$convert" "$work" 6 "$needle" -- export-vdb "$work/forged" --var "$var" \
  -o "$work/out.vdb"
echo '{"subvolumes": [{"id": 1, "limits": [{"var": "'"$var"'", "min": -1000}]}]}' > "$work/scene.json"
expect_cli_error "$serve" "$work" 6 "$needle" -- extract --store "$work/forged" \
  --scene "$work/scene.json" -o "$work/out.vtp"

"$convert" verify "$work/forged" >"$work/verify.out" 2>&1
status=$?
if [[ $status -ne 6 ]] || ! grep -q "PROBLEM: .*$needle.*fpzip stream" "$work/verify.out"; then
  echo "FAIL: verify of the forged store: status $status"; cat "$work/verify.out"; failures=$((failures + 1))
else
  echo "ok: verify status 6: $(grep PROBLEM "$work/verify.out")"
fi
"$convert" verify "$work/store" >/dev/null 2>&1 || { echo "FAIL: clean store does not verify"; failures=$((failures + 1)); }

if [[ $failures -eq 0 ]]; then echo "PASS"; exit 0; fi
echo "$failures FAILED"; exit 1
