#!/bin/bash
# Submits a STRIELAD conversion to Slurm: a job array whose tasks convert disjoint ranges
# of time steps (convert-array.sbatch) plus a finalize job (finalize.sbatch) that runs
# after every task succeeded. See README.md in this folder.
set -euo pipefail

me=$(basename "$0")
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

usage() {
  cat <<EOF
Usage: $me -o STORE [OPTIONS] INPUT...

Converts CF-NetCDF INPUT files into the brick store STORE on a Slurm cluster: one job
array task per STEPS_PER_TASK time steps (strielad-convert --steps A:B --no-finalize),
then a finalize job (--dependency=afterok on the array) that runs
'strielad-convert finalize STORE' and 'strielad-convert verify STORE'.
Prints both job ids. Re-running the same command after a failure submits only the
tasks whose time steps are still missing (see --all-tasks).

Conversion:
  -o, --store DIR          store directory to create or resume (mandatory)
  -n, --steps-per-task N   time steps per array task (default: \$STEPS_PER_TASK or 4)
  --steps-total N          time steps of the store (after --time). Default: read from
                           STORE/MANIFEST when the store exists, else the lengths of the
                           time coordinate in every input summed ('ncdump -h')
  --vars LIST, --brick N, --time A:B, --codec NAME, --level L, --shuffle S, --nan-as-fill
                           passed to strielad-convert (see strielad-convert --help)
  --exe PATH               strielad-convert binary the jobs run (default:
                           \$STRIELAD_CONVERT, else strielad-convert from PATH)
  --all-tasks              when resuming, submit every task, not only those with missing
                           steps (each task still skips the steps already present)
Slurm (given to both jobs unless noted):
  -p, --partition NAME     partition
  -t, --time-limit TIME    time limit of each array task (sbatch --time)
  --finalize-time-limit T  time limit of the finalize job (default: --time-limit)
  -c, --cpus-per-task N    CPUs of each array task = converter threads (default 1; array only)
  --mem SIZE               memory per node (sbatch --mem)
  -A, --account NAME       account
  --qos NAME               quality of service
  --max-parallel N         run at most N array tasks at once (--array=...%N)
  --log-dir DIR            folder for the Slurm output files (default: current folder):
                           strielad-convert-ARRAYJOB_TASK.out, strielad-finalize-JOB.out
  --sbatch-arg ARG         one more sbatch argument for both jobs (repeatable), e.g.
                           --sbatch-arg=--constraint=ssd
Output:
  --parsable               print only "ARRAY_JOB_ID FINALIZE_JOB_ID" (ARRAY_JOB_ID is "-"
                           when no task was needed)
  --dry-run                print the sbatch commands instead of running them
  -h, --help               this text

Environment: SLURM_CONF and the usual sbatch variables apply; STRIELAD_CONVERT and
STEPS_PER_TASK give defaults as above. Input and store paths are made absolute, so run
every submission of one store with the same inputs in the same order.

Example:
  $me -o /scratch/run42.strielad -n 4 -c 8 -p compute -t 01:00:00 \\
      --vars ta,ua,va,wa --brick 20 /data/run42/out_*.nc
EOF
}

die() {
  echo "$me: error: $*" >&2
  exit 2
}
is_count() { [[ $1 =~ ^[0-9]+$ ]]; }
# An absolute, lexically normal path (symbolic links kept), as strielad-convert records it.
absolute() { realpath -m -s -- "$1"; }

store=
per_task=${STEPS_PER_TASK:-4}
steps_total=
exe=${STRIELAD_CONVERT:-strielad-convert}
all_tasks=0
time_range=
convert_flags=()
slurm_common=()
array_only=()
time_limit=
finalize_time_limit=
max_parallel=
log_dir=.
parsable=0
dry_run=0
inputs=()

