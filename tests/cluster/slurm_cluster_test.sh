#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# A real one-node Slurm cluster runs examples/slurm on the demo (ctest cluster/slurm-demo,
# label cluster). As root, in WORK_DIR/daemons/ it
#   1. starts munged with a key of its own (socket, pid, log and seed files in that folder;
#      the sockets in a /tmp/glint-slurm.* folder instead when the path is too long for them),
#   2. writes a slurm.conf for this machine alone (its short host name, nproc CPUs, root as
#      SlurmUser, ports 16817/16818 or the next free ones, no accounting, no cgroups) and
#      starts slurmctld and slurmd with it, then waits (60 s at most) for the node to be idle,
#   3. runs a trivial 4-task array (sbatch --array=0-3 --wrap hostname) as a smoke test,
# then converts examples/demo/sim/demo.sim to WORK_DIR/demo.jsim, submits it with
# examples/slurm/submit.sh as 4 shards plus the merge (convergence 2,4,1e-3, no processing),
# waits for the jobs (10 min at most, polling scontrol show job), renders the demo again in
# one glint-render process into WORK_DIR/single/ and checks that the merged files
# (WORK_DIR/slurm/merged/) are the same files: data byte for byte, headers line for line but
# for `glint command line`.
# Every daemon it started is stopped on exit, failure, SIGINT or SIGTERM (scancel, then
# SIGTERM and a wait for each), and also when the test itself is killed outright (ctest's
# timeout sends SIGKILL): a watchdog process outside the test's process tree waits for the
# test to end and stops them. WORK_DIR is left as it is (configuration, daemon logs, job
# logs, renders); on failure the logs' last lines are printed. The next run stops whatever
# an earlier run left running there and starts afresh.
# Exit status: 0 passed, 1 failed, 77 skipped (not root, or the Slurm or MUNGE programs are
# not installed: scripts/install-deps.sh installs them).
# Usage: tests/cluster/slurm_cluster_test.sh BIN_DIR WORK_DIR
#        (internal) slurm_cluster_test.sh --stop DAEMON_DIR | --watch PID DAEMON_DIR
set -euo pipefail

self=$(cd "$(dirname "$0")" && pwd)/$(basename "$0")
repo=$(cd "$(dirname "$0")/../.." && pwd)
convergence=2,4,1e-3
shards=4
node_wait_s=60
smoke_wait_s=120
jobs_wait_s=600

say() { printf '[%s] %s\n' "$(date +%H:%M:%S)" "$*"; }

# ---- stopping what a run started (idempotent; used by the test, the watchdog, the next run)

# The pid in FILE if it names a live (not zombie) process whose name is NAME.
live_pid() {
    local file=$1 name=$2 pid state
    [ -s "$file" ] || return 1
    pid=$(tr -dc '0-9' < "$file")
    [ -n "$pid" ] && [ -r "/proc/$pid/comm" ] || return 1
    [ "$(cat "/proc/$pid/comm" 2> /dev/null)" = "$name" ] || return 1
    state=$(sed 's/^.*) //' "/proc/$pid/stat" 2> /dev/null | cut -d' ' -f1)
    [ "$state" != Z ] || return 1
    printf '%s\n' "$pid"
}

# Waits up to SECONDS for PID to end; then SIGKILL.
wait_gone() {
    local pid=$1 seconds=$2 name=$3 i
    for ((i = 0; i < seconds * 5; i++)); do
        if [ ! -e "/proc/$pid" ] || [ "$(sed 's/^.*) //' "/proc/$pid/stat" 2> /dev/null | cut -d' ' -f1)" = Z ]; then
            return 0
        fi
        sleep 0.2
    done
    echo "stop: $name ($pid) still running after ${seconds} s: SIGKILL" >&2
    kill -KILL "$pid" 2> /dev/null || true
    sleep 0.5
}

