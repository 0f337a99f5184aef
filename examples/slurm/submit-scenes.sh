#!/usr/bin/env bash
# Renders many scenes on a Slurm cluster: splits them into CHUNKS array tasks, each one vkrt
# run over its share of the scenes (one process per chunk, sharing the Vulkan device).
#
#   submit-scenes.sh [--chunks N] [--vkrt PATH] [--wait] OUT_DIR SCENE.test... [-- VKRT OPTIONS]
#
# Each image goes into OUT_DIR under the name of its scene's `output` line (or the scene's
# stem + .png), as `vkrt -o OUT_DIR/` does. Two scenes that would write the same file are
# refused before anything is submitted (one vkrt run refuses them too; in two chunks one
# would overwrite the other). The scene list is written to OUT_DIR/scenes.list.
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
scenes=() extra=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
  [ -f "$1" ] || { echo "submit-scenes: no such scene file: $1" >&2; exit 1; }
  [[ $1 != *$'\n'* ]] || { echo "submit-scenes: a scene's path holds a line break (the list is one path a line): $1" >&2; exit 1; }
  # The absolute path of the file as named (its folder resolved, not a link it may be): vkrt
  # names an image without an `output` line after the scene file's own stem.
  scenes+=("$(realpath "$(dirname "$1")")/$(basename "$1")"); shift
done
[ "${1:-}" = "--" ] && shift && extra=("$@")

# vkrt itself names each image and refuses two scenes that would write one file, as one run
# of `vkrt -o OUT_DIR/` does (--dry-run: each scene parsed and its output checked, nothing
# rendered): in separate chunks one would overwrite the other. The options are checked too.
# A backslash anywhere in --output's path makes sbatch expand none of its %-patterns: every
# task would write the one log named %a. Refused rather than worked around.
case $out in *\\*) echo "submit-scenes: the output folder '$out' has a backslash in its name, which stops sbatch from naming each task's log (%a); choose one without" >&2; exit 1 ;; esac
made_out=""
[ -d "$out" ] || { mkdir -p "$out" && made_out=1; }
if ! "$vkrt" --dry-run -q -o "$out/" "${extra[@]}" "${scenes[@]}"; then
  [ -z "$made_out" ] || rmdir "$out" 2>/dev/null || true
  echo "submit-scenes: nothing submitted: vkrt refuses the scenes or options above (two scenes that would write one file need different \`output\` lines, or file names without one, or different folders)" >&2
  exit 1
fi

[ "$chunks" -le "${#scenes[@]}" ] || chunks=${#scenes[@]}
printf '%s\n' "${scenes[@]}" > "$out/scenes.list"
# sbatch expands %-patterns (%a, %j, ...) anywhere in --output's path, so a % in OUT_DIR's name
# would send the logs elsewhere: each is doubled (%% is a literal %), the script's own %a kept.
logs=${out//\%/%%}
# The job's variables go through the environment (--export=ALL), not in --export's
# comma-separated list, which would cut a value that holds a comma; VKRT_ARGS as shell words.
vkrt_args=""
[ ${#extra[@]} -eq 0 ] || vkrt_args=$(printf '%q ' "${extra[@]}")
job=$(VKRT=$(realpath "$vkrt") LIST=$out/scenes.list OUT_DIR=$out CHUNKS=$chunks VKRT_ARGS=$vkrt_args \
  sbatch --parsable $wait --export=ALL --array=0-$((chunks - 1)) --output="$logs/chunk-%a.log" \
  "$(dirname "$(realpath "$0")")/scenes-job.sh") || {
  echo "submit-scenes: a chunk failed (see $out/chunk-*.log)" >&2; exit 1; }
echo "scenes: job ${job%%;*} (${#scenes[@]} scenes in $chunks array tasks) -> $out/"
