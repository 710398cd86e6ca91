#!/usr/bin/env bash
# A single-node Slurm cluster (slurm-wlm + munge from Debian) for lacrima's farm test and for
# trying `lacrima farm` on one machine. Needs root (slurmd runs jobs as their owner).
#   tools/slurm/cluster.sh start DIR   write DIR/slurm.conf, start munged (unless one runs),
#                                      slurmctld and slurmd; print `export SLURM_CONF=...`
#   tools/slurm/cluster.sh stop DIR    stop exactly the daemons `start` started (their PIDs in DIR)
# Configuration from ../shared/TOOLCHAIN.md section 4 (Slurm 22.05 on these machines), with every
# path under DIR so nothing in /etc or /var is touched except munge's default socket.
set -euo pipefail

usage() { echo "usage: tools/slurm/cluster.sh start|stop DIR" >&2; exit 2; }
[ $# -eq 2 ] || usage
action="$1"
dir="$(mkdir -p "$2" && cd "$2" && pwd)"
conf="$dir/slurm.conf"
# slurmstepd makes Unix sockets named DIR/spool/d/localhost_<job>.<step> (up to ~40 more
# characters); a socket path has at most 107.
if [ "$action" = start ] && [ ${#dir} -gt 60 ]; then
  echo "cluster.sh: '$dir' is too long for slurmd's socket names (at most 60 characters; e.g. /tmp/lacrima-slurm)" >&2
  exit 2
fi

write_config() {
  local cpus
  cpus="$(nproc)"
  mkdir -p "$dir/spool/ctld" "$dir/spool/d" "$dir/log"
  cat > "$conf" <<CONF
ClusterName=lacrima
SlurmctldHost=localhost
AuthType=auth/munge
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$dir/spool/ctld
SlurmdSpoolDir=$dir/spool/d
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/filetxt
JobCompLoc=$dir/log/jobcomp.log
SchedulerType=sched/backfill
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=1000 State=UNKNOWN
PartitionName=render Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
}

alive() { [ -f "$1" ] && kill -0 "$(cat "$1")" 2>/dev/null; }

wait_for() {  # wait_for SECONDS COMMAND...: poll every 0.2 s
  local tries=$(( $1 * 5 )); shift
  for _ in $(seq "$tries"); do "$@" >/dev/null 2>&1 && return 0; sleep 0.2; done
  return 1
}

start_munge() {
  if munge -n 2>/dev/null | unmunge >/dev/null 2>&1; then return 0; fi  # a munged already serves
  mkdir -p /run/munge /var/log/munge /var/lib/munge
  chown munge:munge /run/munge /var/log/munge /var/lib/munge
  runuser -u munge -- /usr/sbin/munged
  cp /run/munge/munged.pid "$dir/munged.pid"  # ours to stop
  wait_for 10 bash -c 'munge -n | unmunge' || { echo "cluster.sh: munged did not start" >&2; exit 1; }
}

start() {
  for p in slurmctld slurmd; do
    if alive "$dir/$p.pid"; then echo "cluster.sh: $p already runs for $dir" >&2; exit 1; fi
  done
  write_config
  start_munge
  /usr/sbin/slurmctld -f "$conf"
  # -N: the node is called localhost whatever the machine's hostname is.
  /usr/sbin/slurmd -f "$conf" -N localhost
  if ! wait_for 30 bash -c "SLURM_CONF='$conf' sinfo -h -o '%t' | grep -q idle"; then
    echo "cluster.sh: the node did not become idle; logs in $dir/log" >&2; exit 1
  fi
  echo "export SLURM_CONF=$conf"
}

stop() {
  local status=0
  for p in slurmd slurmctld munged; do
    [ -f "$dir/$p.pid" ] || continue
    local pid; pid="$(cat "$dir/$p.pid")"
    if kill -0 "$pid" 2>/dev/null; then
      kill "$pid"
      wait_for 10 bash -c "! kill -0 $pid" || { kill -9 "$pid" 2>/dev/null || true; status=1; }
    fi
    rm -f "$dir/$p.pid"
  done
  return $status
}

case "$action" in
  start) start ;;
  stop) stop ;;
  *) usage ;;
esac
