#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# strielad-bench report --quick: runs the named suites as their own processes and writes
# one BENCHMARKS.md with the machine, each suite's command, exit status and tables, and
# the charts (when gnuplot is installed), with the noise probes taken between suites; an
# unknown suite is one clear error.
# Usage: bench_report_quick_test.sh STRIELAD_CONVERT WORK_DIR (strielad-bench is found
# next to strielad-convert in the build tree).
set -uo pipefail
convert=$1
work=$2
bench="$(dirname "$convert")/../strielad-bench/strielad-bench"
rm -rf "$work" && mkdir -p "$work"
failures=0
# shellcheck source=../support/expect_cli_error.sh
source "$(dirname "$0")/../support/expect_cli_error.sh"
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

expect_cli_error "$bench" "$work" 2 "unknown suite 'nope'" -- report --quick --suites io,nope \
  --out "$work/bad"

"$bench" report --quick --suites scene,scaling,latency,advect --out "$work/report" --work "$work/scratch" \
  >"$work/report.out" 2>"$work/report.err" || fail "report exited $?: $(tail -5 "$work/report.err")"
md="$work/report/BENCHMARKS.md"
[[ -s "$md" ]] || fail "no $md"
for needle in "## Machine" "cores" "## Noise" "slowest / fastest" "## scene" "## advect" \
              "What a scene and a view read" "| scene | view | nodes |" \
              "Fewest field evaluations" "report --quick" "## scaling" "Cost against grid size" \
              "| ranks | threads/rank |" "number of sub-volumes" \
              "against the paper's published figures"; do
  grep -qF -- "$needle" "$md" || fail "BENCHMARKS.md lacks '$needle'"
done
for f in scene.json scene.csv scene.txt advect.json advect.csv advect.txt scaling.json latency.json; do
  [[ -s "$work/report/$f" ]] || fail "no $f"
done
if command -v gnuplot >/dev/null; then
  for png in scene-economy.png advect.png scaling-grid.png scaling-subvolumes.png \
             scaling-ranks.png latency-cut-arrivals.png; do
    [[ -s "$work/report/$png" ]] || fail "no chart $png"
    grep -qF "($png)" "$md" || fail "BENCHMARKS.md does not show $png"
  done
fi

# --rerun runs only the named suite again and keeps the others from runs.json.
[[ -s "$work/report/runs.json" ]] || fail "no runs.json"
before_advect=$(stat -c %Y "$work/report/advect.json")
"$bench" report --quick --rerun scene --out "$work/report" --work "$work/scratch" \
  >"$work/rerun.out" 2>"$work/rerun.err" || fail "rerun exited $?: $(tail -5 "$work/rerun.err")"
for needle in "Re-run by" "## scene" "## advect" "## scaling"; do
  grep -qF -- "$needle" "$md" || fail "BENCHMARKS.md after --rerun lacks '$needle'"
done
grep -qF "re-run, before scene" "$work/report/runs.json" || fail "runs.json lacks the re-run's probes"
[[ $(stat -c %Y "$work/report/advect.json") == "$before_advect" ]] || fail "--rerun scene re-ran advect"
expect_cli_error "$bench" "$work" 2 "unknown suite 'nope'" -- report --quick --rerun nope \
  --out "$work/report"
expect_cli_error "$bench" "$work" 3 "no earlier report" -- report --quick --rerun scene \
  --out "$work/empty"

[[ $failures -eq 0 ]] && echo "bench report quick: ok"
exit $((failures > 0))
