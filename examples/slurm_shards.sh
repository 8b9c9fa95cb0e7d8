#!/usr/bin/env bash
# A Slurm job array that runs one scene as 16 shards (one per array task) and merges them in a
# dependent job:   sbatch --array=1-16 examples/slurm_shards.sh examples/basins.toml
# Each task writes results/<scene>.shard-I-of-16.h5; the last step writes results/<scene>.h5.
# A task stopped at its time limit (SIGTERM) keeps its finished members in the shard's .partial
# file; requeued (scontrol requeue, or --requeue), it resumes from there.
#SBATCH --job-name=rotorsweep-shards
#SBATCH --cpus-per-task=8
#SBATCH --time=02:00:00
#SBATCH --requeue
set -euo pipefail
scene=${1:?usage: sbatch --array=1-N slurm_shards.sh SCENE.toml}
count=${SLURM_ARRAY_TASK_COUNT:?run as a job array (sbatch --array=1-N)}
name=$(basename "$scene" .toml)
shard="results/$name.shard-$SLURM_ARRAY_TASK_ID-of-$count.h5"
resume=()
if [ -f "$shard.partial" ]; then resume=(--resume); fi
build/bin/rotorsweep run "$scene" --shard "$SLURM_ARRAY_TASK_ID/$count" --threads "$SLURM_CPUS_PER_TASK" -q \
  -o "$shard" "${resume[@]}"
# the task that finishes last merges (the merge checks that every shard is there and complete)
done_count=$(ls results/"$name".shard-*-of-"$count".h5 2>/dev/null | wc -l)
if [ "$done_count" -eq "$count" ]; then
  build/bin/rotorsweep merge results/"$name".shard-*-of-"$count".h5 -o "results/$name.h5"
fi
