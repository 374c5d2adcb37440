#!/bin/bash
# Submits a minigolf experiment to Slurm: an array of SHARDS tasks (experiment.sbatch) and the
# merge (merge.sbatch), which starts only when every task has succeeded.
#
#   SUITE=courses/bench OUT=/scratch/$USER/exp1 SHARDS=100 \
#   EXPERIMENT_ARGS="--bots all --seeds 30" docs/cluster/submit.sh [more sbatch options]
#
# Extra arguments go to both sbatch calls (e.g. --partition=short --account=lab).
# Prints the two job ids; the merged results land in $OUT/merged (or $MERGED).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
: "${SUITE:?set SUITE to the folder of course files (*.json)}"
: "${OUT:?set OUT to a folder on a file system every node shares}"
tasks=${SHARDS:-4}
# Absolute paths: the jobs may start in another directory than this shell.
SUITE=$(cd "$SUITE" && pwd)
mkdir -p "$OUT"
OUT=$(cd "$OUT" && pwd)
export SUITE OUT
unset SHARDS   # the tasks take the split from Slurm's own array variables

array=$(sbatch --parsable --array="0-$((tasks - 1))" "$@" "$here/experiment.sbatch")
array=${array%%;*}
merge=$(sbatch --parsable --dependency="afterok:$array" --kill-on-invalid-dep=yes "$@" "$here/merge.sbatch")
merge=${merge%%;*}
echo "submitted: array job $array ($tasks tasks), merge job $merge"
echo "watch:     squeue -j $array,$merge    (logs: minigolf-experiment-${array}_K.out, minigolf-merge-$merge.out)"
echo "results:   ${MERGED:-$OUT/merged}/summary.md"
