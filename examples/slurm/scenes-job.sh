#!/usr/bin/env bash
# One chunk of a list of scenes (a Slurm array task): the scenes of lines
# I+1, I+1+N, I+1+2N, ... of LIST (I = $SLURM_ARRAY_TASK_ID, N = CHUNKS), rendered in one vkrt
# run into OUT_DIR/. Submitted by submit-scenes.sh, which sets the variables below in the job's
# environment (sbatch --export=ALL).
#SBATCH --job-name=vkrt-scenes
#SBATCH --ntasks=1
#SBATCH --cpus-per-task=1
set -euo pipefail
: "${VKRT:?}" "${LIST:?}" "${OUT_DIR:?}" "${CHUNKS:?}"
i=${SLURM_ARRAY_TASK_ID:?not an array task}
[ -f "$LIST" ] && [ -r "$LIST" ] || { echo "chunk $i: cannot read the scene list $LIST" >&2; exit 1; }
mapfile -t scenes < <(awk -v i="$i" -v n="$CHUNKS" 'NF && (NR - 1) % n == i' "$LIST")
if [ "${#scenes[@]}" -eq 0 ]; then echo "chunk $i: no scenes"; exit 0; fi
# VKRT_ARGS: extra options for every scene, as shell words (e.g. "--backend cpu --maxdepth 8";
# quote a value that holds blanks: "--device 'NVIDIA H200'"), as submit-scenes.sh writes them.
vkrt_args=()
eval "vkrt_args=(${VKRT_ARGS:-})"
exec "$VKRT" "${vkrt_args[@]}" --threads "${SLURM_CPUS_PER_TASK:-1}" -o "${OUT_DIR%/}/" "${scenes[@]}"
