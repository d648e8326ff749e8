# shellcheck shell=bash
# Sourced by the shell tests that run jobs on a private single-node Slurm cluster: munged,
# slurmctld and slurmd started by the test as root, all their state in a scratch folder.
# Not a test itself (tests/CMakeLists.txt runs tests/*/*_test.sh only).
#
#   name=my_test                                # used in every message
#   source "$repo/tests/support/slurm_cluster.sh"
#   require_slurm_cluster [PROGRAM...]          # exit 77 (skip) unless all is there
#   start_slurm_cluster WORK_DIR                # sets scratch, node, SLURM_CONF
#   ... sbatch; job_ids+=("$job") ...           # jobs cancelled on exit
#   passed=1                                    # last: the exit trap reports PASS
#
# start_slurm_cluster installs slurm_test_exit as the EXIT trap (INT and TERM exit 130 and
# 143): it stops every daemon started here (stop_slurm_cluster), pass or fail, and
# removes the scratch folder on success or keeps it (its path and the daemons' logs
# printed) on failure. Files of the test to print on failure: glob patterns relative to
# the scratch folder in slurm_test_logs.

: "${name:?set name, the name of the test, before sourcing slurm_cluster.sh}"
job_ids=()
passed=0
slurm_test_logs=()
scratch=
rundir=
munged_pid=
watchdog_pid=
slurmctld_pid=
slurmd_pid=

fail() {
  echo "$name: FAIL: $*" >&2
  exit 1
}

# Exit 77 (skipped), unless STRIELAD_REQUIRE_SLURM=1 (CI), which makes it a failure.
skip() {
  if [[ ${STRIELAD_REQUIRE_SLURM:-0} == 1 ]]; then
    fail "$* (STRIELAD_REQUIRE_SLURM=1, so this is a failure, not a skip)"
  fi
  echo "$name: SKIP: $*"
  exit 77
}

log() { echo "$name: $(date '+%T') $*"; }

# require_slurm_cluster [PROGRAM...]: skips unless Slurm, munge, the given programs and
# root are there.
# shellcheck disable=SC2120  # the programs are optional
require_slurm_cluster() {
  local missing=() tool
  for tool in munged mungekey munge unmunge slurmctld slurmd sbatch squeue scontrol scancel sinfo setpriv "$@"; do
    command -v "$tool" >/dev/null 2>&1 || missing+=("$tool")
  done
  ((${#missing[@]} == 0)) || skip "missing programs: ${missing[*]} (apt-get install -y slurm-wlm munge)"
  ((EUID == 0)) || skip "must run as root to start slurmd and munged"
  id munge >/dev/null 2>&1 || skip "no 'munge' user (install the munge package)"
}

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
  local f pattern files=("$scratch"/slurmctld.log "$scratch"/slurmd.log
    "$rundir"/munge/munged.log "$scratch"/munged.stderr)
  for pattern in "${slurm_test_logs[@]}"; do
    # shellcheck disable=SC2206  # the pattern is globbed on purpose
    files+=("$scratch"/$pattern)
  done
  for f in "${files[@]}"; do
    [[ -f $f ]] || continue
    echo "----- $f (last 40 lines) -----"
    tail -n 40 "$f"
  done
}

# Cancels job_ids and stops slurmd, slurmctld, what outlived them, and munged. Returns 0;
# safe to call again.
stop_slurm_cluster() {
  local i pid
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
  if [[ -n $scratch ]]; then
    for pid in $(stray_pids); do
      echo "$name: stopping leftover process $pid: $(tr '\0' ' ' <"/proc/$pid/cmdline" 2>/dev/null)" >&2
      kill -KILL "$pid" 2>/dev/null
    done
  fi
  stop_pid "$munged_pid" munged
  watchdog_pid='' slurmd_pid='' slurmctld_pid='' munged_pid=''
  return 0
}

# The EXIT trap: stops the cluster, then keeps (failure) or removes (success) the
# scratch folder, and exits with the test's status.
slurm_test_exit() {
  local rc=$?
  set +e
  trap - EXIT INT TERM
  stop_slurm_cluster
  if ((rc != 0 && !passed)); then
    print_logs
    echo "$name: scratch folder kept: $scratch"
  fi
  [[ -z $rundir || $rundir == "$scratch"/* ]] || rm -rf -- "$rundir"
  if ((passed)); then
    rm -rf -- "$scratch"
    echo "$name: PASS"
  else
    echo "$name: FAIL (exit status $rc)"
  fi
  exit "$rc"
}

port_free() { ! ss -Htan "sport = :$1" 2>/dev/null | grep -q .; }

# start_slurm_cluster WORK_DIR: a scratch folder under WORK_DIR ($scratch), munged,
# slurmctld and slurmd on this node ($node, partition "test", all its CPUs), returning
# once the node is idle. Exports SLURM_CONF; settings of an enclosing Slurm job or the
# user's environment are unset.
start_slurm_cluster() {
  local work=$1 var i p cpus state munge_socket ctld_port
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
  trap slurm_test_exit EXIT
  trap 'exit 130' INT
  trap 'exit 143' TERM

  # -------------------------------------------------------------- munge
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

  # -------------------------------------------------------------- slurm
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
}
