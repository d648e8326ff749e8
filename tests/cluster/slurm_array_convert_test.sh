#!/bin/bash
# Runs scripts/slurm/submit-convert.sh for real on a private single-node Slurm cluster
# (munged + slurmctld + slurmd started here, all state in a scratch folder) and checks
# that the job array converted a store byte-identical to a single-process conversion.
#
#   bash tests/cluster/slurm_array_convert_test.sh STRIELAD_CONVERT WORK_DIR
#
# Exit 0: pass; 1: fail; 77: skipped because Slurm/munge (or root) is missing, unless
# STRIELAD_REQUIRE_SLURM=1 (CI), which turns that into a failure.
# Every daemon started here is stopped on exit, pass or fail. The scratch folder is
# removed on success and kept (its path printed) on failure.
set -euo pipefail

name=slurm_array_convert_test
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
submit=$repo/scripts/slurm/submit-convert.sh

# shellcheck source=tests/support/slurm_cluster.sh
source "$repo/tests/support/slurm_cluster.sh"

(($# == 2)) || fail "usage: $0 STRIELAD_CONVERT WORK_DIR"
exe=$(realpath -- "$1")
sample="$(dirname "$exe")/../strielad-sample/strielad-sample"
[[ -x $exe ]] || fail "strielad-convert '$1' is not executable"
[[ -f $submit ]] || fail "$submit is missing"
require_slurm_cluster
slurm_test_logs=('logs/*/*')
start_slurm_cluster "$2"

# ---------------------------------------------------------------- data
"$sample" -o "$scratch/in" --dims 40x30x12 --steps 6 >"$scratch/sample.log" 2>&1 ||
  { cat "$scratch/sample.log"; fail "strielad-sample failed"; }
inputs=("$scratch"/in/sample_t00{0..5}.nc)
for f in "${inputs[@]}"; do [[ -f $f ]] || fail "sample did not write $f"; done

# A store to resume: steps 2 and 3 converted by an earlier, interrupted run.
"$exe" "${inputs[@]}" -o "$scratch/resumed" --steps 2:3 --no-finalize --threads 1 \
  >"$scratch/preconvert.log" 2>&1 || { cat "$scratch/preconvert.log"; fail "pre-conversion failed"; }

# ---------------------------------------------------------------- submit
# Fresh store: 3 tasks of 2 steps, the step count read from the inputs with ncdump -h
# (or given when ncdump is missing).
count_args=()
command -v ncdump >/dev/null 2>&1 || count_args=(--steps-total 6)
out=$(bash "$submit" -o "$scratch/store" --steps-per-task 2 --cpus-per-task 1 \
  --time-limit 10:00 --log-dir "$scratch/logs/fresh" --exe "$exe" "${count_args[@]}" \
  "${inputs[@]}") || fail "submit-convert.sh failed: $out"
echo "$out"
array_id=$(awk '$1 == "array" && $2 == "job:" { print $3 }' <<<"$out")
finalize_id=$(awk '$1 == "finalize" && $2 == "job:" { print $3 }' <<<"$out")
[[ $array_id =~ ^[0-9]+$ && $finalize_id =~ ^[0-9]+$ ]] || fail "no job ids in the output of submit-convert.sh"
grep -q "3 of 3 tasks \[0-2\], 6 steps, 2 per task" <<<"$out" || fail "expected 3 tasks of 2 steps"
job_ids+=("$array_id" "$finalize_id")

# Resumed store: one step per task; only tasks 0, 1, 4, 5 have missing steps.
out2=$(bash "$submit" -o "$scratch/resumed" --steps-per-task 1 --log-dir "$scratch/logs/resumed" \
  --exe "$exe" --parsable "${inputs[@]}") || fail "submit-convert.sh (resume) failed: $out2"
read -r resume_array_id resume_finalize_id <<<"$out2"
[[ $resume_array_id =~ ^[0-9]+$ && $resume_finalize_id =~ ^[0-9]+$ ]] ||
  fail "--parsable printed '$out2', not two job ids"
job_ids+=("$resume_array_id" "$resume_finalize_id")
log "submitted array $array_id + finalize $finalize_id; resume array $resume_array_id + finalize $resume_finalize_id"

# ---------------------------------------------------------------- wait (bounded)
job_state() { scontrol -o show job "$1" 2>/dev/null | grep -o 'JobState=[A-Z_]*' | cut -d= -f2 | sort -u | tr '\n' ' '; }
deadline=$((SECONDS + 300))
while :; do
  s1=$(job_state "$finalize_id")
  s2=$(job_state "$resume_finalize_id")
  done_states='^(COMPLETED|FAILED|CANCELLED|TIMEOUT|NODE_FAIL|OUT_OF_MEMORY|PREEMPTED|BOOT_FAIL|DEADLINE) $'
  [[ $s1 =~ $done_states && $s2 =~ $done_states ]] && break
  if ((SECONDS > deadline)); then
    squeue -a -o '%.12i %.20j %.10T %.20R' || true
    fail "the jobs did not finish within 300 s (finalize states: '$s1', '$s2')"
  fi
  sleep 1
done
log "jobs finished: finalize $finalize_id: $s1; finalize $resume_finalize_id: $s2"

# ---------------------------------------------------------------- check
scontrol -o show job "$array_id" >"$scratch/array-jobs.txt" 2>&1 || true
for id in "$array_id" "$resume_array_id" "$finalize_id" "$resume_finalize_id"; do
  while read -r line; do
    [[ -n $line ]] || continue
    job=$(grep -o 'JobId=[0-9]*' <<<"$line" | head -n 1)
    task=$(grep -o 'ArrayTaskId=[0-9-]*' <<<"$line" || true)
    st=$(grep -o 'JobState=[A-Z_]*' <<<"$line")
    ex=$(grep -o ' ExitCode=[0-9:]*' <<<"$line")
    [[ $st == JobState=COMPLETED && $ex == " ExitCode=0:0" ]] ||
      fail "job $job $task ended $st$ex"
  done < <(scontrol -o show job "$id")
done
tasks_run=$(grep -c 'ArrayTaskId=' "$scratch/array-jobs.txt" || true)
((tasks_run == 3)) || fail "Slurm reports $tasks_run array tasks for job $array_id, expected 3"

for t in 0 1 2; do
  f=$scratch/logs/fresh/strielad-convert-${array_id}_$t.out
  [[ -f $f ]] || fail "array task $t left no output file $f"
  grep -Eq "task $t \(steps $((2 * t)):$((2 * t + 1))\) finished in [0-9]+ s with exit status 0" "$f" ||
    { cat "$f"; fail "output of array task $t does not show steps $((2 * t)):$((2 * t + 1)) converted"; }
done
for t in 0 1 4 5; do
  f=$scratch/logs/resumed/strielad-convert-${resume_array_id}_$t.out
  [[ -f $f ]] || fail "resume array task $t left no output file $f"
done
for t in 2 3; do
  [[ ! -e $scratch/logs/resumed/strielad-convert-${resume_array_id}_$t.out ]] ||
    fail "resume task $t ran although its step was already converted"
done
for f in "$scratch/logs/fresh/strielad-finalize-$finalize_id.out" \
  "$scratch/logs/resumed/strielad-finalize-$resume_finalize_id.out"; do
  grep -q "is complete and verified" "$f" 2>/dev/null || { cat "$f" 2>/dev/null; fail "finalize job output $f does not report success"; }
done

# Single-process reference conversion of the same inputs (same paths, same order).
"$exe" "${inputs[@]}" -o "$scratch/reference" --threads 2 >"$scratch/reference.log" 2>&1 ||
  { cat "$scratch/reference.log"; fail "single-process conversion failed"; }
for store in store resumed reference; do
  "$exe" verify "$scratch/$store" >"$scratch/verify-$store.log" 2>&1 ||
    { cat "$scratch/verify-$store.log"; fail "verify $store failed"; }
done
(cd "$scratch/reference" && find . -type f | sort) >"$scratch/files-reference.txt"
[[ $(wc -l <"$scratch/files-reference.txt") -eq 7 ]] || fail "reference store has not 7 files (MANIFEST + 6 steps)"
for store in store resumed; do
  (cd "$scratch/$store" && find . -type f | sort) >"$scratch/files-$store.txt"
  diff "$scratch/files-reference.txt" "$scratch/files-$store.txt" ||
    fail "the files of $store differ from the single-process store's"
  while read -r f; do
    cmp -- "$scratch/reference/$f" "$scratch/$store/$f" ||
      fail "$store/$f differs from the single-process conversion (conversion must be deterministic)"
  done <"$scratch/files-reference.txt"
done
log "array store, resumed store and single-process store are byte-identical (MANIFEST + 6 steps), verify OK"
passed=1
