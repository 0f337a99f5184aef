#!/usr/bin/env bash
# Merges the parts of submit-tiles.sh (tiles) or submit-samples.sh (sample batches) into
# OUTPUT; runs after every part succeeded (--dependency=afterok on the array). The parts are
# PART_DIR/NAME-0.EXT ... NAME-(PARTS-1).EXT (NAME tile, EXT png unless PART_NAME and PART_EXT
# say otherwise); their records place the tiles, or weight the batches by their sample counts.
#SBATCH --job-name=vkrt-merge
#SBATCH --ntasks=1
#SBATCH --cpus-per-task=1
set -euo pipefail
: "${VKRT:?}" "${PART_DIR:?}" "${OUTPUT:?}" "${PARTS:?}"
parts=()
for ((i = 0; i < PARTS; i++)); do parts+=("$PART_DIR/${PART_NAME:-tile}-$i.${PART_EXT:-png}"); done
exec "$VKRT" merge -o "$OUTPUT" "${parts[@]}"