# The slurmstepd processes of the cluster whose configuration is CONF (their environment
# holds SLURM_CONF=CONF, inherited from the slurmd this script started).
our_stepds() {
    local conf=$1 dir pid
    for dir in /proc/[0-9]*; do
        pid=${dir#/proc/}
        [ "$(cat "$dir/comm" 2> /dev/null)" = slurmstepd ] || continue
        if tr '\0' '\n' 2> /dev/null < "$dir/environ" | grep -qxF "SLURM_CONF=$conf"; then
            printf '%s\n' "$pid"
        fi
    done
}

stop_all() {
    local dd=$1 conf pid i name
    conf="$dd/slurm.conf"
    [ -d "$dd" ] || return 0
    if pid=$(live_pid "$dd/slurmctld.pid" slurmctld); then
        # Cancel every job of this private cluster, so that no slurmstepd outlives slurmd.
        local ids
        ids=$(SLURM_CONF=$conf timeout 10 squeue -h -o %A 2> /dev/null | sort -u | tr '\n' ' ' || true)
        if [ -n "${ids// /}" ]; then
            echo "stop: cancelling jobs $ids" >&2
            # shellcheck disable=SC2086 # job ids, one word each
            SLURM_CONF=$conf timeout 10 scancel $ids 2> /dev/null || true
        fi
    fi
    if [ -f "$conf" ]; then
        for ((i = 0; i < 100; i++)); do
            [ -n "$(our_stepds "$conf")" ] || break
            sleep 0.2
        done
        for pid in $(our_stepds "$conf"); do
            echo "stop: slurmstepd $pid still running: SIGTERM" >&2
            kill -TERM "$pid" 2> /dev/null || true
            wait_gone "$pid" 10 slurmstepd
        done
    fi
    for name in slurmd slurmctld munged; do
        local file="$dd/$name.pid"
        [ "$name" != munged ] || file="$dd/munge/munged.pid"
        if pid=$(live_pid "$file" "$name"); then
            echo "stop: $name ($pid): SIGTERM" >&2
            kill -TERM "$pid" 2> /dev/null || true
            wait_gone "$pid" 20 "$name"
        fi
    done
    # Sockets only: a short folder under /tmp when the work folder's path is too long for them.
    if [ -s "$dd/runtime-dir" ]; then
        local rt
        rt=$(cat "$dd/runtime-dir")
        case "$rt" in /tmp/glint-slurm.*) rm -rf -- "$rt" ;; esac
        rm -f "$dd/runtime-dir"
        [ ! -L "$dd/run" ] || rm -f "$dd/run"
    fi
}

if [ "${1:-}" = --stop ]; then
    stop_all "${2:?usage: --stop DAEMON_DIR}"
    exit 0
fi
if [ "${1:-}" = --watch ]; then
    watched=${2:?usage: --watch PID DAEMON_DIR}
    dd=${3:?usage: --watch PID DAEMON_DIR}
    while kill -0 "$watched" 2> /dev/null; do sleep 1; done
    echo "watchdog: test process $watched ended at $(date +%H:%M:%S); stopping what is left" >&2
    stop_all "$dd"
    exit 0
fi

# ---- the test

