#!/usr/bin/env bash
# Proves the Slurm examples on a one-node cluster made here. First, with a stand-in sbatch
# that must not be called, that the submit scripts refuse what cannot work: scenes in chunks
# that would write the same file, tile options that would make the tiles differ. Then it
# installs slurm and munge when missing (Debian 12; root or sudo), starts a private munged,
# slurmctld and slurmd under a temporary folder (no systemd, nothing under /etc changed),
# renders a scene as a 3x2 tile array plus a dependent merge, a path-traced scene as 4 sample
# batches plus a dependent merge, and a list of scenes in chunks, with paths and an option
# value that hold commas and blanks, and paths that hold a % sbatch would expand (%a, %j);
# checks that the merged tiles (at a --size and at a --scale) and the chunks' images equal
# one-machine renders bit for bit, the merged batches a one-machine render of other samples
# statistically, and every job's log in its work folder; and stops what it started. Needs
# perl (Debian's perl-base) to read the float images.
#
#   examples/slurm/test-local-cluster.sh [path/to/vkrt]      (default: build/vkrt)
#
# Exits 0 on success, else non-zero with a message and the daemons' and jobs' logs. Every
# wait is bounded (VKRT_SLURM_TIMEOUT seconds per wait, default 180).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
vkrt=$(realpath "${1:-$root/build/vkrt}")
timeout_s=${VKRT_SLURM_TIMEOUT:-180}
start=$(date +%s)
say() { echo "slurm-test: $*"; }
[ -x "$vkrt" ] || { say "no vkrt binary at $vkrt (build first)" >&2; exit 1; }

