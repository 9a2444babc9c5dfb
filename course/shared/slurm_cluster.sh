#!/bin/sh
# Test machinery: a real single-node Slurm cluster from Debian's packages, for the job array tests
# (the references', the class grader's). Needs root: it runs munged, slurmctld and slurmd as
# root in a container, with proctrack/linuxproc and task/none (no cgroups), no accounting.
#   course/shared/slurm_cluster.sh up DIR     start the daemons, state and logs under DIR; prints SLURM_CONF
#   course/shared/slurm_cluster.sh down DIR   stop exactly the daemons that `up DIR` started
set -eu
cmd=${1:?usage: cluster.sh up|down DIR}
dir=${2:?usage: cluster.sh up|down DIR}

case "$cmd" in
up)
    mkdir -p "$dir/state" "$dir/spool" "$dir/munge"
    host=$(hostname -s)
    cpus=$(nproc)
    # munge: a key of our own and a socket under DIR, so a machine's own munged is left alone.
    dd if=/dev/urandom of="$dir/munge/munge.key" bs=128 count=1 2>/dev/null
    chmod 600 "$dir/munge/munge.key"
    munged --force --key-file="$dir/munge/munge.key" --socket="$dir/munge/socket" \
        --pid-file="$dir/munge/munged.pid" --log-file="$dir/munge/munged.log" --seed-file="$dir/munge/seed"
    cat > "$dir/slurm.conf" <<CONF
ClusterName=pathlab
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$dir/munge/socket
CredType=cred/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
SlurmctldPort=16817
SlurmdPort=16818
NodeName=$host CPUs=$cpus State=UNKNOWN
PartitionName=debug Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
    export SLURM_CONF="$dir/slurm.conf"
    slurmctld -f "$SLURM_CONF"
    slurmd -f "$SLURM_CONF"
    # Wait until the node takes jobs.
    i=0
    until sinfo -h -o %t 2>/dev/null | grep -qE '^(idle|mix|alloc)'; do
        i=$((i + 1))
        if [ $i -gt 60 ]; then
            echo "cluster.sh: the node did not come up in 30 s; see $dir/*.log" >&2
            exit 1
        fi
        sleep 0.5
    done
    echo "SLURM_CONF=$SLURM_CONF"
    ;;
down)
    # Each daemon is stopped and waited for (10 s at most): slurmctld saves its state as it exits,
    # and a caller that removes DIR at once would race those writes ("Directory not empty").
    for pid in "$dir/slurmd.pid" "$dir/slurmctld.pid" "$dir/munge/munged.pid"; do
        [ -f "$pid" ] || continue
        p=$(cat "$pid")
        kill "$p" 2>/dev/null || continue
        i=0
        while kill -0 "$p" 2>/dev/null && [ $i -lt 100 ]; do
            sleep 0.1
            i=$((i + 1))
        done
    done
    ;;
*)
    echo "usage: cluster.sh up|down DIR" >&2
    exit 2
    ;;
esac
