#!/bin/bash
# Submit a sweep as a Slurm job array of SHARDS tasks, then a job that
# gathers the shards once every task has ended (docs/cluster.md).
#   SHARDS=10 SWEEP=sweep.toml OUT=out examples/slurm/submit.sh
# The gather waits with afterany, not afterok: after a failed task an
# afterok job would never run. A gather with a shard missing writes
# nothing and names the shard; resubmit that task alone
#   sbatch --array=K --export=ALL,SHARDS=10,SWEEP=sweep.toml,OUT=out sweep.sbatch
# and gather again once it has succeeded.
set -euo pipefail
export SHARDS=${SHARDS:-10} SWEEP=${SWEEP:-sweep.toml} OUT=${OUT:-out}
here=$(dirname "$0")
job=$(sbatch --parsable --array=0-$((SHARDS - 1)) --export=ALL "$here/sweep.sbatch")
sbatch --dependency=afterany:"${job%%;*}" --job-name=ladder-gather \
    --wrap "ladder sweep gather $OUT"
