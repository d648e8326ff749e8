// SPDX-License-Identifier: Apache-2.0
// Every fuzz target defines LLVMFuzzerTestOneInput and strielad_fuzz_seeds(). With clang
// and STRIELAD_BUILD_FUZZ=ON it links libFuzzer; otherwise replay_driver.cpp runs the
// seeds and a bounded number of deterministic mutations of them as a ctest.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

// Valid encodings the mutations start from.
std::vector<std::vector<std::uint8_t>> strielad_fuzz_seeds();
