#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The whole test suite: install what is missing (incl. Slurm, munge and libncarg-data),
# build, run every test with ctest (unit, integration, fuzz smoke, Slurm cluster), then
# the sanitizer fuzzing stage (scripts/fuzz.sh: clang, libFuzzer, ASan, UBSan).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --tests
scripts/build.sh
export STRIELAD_REQUIRE_SLURM=${STRIELAD_REQUIRE_SLURM:-1}
ctest --test-dir build --output-on-failure -j "$(nproc)" --timeout 900
scripts/fuzz.sh --seconds "${STRIELAD_FUZZ_SECONDS:-60}"
