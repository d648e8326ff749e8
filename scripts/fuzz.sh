#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Sanitizer fuzzing (docs/development.md): builds every fuzz target (tests/fuzz/*_fuzz.cpp)
# with clang, libFuzzer, AddressSanitizer and UndefinedBehaviorSanitizer into
# ./build-fuzz (STRIELAD_FUZZ_ONLY), replays every file under tests/fuzz/corpus/<target>/
# and tests/fuzz/regressions/<target>/, then fuzzes each target for a bounded time from
# those files and its seeds. Any crash, sanitizer report, leak, timeout or memory blow-up
# fails the script; the reproducer is kept under build-fuzz/findings/<target>/ and its
# path printed.
#
# Usage: scripts/fuzz.sh [--seconds N] [--jobs J] [--update-corpus] [TARGET...]
#   --seconds N       fuzzing time per target (default 60; 0: build and replay only)
#   --jobs J          targets fuzzed at once (default: the number of CPUs)
#   --update-corpus   merge the inputs that add coverage into tests/fuzz/corpus/<target>/
#   TARGET            e.g. scene_decoder (default: every target)
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=60
jobs=$(nproc)
update_corpus=0
targets=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --seconds) seconds=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    --update-corpus) update_corpus=1; shift ;;
    -h|--help) sed -n '3,16p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "error: unknown option $1" >&2; exit 2 ;;
    *) targets+=("$1"); shift ;;
  esac
done

build=build-fuzz
root=$PWD
cmake -S . -B "$build" -G Ninja -DSTRIELAD_FUZZ_ONLY=ON \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only" \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only" >/dev/null
if [[ ${#targets[@]} -eq 0 ]]; then
  for f in tests/fuzz/*_fuzz.cpp; do
    n=$(basename "$f" .cpp)
    targets+=("${n%_fuzz}")
  done
fi
cmake --build "$build" -j "$(nproc)" --target "${targets[@]/%/_fuzz_libfuzzer}"

# A sanitizer report is a finding: UBSan aborts (built with -fno-sanitize-recover), ASan
# reports leaks at exit. One allocation above 1 GB fails as an impossible one does in
# production (malloc returns null, operator new throws std::bad_alloc:
# tests/fuzz/allocation_failure.cpp); memory in use above -rss_limit_mb is a finding.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=1:max_allocation_size_mb=1024}
# Leaks inside third-party code the project cannot fix: tests/fuzz/lsan.supp.
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/tests/fuzz/lsan.supp:print_suppressions=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

findings=$build/findings
work=$build/fuzz-work
rm -rf "$work" "$findings"
mkdir -p "$findings" "$work"

# Prints what a failed run left: its log's end and the reproducer's path.
report() {
  local t=$1 log=$2
  echo "FAIL $t: see $log" >&2
  grep -E 'ERROR: |runtime error: |SUMMARY: |Test unit written to|Running: ' "$log" | head -20 >&2 || true
  tail -40 "$log" >&2
  local f
  for f in "$findings/$t"/*; do
    [[ -f $f ]] || continue
    echo "  reproducer: $root/$f ($(stat -c %s "$f") bytes; add it to tests/fuzz/regressions/$t/ with the fix)" >&2
  done
}

# 1. Replay: every kept input runs once, crash reproducers included.
failed=()
for t in "${targets[@]}"; do
  bin=$build/tests/fuzz/${t}_fuzz_libfuzzer
  mapfile -t inputs < <(find "tests/fuzz/corpus/$t" "tests/fuzz/regressions/$t" -type f 2>/dev/null | sort)
  mkdir -p "$findings/$t"
  if [[ ${#inputs[@]} -eq 0 ]]; then
    echo "replay $t: no inputs"
    continue
  fi
  log=$work/$t.replay.log
  if "$bin" -timeout=10 -rss_limit_mb=2048 -artifact_prefix="$findings/$t/" "${inputs[@]}" >"$log" 2>&1; then
    echo "replay $t: ${#inputs[@]} inputs, no finding"
  else
    failed+=("$t")
    # In replay the input that failed is the last one started.
    last=$(grep -E '^Running: ' "$log" | tail -1 | sed 's/^Running: //')
    [[ -n $last ]] && cp "$last" "$findings/$t/replay-$(basename "$last")"
    report "$t" "$log"
  fi
done

# 2. Fuzzing: J targets at a time, each from its seeds, corpus and regressions.
fuzz_one() {
  local t=$1
  local bin=$build/tests/fuzz/${t}_fuzz_libfuzzer log=$work/$t.fuzz.log
  mkdir -p "$work/$t/new" "$work/$t/seeds"
  "$bin" --write-seeds "$work/$t/seeds" >/dev/null
  local dirs=("$work/$t/new" "$work/$t/seeds")
  [[ -d tests/fuzz/corpus/$t ]] && dirs+=("tests/fuzz/corpus/$t")
  [[ -d tests/fuzz/regressions/$t ]] && dirs+=("tests/fuzz/regressions/$t")
  if "$bin" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=2048 \
      -print_final_stats=1 -artifact_prefix="$findings/$t/" "${dirs[@]}" >"$log" 2>&1; then
    echo "fuzz $t: $(grep -Eo 'stat::number_of_executed_units: *[0-9]+' "$log" | grep -Eo '[0-9]+$') inputs in ${seconds} s, $(grep -Eo 'cov: [0-9]+' "$log" | tail -1), no finding"
  else
    echo "fuzz $t: FINDING" >&2
    return 1
  fi
}

if [[ $seconds -gt 0 ]]; then
  declare -A pids=()
  finish_one() {  # waits for a fuzzing job to end and records a finding
    local done_pid="" rc=0 t
    wait -n -p done_pid || rc=$?
    for t in "${!pids[@]}"; do
      [[ ${pids[$t]} == "$done_pid" ]] || continue
      unset "pids[$t]"
      if [[ $rc -ne 0 ]]; then
        failed+=("$t")
        report "$t" "$work/$t.fuzz.log"
      fi
    done
  }
  for t in "${targets[@]}"; do
    while [[ ${#pids[@]} -ge $jobs ]]; do finish_one; done
    fuzz_one "$t" &
    pids[$t]=$!
  done
  while [[ ${#pids[@]} -gt 0 ]]; do finish_one; done
fi

if [[ $update_corpus -eq 1 ]]; then
  for t in "${targets[@]}"; do
    mkdir -p "tests/fuzz/corpus/$t"
    "$build/tests/fuzz/${t}_fuzz_libfuzzer" -merge=1 -timeout=10 -rss_limit_mb=2048 \
      "tests/fuzz/corpus/$t" "$work/$t/seeds" "$work/$t/new" >"$work/$t.merge.log" 2>&1 ||
      { echo "merge $t failed: $work/$t.merge.log" >&2; failed+=("$t"); }
  done
fi

if [[ ${#failed[@]} -gt 0 ]]; then
  echo "fuzzing found problems in: ${failed[*]} (reproducers under $root/$findings/)" >&2
  exit 1
fi
echo "fuzzing: ${#targets[@]} targets, no finding"
