#!/usr/bin/env bash
# Merges the tiles of submit-tiles.sh into OUTPUT (runs after every tile succeeded:
# --dependency=afterok on the tile array). The tiles' records place them.
#SBATCH --job-name=vkrt-merge
#SBATCH --ntasks=1
#SBATCH --cpus-per-task=1
set -euo pipefail
: "${VKRT:?}" "${TILE_DIR:?}" "${OUTPUT:?}" "${TILES:?}"
tiles=()
for ((i = 0; i < TILES; i++)); do tiles+=("$TILE_DIR/tile-$i.png"); done
exec "$VKRT" merge -o "$OUTPUT" "${tiles[@]}"
