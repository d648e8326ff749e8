#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# A lossless store whose index claims an fpzip or a zfp chunk for a variable whose codec
# allows neither (every checksum recomputed) is corrupt: export-vdb fails with status 6
# and one line naming the step file, variable and node and what the codec allows; the
# chunk is never handed to fpzip or zfp.
# Usage: chunk_coding_mismatch_cli_test.sh STRIELAD_CONVERT WORK_DIR
set -uo pipefail
convert=$1
sample="$(dirname "$convert")/../strielad-sample/strielad-sample"
work=$2
here="$(dirname "$0")"
rm -rf "$work" && mkdir -p "$work"
failures=0

# shellcheck source=../support/expect_cli_error.sh
source "$here/../support/expect_cli_error.sh"

"$sample" -o "$work/data" --dims 12x10x5 --steps 1 --vars clw,ta -q
"$convert" "$work"/data/*.nc -o "$work/store" --brick 4 -q
for case in "1 fpzip, but the codec does not allow it" "2 zfp, but the codec is not lossy"; do
  coding=${case%% *}
  reason=${case#* }
  rm -rf "$work/relabelled" && cp -r "$work/store" "$work/relabelled"
  node=$(python3 "$here/../support/relabel_chunk_coding.py" "$work/relabelled" "$coding") ||
    { echo "FAIL: could not relabel a chunk"; exit 1; }
  read -r step_file var node_id <<<"$node"
  expect_cli_error "$convert" "$work" 6 "chunk is coded with $reason" -- \
    export-vdb "$work/relabelled" --var "$var" -o "$work/out.vdb"
  if ! grep -q "$step_file: step 0 variable '$var' node $node_id " "$work/err"; then
    echo "FAIL: the error does not name $step_file, '$var', node $node_id:"; cat "$work/err"
    failures=$((failures + 1))
  fi
done

if [[ $failures -eq 0 ]]; then echo "PASS"; exit 0; fi
echo "$failures FAILED"; exit 1
