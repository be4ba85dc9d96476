#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Renders a simulation on a Slurm cluster in N shards (examples/slurm/README.md): submits
#   1. a job array of N tasks, render.sbatch: task I renders shard I+1 of N into OUT/parts/I+1
#   2. merge.sbatch, which waits for every task to succeed (--dependency=afterok) and joins
#      the parts into OUT/merged with glint-envi merge
# and prints the two job ids on stdout as render_job=ID and merge_job=ID. Should a shard fail,
# the merge job is cancelled (--kill-on-invalid-dep=yes); the README says how to resubmit.
#
# Usage: examples/slurm/submit.sh SIM N [OUT]
#   SIM   the simulation (.jsim or .sim); its folder and OUT must be on a filesystem that the
#         submitting machine and every compute node see at the same path
#   N     the number of shards (array tasks)
#   OUT   where everything goes (default: ./glint-slurm): shards/ (each shard's schedule),
#         parts/K/ (shard K's files), logs/ (the jobs' output), full.json, merged/ (the result)
#
# Environment (passed on to the jobs; see render.sbatch):
#   GLINT_BIN, GLINT_CONVERGENCE, GLINT_SCHEDULE_ARGS, GLINT_RENDER_ARGS, GLINT_SHARD_BY
#   GLINT_CPUS_PER_TASK   CPUs of each render task (sbatch --cpus-per-task; default Slurm's)
#   SBATCH_PARTITION, SBATCH_TIMELIMIT, SBATCH_ACCOUNT, ...: read by sbatch itself
set -euo pipefail

usage="usage: submit.sh SIM N [OUT]"
if [ $# -lt 2 ] || [ $# -gt 3 ]; then echo "$usage" >&2; exit 2; fi
here=$(cd -P -- "$(dirname -- "$0")" > /dev/null && pwd -P)
sim=$1
count=$2
out=${3:-glint-slurm}
if ! [[ "$count" =~ ^[1-9][0-9]*$ ]]; then
    echo "submit.sh: N must be a positive whole number, not '$count'" >&2
    exit 2
fi
[ -f "$sim" ] || { echo "submit.sh: $sim: no such file" >&2; exit 1; }
command -v sbatch > /dev/null || { echo "submit.sh: sbatch not found (is Slurm installed here?)" >&2; exit 1; }

# Absolute paths: the jobs may start in another folder, on another machine.
sim="$(cd -P -- "$(dirname -- "$sim")" > /dev/null && pwd -P)/$(basename "$sim")"
mkdir -p "$out"
out=$(cd -P -- "$out" > /dev/null && pwd -P)
if [ -n "${GLINT_BIN:-}" ]; then
    GLINT_BIN=$(cd -P -- "$GLINT_BIN" > /dev/null && pwd -P)
    export GLINT_BIN
fi
# Parts of an earlier run would be merged with this one's: start from an empty OUT/parts.
if [ -n "$(ls -A "$out/parts" 2> /dev/null)" ]; then
    echo "submit.sh: $out/parts is not empty (an earlier run?): remove it or choose another OUT" >&2
    exit 1
fi
mkdir -p "$out/logs"

# Check the simulation here, before anything waits in the queue: the summary is analytic and
# takes a moment (the jobs need glint-schedule too, so it should be found here as well).
schedule=glint-schedule
[ -z "${GLINT_BIN:-}" ] || schedule="$GLINT_BIN/glint-schedule"
schedule_args=()
read -r -a schedule_args <<< "${GLINT_SCHEDULE_ARGS:-}"
if command -v "$schedule" > /dev/null; then
    "$schedule" "$sim" ${schedule_args[@]+"${schedule_args[@]}"} --summary > "$out/summary.txt"
else
    echo "submit.sh: warning: $schedule not found here; the simulation is not checked before submitting" >&2
fi

render_opts=(--parsable --export=ALL --array="0-$((count - 1))"
             --output="$out/logs/render-%A_%a.out")
if [ -n "${GLINT_CPUS_PER_TASK:-}" ]; then
    render_opts+=(--cpus-per-task="$GLINT_CPUS_PER_TASK")
fi
render_job=$(sbatch ${render_opts[@]+"${render_opts[@]}"} "$here/render.sbatch" "$sim" "$count" "$out")
render_job=${render_job%%;*}  # --parsable prints ID or ID;CLUSTER

if ! merge_job=$(sbatch --parsable --export=ALL --dependency="afterok:$render_job" \
                     --kill-on-invalid-dep=yes --output="$out/logs/merge-%j.out" \
                     "$here/merge.sbatch" "$sim" "$count" "$out"); then
    echo "submit.sh: the merge job was not accepted; cancelling the render array $render_job" >&2
    scancel "$render_job" || true
    exit 1
fi
merge_job=${merge_job%%;*}

resubmit=$(printf ' %q' --export=ALL --output="$out/logs/render-%A_%a.out" \
             "$here/render.sbatch" "$sim" "$count" "$out")
cat >&2 <<MSG
submit.sh: $count render tasks (job array $render_job) and the merge (job $merge_job) submitted.
  watch:   squeue -j $render_job,$merge_job
  logs:    $out/logs/
  result:  $out/merged/ (once job $merge_job has completed)
  a failed shard K: sbatch --array=\$((K-1))${resubmit}
           then the merge again, with --dependency=afterok:<that job id> (README.md)
MSG
printf 'render_job=%s\nmerge_job=%s\n' "$render_job" "$merge_job"
