#!/usr/bin/env bash
# Renders a path-traced scene as BATCHES sample batches on a Slurm cluster: a job array (task i
# renders with --seed BASE+i into a PFM batch) and a merge job that starts when every batch
# succeeded and averages them, weighted by their sample counts. Prints the two job ids.
#
#   submit-samples.sh [--batches N] [--spp K] [--seed BASE] [--time S] [--vkrt PATH] [--work DIR] [--wait] SCENE.test OUT.png|OUT.ppm|OUT.pfm|OUT.exr [-- VKRT OPTIONS]
#
# --batches   the number of batches (default 4); --spp samples per pixel in each batch
#             (default: the scene's spp), so N x K in all; --seed the first batch's seed
#             (default 0; batch i uses BASE+i); --time each batch's time limit in seconds (then
#             the samples taken by then, at most K; the merge weights each by its count);
# --vkrt      the binary (default: vkrt on PATH); --work the folder for the batches and logs
#             (default OUT.batches), on storage every node sees;
# --wait      wait for the merge to finish and exit with its status.
# VKRT OPTIONS go to every batch (e.g. --backend cpu, --size 1920x1080, --maxdepth 8).
# Any further sbatch options: the environment variables SBATCH_* (e.g. SBATCH_PARTITION).
set -euo pipefail
batches=4 spp="" seed=0 time="" vkrt=$(command -v vkrt || true) work="" wait=""
while [ $# -gt 0 ]; do
  case "$1" in
    --batches) batches=$2; shift 2 ;;
    --spp) spp=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    --time) time=$2; shift 2 ;;
    --vkrt) vkrt=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --wait) wait=--wait; shift ;;
    --) break ;;
    -*) echo "submit-samples: unknown option $1" >&2; exit 1 ;;
    *) break ;;
  esac
done
[ $# -ge 2 ] || { sed -n '6p' "$0" | sed 's/^# *//' >&2; exit 1; }
scene=$(realpath "$1") output=$(realpath -m "$2"); shift 2
[ "${1:-}" = "--" ] && shift
extra=("$@")
[ -n "$vkrt" ] || { echo "submit-samples: no vkrt on PATH; give --vkrt PATH" >&2; exit 1; }
vkrt=$(realpath "$vkrt")
[[ $batches =~ ^[1-9][0-9]*$ ]] || { echo "submit-samples: --batches expects a number" >&2; exit 1; }
[[ -z $spp || $spp =~ ^[1-9][0-9]*$ ]] || { echo "submit-samples: --spp expects a number" >&2; exit 1; }
[[ $seed =~ ^[0-9]+$ ]] && [ "$((seed + batches - 1))" -le 4294967295 ] ||
  { echo "submit-samples: --seed expects a number, with BASE+BATCHES-1 at most 4294967295" >&2; exit 1; }
[[ -z $time || $time =~ ^[0-9]*\.?[0-9]+$ ]] || { echo "submit-samples: --time expects seconds" >&2; exit 1; }
for option in "${extra[@]}"; do
  case "$option" in
    --seed|--seed=*|--spp|--spp=*|--time|--time=*|-o|--output|--output=*|--crop|--crop=*)
      echo "submit-samples: $option is not for the batches' options: give --seed, --spp, --time to this script (it names the batches; a batch is the whole image)" >&2; exit 1 ;;
    --watch|--compare|--check|--check=*|--dry-run|--list-devices|-h|--help|--version)
      echo "submit-samples: $option is not for the batches' options: a render with it writes no batch to merge" >&2; exit 1 ;;
  esac
done
case "$output" in
  *.png|*.ppm|*.pfm|*.exr) ;;
  *) echo "submit-samples: the merged image is .png, .ppm, .pfm or .exr: $output" >&2; exit 1 ;;
esac

work=$(realpath -m "${work:-$output.batches}")
# A backslash anywhere in --output's path makes sbatch expand none of its %-patterns: every
# task would write the one log named %a. Refused rather than worked around.
case $work in *\\*) echo "submit-samples: the work folder '$work' has a backslash in its name, which stops sbatch from naming each task's log (%a); choose one without (--work DIR)" >&2; exit 1 ;; esac
mkdir -p "$work"
# sbatch expands %-patterns (%a, %j, ...) anywhere in --output's path, so a % in the folder's
# name would send the logs elsewhere: each is doubled (%% is a literal %), the script's own %a kept.
logs=${work//\%/%%}
here=$(dirname "$(realpath "$0")")
# The jobs' variables go through the environment (--export=ALL), not in --export's
# comma-separated list, which would cut a value that holds a comma; VKRT_ARGS as shell words.
vkrt_args=""
[ ${#extra[@]} -eq 0 ] || vkrt_args=$(printf '%q ' "${extra[@]}")
array=$(VKRT=$vkrt BATCH_DIR=$work SCENE=$scene SEED_BASE=$seed SPP=$spp TIME=$time VKRT_ARGS=$vkrt_args \
  sbatch --parsable --export=ALL --array=0-$((batches - 1)) --output="$logs/batch-%a.log" \
  "$here/samples-job.sh")
array=${array%%;*}   # (a cluster name may follow)
merge=$(VKRT=$vkrt PART_DIR=$work PART_NAME=batch PART_EXT=pfm PARTS=$batches OUTPUT=$output \
  sbatch --parsable $wait --export=ALL --dependency="afterok:$array" --kill-on-invalid-dep=yes \
  --output="$logs/merge.log" "$here/merge-job.sh") || {
  echo "submit-samples: the merge job failed (see $work/merge.log and $work/batch-*.log)" >&2; exit 1; }
# (sbatch --wait may report success for a merge cancelled because a batch failed.)
if [ -n "$wait" ] && [ ! -f "$output" ]; then
  echo "submit-samples: no merged image: a batch failed (see $work/batch-*.log)" >&2; exit 1
fi
echo "samples: job $array (array 0-$((batches - 1)), seeds $seed-$((seed + batches - 1))${spp:+, $spp spp each}${time:+, ${time} s each}); merge: job ${merge%%;*} -> $output"
