#!/usr/bin/env bash
# Renders many scenes on a Slurm cluster: splits them into CHUNKS array tasks, each one vkrt
# run over its share of the scenes (one process per chunk, sharing the Vulkan device).
#
#   submit-scenes.sh [--chunks N] [--vkrt PATH] [--wait] OUT_DIR SCENE.test... [-- VKRT OPTIONS]
#
# Each image goes into OUT_DIR under the name of its scene's `output` line (or the scene's
# stem + .png), as `vkrt -o OUT_DIR/` does. The scene list is written to OUT_DIR/scenes.list.
set -euo pipefail
chunks=4 vkrt=$(command -v vkrt || true) wait=""
while [ $# -gt 0 ]; do
  case "$1" in
    --chunks) chunks=$2; shift 2 ;;
    --vkrt) vkrt=$2; shift 2 ;;
    --wait) wait=--wait; shift ;;
    -*) echo "submit-scenes: unknown option $1" >&2; exit 1 ;;
    *) break ;;
  esac
done
[ $# -ge 2 ] || { sed -n '5p' "$0" | sed 's/^# *//' >&2; exit 1; }
[[ $chunks =~ ^[1-9][0-9]*$ ]] || { echo "submit-scenes: --chunks expects a number" >&2; exit 1; }
[ -n "$vkrt" ] || { echo "submit-scenes: no vkrt on PATH; give --vkrt PATH" >&2; exit 1; }
out=$(realpath -m "$1"); shift
mkdir -p "$out"
scenes=() extra=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do scenes+=("$(realpath "$1")"); shift; done
[ "${1:-}" = "--" ] && shift && extra=("$@")
[ "$chunks" -le "${#scenes[@]}" ] || chunks=${#scenes[@]}
printf '%s\n' "${scenes[@]}" > "$out/scenes.list"
job=$(sbatch --parsable $wait --array=0-$((chunks - 1)) --output="$out/chunk-%a.log" \
  --export="ALL,VKRT=$(realpath "$vkrt"),LIST=$out/scenes.list,OUT_DIR=$out,CHUNKS=$chunks,VKRT_ARGS=${extra[*]}" \
  "$(dirname "$(realpath "$0")")/scenes-job.sh") || {
  echo "submit-scenes: a chunk failed (see $out/chunk-*.log)" >&2; exit 1; }
echo "scenes: job ${job%%;*} (${#scenes[@]} scenes in $chunks array tasks) -> $out/"
