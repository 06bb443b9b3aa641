#!/usr/bin/env bash
# A single-node Slurm cluster (this host) from the distribution's packages, for
# trying the farm scripts and for the farm test; no systemd, no cgroups needed.
#   farm/slurm/single-node.sh start STATE_DIR   munged, slurmctld and slurmd, waits for the node to be idle
#   farm/slurm/single-node.sh stop  STATE_DIR   cancels leftover jobs and stops the three daemons
# Then: export SLURM_CONF=STATE_DIR/slurm.conf (or source STATE_DIR/env) before sbatch, squeue, sinfo.
# Packages: bash scripts/install-deps.sh --farm (slurm-wlm, munge). Runs as root; the jobs run as the submitter.
# Ports: FARM_SLURMCTLD_PORT (6817) and FARM_SLURMD_PORT (6818), in case a real cluster uses the defaults here.
set -euo pipefail

usage() { echo "usage: $0 start|stop STATE_DIR" >&2; exit 2; }
[[ $# -eq 2 ]] || usage
action=$1
mkdir -p "$2"
state=$(cd "$2" && pwd)
host=$(hostname -s)
export SLURM_CONF=$state/slurm.conf
socket=$state/munge/munge.socket

log() { echo "single-node: $*" >&2; }

# A pid runs the daemon only while it still runs that program (pids get reused) and is no
# zombie (an init that does not reap, as in many containers, leaves those behind).
running() {
  local stat
  stat=$(cat "/proc/$1/stat" 2>/dev/null) || return 1
  [[ $stat == "$1 ($2"* && ${stat#*) } != Z* ]]
}
alive() {
  local pid
  pid=$(cat "$1" 2>/dev/null) && [[ -n $pid ]] && running "$pid" "$2"
}

# SIGTERM is a clean shutdown for all three daemons; SIGKILL only if one hangs.
stop_daemon() {
  local pidfile=$1 name=$2 pid i
  pid=$(cat "$pidfile" 2>/dev/null) || return 0
  rm -f "$pidfile"
  running "$pid" "$name" || return 0
  kill -TERM "$pid" 2>/dev/null || true
  # Waiting on the pid, not the pid file, so the ports are free once stop returns.
  for ((i = 0; i < 100; i++)); do running "$pid" "$name" || return 0; sleep 0.1; done
  log "$name did not stop on SIGTERM, killing it"
  kill -KILL "$pid" 2>/dev/null || true
}

write_conf() {
  # slurmd -C prints this host's node line as slurmd detects it, so the node never registers as mismatched.
  local hw
  hw=$(slurmd -C | head -n1 | tr ' ' '\n' | grep -E '^(CPUs|Boards|SocketsPerBoard|CoresPerSocket|ThreadsPerCore|RealMemory)=' | tr '\n' ' ')
  cat >"$SLURM_CONF" <<CONF
# Written by farm/slurm/single-node.sh: one node, everything under $state.
ClusterName=recoil-farm
# The loopback address keeps the cluster working where the hostname does not resolve.
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=${FARM_SLURMCTLD_PORT:-6817}
SlurmdPort=${FARM_SLURMD_PORT:-6818}
SlurmUser=root
AuthType=auth/munge
CredType=cred/munge
# A private munged, so a system one (or its key) is neither needed nor touched.
AuthInfo=socket=$socket
StateSaveLocation=$state/ctld
SlurmdSpoolDir=$state/spool
SlurmctldPidFile=$state/run/slurmctld.pid
SlurmdPidFile=$state/run/slurmd.pid
SlurmctldLogFile=$state/log/slurmctld.log
SlurmdLogFile=$state/log/slurmd.log
# Containers often lack usable cgroups: track job processes through /proc and bind nothing.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SwitchType=switch/none
MpiDefault=none
MailProg=/bin/true
# CPUs are the consumable: array tasks share the node one CPU each, the rest wait in the queue.
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
# A node that went down with the daemons comes back by itself on the next start.
ReturnToService=2
NodeName=$host NodeAddr=127.0.0.1 ${hw}State=UNKNOWN
PartitionName=farm Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
}

start() {
  local cmd
  for cmd in munged mungekey munge unmunge slurmctld slurmd sinfo scontrol; do
    command -v "$cmd" >/dev/null || { log "$cmd not found: install with bash scripts/install-deps.sh --farm"; exit 1; }
  done
  mkdir -p "$state"/{munge,ctld,spool,run,log}
  # munged wants its socket folder reachable by every user (jobs run as the submitter) and writable by none.
  chmod 755 "$state/munge"
  [[ -s $state/munge/munge.key ]] || mungekey --create --keyfile="$state/munge/munge.key"
  if ! alive "$state/munge/munged.pid" munged; then
    munged --key-file="$state/munge/munge.key" --socket="$socket" --pid-file="$state/munge/munged.pid" \
      --log-file="$state/munge/munged.log" --seed-file="$state/munge/munged.seed"
  fi
  munge -n -S "$socket" | unmunge -S "$socket" >/dev/null || { log "munged does not answer on $socket"; exit 1; }

  write_conf
  printf 'export SLURM_CONF=%q\n' "$SLURM_CONF" >"$state/env"
  # -i: a state folder left by a killed controller must not stop this one from starting.
  alive "$state/run/slurmctld.pid" slurmctld || { rm -f "$state/run/slurmctld.pid"; slurmctld -i; }
  alive "$state/run/slurmd.pid" slurmd || { rm -f "$state/run/slurmd.pid"; slurmd -N "$host"; }

  local i d node="" why=""
  for ((i = 0; i < 60; i++)); do
    node=$(sinfo -h -N -n "$host" -o %T 2>/dev/null || true)
    [[ $node == idle || $node == mixed || $node == allocated ]] && break
    # A daemon that exits at once (a port in use, a bad config) will not come back, so say so now;
    # one still starting up may not have written its pid file yet.
    for d in slurmctld slurmd; do
      if [[ -s $state/run/$d.pid ]] || ((i >= 5)); then alive "$state/run/$d.pid" $d || why="$d exited"; fi
    done
    [[ -z $why ]] || break
    sleep 1
  done
  if [[ $node != idle && $node != mixed && $node != allocated ]]; then
    log "node $host is '${node:-not reported}', not idle (${why:-after 60 s}); the logs' last lines:"
    tail -n 15 "$state/log/slurmctld.log" "$state/log/slurmd.log" >&2 || true
    exit 1
  fi
  log "node $host is $node (SLURM_CONF=$SLURM_CONF)"
}

stop() {
  # Jobs left running (a test stopped half-way) would outlive slurmd and hold the outputs open.
  if alive "$state/run/slurmctld.pid" slurmctld; then
    local ids i
    ids=$(squeue -h -o %A 2>/dev/null || true)
    if [[ -n $ids ]]; then
      # shellcheck disable=SC2086
      scancel $ids || true
      for ((i = 0; i < 20; i++)); do [[ -z $(squeue -h -o %A 2>/dev/null) ]] && break; sleep 0.5; done
    fi
  fi
  stop_daemon "$state/run/slurmd.pid" slurmd
  stop_daemon "$state/run/slurmctld.pid" slurmctld
  stop_daemon "$state/munge/munged.pid" munged
  log "stopped"
}

case $action in
  start) start ;;
  stop) stop ;;
  *) usage ;;
esac