while (($# > 0)); do
  arg=$1
  value=
  has_value=0
  if [[ $arg == --*=* ]]; then
    value=${arg#*=}
    arg=${arg%%=*}
    has_value=1
  fi
  takes_value=1
  case $arg in
    -h | --help | --all-tasks | --nan-as-fill | --parsable | --dry-run) takes_value=0 ;;
  esac
  if ((takes_value && !has_value)); then
    case $arg in
      -*)
        (($# >= 2)) || die "$arg needs a value"
        value=$2
        shift
        ;;
    esac
  elif ((!takes_value && has_value)); then
    die "$arg takes no value"
  fi
  shift
  case $arg in
    -h | --help) usage; exit 0 ;;
    -o | --store | --output) store=$value ;;
    -n | --steps-per-task) per_task=$value ;;
    --steps-total) steps_total=$value ;;
    --vars | --brick | --codec | --level | --shuffle) convert_flags+=("$arg" "$value") ;;
    --time) time_range=$value; convert_flags+=(--time "$value") ;;
    --nan-as-fill) convert_flags+=(--nan-as-fill) ;;
    --exe) exe=$value ;;
    --all-tasks) all_tasks=1 ;;
    -p | --partition) slurm_common+=("--partition=$value") ;;
    -t | --time-limit) time_limit=$value ;;
    --finalize-time-limit) finalize_time_limit=$value ;;
    -c | --cpus-per-task) array_only+=("--cpus-per-task=$value") ;;
    --mem) slurm_common+=("--mem=$value") ;;
    -A | --account) slurm_common+=("--account=$value") ;;
    --qos) slurm_common+=("--qos=$value") ;;
    --max-parallel) max_parallel=$value ;;
    --log-dir) log_dir=$value ;;
    --sbatch-arg) slurm_common+=("$value") ;;
    --parsable) parsable=1 ;;
    --dry-run) dry_run=1 ;;
    --)
      inputs+=("$@")
      break
      ;;
    -*) die "unknown option '$arg' (see --help)" ;;
    *) inputs+=("$arg") ;;
  esac
done

