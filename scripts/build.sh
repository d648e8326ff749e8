#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Configures and builds STRIELAD into ./build (Release with debug info, Ninja).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build -j "$(nproc)"
