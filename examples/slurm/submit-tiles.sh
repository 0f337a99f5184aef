#!/usr/bin/env bash
# Renders one scene as COLSxROWS tiles on a Slurm cluster: a job array (task i renders tile i
# with --crop) and a merge job that starts when every tile succeeded. Prints the two job ids.
#
#   submit-tiles.sh [--tiles COLSxROWS] [--vkrt PATH] [--work DIR] [--wait] SCENE.test OUT.png [-- VKRT OPTIONS]
#
# --tiles     the grid (default 4x4); --vkrt the binary (default: vkrt on PATH); --work the
#             folder for the tiles and logs (default OUT.png.tiles), on storage every node sees;
# --wait      wait for the merge to finish and exit with its status.
# VKRT OPTIONS go to every tile (e.g. --backend cpu, --size 1920x1080, --scale 0.5, --spp 64). The
# full image size is the one vkrt itself makes of the scene and these options (the scene's last
# `size`, --size or --scale), as `vkrt --dry-run` prints it; that run also checks the scene, the
# options and OUT.png as a render would, before anything is submitted.
# Refused before anything is submitted: options that would make the tiles differ (--time: each
# tile would stop at its own sample count, and tiles of different counts do not merge), that
# this script sets (--crop, -o/--output) and that write no tile (--watch, --compare, --check,
# --list-devices, --help, --version).
# Any further sbatch options: the environment variables SBATCH_* (e.g. SBATCH_PARTITION).
set -euo pipefail
tiles=4x4 vkrt=$(command -v vkrt || true) work="" wait=""
while [ $# -gt 0 ]; do
  case "$1" in
    --tiles) tiles=$2; shift 2 ;;
    --vkrt) vkrt=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --wait) wait=--wait; shift ;;
    --) break ;;
    -*) echo "submit-tiles: unknown option $1" >&2; exit 1 ;;
    *) break ;;
  esac
done
[ $# -ge 2 ] || { sed -n '5p' "$0" | sed 's/^# *//' >&2; exit 1; }
scene=$(realpath "$1") output=$(realpath -m "$2"); shift 2
[ "${1:-}" = "--" ] && shift
extra=("$@")
[ -n "$vkrt" ] || { echo "submit-tiles: no vkrt on PATH; give --vkrt PATH" >&2; exit 1; }
vkrt=$(realpath "$vkrt")
[[ $tiles =~ ^([1-9][0-9]*)x([1-9][0-9]*)$ ]] || { echo "submit-tiles: --tiles expects COLSxROWS" >&2; exit 1; }
cols=${BASH_REMATCH[1]} rows=${BASH_REMATCH[2]}

# The options that cannot work in a tile.
for ((k = 0; k < ${#extra[@]}; k++)); do
  case "${extra[k]}" in
    --time|--time=*)
      echo "submit-tiles: ${extra[k]} is not for tiles: each tile would stop at its own number of samples, and tiles of different sample counts do not merge; give --spp" >&2; exit 1 ;;
    --crop|--crop=*|-o|--output|--output=*)
      echo "submit-tiles: ${extra[k]} is not for the tiles' options: this script gives each tile its --crop and -o (OUT.png is the merged image)" >&2; exit 1 ;;
    --watch|--compare|--check|--check=*|--dry-run|--list-devices|-h|--help|--version)
      echo "submit-tiles: ${extra[k]} is not for the tiles' options: a tile render with it writes no tile to merge" >&2; exit 1 ;;
  esac
done

# The full image size: vkrt's own, not this script's reading of the scene (--size and --scale,
# the last of several `size` lines, and whatever vkrt adds later are all its). One scene under
# --dry-run prints "vkrt: SCENE -> OUT (WxH), not rendered (--dry-run)" on stderr; -q would
# silence that line, so it is left out of this run (the tiles run quiet anyway). -o OUT.png:
# the merged image is checked (its folder must exist), not the scene's own `output`, which no
# tile writes.
dry_args=()
for option in "${extra[@]}"; do
  case "$option" in -q|--quiet) ;; *) dry_args+=("$option") ;; esac
