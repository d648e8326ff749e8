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

fail() {
  echo "$name: FAIL: $*" >&2
  exit 1
}
skip() {
  if [[ ${STRIELAD_REQUIRE_SLURM:-0} == 1 ]]; then
    fail "$* (STRIELAD_REQUIRE_SLURM=1, so this is a failure, not a skip)"
  fi
  echo "$name: SKIP: $*"
  exit 77
}

(($# == 2)) || fail "usage: $0 STRIELAD_CONVERT WORK_DIR"
exe=$(realpath -- "$1")
work=$2
[[ -x $exe ]] || fail "strielad-convert '$1' is not executable"
[[ -f $submit ]] || fail "$submit is missing"

missing=()
for tool in munged mungekey munge unmunge slurmctld slurmd sbatch squeue scontrol scancel sinfo setpriv; do
  command -v "$tool" >/dev/null 2>&1 || missing+=("$tool")
done
((${#missing[@]} == 0)) || skip "missing programs: ${missing[*]} (apt-get install -y slurm-wlm munge)"
((EUID == 0)) || skip "must run as root to start slurmd and munged"
id munge >/dev/null 2>&1 || skip "no 'munge' user (install the munge package)"

# Settings from an enclosing Slurm job or the user's environment must not leak in.
while read -r var; do
  [[ $var == SLURM_CONF ]] || unset "$var"
done < <(compgen -e | grep -E '^(SLURM_|SBATCH_|SALLOC_|SRUN_|SQUEUE_|SINFO_|SCONTROL_)' || true)

mkdir -p -- "$work"
work=$(realpath -- "$work")
scratch=$(mktemp -d "$work/run.XXXXXX")
chmod 0755 "$scratch"
# The sockets (munge's, and slurmd's SPOOL/NODE_JOBID.STEPID) and munged's files go to a
# folder with a short path (Unix socket paths have at most 107 bytes) that user munge
# can reach: in the scratch folder, or under /tmp (removed on exit) when that fails.
node=$(hostname -s)
rundir=$scratch/run
if ((${#rundir} + ${#node} + 30 > 107)) ||
  ! setpriv --reuid=munge --regid=munge --clear-groups -- test -x "$scratch"; then
  rundir=$(mktemp -d /tmp/strielad-slurm.XXXXXX)
fi
mkdir -p "$rundir/spool" "$rundir/munge" "$scratch/state" "$scratch/logs"
chmod 0755 "$rundir"
export SLURM_CONF=$scratch/slurm.conf

munged_pid=
watchdog_pid=
slurmctld_pid=
slurmd_pid=
job_ids=()
passed=0

log() { echo "$name: $(date '+%T') $*"; }

# Processes of this test's cluster that outlived slurmd (slurmstepd, job scripts): found
# by the SLURM_CONF they inherited, which names this run's scratch folder. This shell's
# own children (munged, this function's commands) are not strays.
stray_pids() {
  local environ pid ppid self=$BASHPID
  # shellcheck disable=SC2013  # /proc/PID/environ paths have no spaces
  for environ in $(grep -lzxF "SLURM_CONF=$SLURM_CONF" /proc/[0-9]*/environ 2>/dev/null); do
    pid=${environ#/proc/}
    pid=${pid%/environ}
    [[ $pid != "$$" && $pid != "$self" ]] || continue
    ppid=$(awk '$1 == "PPid:" { print $2 }' "/proc/$pid/status" 2>/dev/null) || continue
    [[ -n $ppid && $ppid != "$$" && $ppid != "$self" ]] || continue
    echo "$pid"
  done
}

stop_pid() {  # stop_pid PID NAME: SIGTERM, wait up to 15 s, then SIGKILL
  local pid=$1 what=$2 i
  [[ -n $pid ]] && kill -0 "$pid" 2>/dev/null || return 0
  kill -TERM "$pid" 2>/dev/null || true
  for ((i = 0; i < 150; i++)); do
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
  done
  if kill -0 "$pid" 2>/dev/null; then
    echo "$name: $what (pid $pid) ignored SIGTERM; killing it" >&2
    kill -KILL "$pid" 2>/dev/null || true
  fi
  wait "$pid" 2>/dev/null || true
}

print_logs() {
  local f
  for f in "$scratch"/slurmctld.log "$scratch"/slurmd.log "$rundir"/munge/munged.log \
    "$scratch"/munged.stderr "$scratch"/logs/*/*; do
    [[ -f $f ]] || continue
    echo "----- $f (last 40 lines) -----"
    tail -n 40 "$f"
  done
}

cleanup() {
  local rc=$? i pid
  set +e
  trap - EXIT INT TERM
  if ((${#job_ids[@]} > 0)) && [[ -n $slurmctld_pid ]] && kill -0 "$slurmctld_pid" 2>/dev/null; then
    scancel "${job_ids[@]}" 2>/dev/null
    for ((i = 0; i < 100; i++)); do  # let slurmd end the jobs' steps (10 s at most)
      [[ -z $(squeue -h -o %i 2>/dev/null) ]] && break
      sleep 0.1
    done
  fi
  if [[ -n $watchdog_pid ]]; then
    kill -TERM "$watchdog_pid" 2>/dev/null
    wait "$watchdog_pid" 2>/dev/null
  fi
  stop_pid "$slurmd_pid" slurmd
  stop_pid "$slurmctld_pid" slurmctld
  for pid in $(stray_pids); do
    echo "$name: stopping leftover process $pid: $(tr '\0' ' ' <"/proc/$pid/cmdline" 2>/dev/null)" >&2
    kill -KILL "$pid" 2>/dev/null
  done
  stop_pid "$munged_pid" munged
  if ((rc != 0 && !passed)); then
    print_logs
    echo "$name: scratch folder kept: $scratch"
  fi
  [[ $rundir == "$scratch"/* ]] || rm -rf -- "$rundir"
  if ((passed)); then
    rm -rf -- "$scratch"
    echo "$name: PASS"
  else
    echo "$name: FAIL (exit status $rc)"
  fi
  exit "$rc"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

# ---------------------------------------------------------------- munge
munge_socket=$rundir/munge/munge.socket
chown munge:munge "$rundir/munge"
chmod 0755 "$rundir/munge"
mungekey --create --keyfile="$rundir/munge/munge.key" >/dev/null 2>&1 ||
  fail "mungekey --create failed"
chown munge:munge "$rundir/munge/munge.key"
chmod 0600 "$rundir/munge/munge.key"
setpriv --reuid=munge --regid=munge --init-groups -- munged --foreground --force \
  --socket="$munge_socket" --key-file="$rundir/munge/munge.key" \
  --pid-file="$rundir/munge/munged.pid" --seed-file="$rundir/munge/munged.seed" \
  --log-file="$rundir/munge/munged.log" 2>"$scratch/munged.stderr" &
munged_pid=$!
for ((i = 0; i < 100; i++)); do
  [[ -S $munge_socket ]] && break
  kill -0 "$munged_pid" 2>/dev/null || fail "munged exited at start"
  sleep 0.1
done
munge -n -S "$munge_socket" | unmunge -S "$munge_socket" >/dev/null ||
  fail "munged does not answer on $munge_socket"
log "munged running (pid $munged_pid)"

# ---------------------------------------------------------------- slurm
port_free() { ! ss -Htan "sport = :$1" 2>/dev/null | grep -q .; }
ctld_port=
for ((i = 0; i < 50; i++)); do  # a free port pair derived from this shell's PID
  p=$((20000 + (($$ + 7919 * i) % 20000) * 2))
  if port_free "$p" && port_free $((p + 1)); then
    ctld_port=$p
    break
  fi
done
[[ -n $ctld_port ]] || fail "no free port pair found for slurmctld/slurmd"
cpus=$(nproc)
cat >"$SLURM_CONF" <<EOF
ClusterName=strieladtest
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$((ctld_port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$munge_socket
StateSaveLocation=$scratch/state
SlurmdSpoolDir=$rundir/spool
SlurmctldPidFile=$scratch/slurmctld.pid
SlurmdPidFile=$scratch/slurmd.pid
SlurmctldLogFile=$scratch/slurmctld.log
SlurmdLogFile=$scratch/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MpiDefault=none
MinJobAge=600
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF
slurmctld -D -f "$SLURM_CONF" >"$scratch/slurmctld.stderr" 2>&1 &
slurmctld_pid=$!
slurmd -D -f "$SLURM_CONF" -N "$node" >"$scratch/slurmd.stderr" 2>&1 &
slurmd_pid=$!
state=
for ((i = 0; i < 300; i++)); do  # 30 s
  kill -0 "$slurmctld_pid" 2>/dev/null || { cat "$scratch/slurmctld.stderr"; fail "slurmctld exited at start"; }
  kill -0 "$slurmd_pid" 2>/dev/null || { cat "$scratch/slurmd.stderr"; fail "slurmd exited at start"; }
  state=$(sinfo -h -n "$node" -o %T 2>/dev/null || true)
  [[ $state == idle ]] && break
  sleep 0.1
done
[[ $state == idle ]] || fail "node $node is not idle after 30 s (state '$state')"
log "slurmctld (pid $slurmctld_pid, port $ctld_port) and slurmd (pid $slurmd_pid) up, node $node idle"
# Should this shell be killed by SIGKILL (no EXIT trap), stop the daemons all the same.
(
  unset SLURM_CONF
  while kill -0 $$ 2>/dev/null; do sleep 1; done
  kill -TERM "$slurmd_pid" "$slurmctld_pid" "$munged_pid" 2>/dev/null
) &
watchdog_pid=$!

# ---------------------------------------------------------------- data
"$exe" sample -o "$scratch/in" --dims 40x30x12 --steps 6 >"$scratch/sample.log" 2>&1 ||
  { cat "$scratch/sample.log"; fail "strielad-convert sample failed"; }
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
