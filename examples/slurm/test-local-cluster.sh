#!/usr/bin/env bash
# Proves the Slurm examples on a one-node cluster made here: installs slurm and munge when
# missing (Debian 12; root or sudo), starts a private munged, slurmctld and slurmd under a
# temporary folder (no systemd, nothing under /etc changed), renders a scene as a 3x2 tile
# array plus a dependent merge, and a list of scenes in chunks, checks that the merged image
# and the chunks' images equal one-machine renders bit for bit, and stops what it started.
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

# Packages: slurmctld, slurmd, the client commands and munge, from Debian's mirrors.
if ! command -v slurmctld >/dev/null || ! command -v slurmd >/dev/null || ! command -v sbatch >/dev/null ||
   ! command -v munged >/dev/null; then
  bash "$root/.ci/install-deps" --slurm
fi

tmp=$(mktemp -d -t vkrt-slurm.XXXXXX)
chmod 755 "$tmp"   # munged wants its socket's folders searchable by all
pids=()
dump_logs() {
  for f in "$tmp"/log/* "$tmp"/work/tiles/*.log "$tmp"/out/chunks/*.log; do
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

mkdir -p "$tmp"/{munge,log,state,spool,work,out}
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

cd "$tmp/work"
scene=$root/scenes/showcase.test
args=(--backend cpu --size 123x77)   # odd sizes: tiles of unequal widths and heights

# A scene as 3x2 tiles and a dependent merge, against a one-machine render.
"$vkrt" "${args[@]}" -q -o "$tmp/work/single.png" "$scene"
timeout "$timeout_s" "$root/examples/slurm/submit-tiles.sh" --tiles 3x2 --vkrt "$vkrt" --work "$tmp/work/tiles" \
  --wait "$scene" "$tmp/work/merged.png" -- "${args[@]}" ||
  { say "the tile jobs or the merge failed or timed out" >&2; exit 1; }
"$vkrt" diff "$tmp/work/merged.png" "$tmp/work/single.png" >/dev/null ||
  { say "the merged image differs from the one-machine render" >&2; exit 1; }
cmp "$tmp/work/merged.png" "$tmp/work/single.png" ||
  { say "the merged PNG's bytes differ from the one-machine render's" >&2; exit 1; }
say "3x2 tiles merged: equal to the one-machine render, bit for bit"

# Scenes in chunks, against one run over all of them.
scenes=("$root"/scenes/*.test)
mkdir -p "$tmp/out/single"
"$vkrt" --backend cpu -q -o "$tmp/out/single/" "${scenes[@]}"
timeout "$timeout_s" "$root/examples/slurm/submit-scenes.sh" --chunks 3 --vkrt "$vkrt" --wait "$tmp/out/chunks" \
  "${scenes[@]}" -- --backend cpu ||
  { say "a scene chunk failed or timed out" >&2; exit 1; }
for f in "$tmp"/out/single/*; do
  cmp "$f" "$tmp/out/chunks/$(basename "$f")" || { say "$(basename "$f") differs between the chunks and one run" >&2; exit 1; }
done
say "${#scenes[@]} scenes in 3 chunks: the same images as one run"
say "passed in $(($(date +%s) - start)) s"
