#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Strong scaling of sharded rendering on this machine (bench/README.md, "Strong scaling").
# The demo (examples/demo/sim/demo.sim, converted to a .jsim) is rendered split into 1, 2 and
# 4 shards (glint-schedule --shard K/N), the N glint-render processes of a configuration
# started at once, each into its own folder, then the parts merged (glint-envi merge, when
# the tools have it). Measured: the wall time of each configuration's renders (first start
# to last end; also each shard's own time), of its shard schedules and of its merge; once,
# glint-schedule's time for the whole schedule, glint-render's start-up (inputs, scene and
# planning: a run of the cheapest single capture, and the --dry-run load alone), and the
# render of one shard. Speedup is against 1 shard; efficiency against the speedup the cores
# allow (below). Prints a markdown table, then one JSON line. Every merged render is
# compared with the 1-shard one (data bytes).
#
# Threads: by default each shard runs with --threads ceil(cores / N), so every configuration
# uses the whole machine and the ideal speedup on one machine is 1: what the bench measures
# is what splitting costs (start-up paid N times, imbalance, merge). --threads T fixes T
# threads per shard in every configuration (--threads 1: N one-core "nodes", ideal speedup
# min(N, cores)). ideal = min(cores, N * T_N) / min(cores, T_1); efficiency = speedup / ideal.
#
# Usage: bench/scale.sh BIN_DIR [OUT] [--shards "1 2 4"] [--threads T]
#            [--convergence MIN,MAX,T] [--scale-resolution F] [--by captures|rows] [--repeats R]
# OUT (default: a temporary folder, removed at the end) keeps the renders and logs.
# Defaults: the demo's convergence 8,64,1e-5, full resolution, captures, 1 repeat (the
# fastest of R repeats is kept). A quick check of the script itself:
#   bench/scale.sh build/release/bin --scale-resolution 0.25 --convergence 2,4,1e-3
set -euo pipefail

usage() { sed -n 's/^# Usage: /usage: /p; s/^#            /    /p' "$0" | head -2 >&2; exit 2; }
[[ $# -ge 1 ]] || usage
bin=$(cd "$1" && pwd)
shift
out=
if [[ $# -ge 1 && "$1" != --* ]]; then
    out=$1
    shift
fi
shard_counts="1 2 4"
threads_fixed=
convergence=8,64,1e-5
scale=1
by=captures
repeats=1
while [[ $# -gt 0 ]]; do
    case "$1" in
        --shards) shard_counts=${2:?--shards needs a list}; shift 2 ;;
        --threads) threads_fixed=${2:?--threads needs a number}; shift 2 ;;
        --convergence) convergence=${2:?--convergence needs MIN,MAX,T}; shift 2 ;;
        --scale-resolution) scale=${2:?--scale-resolution needs a number}; shift 2 ;;
        --by) by=${2:?--by needs captures or rows}; shift 2 ;;
        --repeats) repeats=${2:?--repeats needs a number}; shift 2 ;;
        -h|--help) usage ;;
        *) printf 'scale.sh: unknown option %s\n' "$1" >&2; usage ;;
    esac
done
# 1 (the baseline) first, each count once, in increasing order
read -r -a counts <<<"$shard_counts"
for n in "${counts[@]}"; do
    [[ "$n" =~ ^[1-9][0-9]*$ ]] || { echo "scale.sh: --shards: $n is not a whole number >= 1" >&2; exit 2; }
done
shard_counts=$(printf '%s\n' 1 "${counts[@]}" | sort -n -u | tr '\n' ' ')
[[ "$by" == captures || "$by" == rows ]] || { echo "scale.sh: --by captures|rows" >&2; exit 2; }
[[ -z "$threads_fixed" || "$threads_fixed" =~ ^[1-9][0-9]*$ ]] ||
    { echo "scale.sh: --threads needs a whole number >= 1" >&2; exit 2; }
[[ "$repeats" =~ ^[1-9][0-9]*$ ]] || { echo "scale.sh: --repeats needs a whole number >= 1" >&2; exit 2; }

