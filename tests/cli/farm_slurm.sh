# A real scheduler: a single-node Slurm (slurmctld + slurmd + munged) on localhost, configured in
# a temp folder, runs scripts/slurm as an array job; its frames must equal a serial render's.
source "$(dirname "$0")/lib.sh"
skip() { echo "SKIP: $*" >&2; exit 77; }
for tool in munged slurmctld slurmd sbatch sinfo; do
    command -v "$tool" >/dev/null || [ -x "/usr/sbin/$tool" ] ||
        skip "$tool missing (scripts/setup installs slurm-wlm and munge)"
done
[ "$(id -u)" -eq 0 ] || skip "slurmd needs root here (SlurmdUser=root); run as root to test the farm"
export PATH="$PATH:/usr/sbin"
T="$WORK/slurm"
mkdir -p "$T/state" "$T/spool" "$T/munge" "$T/out"
chmod 700 "$T/munge"
# Stop only the daemons this test started (by their pid files), then remove the scratch folder.
stop() {
    for pidfile in "$T/slurmd.pid" "$T/slurmctld.pid" "$T/munge/pid"; do
        [ -f "$pidfile" ] && kill "$(cat "$pidfile")" 2>/dev/null || true
    done
    sleep 0.5
    rm -rf "$WORK"
}
trap stop EXIT

# munge: a key of our own, a socket in the temp folder (no system daemon is touched).
dd if=/dev/urandom of="$T/munge/key" bs=1024 count=1 status=none
chmod 600 "$T/munge/key"
munged -f --socket="$T/munge/sock" --key-file="$T/munge/key" --log-file="$T/munge/log" \
    --pid-file="$T/munge/pid" --seed-file="$T/munge/seed" || skip "munged does not start"

read -r port1 port2 < <(python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*[x.getsockname()[1] for x in s])')
host=$(hostname -s)
cat >"$T/slurm.conf" <<CONF
ClusterName=penumbra-test
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$T/munge/sock
CredType=cred/munge
SlurmctldPort=$port1
SlurmdPort=$port2
StateSaveLocation=$T/state
SlurmdSpoolDir=$T/spool
SlurmctldPidFile=$T/slurmctld.pid
SlurmdPidFile=$T/slurmd.pid
SlurmctldLogFile=$T/slurmctld.log
SlurmdLogFile=$T/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
MpiDefault=none
ReturnToService=2
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=local Nodes=ALL Default=YES MaxTime=10 State=UP
CONF
export SLURM_CONF="$T/slurm.conf"
slurmctld -f "$SLURM_CONF" -i || skip "slurmctld does not start: $(tail -n 3 "$T/slurmctld.log" 2>/dev/null)"
slurmd -f "$SLURM_CONF" || skip "slurmd does not start: $(tail -n 3 "$T/slurmd.log" 2>/dev/null)"
for _ in $(seq 40); do
    sinfo -h -o %T 2>/dev/null | grep -qx idle && break
    sleep 0.5
done
sinfo -h -o %T | grep -qx idle || skip "the node never became idle: $(tail -n 3 "$T/slurmd.log")"

# The array job: scripts/slurm, frames 1-4 of the shipped animated scene, from the checkout.
cd "$PENUMBRA_SOURCE_DIR"
PENUMBRA="$PENUMBRA" timeout 120 sbatch --wait --array=1-4 --cpus-per-task=1 --quiet \
    --output="$T/out/task-%a.log" scripts/slurm scenes/walk.json "$T/out/farm/walk.####.exr" \
    --size 64x48 || { cat "$T"/out/task-*.log "$T/slurmd.log" >&2; fail "the array job failed"; }
"$PENUMBRA" render scenes/walk.json -f 1-4 -o "$T/out/serial/walk.####.exr" --size 64x48 --quiet
for f in 0001 0002 0003 0004; do
    cmp "$T/out/farm/walk.$f.exr" "$T/out/serial/walk.$f.exr" ||
        fail "frame $f: the Slurm task's EXR differs from the serial render's"
done
# A requeued task finds its frame's files and skips it.
before=$(stat -c %y "$T/out/farm/walk.0002.exr")
PENUMBRA="$PENUMBRA" timeout 60 sbatch --wait --array=2 --quiet --output="$T/out/again.log" \
    scripts/slurm scenes/walk.json "$T/out/farm/walk.####.exr" --size 64x48 || fail "requeue"
[ "$(stat -c %y "$T/out/farm/walk.0002.exr")" = "$before" ] || fail "the requeued task rendered again"
echo "farm: Slurm ran 4 array tasks on $host; frames equal the serial render"
