#!/usr/bin/env bash
# One tile of a scene (a Slurm array task): tile $SLURM_ARRAY_TASK_ID of a COLS x ROWS grid
# over the full W x H image, rendered with --crop into TILE_DIR/tile-I.png. Submitted by
# submit-tiles.sh, which sets the variables below in the job's environment (sbatch --export=ALL).
#SBATCH --job-name=vkrt-tile
#SBATCH --ntasks=1
#SBATCH --cpus-per-task=1
set -euo pipefail
: "${VKRT:?}" "${SCENE:?}" "${TILE_DIR:?}" "${COLS:?}" "${ROWS:?}" "${FULL_W:?}" "${FULL_H:?}"
i=${SLURM_ARRAY_TASK_ID:?not an array task}
col=$((i % COLS)) row=$((i / COLS))
# Column c covers [c*W/COLS, (c+1)*W/COLS): every pixel in exactly one tile.
x0=$((col * FULL_W / COLS)) x1=$(((col + 1) * FULL_W / COLS))
y0=$((row * FULL_H / ROWS)) y1=$(((row + 1) * FULL_H / ROWS))
# VKRT_ARGS: extra options for every tile, as shell words (e.g. "--backend cpu --size 640x480";
# quote a value that holds blanks: "--device 'NVIDIA H200'"), as submit-tiles.sh writes them.
vkrt_args=()
eval "vkrt_args=(${VKRT_ARGS:-})"
exec "$VKRT" "${vkrt_args[@]}" --threads "${SLURM_CPUS_PER_TASK:-1}" -q --crop "$x0,$y0,$x1,$y1" \
  -o "$TILE_DIR/tile-$i.png" "$SCENE"
