#!/bin/bash
# A stand-in for Slurm's sbatch (tests/integration/cluster_recipe.rs):
# runs the job at once, each array task with the variables Slurm sets
# (SLURM_JOB_ID, SLURM_ARRAY_JOB_ID, SLURM_ARRAY_TASK_ID,
# SLURM_ARRAY_TASK_COUNT, _MIN, _MAX, SLURM_CPUS_PER_TASK) and the
# --export list, and follows Slurm's dependency rules: afterok:J runs only
# if every task of J succeeded (else the job never runs), afterany:J runs
# once J has ended. FAKE_SLURM_DIR holds the job counter, each task's
# exit status (JOB_TASK.rc) and output (JOB_TASK.out); FAKE_SLURM_LOSE=K
# fails array task K the first time it is submitted (a node lost).
set -u
dir=${FAKE_SLURM_DIR:?}
array='' exports='ALL' dep='' wrap='' script='' parsable=0
while (($#)); do
    case $1 in
    --parsable) parsable=1 ;;
    --job-name=* | --time=* | --output=*) ;;
    --array=*) array=${1#--array=} ;;
    --export=*) exports=${1#--export=} ;;
    --dependency=*) dep=${1#--dependency=} ;;
    --wrap) wrap=$2; shift ;;
    --wrap=*) wrap=${1#--wrap=} ;;
    -*) echo "sbatch: unknown option $1" >&2; exit 2 ;;
    *) script=$1; shift; break ;;
    esac
    shift
done
job=$(($(cat "$dir/count" 2>/dev/null || echo 1000) + 1))
echo "$job" >"$dir/count"
if [[ -n $dep ]]; then
    kind=${dep%%:*} on=${dep#*:}
    for rc in "$dir/$on"_*.rc; do
        if [[ $kind == afterok && $(cat "$rc") != 0 ]]; then
            echo never >"$dir/${job}_0.rc"
            ((parsable)) && echo "$job" || echo "Submitted batch job $job"
            exit 0
        fi
    done
fi
tasks=()
if [[ -n $array ]]; then
    IFS=, read -ra parts <<<"$array"
    for p in "${parts[@]}"; do
        if [[ $p == *-* ]]; then
            for ((k = ${p%-*}; k <= ${p#*-}; k++)); do tasks+=("$k"); done
        else
            tasks+=("$p")
        fi
    done
fi
vars=()
IFS=, read -ra list <<<"$exports"
for v in "${list[@]}"; do [[ $v == ALL ]] || vars+=("$v"); done
run_task() { # task id or '' for a plain job
    local k=$1 name=${job}_${1:-0} lose=${FAKE_SLURM_LOSE:-}
    shift
    if [[ -n $k && $k == "$lose" && ! -e $dir/lost ]]; then
        touch "$dir/lost"
        echo "node lost" >"$dir/$name.out"
        echo 1 >"$dir/$name.rc"
        return
    fi
    local slurm=(SLURM_JOB_ID="$job" SLURM_CPUS_PER_TASK=1)
    if [[ -n $k ]]; then
        local sorted
        sorted=$(printf '%s\n' "${tasks[@]}" | sort -n)
        slurm+=(SLURM_ARRAY_JOB_ID="$job" SLURM_ARRAY_TASK_ID="$k"
            SLURM_ARRAY_TASK_COUNT="${#tasks[@]}"
            SLURM_ARRAY_TASK_MIN="$(head -1 <<<"$sorted")"
            SLURM_ARRAY_TASK_MAX="$(tail -1 <<<"$sorted")")
    fi
    if [[ -n $wrap ]]; then
        env "${vars[@]}" "${slurm[@]}" bash -c "$wrap" >"$dir/$name.out" 2>&1
    else
        env "${vars[@]}" "${slurm[@]}" bash "$script" "$@" >"$dir/$name.out" 2>&1
    fi
    echo $? >"$dir/$name.rc"
}
if ((${#tasks[@]})); then
    for k in "${tasks[@]}"; do run_task "$k" "$@"; done
else
    run_task '' "$@"
fi
((parsable)) && echo "$job" || echo "Submitted batch job $job"
