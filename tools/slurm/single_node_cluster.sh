#!/usr/bin/env bash
# A single-node Slurm cluster for tests and trials, from Debian's slurmctld, slurmd and
# munge, run as root without systemd: everything it makes lives in one folder.
#   single_node_cluster.sh start DIR   writes DIR/slurm.conf, starts munged, slurmctld and
#                                      slurmd, waits until the node takes jobs
#   single_node_cluster.sh stop DIR    stops them by their pid files
# Clients find the cluster through SLURM_CONF=DIR/slurm.conf. The node has this
# machine's CPUs; jobs run as the user who submits them (proctrack/linuxproc, task/none:
# no cgroups). TIDEWATER_SLURM_PORT picks the controller's port (default 6817; slurmd
# takes the next).
set -euo pipefail

usage() { echo "usage: $0 start|stop DIR" >&2; exit 2; }
[ $# -eq 2 ] || usage
action="$1"
mkdir -p "$2"
dir="$(cd "$2" && pwd)"

pid_of() { [ -s "$1" ] && cat "$1" || true; }
stop_pid_file() {  # stop_pid_file FILE NAME: TERM, then KILL after 10 s
  local pid
  pid="$(pid_of "$1")"
  [ -n "$pid" ] || return 0
  if kill -0 "$pid" 2>/dev/null; then
    kill -TERM "$pid" 2>/dev/null || true
    for _ in $(seq 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -0 "$pid" 2>/dev/null && { echo "$2 ($pid) did not stop: killing it" >&2; kill -KILL "$pid" 2>/dev/null || true; }
  fi
  rm -f "$1"
}

case "$action" in
  start)
    [ "$(id -u)" -eq 0 ] || { echo "$0: the cluster's daemons run as root" >&2; exit 1; }
    for tool in munged mungekey slurmctld slurmd sinfo; do
      command -v "$tool" >/dev/null || { echo "$0: $tool is missing (apt-get install slurmctld slurmd slurm-client munge)" >&2; exit 1; }
    done
    port="${TIDEWATER_SLURM_PORT:-6817}"
    host="$(hostname -s)"
    cpus="$(nproc)"
    mkdir -p "$dir/state" "$dir/spool" "$dir/munge"
    chmod 700 "$dir/munge"
    [ -s "$dir/munge/munge.key" ] || mungekey --create --keyfile="$dir/munge/munge.key" >/dev/null
    chmod 600 "$dir/munge/munge.key"
    munged --force --key-file="$dir/munge/munge.key" --socket="$dir/munge/munge.socket" \
      --pid-file="$dir/munge/munged.pid" --log-file="$dir/munge/munged.log" --seed-file="$dir/munge/munged.seed"
    cat > "$dir/slurm.conf" <<CONF
ClusterName=tidewater
SlurmctldHost=$host
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$dir/munge/munge.socket
CredType=cred/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
MpiDefault=none
ReturnToService=2
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
NodeName=$host CPUs=$cpus State=UNKNOWN
PartitionName=local Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
    export SLURM_CONF="$dir/slurm.conf"
    slurmctld -f "$SLURM_CONF"
    slurmd -f "$SLURM_CONF"
    for _ in $(seq 300); do
      state="$(sinfo -h -N -o %t 2>/dev/null | head -1)"
      case "$state" in idle|mix|alloc) echo "slurm: node $host ($cpus CPUs) is $state; export SLURM_CONF=$SLURM_CONF"; exit 0 ;; esac
      sleep 0.1
    done
    echo "$0: the node did not come up (state: ${state:-none}); logs in $dir" >&2
    tail -n 20 "$dir/slurmctld.log" "$dir/slurmd.log" >&2 || true
    exit 1
    ;;
  stop)
    stop_pid_file "$dir/slurmd.pid" slurmd
    stop_pid_file "$dir/slurmctld.pid" slurmctld
    stop_pid_file "$dir/munge/munged.pid" munged
    ;;
  *) usage ;;
esac
