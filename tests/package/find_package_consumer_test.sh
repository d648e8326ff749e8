#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# find_package(strielad): installs the build into a scratch prefix, builds
# tests/package/consumer against it as a separate CMake project, and runs it on a small
# sample store. The root node's range from the index must equal the decoded brick's.
# Usage: find_package_consumer_test.sh STRIELAD_CONVERT WORK_DIR
set -euo pipefail
convert=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
build_dir=$(dirname "$convert")
while [[ ! -f "$build_dir/CMakeCache.txt" ]]; do build_dir=$(dirname "$build_dir"); done
rm -rf "$work" && mkdir -p "$work"

cmake --install "$build_dir" --prefix "$work/prefix" >"$work/install.log"
test -f "$work/prefix/lib/cmake/strielad/strielad-config.cmake"
test -f "$work/prefix/include/strielad/store/store.h"
test -f "$work/prefix/include/strielad/core/version.h"

cmake -S "$here/consumer" -B "$work/consumer" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/prefix" >"$work/configure.log" 2>&1 ||
  { cat "$work/configure.log"; exit 1; }
cmake --build "$work/consumer" >"$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }

"$convert" sample -o "$work/sample" --dims 40x36x16 --steps 1 --vars ta,clw >/dev/null
"$convert" "$work"/sample/*.nc -o "$work/store" --brick 8 -q
"$work/consumer/store_summary" "$work/store" >"$work/summary.txt"
cat "$work/summary.txt"
test "$(wc -l <"$work/summary.txt")" -ge 1
# "NAME index [a, b] brick [a, b]": the same range twice.
awk '{ if ($3 $4 != $6 $7) { print "range mismatch: " $0; exit 1 } }' "$work/summary.txt"
