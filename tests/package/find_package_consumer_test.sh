#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# find_package(strielad): installs the build into a scratch prefix, builds
# tests/package/consumer against it as a separate CMake project, and runs it on a small
# sample store. The root node's range in the index (that of all the data below it) must
# hold the range of its decoded, sub-sampled brick.
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

"$(dirname "$convert")/../strielad-sample/strielad-sample" -o "$work/sample" --dims 40x36x16 --steps 1 --vars ta,clw -q
"$convert" "$work"/sample/*.nc -o "$work/store" --brick 8 -q
"$work/consumer/store_summary" "$work/store" >"$work/summary.txt"
cat "$work/summary.txt"
test "$(wc -l <"$work/summary.txt")" -eq 2
# "NAME index [lo, hi] brick [lo, hi]"
tr -d '[],' <"$work/summary.txt" |
  awk '{ if (!($6 >= $3 && $7 <= $4)) { print "brick outside the index range: " $0; bad = 1 } }
       END { exit bad }'