done
if ! dry=$("$vkrt" --dry-run "${dry_args[@]}" -o "$output" "$scene" 2>&1); then
  [ -z "$dry" ] || printf '%s\n' "$dry" >&2
  echo "submit-tiles: nothing submitted: vkrt refuses the scene, the options or OUT.png above" >&2; exit 1
fi
result=', not rendered (--dry-run)'
size=$(printf '%s\n' "$dry" | sed -n 's/^vkrt: .* (\([0-9]\{1,\}x[0-9]\{1,\}\)), not rendered (--dry-run)$/\1/p')
# Exactly one such line (two, from a path that holds a line break, tell no size).
if ! [[ $size =~ ^([1-9][0-9]*)x([1-9][0-9]*)$ ]]; then
  [ -z "$dry" ] || printf '%s\n' "$dry" >&2
  echo "submit-tiles: cannot tell the image size of $scene: \`vkrt --dry-run\` (above) printed no single line ending in '(WxH)$result'" >&2
  exit 1
fi
width=${BASH_REMATCH[1]} height=${BASH_REMATCH[2]}
# Its warnings, if any: the tiles run with -q and print none.
printf '%s\n' "$dry" | grep -vF -- "$result" >&2 || true
if [ "$cols" -gt "$width" ] || [ "$rows" -gt "$height" ]; then
  echo "submit-tiles: a ${cols}x${rows} grid does not fit a ${width}x${height} image" >&2; exit 1
fi

work=$(realpath -m "${work:-$output.tiles}")
# A backslash anywhere in --output's path makes sbatch expand none of its %-patterns: every
# task would write the one log named %a. Refused rather than worked around.
case $work in *\\*) echo "submit-tiles: the work folder '$work' has a backslash in its name, which stops sbatch from naming each task's log (%a); choose one without (--work DIR)" >&2; exit 1 ;; esac
mkdir -p "$work"
# sbatch expands %-patterns (%a, %j, ...) anywhere in --output's path, so a % in the folder's
# name would send the logs elsewhere: each is doubled (%% is a literal %), the script's own %a kept.
logs=${work//\%/%%}
here=$(dirname "$(realpath "$0")")
count=$((cols * rows))
# The jobs' variables go through the environment (--export=ALL), not in --export's
# comma-separated list, which would cut a value that holds a comma; VKRT_ARGS as shell words.
vkrt_args=""
[ ${#extra[@]} -eq 0 ] || vkrt_args=$(printf '%q ' "${extra[@]}")
array=$(VKRT=$vkrt TILE_DIR=$work SCENE=$scene COLS=$cols ROWS=$rows FULL_W=$width FULL_H=$height \
  VKRT_ARGS=$vkrt_args sbatch --parsable --export=ALL --array=0-$((count - 1)) --output="$logs/tile-%a.log" \
  "$here/tile-job.sh")
array=${array%%;*}   # (a cluster name may follow)
merge=$(VKRT=$vkrt PART_DIR=$work PART_NAME=tile PART_EXT=png OUTPUT=$output PARTS=$count \
  sbatch --parsable $wait --export=ALL --dependency="afterok:$array" --kill-on-invalid-dep=yes \
  --output="$logs/merge.log" "$here/merge-job.sh") || {
  echo "submit-tiles: the merge job failed (see $work/merge.log and $work/tile-*.log)" >&2; exit 1; }
# (sbatch --wait may report success for a merge cancelled because a tile failed.)
if [ -n "$wait" ] && [ ! -f "$output" ]; then
  echo "submit-tiles: no merged image: a tile failed (see $work/tile-*.log)" >&2; exit 1
fi
echo "tiles: job $array (array 0-$((count - 1)), ${cols}x${rows} of ${width}x${height}); merge: job ${merge%%;*} -> $output"
