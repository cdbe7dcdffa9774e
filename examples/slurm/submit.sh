#!/bin/bash
# Submit a sweep as a Slurm job array of SHARDS tasks, then a job that
# gathers the shards once every task has succeeded (docs/cluster.md).
#   SHARDS=10 SWEEP=sweep.toml OUT=out examples/slurm/submit.sh
set -euo pipefail
SHARDS=${SHARDS:-10}
export SWEEP=${SWEEP:-sweep.toml} OUT=${OUT:-out}
here=$(dirname "$0")
job=$(sbatch --parsable --array=0-$((SHARDS - 1)) --export=ALL "$here/sweep.sbatch")
sbatch --dependency=afterok:"${job%%;*}" --job-name=ladder-gather \
    --wrap "ladder sweep gather $OUT"
