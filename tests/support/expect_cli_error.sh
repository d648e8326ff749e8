# SPDX-License-Identifier: Apache-2.0
# Sourced by the CLI tests (not a test itself). expect_cli_error TOOL WORK STATUS NEEDLE -- ARGS...
# runs TOOL ARGS and checks its exit status and that stderr, log lines ("[...") aside, is
# exactly one line containing "error: " and NEEDLE. Counts mismatches in $failures.
failures=${failures:-0}

expect_cli_error() {
  local tool=$1 work=$2 status=$3 needle=$4
  shift 5
  "$tool" "$@" >"$work/out" 2>"$work/err"
  local got=$?
  local last
  last=$(grep -v '^\[' "$work/err" | tail -n 1)
  if [[ $got -ne $status ]] || [[ "$last" != *"error: "* ]] || [[ "$last" != *"$needle"* ]] ||
     [[ $(grep -vc '^\[' "$work/err") -ne 1 ]]; then
    echo "FAIL: $(basename "$tool") $* -> status $got (want $status), stderr:"
    cat "$work/err"
    failures=$((failures + 1))
  else
    echo "ok: status $got: $last"
  fi
}
