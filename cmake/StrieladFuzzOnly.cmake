# SPDX-License-Identifier: Apache-2.0
# STRIELAD_FUZZ_ONLY: the sanitizer fuzzing build scripts/fuzz.sh runs in CI. Every
# translation unit (library and fuzz targets) gets AddressSanitizer, UndefinedBehavior-
# Sanitizer (a report aborts) and libFuzzer's coverage instrumentation. scripts/fuzz.sh
# builds only the <name>_libfuzzer targets, so only the layers they link are compiled
# (tests/fuzz/CMakeLists.txt), and no tool, test, viewer or benchmark.
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang" OR NOT CMAKE_C_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "STRIELAD_FUZZ_ONLY needs clang (libFuzzer): configure with "
                      "-DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++")
endif()
set(STRIELAD_BUILD_FUZZ ON)
add_compile_options(-fsanitize=address,undefined,fuzzer-no-link
                    -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
add_link_options(-fsanitize=address,undefined)