[[ -n $store ]] || die "no store given: -o STORE is required (see --help)"
((${#inputs[@]} > 0)) || die "no INPUT files given (see --help)"
{ is_count "$per_task" && ((10#$per_task > 0)); } || die "--steps-per-task '$per_task' is not a positive integer"
per_task=$((10#$per_task))
[[ -z $max_parallel ]] || { is_count "$max_parallel" && ((10#$max_parallel > 0)); } ||
  die "--max-parallel '$max_parallel' is not a positive integer"
[[ -z $steps_total ]] || { is_count "$steps_total" && ((10#$steps_total > 0)); } ||
  die "--steps-total '$steps_total' is not a positive integer"

if [[ $exe != */* ]]; then
  resolved=$(command -v -- "$exe" 2>/dev/null) || die "strielad-convert not found ('$exe'): pass --exe PATH or set STRIELAD_CONVERT"
  exe=$resolved
fi
[[ -x $exe ]] || die "'$exe' is not an executable file"
exe=$(absolute "$exe")
store=$(absolute "$store")
for i in "${!inputs[@]}"; do
  [[ -f ${inputs[$i]} ]] || die "input '${inputs[$i]}' is not a file"
  inputs[i]=$(absolute "${inputs[$i]}")
done
log_dir=$(absolute "$log_dir")
((dry_run)) || command -v sbatch >/dev/null 2>&1 || die "sbatch not found: run this on a Slurm login node"

# Prints the lengths of the time coordinate(s) of one netCDF file, one per line: a 1-D
# coordinate variable (named like its dimension) with axis "T", standard_name "time" or
# units "<unit> since <date>", as strielad-convert recognises time.
time_lengths() {
  ncdump -h "$1" | awk '
    /^[ \t]*dimensions:/ { section = "dims"; next }
    /^[ \t]*variables:/ { section = "vars"; next }
    /^[ \t]*(\/\/|group:|types:|data:|})/ { section = ""; next }
    section == "dims" && $2 == "=" {
      name = $1
      if ($3 == "UNLIMITED") {
        n = $0; sub(/.*\/\/ *\(/, "", n); sub(/ currently.*/, "", n)
      } else {
        n = $3
      }
      len[name] = n
      next
    }
    section == "vars" && $0 !~ /:/ && $0 ~ /\(/ {
      decl = $2; v = decl; sub(/\(.*/, "", v)
      d = decl; sub(/^[^(]*\(/, "", d); sub(/\).*/, "", d)
      if (d == v) coord[v] = 1
      next
    }
    section == "vars" && $1 ~ /^[^:]+:[A-Za-z_]+$/ && $2 == "=" {
      split($1, p, ":")
      if ((p[2] == "axis" && $0 ~ /= *"T"/) || (p[2] == "standard_name" && $0 ~ /= *"time"/) ||
          (p[2] == "units" && $0 ~ / since /)) is_time[p[1]] = 1
    }
    END { for (v in is_time) if ((v in coord) && (v in len)) print len[v] }
  ' | sort -u
}

count_steps_from_inputs() {
  command -v ncdump >/dev/null 2>&1 ||
    die "ncdump not found: cannot count the time steps; pass --steps-total N (install netcdf-bin for ncdump)"
  local sum=0 f lengths
  for f in "${inputs[@]}"; do
    lengths=$(time_lengths "$f") || die "ncdump -h '$f' failed"
    if [[ -z $lengths ]]; then
      die "no time coordinate found in '$f' by ncdump -h; pass --steps-total N"
    elif [[ $lengths == *$'\n'* ]] || ! is_count "$lengths"; then
      die "'$f' has several time coordinates ($(echo "$lengths" | tr '\n' ' ')); pass --steps-total N"
    fi
    sum=$((sum + 10#$lengths))
  done
  local first=0 last=$((sum - 1))
  if [[ -n $time_range ]]; then  # --time A:B, A:, :B or A selects merged steps (inclusive)
    local a b
    if [[ $time_range == *:* ]]; then a=${time_range%%:*}; b=${time_range#*:}; else a=$time_range; b=$time_range; fi
    if [[ -n $a ]]; then
      is_count "$a" || die "--time '$time_range' is not A:B"
      first=$((10#$a))
    fi
    if [[ -n $b ]]; then
      is_count "$b" || die "--time '$time_range' is not A:B"
      if ((10#$b < last)); then last=$((10#$b)); fi
    fi
  fi
  ((first <= last)) || die "--time '$time_range' selects none of the inputs' $sum time steps"
  echo $((last - first + 1))
}

# Reads a value from 'strielad-convert info STORE --json': state, step count or the
# converted steps (one per line).
store_fact() {
  local what=$1 json
  json=$("$exe" info "$store" --json 2>/dev/null) || return 1
  if command -v jq >/dev/null 2>&1; then
    case $what in
      state) jq -r '.state' <<<"$json" ;;
      steps) jq -r '.time.values | length' <<<"$json" ;;
      converted) jq -r '.converted_steps[]' <<<"$json" ;;
    esac
  elif command -v python3 >/dev/null 2>&1; then
    python3 -c '
import json, sys
d = json.load(sys.stdin)
w = sys.argv[1]
if w == "state": print(d["state"])
elif w == "steps": print(len(d["time"]["values"]))
else: print("\n".join(str(s) for s in d["converted_steps"]))
' "$what" <<<"$json"
  else
    return 1
  fi
}

# Compresses sorted task indices into Slurm's array syntax: 0-3,7,9-12.
array_spec() {
  local out='' start='' prev='' i
  for i in "$@" end; do
    if [[ $i != end && -n $prev ]] && ((i == prev + 1)); then
      prev=$i
      continue
    fi
    if [[ -n $start ]]; then
      out+="${out:+,}$start"
      if ((prev > start)); then out+="-$prev"; fi
    fi
    start=$i
    prev=$i
  done
  echo "$out"
}

resuming=0
converted=()
if [[ -f $store/MANIFEST ]]; then
  if state=$(store_fact state) && [[ -n $state ]]; then
    resuming=1
    if [[ $state == complete ]]; then
      echo "$me: $store is already complete; nothing to submit" >&2
      ((parsable)) && echo "- -"
      exit 0
    fi
    store_steps=$(store_fact steps)
    if [[ -n $steps_total && $steps_total != "$store_steps" ]]; then
      die "--steps-total $steps_total, but $store/MANIFEST has $store_steps time steps"
    fi
    steps_total=$store_steps
    mapfile -t converted < <(store_fact converted)
  else
    echo "$me: warning: cannot read $store (needs jq or python3 and a sound MANIFEST); submitting every task" >&2
  fi
fi
[[ -n $steps_total ]] || steps_total=$(count_steps_from_inputs)
steps_total=$((10#$steps_total))
ntasks=$(((steps_total + per_task - 1) / per_task))

tasks=()
if ((resuming && !all_tasks)); then
  declare -A present=()
  for s in "${converted[@]}"; do present[$s]=1; done
  for ((t = 0; t < ntasks; t++)); do
    for ((s = t * per_task; s < (t + 1) * per_task && s < steps_total; s++)); do
      if [[ -z ${present[$s]:-} ]]; then
        tasks+=("$t")
        break
      fi
    done
  done
else
  for ((t = 0; t < ntasks; t++)); do tasks+=("$t"); done
fi

mkdir -p -- "$log_dir"
# run_sbatch LABEL SBATCH_ARGS...: submits and prints the job id.
run_sbatch() {
  local label=$1
  shift
  if ((dry_run)); then
    printf '%q ' sbatch "$@" >&2
    echo >&2
    echo "DRYRUN-$label"
  else
    sbatch --parsable "$@" | cut -d';' -f1  # "JOBID[;CLUSTER]"
  fi
}

array_id=-
dependency=()
if ((${#tasks[@]} > 0)); then
  spec=$(array_spec "${tasks[@]}")
  [[ -z $max_parallel ]] || spec+="%$((10#$max_parallel))"
  array_args=(--array="$spec" --job-name=strielad-convert --export=ALL
    --output="$log_dir/strielad-convert-%A_%a.out" "${slurm_common[@]}" "${array_only[@]}")
  [[ -z $time_limit ]] || array_args+=(--time="$time_limit")
  array_id=$(run_sbatch array "${array_args[@]}" "$here/convert-array.sbatch" \
    --store "$store" --steps-per-task "$per_task" --steps-total "$steps_total" --exe "$exe" \
    -- "${inputs[@]}" "${convert_flags[@]}") || array_id=
  [[ -n $array_id ]] || die "submitting the job array failed (see sbatch's message above)"
  dependency=(--dependency="afterok:$array_id" --kill-on-invalid-dep=yes)
fi

finalize_args=(--job-name=strielad-finalize --export=ALL --output="$log_dir/strielad-finalize-%j.out"
  "${dependency[@]}" "${slurm_common[@]}")
finalize_time_limit=${finalize_time_limit:-$time_limit}
[[ -z $finalize_time_limit ]] || finalize_args+=(--time="$finalize_time_limit")
finalize_id=$(run_sbatch finalize "${finalize_args[@]}" "$here/finalize.sbatch" --exe "$exe" "$store") ||
  finalize_id=
[[ -n $finalize_id ]] || die "submitting the finalize job failed${dependency:+ (array job $array_id is submitted)}; \
submit it by hand: sbatch ${dependency[*]} $here/finalize.sbatch --exe $exe $store"

if ((parsable)); then
  echo "$array_id $finalize_id"
else
  if [[ $array_id == - ]]; then
    echo "array job:    none (every time step is already converted)"
  else
    echo "array job:    $array_id (${#tasks[@]} of $ntasks tasks [$spec], $steps_total steps, $per_task per task)"
  fi
  echo "finalize job: $finalize_id${dependency:+ (runs after array job $array_id succeeds)}"
  echo "logs:         $log_dir"
fi
