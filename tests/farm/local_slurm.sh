#!/bin/sh
# A one-node Slurm cluster on localhost for tests, started without systemd:
#   local_slurm.sh start DIR   writes DIR/slurm.conf, starts slurmctld and slurmd, waits until
#                              the node is idle; exits non-zero with the daemons' logs otherwise
#   local_slurm.sh stop DIR    stops both daemons
# Clients find the cluster through SLURM_CONF=DIR/slurm.conf. No authentication (auth/none):
# for a throw-away test cluster only.
set -eu
action=$1
dir=$2
stop() {
    for daemon in slurmd slurmctld; do
        if [ -f "$dir/$daemon.pid" ]; then kill "$(cat "$dir/$daemon.pid")" 2>/dev/null || true; fi
    done
    for _ in 1 2 3 4 5 6 7 8 9 10; do
        alive=0
        for daemon in slurmd slurmctld; do
            if [ -f "$dir/$daemon.pid" ] && kill -0 "$(cat "$dir/$daemon.pid")" 2>/dev/null; then alive=1; fi
        done
        [ "$alive" = 0 ] && return 0
        sleep 0.5
    done
}
fail() {
    echo "local_slurm.sh: $1" >&2
    for log in "$dir/slurmctld.log" "$dir/slurmd.log"; do
        [ -f "$log" ] && { echo "--- $log" >&2; tail -n 20 "$log" >&2; }
    done
    stop
    exit 1
}
if [ "$action" = stop ]; then stop; exit 0; fi

for tool in slurmctld slurmd sbatch sinfo; do
    command -v "$tool" >/dev/null 2>&1 || fail "$tool is not installed (Debian package slurm-wlm)"
done
host=$(hostname -s)
user=$(id -un)
# Ports from the process id, so that two clusters on one machine (parallel CI jobs) do not collide.
port=$((20000 + ($$ % 20000) * 2))
mkdir -p "$dir/state" "$dir/spool"
cat > "$dir/slurm.conf" <<CONF
ClusterName=glinttest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/none
CredType=cred/none
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
MpiDefault=none
SchedulerType=sched/builtin
SchedulerParameters=sched_min_interval=100000
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$dir/slurm.conf"
slurmctld -i || fail "slurmctld did not start"
slurmd || fail "slurmd did not start"
for _ in $(seq 1 60); do
    state=$(sinfo -h -o %t 2>/dev/null || true)
    [ "$state" = idle ] && exit 0
    sleep 0.5
done
fail "the node did not become idle within 30 s (state: '${state:-none}')"