[ $# -eq 2 ] || { echo "usage: slurm_cluster_test.sh BIN_DIR WORK_DIR" >&2; exit 2; }
if [ "$(id -u)" -ne 0 ]; then
    echo "SKIP: cluster/slurm-demo starts munged, slurmctld and slurmd as root: run as root" >&2
    exit 77
fi
missing=()
for program in munged munge unmunge slurmctld slurmd sbatch squeue scontrol sinfo scancel; do
    command -v "$program" > /dev/null || missing+=("$program")
done
if [ ${#missing[@]} -gt 0 ]; then
    echo "SKIP: cluster/slurm-demo needs ${missing[*]} (Debian packages slurm-wlm and munge; scripts/install-deps.sh)" >&2
    exit 77
fi
bin=$(cd "$1" && pwd)
for tool in glint-platform2jsim glint-schedule glint-render glint-envi; do
    [ -x "$bin/$tool" ] || { echo "FAIL: $bin/$tool not found (build first)" >&2; exit 1; }
done
mkdir -p "$2"
work=$(cd "$2" && pwd)
dd="$work/daemons"

# An earlier run's daemons (if its watchdog could not stop them), then a clean folder: only
# a folder this test made (it holds the marker file) or an empty one is emptied.
marker="$work/.glint-slurm-cluster-test"
if [ -n "$(ls -A "$work")" ] && [ ! -f "$marker" ]; then
    echo "FAIL: $work is not empty and not a work folder of this test: give another WORK_DIR" >&2
    exit 1
fi
stop_all "$dd"
find "$work" -mindepth 1 -maxdepth 1 -exec rm -rf -- {} +
touch "$marker"
mkdir -p "$dd/munge" "$dd/state"
chmod 755 "$dd" "$dd/munge"

failed_step=""
on_exit() {
    local rc=$?
    set +e
    trap - EXIT INT TERM HUP
    if [ "$rc" -ne 0 ]; then
        echo "FAIL${failed_step:+ at: $failed_step} (exit $rc); the last lines of the logs:" >&2
        local f
        for f in "$dd/munge/munged.log" "$dd/slurmctld.log" "$dd/slurmd.log" \
                 "$dd"/smoke-*.out "$work"/slurm/logs/*.out "$work/single.log"; do
            [ -f "$f" ] || continue
            printf '\n---- %s\n' "$f" >&2
            tail -n 25 "$f" >&2
        done
        echo >&2
    fi
    say "stopping the daemons"
    stop_all "$dd"
    say "left in $work (daemons/: slurm.conf and the daemon logs; slurm/: the jobs' outputs and logs)"
    exit "$rc"
}
trap on_exit EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
trap 'exit 129' HUP

# The watchdog: started through a subshell that exits at once, so that it belongs to no
# process tree of the test (ctest kills the test's tree on timeout), in its own session.
( setsid "$BASH" "$self" --watch "$$" "$dd" < /dev/null >> "$dd/watchdog.log" 2>&1 & )

# The caller's settings for examples/slurm, sbatch and Slurm do not reach this cluster.
unset GLINT_BIN GLINT_CONVERGENCE GLINT_SCHEDULE_ARGS GLINT_RENDER_ARGS GLINT_SHARD_BY GLINT_CPUS_PER_TASK
while IFS= read -r var; do
    unset "$var"
done < <(compgen -e | grep -E '^(SBATCH|SLURM|SQUEUE|SINFO|SCONTROL)_' || true)

node=$(hostname -s)
ncpu=$(nproc)
# Unix socket paths are limited to 107 bytes: slurmd's spool holds NODE_JOB.STEP sockets.
rt="$dd/run"
if [ $(( ${#rt} + ${#node} + 32 )) -gt 100 ]; then
    rt=$(mktemp -d /tmp/glint-slurm.XXXXXX)
    printf '%s\n' "$rt" > "$dd/runtime-dir"
    ln -s "$rt" "$dd/run"
else
    mkdir -p "$rt"
fi
chmod 755 "$rt"
mkdir -p "$rt/spool"

# Ports: 16817/16818 unless something listens there (a cluster of the machine's own).
port_free() { ! (exec 3<> "/dev/tcp/127.0.0.1/$1") 2> /dev/null; }
ctld_port=16817
while ! port_free "$ctld_port" || ! port_free $((ctld_port + 1)); do
    ctld_port=$((ctld_port + 2))
    [ "$ctld_port" -lt 16917 ] || { failed_step="ports"; echo "no free port pair in 16817-16916" >&2; exit 1; }
done
slurmd_port=$((ctld_port + 1))

failed_step="munged"
say "starting munged (key, socket and logs in $dd/munge)"
dd if=/dev/urandom of="$dd/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$dd/munge/munge.key"
sock="$rt/munge.socket"
munged_args=(--key-file="$dd/munge/munge.key" --socket="$sock" --pid-file="$dd/munge/munged.pid"
             --log-file="$dd/munge/munged.log" --seed-file="$dd/munge/munged.seed")
if ! munged "${munged_args[@]}" < /dev/null > "$dd/munge/munged.out" 2>&1; then
    # munged refuses folders whose parents others may write to; --force accepts them.
    say "munged refused to start ($(tail -n 1 "$dd/munge/munged.out")); again with --force"
    munged --force "${munged_args[@]}" < /dev/null >> "$dd/munge/munged.out" 2>&1
fi
for ((i = 0; i < 50; i++)); do [ -S "$sock" ] && break; sleep 0.2; done
munge -S "$sock" -n | unmunge -S "$sock" > "$dd/munge/unmunge.out"

failed_step="slurmctld/slurmd"
conf="$dd/slurm.conf"
cat > "$conf" <<CONF
# A one-node cluster for tests/cluster/slurm_cluster_test.sh (written by it).
ClusterName=glinttest
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$sock
CredType=cred/munge
StateSaveLocation=$dd/state
SlurmdSpoolDir=$rt/spool
SlurmctldPidFile=$dd/slurmctld.pid
SlurmdPidFile=$dd/slurmd.pid
SlurmctldLogFile=$dd/slurmctld.log
SlurmdLogFile=$dd/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SwitchType=switch/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MinJobAge=3600
MailProg=/bin/true
NodeName=$node NodeAddr=127.0.0.1 CPUs=$ncpu State=UNKNOWN
PartitionName=debug Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$conf"
say "starting slurmctld and slurmd ($conf: node $node, $ncpu CPUs, ports $ctld_port/$slurmd_port)"
(cd "$dd" && slurmctld -f "$conf" < /dev/null > "$dd/slurmctld.out" 2>&1)
(cd "$dd" && slurmd -f "$conf" -N "$node" < /dev/null > "$dd/slurmd.out" 2>&1)

failed_step="waiting for the node to be idle"
state=""
for ((i = 0; i < node_wait_s; i++)); do
    state=$(sinfo -h -N -n "$node" -o %T 2> /dev/null | head -n 1 || true)
    [ "$state" = idle ] && break
    sleep 1
done
[ "$state" = idle ] || { echo "node $node is '${state:-unknown}' after ${node_wait_s} s, not idle" >&2; exit 1; }
say "node $node idle"

# JobState of every record of job ID (one per array task once they have started).
job_states() { scontrol show job -o "$1" 2> /dev/null | grep -o 'JobState=[A-Z_]*' | cut -d= -f2 || true; }
is_final() {
    case "$1" in
        COMPLETED | FAILED | CANCELLED | TIMEOUT | NODE_FAIL | OUT_OF_MEMORY | PREEMPTED | BOOT_FAIL | DEADLINE) return 0 ;;
        *) return 1 ;;
    esac
}
# Waits until every record of the jobs IDS is final or SECONDS pass: 0 when all completed,
# 1 when one did not complete, 2 on timeout (after printing the jobs).
wait_jobs() {
    local seconds=$1 id s all_final
    shift
    local start=$SECONDS last=""
    while :; do
        all_final=yes
        local summary=""
        for id in "$@"; do
            local states
            states=$(job_states "$id")
            [ -n "$states" ] || states=UNKNOWN
            summary+="job $id: $(sort <<< "$states" | uniq -c | awk '{printf "%s%s %s", sep, $1, $2; sep=", "}')  "
            for s in $states; do is_final "$s" || all_final=no; done
        done
        if [ "$summary" != "$last" ]; then say "${summary%  }"; last=$summary; fi
        [ "$all_final" = no ] || break
        if [ $((SECONDS - start)) -ge "$seconds" ]; then
            echo "the jobs did not end within ${seconds} s:" >&2
            squeue >&2 || true
            for id in "$@"; do scontrol show job "$id" >&2 || true; done
            return 2
        fi
        sleep 1
    done
    for id in "$@"; do
        for s in $(job_states "$id"); do [ "$s" = COMPLETED ] || return 1; done
    done
}

failed_step="smoke test (sbatch --array=0-3 --wrap hostname)"
# shellcheck disable=SC2016 # $SLURM_ARRAY_TASK_ID is the job's
smoke=$(sbatch --parsable --array=0-3 --output="$dd/smoke-%A_%a.out" --wrap 'hostname; echo "task $SLURM_ARRAY_TASK_ID"')
smoke=${smoke%%;*}
say "smoke test: job array $smoke"
wait_jobs "$smoke_wait_s" "$smoke"
for t in 0 1 2 3; do
    grep -qx "task $t" "$dd/smoke-${smoke}_$t.out" || { echo "$dd/smoke-${smoke}_$t.out lacks 'task $t'" >&2; exit 1; }
done
say "smoke test passed: 4 array tasks ran"

failed_step="the demo's .jsim"
"$bin/glint-platform2jsim" "$repo/examples/demo/sim/demo.sim" -o "$work/demo.jsim"

failed_step="submit.sh"
say "examples/slurm/submit.sh $work/demo.jsim $shards $work/slurm (convergence $convergence)"
# Started by a relative path with CDPATH set, as a user's shell may have it: a cd that
# finds its folder through CDPATH prints it, which must not end up in the paths.
(cd "$repo" && CDPATH=. GLINT_BIN="$bin" GLINT_CONVERGENCE="$convergence" \
    examples/slurm/submit.sh "$work/demo.jsim" "$shards" "$work/slurm") > "$work/submit.out"
render_job=$(sed -n 's/^render_job=//p' "$work/submit.out")
merge_job=$(sed -n 's/^merge_job=//p' "$work/submit.out")
if [ -z "$render_job" ] || [ -z "$merge_job" ]; then
    echo "submit.sh printed no job ids:" >&2
    cat "$work/submit.out" >&2
    exit 1
fi

failed_step="the render array $render_job and the merge job $merge_job"
SECONDS_JOBS=$SECONDS
if ! wait_jobs "$jobs_wait_s" "$render_job" "$merge_job"; then
    for id in "$render_job" "$merge_job"; do scontrol show job -o "$id" 2> /dev/null || true; done |
        awk '{ line = ""
               for (i = 1; i <= NF; i++)
                   if ($i ~ /^(JobId|ArrayTaskId|JobName|JobState|ExitCode|StdOut)=/) line = line " " $i
               print line }' >&2
    exit 1
fi
completed=$(job_states "$render_job" | grep -c '^COMPLETED$' || true)
[ "$completed" -eq "$shards" ] || { echo "$completed of $shards render tasks completed" >&2; exit 1; }
say "the $shards shards and the merge completed in $((SECONDS - SECONDS_JOBS)) s"

failed_step="the single-process render"
say "glint-render $work/demo.jsim --output-folder $work/single --no-processing --convergence $convergence"
# The same simulation path as the shards (it is recorded in every header).
"$bin/glint-render" "$work/demo.jsim" --output-folder "$work/single" --no-processing \
    --convergence "$convergence" > "$work/single.files" 2> "$work/single.log"

failed_step="comparing slurm/merged/ with single/"
merged="$work/slurm/merged"
diff <(cd "$merged" && find . -type f | sort) <(cd "$work/single" && find . -type f | sort) >&2 || {
    echo "the merged and the single-process renders hold different files (< merged, > single)" >&2
    exit 1
}
count=0
bad=0
while IFS= read -r -d '' file; do
    rel=${file#"$merged"/}
    count=$((count + 1))
    case "$rel" in
        *.hdr)
            if ! diff <(grep -v '^glint command line' "$file") \
                      <(grep -v '^glint command line' "$work/single/$rel") > "$work/diff.tmp"; then
                echo "header $rel differs (< merged, > single):" >&2
                head -n 20 "$work/diff.tmp" >&2
                bad=$((bad + 1))
            fi ;;
        *)
            if ! cmp "$file" "$work/single/$rel" >&2; then
                bad=$((bad + 1))
            fi ;;
    esac
done < <(find "$merged" -type f -print0 | sort -z)
rm -f "$work/diff.tmp"
[ "$count" -gt 0 ] || { echo "no files in $merged" >&2; exit 1; }
[ "$bad" -eq 0 ] || { echo "$bad of $count files differ" >&2; exit 1; }
failed_step=""
say "PASS: $count files of the $shards-shard Slurm render merged equal the single-process render (headers but for 'glint command line')"