tmp=$(realpath "$(mktemp -d -t vkrt-slurm.XXXXXX)")
chmod 755 "$tmp"   # munged wants its socket's folders searchable by all
pids=()
dump_logs() {
  for f in "$tmp"/log/* "$tmp"/refused.err "$tmp"/jobs/*/tiles*/*.log "$tmp"/jobs/*/samples/*.log "$tmp"/out/*/*.log; do
    [ -f "$f" ] || continue
    echo "----- $f (last 40 lines)"; tail -n 40 "$f"
  done
}
cleanup() {
  local status=$?
  trap - EXIT
  if [ "$status" -ne 0 ]; then
    say "FAILED (status $status); logs:" >&2
    dump_logs >&2 || true
  fi
  if [ -n "${SLURM_CONF:-}" ] && [ -f "$SLURM_CONF" ]; then scancel --quiet --full "--user=$(id -un)" 2>/dev/null || true; fi
  # Stop the daemons started here (by their process ids), newest first, then wait for them.
  for ((k = ${#pids[@]} - 1; k >= 0; k--)); do kill "${pids[k]}" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
  done
  rm -rf "$tmp"
  exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

# Waits until `$@` succeeds, at most timeout_s seconds; fails with `what`.
wait_for() {
  local what=$1; shift
  local deadline=$(($(date +%s) + timeout_s))
  until "$@" >/dev/null 2>&1; do
    if [ "$(date +%s)" -ge "$deadline" ]; then say "timed out after ${timeout_s}s waiting for $what" >&2; return 1; fi
    sleep 0.5
  done
}

# Refused before anything is submitted (no cluster needed): a stand-in sbatch, first on PATH,
# records each call in $fake_calls; the refusals must leave it uncalled.
mkdir -p "$tmp/fake-bin"
fake_calls=$tmp/fake-bin/calls
cat > "$tmp/fake-bin/sbatch" <<'FAKE'
#!/usr/bin/env bash
echo "$*" >> "$(dirname "$0")/calls"
echo 1
FAKE
chmod +x "$tmp/fake-bin/sbatch"
# refused COMMAND...: COMMAND fails without calling sbatch (its messages in $tmp/refused.err).
refused() {
  rm -f "$fake_calls"
  if PATH=$tmp/fake-bin:$PATH "$@" >/dev/null 2>"$tmp/refused.err"; then say "not refused: $*" >&2; return 1; fi
  [ ! -e "$fake_calls" ] || { say "refused but submitted: $*" >&2; return 1; }
}
# says TEXT: the last refusal's messages hold TEXT.
says() { grep -qF -- "$1" "$tmp/refused.err" || { say "the refusal does not say: $1" >&2; return 1; }; }

# Scenes whose images would have the same name in OUT_DIR: from their `output` lines (in two
# folders; one written `Output renders/dragon.png`, with a comment and CRLF line ends), or a
# scene's stem against another's `output`. A commented-out `output` line names nothing.
names=$tmp/names
mkdir -p "$names/hw 2" "$names/hw3" "$names/x" "$names/y" "$names/z"
spheres=$root/scenes/spheres.test
sed 's/^output .*/output dragon.png/' "$spheres" > "$names/hw 2/dragon.test"
sed -e 's|^output .*|Output renders/dragon.png  # the same name|' -e 's/$/\r/' "$spheres" > "$names/hw3/dragon.test"
grep -v '^output' "$spheres" > "$names/x/plain.test"
sed 's/^output .*/output plain.png/' "$spheres" > "$names/y/other.test"
sed 's/^output .*/# output plain.png/' "$spheres" > "$names/z/commented.test"
refused "$root/examples/slurm/submit-scenes.sh" --chunks 3 --vkrt "$vkrt" "$names/out" "$names/hw 2/dragon.test" \
  "$names/hw3/dragon.test" "$names/x/plain.test" "$names/y/other.test" "$names/z/commented.test"
says "refusing to write the output of $names/hw3/dragon.test '$names/out/dragon.png': it is also the output of $names/hw 2/dragon.test"
says "refusing to write the output of $names/y/other.test '$names/out/plain.png': it is also the output of $names/x/plain.test"
says "submit-scenes: nothing submitted"
! grep -q commented "$tmp/refused.err" || { say "a commented-out output line was read" >&2; exit 1; }
[ ! -e "$names/out" ] || { say "submit-scenes wrote $names/out although it refused" >&2; exit 1; }
say "scenes that would write the same file in OUT_DIR: refused, nothing submitted"

# refuses_options SCRIPT WORK OUT "COUNT OPTION" OPTION...: SCRIPT (submit-tiles or
# submit-samples) refuses each of the vkrt options, submitting nothing and making no WORK.
refuses_options() {
  local script=$1 work=$2 out=$3 count=$4 option
  shift 4
  for option in "$@"; do
    # shellcheck disable=SC2086
    refused "$root/examples/slurm/$script.sh" $count --vkrt "$vkrt" --work "$work" \
      "$root/examples/slurm/cornell.test" "$out" -- --backend cpu $option
    says "$script: ${option%% *} is not for"
  done
  [ ! -e "$work" ] || { say "$script made $work although it refused" >&2; exit 1; }
}
# Tile options that make the tiles of one render differ or clash with the script's own.
refuses_options submit-tiles "$names/tiles" "$names/tiled.png" "--tiles 2x1" \
  "--time 0.05" "--time=0.05" "--crop 0,0,8,8" "-o tile.png" "--output=tile.png" "--watch"
say "tile options that cannot work in a tile (--time, --crop, -o, --watch): refused, nothing submitted"
refuses_options submit-samples "$names/batches" "$names/batched.png" "--batches 2" \
  "--seed 3" "--time=1" "-o b.pfm" "--watch" "--dry-run"
say "batch options that cannot work in a batch (--seed, --time, -o, --watch, --dry-run): refused, nothing submitted"

# A backslash in a folder's name stops sbatch from expanding %a in the logs' names (every task
# would write one log): each script refuses it, submitting nothing and making no folder.
bs="$names/back\\slash"
refused "$root/examples/slurm/submit-tiles.sh" --tiles 2x1 --vkrt "$vkrt" --work "$bs" \
  "$root/examples/slurm/cornell.test" "$names/bs-tiled.png" -- --backend cpu
says "submit-tiles: the work folder '$bs' has a backslash in its name"
refused "$root/examples/slurm/submit-samples.sh" --batches 2 --vkrt "$vkrt" --work "$bs" \
  "$root/examples/slurm/cornell.test" "$names/bs-batched.pfm" -- --backend cpu
says "submit-samples: the work folder '$bs' has a backslash in its name"
refused "$root/examples/slurm/submit-scenes.sh" --chunks 2 --vkrt "$vkrt" "$bs" "$names/x/plain.test"
says "submit-scenes: the output folder '$bs' has a backslash in its name"
[ ! -e "$bs" ] || { say "a script made $bs although it refused" >&2; exit 1; }
say "a folder with a backslash in its name (sbatch would name no task's log): refused, nothing submitted"

# Packages: slurmctld, slurmd, the client commands and munge, from Debian's mirrors.
if ! command -v slurmctld >/dev/null || ! command -v slurmd >/dev/null || ! command -v sbatch >/dev/null ||
   ! command -v munged >/dev/null; then
  bash "$root/.ci/install-deps" --slurm
fi

mkdir -p "$tmp"/{munge,log,state,spool,jobs,out}
chmod 755 "$tmp/munge"

# munge: a private key and daemon, on a socket of its own.
dd if=/dev/urandom of="$tmp/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$tmp/munge/munge.key"
socket=$tmp/munge/munge.socket
munged --socket="$socket" --key-file="$tmp/munge/munge.key" --pid-file="$tmp/munge/munged.pid" \
  --log-file="$tmp/log/munged.log" --seed-file="$tmp/munge/seed"
wait_for "munged's pid file" test -s "$tmp/munge/munged.pid"
pids+=("$(cat "$tmp/munge/munged.pid")")
munge -n -S "$socket" | unmunge -S "$socket" >/dev/null || { say "munge does not work" >&2; exit 1; }

# slurm.conf: one node, this machine, as slurmd itself sees it (CPUs, sockets, memory).
host=$(hostname -s 2>/dev/null || echo localhost)
node=$(slurmd -C | head -n 1)   # NodeName=HOST CPUs=N Boards=... RealMemory=MB
node=${node/NodeName=* CPUs=/NodeName=$host NodeHostname=$host NodeAddr=127.0.0.1 CPUs=}
port=$((20000 + RANDOM % 20000))   # two free-looking ports, so as not to meet a real cluster's
export SLURM_CONF=$tmp/slurm.conf
cat > "$SLURM_CONF" <<CONF
ClusterName=vkrt-test
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=$(id -un)
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$socket
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/log/slurmctld.log
SlurmdLogFile=$tmp/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
DependencyParameters=kill_invalid_depend
SlurmdTimeout=60
MinJobAge=600
$node State=UNKNOWN
PartitionName=debug Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF

slurmctld -D -i -f "$SLURM_CONF" >"$tmp/log/slurmctld.out" 2>&1 &
pids+=("$!")
slurmd -D -f "$SLURM_CONF" -N "$host" >"$tmp/log/slurmd.out" 2>&1 &
pids+=("$!")
node_idle() { [ "$(sinfo -h -n "$host" -o %T 2>/dev/null)" = idle ]; }
wait_for "node $host to be idle in sinfo" node_idle
say "cluster up: $(sinfo -h -o '%P %D %T %c CPUs %m MB' | head -n 1) ($(($(date +%s) - start)) s)"

cd "$tmp/jobs"
# The jobs' scenes, work folders and images lie in a folder whose name holds a comma and a
# blank, and their options include a value that does: each must reach the jobs whole. The name
# holds a %a too, which sbatch expands in --output's path (to the array index): unless the
# scripts write it %%a there, the logs go to folders `odd, 500 name` and so on, which do not
# exist, and the jobs fail.
odd="$tmp/jobs/odd, 50%a name"
mkdir -p "$odd"
probe=(--device "no such, device")   # one word; the CPU backend does not read --device
scene="$odd/show, case.test"
cp "$root/scenes/showcase.test" "$scene"
args=(--backend cpu --size 123x77)   # odd sizes: tiles of unequal widths and heights
# logs_in DIR LOG...: each job's log is in DIR (where the script's --output put it).
logs_in() {
  local dir=$1 log; shift
  for log in "$@"; do
    [ -f "$dir/$log" ] || { say "no log $dir/$log: sbatch wrote it elsewhere (under an expanded %?)" >&2; return 1; }
  done
}

# A scene as 3x2 tiles and a dependent merge, against a one-machine render.
"$vkrt" "${args[@]}" -q -o "$tmp/jobs/single.png" "$scene"
timeout "$timeout_s" "$root/examples/slurm/submit-tiles.sh" --tiles 3x2 --vkrt "$vkrt" --work "$odd/tiles" \
  --wait "$scene" "$odd/merged.png" -- "${args[@]}" "${probe[@]}" ||
  { say "the tile jobs or the merge failed or timed out" >&2; exit 1; }
"$vkrt" diff "$odd/merged.png" "$tmp/jobs/single.png" >/dev/null ||
  { say "the merged image differs from the one-machine render" >&2; exit 1; }
cmp "$odd/merged.png" "$tmp/jobs/single.png" ||
  { say "the merged PNG's bytes differ from the one-machine render's" >&2; exit 1; }
logs_in "$odd/tiles" tile-{0..5}.log merge.log
say "3x2 tiles merged: equal to the one-machine render, bit for bit"

# The full size comes from vkrt (--dry-run), so --scale places the tiles too: 800x500 x 0.37 is
# 296x185 (the scene's `size` would put every tile's crop off the smaller image). -q must not
# hide the size from the script.
scaled=(--backend cpu --scale 0.37)
"$vkrt" "${scaled[@]}" -q -o "$tmp/jobs/single-scaled.png" "$scene"
summary=$(timeout "$timeout_s" "$root/examples/slurm/submit-tiles.sh" --tiles 3x2 --vkrt "$vkrt" \
  --work "$odd/tiles, scaled" --wait "$scene" "$odd/merged-scaled.png" -- "${scaled[@]}" -q "${probe[@]}") ||
  { say "the tile jobs or the merge at --scale 0.37 failed or timed out" >&2; exit 1; }
[[ $summary == *"3x2 of 296x185)"* ]] || { say "the tiles at --scale 0.37 are not of 296x185: $summary" >&2; exit 1; }
cmp "$odd/merged-scaled.png" "$tmp/jobs/single-scaled.png" ||
  { say "the merged image at --scale 0.37 differs from the one-machine render's" >&2; exit 1; }
logs_in "$odd/tiles, scaled" tile-{0..5}.log merge.log
say "3x2 tiles at --scale 0.37 (296x185) merged: equal to the one-machine render, bit for bit"

# A path-traced scene as 4 batches of 4 samples (seeds 1-4) and a dependent merge, against a
# one-machine render of 16 samples of another seed: two independent estimates of the same
# expected image, so they agree statistically, not bit for bit.
pt_scene="$odd/cornell, box.test"   # examples/slurm/cornell.test: 64x64, path-traced
cp "$root/examples/slurm/cornell.test" "$pt_scene"
"$vkrt" --backend cpu -q --spp 16 --seed 100 -o "$tmp/jobs/single-16spp.pfm" "$pt_scene"
timeout "$timeout_s" "$root/examples/slurm/submit-samples.sh" --batches 4 --spp 4 --seed 1 --vkrt "$vkrt" \
  --work "$odd/samples" --wait "$pt_scene" "$odd/merged-16spp.pfm" -- --backend cpu "${probe[@]}" ||
  { say "the sample batch jobs or the merge failed or timed out" >&2; exit 1; }
record=$(LC_ALL=C grep -a '^vkrt-samples ' "$odd/merged-16spp.pfm" || true)
[[ $record == "vkrt-samples 16 gamma "*" seeds 1:0+4 2:0+4 3:0+4 4:0+4" ]] ||
  { say "the merged batches' record is not 16 samples of seeds 1-4: '$record'" >&2; exit 1; }
logs_in "$odd/samples" batch-{0..3}.log merge.log

# same_expectation A.pfm B.pfm: whether two independent renders estimate the same expected
# image. For each pixel and channel d = A - B has mean 0 (both unbiased for the same pixel)
# and pixels are independent, so over a set of pixels z = sum d / sqrt(sum d^2) is about
# N(0,1), whatever each pixel's variance (the noise is estimated from the images themselves):
# - the image's mean radiance, per channel: |z| <= 4 (4 standard errors of the difference;
#   about 3% of the mean for 16 spp at 64x64);
# - 8x8-pixel blocks, per channel (192 here): every |z| <= 5, and the mean of z^2 <= 1.5.
# Over 40 pairs of seeds the largest values seen were |z| 2.0, 3.8 and 1.12 (the mean of z^2
# stays under 1: path tracing's heavy tails make z lighter-tailed than a normal); rendering
# the box with maxdepth 2 instead of 5 (11% darker) fails all three (z 10, 7, 19).
same_expectation() {
  perl -e '
    use strict; use warnings;
    sub pfm {   # the raster of a colour PFM, whatever follows it
      my ($path) = @_;
      open(my $f, "<:raw", $path) or die "cannot read $path\n";
      local $/; my $data = <$f>;
      $data =~ /\APF\s+(\d+)\s+(\d+)\s+(\S+)\s/ or die "$path: not a colour PFM\n";
      my ($w, $h, $scale, $at) = ($1, $2, $3, $+[0]);
      return ($w, $h, [unpack(($scale < 0 ? "f<" : "f>") . ($w * $h * 3), substr($data, $at, $w * $h * 12))]);
    }
    my ($w, $h, $a) = pfm($ARGV[0]); my ($wb, $hb, $b) = pfm($ARGV[1]);
    die "the sizes differ\n" unless $w == $wb && $h == $hb;
    sub z { my ($s, $s2) = @_; return $s2 > 0 ? $s / sqrt($s2) : 0 }
    my ($ok, $chi2, $blocks, $zmax) = (1, 0, 0, 0);
    for my $c (0 .. 2) {
      my ($ma, $mb, $s, $s2, %bs, %bs2) = (0, 0, 0, 0);
      for my $p (0 .. $w * $h - 1) {
        my $k = 3 * $p + $c; my $d = $a->[$k] - $b->[$k];
        my $block = int(int($p / $w) / 8) . "," . int(($p % $w) / 8);
        $ma += $a->[$k]; $mb += $b->[$k]; $s += $d; $s2 += $d * $d; $bs{$block} += $d; $bs2{$block} += $d * $d;
      }
      my $z = z($s, $s2);
      printf "  %s: mean radiance %.4f vs %.4f (%+.2f%%), z %+.2f\n", (qw(red green blue))[$c],
        $ma / ($w * $h), $mb / ($w * $h), $mb ? 100 * ($ma - $mb) / $mb : 0, $z;
      $ok = 0 if abs($z) > 4;
      for my $k (keys %bs) { my $zb = z($bs{$k}, $bs2{$k}); $chi2 += $zb * $zb; $blocks++; $zmax = abs($zb) if abs($zb) > $zmax }
    }
    printf "  %d blocks of 8x8: max |z| %.2f, mean z^2 %.3f\n", $blocks, $zmax, $chi2 / $blocks;
    $ok = 0 if $zmax > 5 || $chi2 / $blocks > 1.5;
    exit($ok ? 0 : 1);
  ' "$1" "$2"
}
same_expectation "$odd/merged-16spp.pfm" "$tmp/jobs/single-16spp.pfm" ||
  { say "the merged batches and the one-machine render differ beyond noise" >&2; exit 1; }
# The check can fail: a render of a different expected image (fewer bounces) does.
"$vkrt" --backend cpu -q --spp 16 --seed 200 --maxdepth 2 -o "$tmp/jobs/maxdepth2.pfm" "$pt_scene"
if same_expectation "$odd/merged-16spp.pfm" "$tmp/jobs/maxdepth2.pfm" >/dev/null; then
  say "the statistical check does not tell maxdepth 2 from maxdepth 5" >&2; exit 1
fi
say "4 sample batches x 4 spp merged: 16 samples, equal to a one-machine 16-spp render within noise"

# Scenes in chunks, against one run over all of them; two more from the odd folder: one
# without an `output` line (named after its stem) and one whose `output` line is a comment.
grep -v '^output' "$spheres" > "$odd/no output, 1.test"
sed 's/^output .*/# output spheres.png/' "$spheres" > "$odd/commented.test"
scenes=("$root"/scenes/*.test "$odd/no output, 1.test" "$odd/commented.test")
mkdir -p "$tmp/out/single"
"$vkrt" --backend cpu -q -o "$tmp/out/single/" "${scenes[@]}"
chunks="$tmp/out/chunks, 1%j"   # (%j: the job's id in --output, unless written %%j)
timeout "$timeout_s" "$root/examples/slurm/submit-scenes.sh" --chunks 3 --vkrt "$vkrt" --wait "$chunks" \
  "${scenes[@]}" -- --backend cpu "${probe[@]}" ||
  { say "a scene chunk failed or timed out" >&2; exit 1; }
for f in "$tmp"/out/single/*; do
  cmp "$f" "$chunks/$(basename "$f")" || { say "$(basename "$f") differs between the chunks and one run" >&2; exit 1; }
done
[ -f "$chunks/no output, 1.png" ] && [ -f "$chunks/commented.png" ] ||
  { say "the chunks did not name the scenes without an output line after their stems" >&2; exit 1; }
logs_in "$chunks" chunk-{0..2}.log
say "${#scenes[@]} scenes in 3 chunks: the same images as one run"
say "passed in $(($(date +%s) - start)) s"
