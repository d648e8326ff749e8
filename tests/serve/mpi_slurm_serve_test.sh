#!/bin/bash
# Runs scripts/slurm/serve.sbatch for real on a private single-node Slurm cluster (munged
# + slurmctld + slurmd started here, all state in a scratch folder): strielad-serve
# under mpirun with 3 ranks in a batch job, reached at the address the script writes,
# asked for 16 nodes and its statistics by a minimal protocol client (Python), then
# stopped with `scancel --batch --signal=TERM` (job COMPLETED, exit 0, every rank stopped
# by rank 0); again, stopped with a plain scancel (CANCELLED, no process left); then
# once more with --launcher srun (srun --mpi=pmix) when Slurm's PMIx plugin works here,
# stopped with a plain scancel.
#
#   bash tests/serve/mpi_slurm_serve_test.sh STRIELAD_CONVERT WORK_DIR
#
# strielad-serve is taken next to strielad-convert in the build tree
# (../strielad-serve/strielad-serve) or from $STRIELAD_SERVE.
# Exit 0: pass; 1: fail; 77: skipped because Slurm/munge/Open MPI/python3 (or root) is
# missing, unless STRIELAD_REQUIRE_SLURM=1. Every daemon started here is stopped on exit.
set -euo pipefail

name=mpi_slurm_serve_test
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
sbatch_script=$repo/scripts/slurm/serve.sbatch

# shellcheck source=tests/support/slurm_cluster.sh
source "$repo/tests/support/slurm_cluster.sh"