here=$(cd "$(dirname "$0")" && pwd)
sim="$here/../examples/demo/sim/demo.sim"
if [[ -n "$out" ]]; then
    mkdir -p "$out"
    work=$(cd "$out" && pwd)
else
    work=$(mktemp -d "${TMPDIR:-/tmp}/glint-scale.XXXXXX")
    trap 'rm -rf "$work"' EXIT
fi
cores=$(nproc)
render="$bin/glint-render"
schedule="$bin/glint-schedule"
envi="$bin/glint-envi"

now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.3f", b - a }'; }
min() { awk -v a="$1" -v b="$2" 'BEGIN { print (a == "" || b + 0 < a + 0) ? b : a }'; }
log() { printf 'scale.sh: %s\n' "$*" >&2; }
# timed LOG COMMAND...: runs it (stdout to /dev/null, stderr to LOG), prints its seconds
timed() {
    local logf=$1 start end
    shift
    start=$(now)
    "$@" > /dev/null 2> "$logf" || { cat "$logf" >&2; log "failed: $*"; exit 1; }
    end=$(now)
    elapsed "$start" "$end"
}
threads_for() {  # N: threads of each of N shards
    if [[ -n "$threads_fixed" ]]; then echo "$threads_fixed"; else echo $(((cores + $1 - 1) / $1)); fi
}

merge_help=$("$envi" merge --help 2>&1 || true)
if grep -q '^Usage: .*merge' <<<"$merge_help"; then
    have_merge=true
else
    have_merge=false
    log "glint-envi has no merge subcommand: merge times are left out (null)"
fi

# ---- Once: the .jsim, the schedule, the start-up of one process --------------------------
"$bin/glint-platform2jsim" -q "$sim" -o "$work/demo.jsim"
jsim="$work/demo.jsim"
opts=(--scale-resolution "$scale")
by_opts=()
[[ "$by" == rows ]] && by_opts=(--by rows)
t_schedule=
for _ in $(seq "$repeats"); do
    t=$(timed "$work/schedule.log" "$schedule" "$jsim" "${opts[@]}" -o "$work/schedule.json")
    t_schedule=$(min "$t_schedule" "$t")
done
captures=$("$schedule" "$jsim" "${opts[@]}" --summary --format json |
    sed -n 's/^ *"capture_count": *\([0-9]*\).*/\1/p' | head -1)
problems=$("$schedule" "$jsim" "${opts[@]}" --summary --format json |
    sed -n 's/^ *"problem_count": *\([0-9]*\).*/\1/p' | head -1)
# The cheapest capture (fewest pixels): its render is the start-up plus almost nothing.
cheapest=$(awk '/"time_window_s"/ {
        line = $0
        match(line, /"index": *[0-9]+/); i = substr(line, RSTART, RLENGTH); gsub(/[^0-9]/, "", i)
        match(line, /"problem_count": *[0-9]+/); p = substr(line, RSTART, RLENGTH); gsub(/[^0-9]/, "", p)
        if (best == "" || p + 0 < best + 0) { best = p; idx = i }
    } END { print idx }' "$work/schedule.json")
"$schedule" "$jsim" "${opts[@]}" --captures "$cheapest" -o "$work/one.json"
t1_threads=$(threads_for 1)
render_opts=(--no-processing --radiance-only --convergence "$convergence" "${opts[@]}")
t_startup=
t_load=
for _ in $(seq "$repeats"); do
    rm -rf "$work/startup"
    t=$(timed "$work/startup.log" "$render" "$jsim" --schedule "$work/one.json" \
        --output-folder "$work/startup" --threads "$t1_threads" "${render_opts[@]}")
    t_startup=$(min "$t_startup" "$t")
    t=$(timed "$work/dry-run.log" "$render" "$jsim" --dry-run --threads "$t1_threads" "${render_opts[@]}")
    t_load=$(min "$t_load" "$t")
done
log "schedule ${t_schedule} s, start-up ${t_startup} s (load ${t_load} s), $captures captures, $problems pixels"

