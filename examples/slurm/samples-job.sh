#!/usr/bin/env bash
# One sample batch of a path-traced scene (a Slurm array task): batch I = $SLURM_ARRAY_TASK_ID
# renders with --seed SEED_BASE+I (independent samples for each batch) into
# BATCH_DIR/batch-I.pfm, a float image whose vkrt-samples record carries its seed and sample
# count for vkrt merge. SPP (samples per batch) and TIME (seconds per batch) are optional:
# without SPP the scene's spp; with TIME the samples taken when the time was up (at most SPP).
# Submitted by submit-samples.sh, which sets the variables below in the job's environment
# (sbatch --export=ALL).
#SBATCH --job-name=vkrt-samples
#SBATCH --ntasks=1
#SBATCH --cpus-per-task=1
set -euo pipefail
: "${VKRT:?}" "${SCENE:?}" "${BATCH_DIR:?}" "${SEED_BASE:?}"
i=${SLURM_ARRAY_TASK_ID:?not an array task}
limits=()
[ -z "${SPP:-}" ] || limits+=(--spp "$SPP")
[ -z "${TIME:-}" ] || limits+=(--time "$TIME")
# VKRT_ARGS: extra options for every batch, as shell words (e.g. "--backend cpu --size 640x480";
# quote a value that holds blanks: "--device 'NVIDIA H200'"), as submit-samples.sh writes them.
vkrt_args=()
eval "vkrt_args=(${VKRT_ARGS:-})"
# Not quiet: the log says how many samples the batch took.
exec "$VKRT" "${vkrt_args[@]}" --threads "${SLURM_CPUS_PER_TASK:-1}" "${limits[@]}" \
  --seed $((SEED_BASE + i)) -o "$BATCH_DIR/batch-$i.pfm" "$SCENE"