(($# == 2)) || fail "usage: $0 STRIELAD_CONVERT WORK_DIR"
exe=$(realpath -- "$1")
sample="$(dirname "$exe")/../strielad-sample/strielad-sample"
[[ -x $exe ]] || fail "strielad-convert '$1' is not executable"
serve=${STRIELAD_SERVE:-$(dirname "$exe")/../strielad-serve/strielad-serve}
[[ -x $serve ]] || fail "strielad-serve '$serve' is not executable (set STRIELAD_SERVE)"
serve=$(realpath -- "$serve")
[[ -f $sbatch_script ]] || fail "$sbatch_script is missing"
command -v mpirun >/dev/null 2>&1 || skip "mpirun is missing (apt-get install -y openmpi-bin)"
command -v python3 >/dev/null 2>&1 || skip "python3 is missing (the test's protocol client)"
require_slurm_cluster srun
slurm_test_logs=('serve-*.out')
start_slurm_cluster "$2"

# ---------------------------------------------------------------- data
"$sample" -o "$scratch/in" --dims 40x30x12 --steps 2 --vars clw,ta >"$scratch/sample.log" 2>&1 ||
  { cat "$scratch/sample.log"; fail "strielad-sample failed"; }
mkdir -p "$scratch/root"
"$exe" "$scratch"/in/sample_t00{0..1}.nc -o "$scratch/root/sample" --brick 8 --threads 2 \
  >"$scratch/convert.log" 2>&1 || { cat "$scratch/convert.log"; fail "conversion failed"; }

# Hello, OpenDataset, SetScene, CutUpdate of nodes 0..15, then StatsRequest: prints the
# Stats JSON once every node has its NodeResult (formats/protocol.md).
cat >"$scratch/client.py" <<'EOF'
import json, socket, struct, sys
host, port = sys.argv[1].rsplit(":", 1)
s = socket.create_connection((host, int(port)), timeout=120)
def send(kind, payload=b""):
    s.sendall(struct.pack("<IHH", len(payload), kind, 0) + payload)
def exact(n):
    data = b""
    while len(data) < n:
        chunk = s.recv(n - len(data))
        if not chunk:
            sys.exit("connection closed")
        data += chunk
    return data
def receive():
    n, kind, _ = struct.unpack("<IHH", exact(8))
    payload = exact(n)
    if kind == 106:
        sys.exit("server error: " + payload[5:].decode(errors="replace"))
    return kind, payload
def str16(b):
    return struct.pack("<H", len(b)) + b
send(1, b"STRIELAD" + struct.pack("<H", 1) + str16(b"mpi_slurm_serve_test") + str16(b""))
assert receive()[0] == 101, "no Welcome"
send(2, str16(b"sample"))
assert receive()[0] == 102, "no DatasetOpened"
scene = json.dumps({"time": 0, "subvolumes": [
    {"id": 1, "name": "cloud", "limits": [{"var": "clw", "min": 1e-6}]}],
    "attributes": ["ta"]}).encode()
send(3, struct.pack("<II", 1, len(scene)) + scene)
assert receive()[0] == 103, "no GenerationStarted"
nodes = range(16)
send(5, struct.pack("<II", 1, len(nodes)) + b"".join(struct.pack("<If", n, float(n)) for n in nodes)
     + struct.pack("<II", 0, 0))
results = set()
while len(results) < len(nodes):
    kind, payload = receive()
    if kind == 105:
        sys.exit("NodeFailed: " + payload.decode(errors="replace"))
    if kind == 104:
        generation, node = struct.unpack("<II", payload[:8])
        assert generation == 1
        results.add(node)
send(6)
while True:
    kind, payload = receive()
    if kind == 107:
        (n,) = struct.unpack("<I", payload[:4])
        print(payload[4:4 + n].decode())
        break
send(7)
EOF

job_state() { scontrol -o show job "$1" 2>/dev/null | grep -o 'JobState=[A-Z_]*' | cut -d= -f2; }
job_exit() { scontrol -o show job "$1" 2>/dev/null | grep -o ' ExitCode=[0-9:]*' | cut -d= -f2; }
wait_for_end() {  # wait_for_end JOB: until a final state (60 s at most); prints it
  local i s
  for ((i = 0; i < 600; i++)); do
    s=$(job_state "$1")
    case $s in COMPLETED | FAILED | CANCELLED | TIMEOUT | NODE_FAIL | OUT_OF_MEMORY) echo "$s"; return 0 ;; esac
    sleep 0.1
  done
  echo "$s"
  return 1
}
serve_pids() {  # strielad-serve processes of this test's cluster
  local environ pid
  for environ in $(grep -lzxF "SLURM_CONF=$SLURM_CONF" /proc/[0-9]*/environ 2>/dev/null); do
    pid=${environ#/proc/}
    pid=${pid%/environ}
    [[ $(readlink "/proc/$pid/exe" 2>/dev/null) == "$serve" ]] && echo "$pid"
  done
  return 0
}

# run_job LAUNCHER STOP: submits serve.sbatch with 3 tasks, checks the server through the
# address file, stops it with STOP (gentle: scancel --batch --signal=TERM; plain: scancel).
run_job() {
  local launcher=$1 stop=$2 out address_file job address stats state i
  out=$scratch/serve-$launcher.out
  address_file=$scratch/serve-$launcher.address
  job=$(sbatch --parsable -n 3 --overcommit -c 1 --time 10:00 --output="$out" "$sbatch_script" \
    --root "$scratch/root" --port 0 --address-file "$address_file" --exe "$serve" \
    --launcher "$launcher" -- --cache-mib 16) || fail "sbatch failed"
  job=${job%%;*}
  job_ids+=("$job")
  for ((i = 0; i < 1200; i++)); do  # 120 s
    [[ -s $address_file ]] && break
    case $(job_state "$job") in PENDING | RUNNING | CONFIGURING | "") ;; *) cat "$out"; fail "job $job ($launcher) ended before listening" ;; esac
    sleep 0.1
  done
  [[ -s $address_file ]] || { cat "$out"; fail "no address file after 120 s ($launcher)"; }
  address=$(<"$address_file")
  log "job $job ($launcher) listening on $address"
  [[ $address =~ ^[^:]+:[0-9]+$ ]] || fail "address file holds '$address'"
  grep -q "listening on $address (3 ranks" "$out" || { cat "$out"; fail "the job output does not give the address"; }
  stats=$(timeout 120 python3 "$scratch/client.py" "$address") || { cat "$out"; fail "client failed ($launcher)"; }
  log "stats: $stats"
  grep -q '"ranks":3' <<<"$stats" || fail "stats do not report 3 ranks: $stats"
  [[ $(serve_pids | wc -l) -eq 3 ]] || fail "expected 3 strielad-serve processes, found $(serve_pids | wc -l)"
  if [[ $stop == gentle ]]; then
    scancel --batch --signal=TERM "$job"
  else
    scancel "$job"
  fi
  state=$(wait_for_end "$job") || fail "job $job ($launcher) still $state 60 s after scancel"
  log "job $job ($launcher) ended: $state, exit code $(job_exit "$job")"
  # Slurm marks a cancelled job at once; its processes may need a moment to end.
  for ((i = 0; i < 300; i++)); do
    [[ -z $(serve_pids) && ! -e $address_file ]] && break
    sleep 0.1
  done
  [[ -z $(serve_pids) ]] || fail "strielad-serve processes left 30 s after job $job: $(serve_pids | tr '\n' ' ')"
  [[ ! -e $address_file ]] || fail "the address file outlived job $job by 30 s"
  if [[ $stop == gentle ]]; then
    [[ $state == COMPLETED && $(job_exit "$job") == 0:0 ]] ||
      { cat "$out"; fail "job $job ($launcher) ended $state with exit code $(job_exit "$job"), not COMPLETED 0:0"; }
    grep -q "MPI: 2 worker ranks stopped" "$out" || { cat "$out"; fail "rank 0 did not stop the workers"; }
    grep -q "serve.sbatch: stopped at .* (launcher exit status 0)" "$out" || { cat "$out"; fail "no clean stop in the job output"; }
  else
    [[ $state == CANCELLED ]] || { cat "$out"; fail "job $job ($launcher) ended $state after scancel"; }
  fi
}

run_job mpirun gentle
log "mpirun job: served 16 nodes with 3 ranks, stopped cleanly (COMPLETED, 0:0)"
run_job mpirun plain
log "mpirun job: served 16 nodes with 3 ranks, ended by scancel"

# srun --mpi=pmix needs Slurm's PMIx plugin to work with this Open MPI.
if srun --mpi=list 2>&1 | grep -q pmix &&
  timeout 60 srun --mpi=pmix -n 2 --overcommit -t 1:00 bash -c '[[ -n ${PMIX_RANK:-} ]]' >/dev/null 2>&1; then
  run_job srun plain
  log "srun job: served 16 nodes with 3 ranks, ended by scancel"
else
  log "srun --mpi=pmix does not work here; skipped the srun launcher"
fi
passed=1