# ---- Each configuration: N shards at once ------------------------------------------------
declare -A render_s shard_min_s shard_max_s schedules_s merge_s identical threads_of
for n in $shard_counts; do
    threads=$(threads_for "$n")
    threads_of[$n]=$threads
    dir="$work/n$n"
    for _ in $(seq "$repeats"); do
        rm -rf "$dir"
        mkdir -p "$dir/schedule" "$dir/parts" "$dir/logs"
        # The shard schedules, all at once (each node computes its own).
        start=$(now)
        pids=()
        for k in $(seq "$n"); do
            "$schedule" "$jsim" "${opts[@]}" --shard "$k/$n" "${by_opts[@]}" \
                -o "$dir/schedule/shard-$k.json" 2> "$dir/logs/schedule-$k.log" &
            pids+=($!)
        done
        for pid in "${pids[@]}"; do wait "$pid" || { log "a shard schedule failed (N=$n)"; exit 1; }; done
        t_sched=$(elapsed "$start" "$(now)")
        # The renders, all at once; each records its own start and end.
        start=$(now)
        pids=()
        for k in $(seq "$n"); do
            (
                s=$(now)
                "$render" "$jsim" --schedule "$dir/schedule/shard-$k.json" \
                    --output-folder "$dir/parts/$k" --threads "$threads" "${render_opts[@]}" \
                    > /dev/null 2> "$dir/logs/render-$k.log"
                elapsed "$s" "$(now)" > "$dir/logs/render-$k.s"
            ) &
            pids+=($!)
        done
        for pid in "${pids[@]}"; do
            wait "$pid" || { cat "$dir"/logs/render-*.log >&2; log "a shard render failed (N=$n)"; exit 1; }
        done
        t_render=$(elapsed "$start" "$(now)")
        t_merge=null
        if $have_merge; then
            "$schedule" "$jsim" "${opts[@]}" --output-folder "$dir/merged" -o "$dir/schedule/full.json"
            parts=()
            for k in $(seq "$n"); do parts+=("$dir/parts/$k"); done
            t_merge=$(timed "$dir/logs/merge.log" "$envi" merge "${parts[@]}" -o "$dir/merged" \
                --expect "$dir/schedule/full.json")
        fi
        if [[ -z "${render_s[$n]:-}" ]] || awk -v a="$t_render" -v b="${render_s[$n]}" 'BEGIN { exit !(a < b) }'; then
            render_s[$n]=$t_render
            schedules_s[$n]=$t_sched
            merge_s[$n]=$t_merge
            shard_min_s[$n]=$(sort -g "$dir"/logs/render-*.s | head -1)
            shard_max_s[$n]=$(sort -g "$dir"/logs/render-*.s | tail -1)
        fi
    done
    # The merged render must be the 1-shard one, byte for byte (data files).
    same=null
    if $have_merge && [[ "$n" != 1 ]]; then
        same=true
        while IFS= read -r f; do
            cmp -s "$work/n1/merged/$f" "$dir/merged/$f" || same=false
        done < <(cd "$work/n1/merged" && find . -type f ! -name '*.hdr')
        [[ "$(cd "$work/n1/merged" && find . -type f | sort)" == "$(cd "$dir/merged" && find . -type f | sort)" ]] ||
            same=false
        $same || log "N=$n: the merged render differs from the 1-shard render"
    fi
    identical[$n]=$same
    log "N=$n: $threads threads each, renders ${render_s[$n]} s, merge ${merge_s[$n]} s"
done

# ---- Report --------------------------------------------------------------------------------
t1=${render_s[1]}
total() {  # N: shard schedules + renders + merge
    awk -v a="${schedules_s[$1]}" -v b="${render_s[$1]}" -v c="${merge_s[$1]}" \
        'BEGIN { if (c == "null") c = 0; printf "%.3f", a + b + c }'
}
printf '\nglint strong scaling: demo, %s captures, %s pixels, convergence %s, scale %s, by %s, %s cores, fastest of %s\n\n' \
    "$captures" "$problems" "$convergence" "$scale" "$by" "$cores" "$repeats"
printf 'glint-schedule (whole schedule): %s s; glint-render start-up (cheapest capture): %s s, of which loading (--dry-run) %s s\n\n' \
    "$t_schedule" "$t_startup" "$t_load"
printf '| shards | threads each | shard schedules s | renders s | shard min–max s | merge s | total s | speedup | ideal | efficiency | total speedup | same bytes |\n'
printf '|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|:---:|\n'
results=
for n in $shard_counts; do
    read -r speedup ideal eff tspeed < <(awk -v t1="$t1" -v tn="${render_s[$n]}" -v n="$n" \
        -v c="$cores" -v th="${threads_of[$n]}" -v th1="${threads_of[1]}" \
        -v tt1="$(total 1)" -v ttn="$(total "$n")" 'BEGIN {
            s = t1 / tn; used = (n * th < c) ? n * th : c; base = (th1 < c) ? th1 : c
            ideal = used / base
            printf "%.3f %.3f %.3f %.3f\n", s, ideal, s / ideal, tt1 / ttn }')
    merge_col=${merge_s[$n]}
    [[ "$merge_col" == null ]] && merge_col="n/a"
    same=${identical[$n]}
    [[ "$n" == 1 ]] && same="(ref)"
    [[ "$same" == null ]] && same="n/a"
    printf '| %s | %s | %s | %s | %s–%s | %s | %s | %s | %s | %s | %s | %s |\n' "$n" "${threads_of[$n]}" \
        "${schedules_s[$n]}" "${render_s[$n]}" "${shard_min_s[$n]}" "${shard_max_s[$n]}" "$merge_col" \
        "$(total "$n")" "$speedup" "$ideal" "$eff" "$tspeed" "$same"
    results+="${results:+,}{\"shards\":$n,\"threads_per_shard\":${threads_of[$n]},\"schedules_s\":${schedules_s[$n]},\"render_s\":${render_s[$n]},\"shard_min_s\":${shard_min_s[$n]},\"shard_max_s\":${shard_max_s[$n]},\"merge_s\":${merge_s[$n]},\"total_s\":$(total "$n"),\"speedup\":$speedup,\"ideal_speedup\":$ideal,\"efficiency\":$eff,\"total_speedup\":$tspeed,\"identical\":${identical[$n]}}"
done
$have_merge || printf '\n(merge: glint-envi has no merge subcommand; merge times left out)\n'
# The model of docs/performance.md: T(N) ~ t_startup + W / N + t_merge, W the captures' cost
# (the 1-shard render less its start-up), t_merge that of the most shards ($n, the last).
captures_cost=$(awk -v a="$t1" -v b="$t_startup" 'BEGIN { w = a - b; printf "%.3f", (w > 0 ? w : 0) }')
printf '\nmodel: per-node start-up %s s (schedule %s s + render start-up %s s), captures'"'"' cost W = %s s (1 shard, %s threads), merge %s\n' \
    "$(awk -v a="$t_schedule" -v b="$t_startup" 'BEGIN { printf "%.3f", a + b }')" "$t_schedule" "$t_startup" \
    "$captures_cost" "${threads_of[1]}" "$([[ "${merge_s[$n]}" == null ]] && echo n/a || echo "${merge_s[$n]} s")"
printf '{"bench":"scale","simulation":"examples/demo/sim/demo.sim","cores":%s,"captures":%s,"problems":%s,"convergence":"%s","scale_resolution":%s,"by":"%s","repeats":%s,"threads":"%s","merge":%s,"schedule_s":%s,"startup_s":%s,"load_s":%s,"captures_cost_s":%s,"results":[%s]}\n' \
    "$cores" "$captures" "$problems" "$convergence" "$scale" "$by" "$repeats" \
    "${threads_fixed:-ceil(cores/shards)}" "$have_merge" "$t_schedule" "$t_startup" "$t_load" \
    "$captures_cost" "$results"
