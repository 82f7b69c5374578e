#!/usr/bin/env bash
# A real multi-node Slurm on this one machine, for the sweep's Slurm tests (scripts/slurm_faults.sh)
# and for trying `slamkit sweep --backend slurm` without a cluster.
#   scripts/slurm_cluster.sh start STATE_DIR [NODES]   munged, MariaDB + slurmdbd (for sacct),
#                                                      slurmctld, and NODES (default 3) compute
#                                                      nodes node1..nodeN, each a slurmd in its
#                                                      own network namespace with its own address
#   scripts/slurm_cluster.sh kill-node STATE_DIR NODE  a node dies: SIGKILL to its slurmd and to
#                                                      every job step and process on it
#   scripts/slurm_cluster.sh start-node STATE_DIR NODE the node's slurmd again (it rejoins)
#   scripts/slurm_cluster.sh stop STATE_DIR            stops every daemon, removes the namespaces
# After start, `source STATE_DIR/env` points Slurm's commands at the cluster (SLURM_CONF).
# Traffic stays on this machine: a bridge with private addresses joins the namespaces to the
# controller, which listens on the bridge only. Every file is under STATE_DIR.
# Exit 0 done, 1 failed, 77 cannot run here: without root, network namespaces or the packages
# (scripts/setup.sh --with-slurm installs them) it says why.
set -euo pipefail
export PATH="$PATH:/usr/sbin:/sbin"

usage="usage: slurm_cluster.sh start|stop|kill-node|start-node STATE_DIR [NODES|NODE]"
action="${1:?$usage}"
state="${2:?$usage}"
say() { echo "cluster: $*"; }
fail() { echo "cluster: FAIL: $*" >&2; exit 1; }
cannot_run() { echo "cluster: cannot run here: $*"; exit 77; }

# The names of this cluster's namespaces and links, from its state folder, so that two
# clusters (two build trees) never share one.
names() {
  local tag
  tag="$(printf '%s' "$state" | cksum | cut -c1-5)"
  bridge="skbr$tag"
  namespace_prefix="slamkit-$tag-"
  veth_prefix="sk$tag"
  subnet="10.$((tag % 200 + 20)).$((tag / 200 % 250)).0"
  subnet_base="${subnet%.0}"
}

source "$(dirname "${BASH_SOURCE[0]}")/wait_for.sh"

stop_pid_file() {
  local pid_file="$1" pid
  [[ -s "$pid_file" ]] || return 0
  pid="$(cat "$pid_file")"
  kill "$pid" 2>/dev/null || { rm -f "$pid_file"; return 0; }
  for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.2; done
  kill -0 "$pid" 2>/dev/null && kill -9 "$pid" 2>/dev/null
  rm -f "$pid_file"
  say "stopped $(basename "$pid_file" .pid) (pid $pid)"
}

# Every process in a node's namespace (its slurmd, slurmstepd and the jobs' processes), SIGKILLed.
kill_namespace() {
  local namespace="$1" pids
  pids="$(ip netns pids "$namespace" 2>/dev/null || true)"
  [[ -z "$pids" ]] || kill -9 $pids 2>/dev/null || true
}

stop_cluster() {
  names
  [[ -f "$state/slurm.conf" ]] && export SLURM_CONF="$state/slurm.conf"
  if [[ -s "$state/slurmctld.pid" ]] && kill -0 "$(cat "$state/slurmctld.pid")" 2>/dev/null; then
    scancel --user=root 2>/dev/null || true
  fi
  local namespace
  for namespace in $(ip netns list 2>/dev/null | awk '{print $1}' | grep "^$namespace_prefix" || true); do
    local pids
    pids="$(ip netns pids "$namespace" 2>/dev/null || true)"
    [[ -z "$pids" ]] || kill $pids 2>/dev/null || true
    sleep 0.5
    kill_namespace "$namespace"
    ip netns delete "$namespace" 2>/dev/null || true
    say "removed $namespace"
  done
  rm -f "$state"/slurmd-*.pid
  stop_pid_file "$state/slurmctld.pid"
  stop_pid_file "$state/slurmdbd.pid"
  stop_pid_file "$state/db/mariadbd.pid"
  stop_pid_file "$state/munge/munged.pid"
  if ip link show "$bridge" >/dev/null 2>&1; then
    ip link delete "$bridge"
    say "removed bridge $bridge"
  fi
  if [[ -f "$state/sockets" ]]; then
    local sockets
    sockets="$(cat "$state/sockets")"
    [[ "$sockets" == "$state/munge" ]] || rm -rf "$sockets"
  fi
}

check_can_run() {
  [[ "$(id -u)" -eq 0 ]] || cannot_run "needs root: the daemons run as root and the nodes are network namespaces"
  local missing=() command
  for command in ip nsenter munged mungekey mariadb-install-db my_print_defaults mariadbd slurmdbd \
    slurmctld slurmd sacctmgr sbatch squeue sacct scancel sinfo scontrol; do
    command -v "$command" >/dev/null || missing+=("$command")
  done
  ((${#missing[@]} == 0)) ||
    cannot_run "missing ${missing[*]}: scripts/setup.sh --with-slurm installs slurm-wlm," \
      "slurmdbd, munge, mariadb-server-core, mariadb-client-core and iproute2"
  ip netns add "${namespace_prefix}probe" 2>/dev/null ||
    cannot_run "cannot create a network namespace (ip netns add needs CAP_SYS_ADMIN and CAP_NET_ADMIN)"
  ip netns delete "${namespace_prefix}probe"
}

# The bridge on this side, one namespace per node with a veth into it.
make_network() {
  local nodes="$1" i namespace
  ip link add "$bridge" type bridge
  ip addr add "$subnet_base.1/24" dev "$bridge"
  ip link set "$bridge" up
  for ((i = 1; i <= nodes; i++)); do
    namespace="${namespace_prefix}node$i"
    ip netns add "$namespace"
    ip link add "${veth_prefix}h$i" type veth peer name "${veth_prefix}n$i"
    ip link set "${veth_prefix}n$i" netns "$namespace"
    ip link set "${veth_prefix}h$i" master "$bridge" up
    ip -n "$namespace" link set lo up
    ip -n "$namespace" addr add "$subnet_base.$((10 + i))/24" dev "${veth_prefix}n$i"
    ip -n "$namespace" link set "${veth_prefix}n$i" up
  done
  say "bridge $bridge $subnet_base.1/24; $nodes node namespaces ${namespace_prefix}node1..$nodes"
}

start_cluster() {
  local nodes="${1:-3}"
  names
  check_can_run
  stop_cluster >/dev/null 2>&1 || true  # what a killed earlier test left
  rm -rf "$state"
  mkdir -p "$state"/{munge,db,spool,slurmstate,log}
  state="$(cd "$state" && pwd)"
  names
  # Unix sockets take at most 107 bytes of path.
  local sockets="$state/munge"
  if ((${#state} > 70)); then sockets="$(mktemp -d /tmp/slamkit-slurm.XXXXXX)"; fi
  echo "$sockets" >"$state/sockets"
  trap 'code=$?; ((code == 0)) || stop_cluster; exit $code' EXIT  # a start cut short stops all
  make_network "$nodes"

  local ctld_port slurmd_port dbd_port db_port
  read -r ctld_port slurmd_port dbd_port db_port < <(/usr/bin/python3 -c '
import socket
sockets = [socket.socket() for _ in range(4)]
for s in sockets: s.bind(("127.0.0.1", 0))
print(*[s.getsockname()[1] for s in sockets])')

  # munge: a fresh key, its own socket (a path: the node namespaces reach it too).
  mungekey --create --keyfile="$state/munge/munge.key"
  chmod 600 "$state/munge/munge.key"
  munged --key-file="$state/munge/munge.key" --socket="$sockets/munge.socket" \
    --pid-file="$state/munge/munged.pid" --log-file="$state/log/munged.log" \
    --seed-file="$state/munge/munged.seed"
  say "munged started (pid $(cat "$state/munge/munged.pid"))"

  # MariaDB for slurmdbd: loopback TCP only, no grant tables (nothing but this cluster reaches it).
  mariadb-install-db --no-defaults --datadir="$state/db/data" --user=root \
    --auth-root-authentication-method=normal --skip-test-db >"$state/log/mariadb-install.log" 2>&1 ||
    { tail -n 20 "$state/log/mariadb-install.log"; fail "mariadb-install-db"; }
  mariadbd --no-defaults --datadir="$state/db/data" --user=root --bind-address=127.0.0.1 \
    --port="$db_port" --socket="$sockets/mysqld.sock" --pid-file="$state/db/mariadbd.pid" \
    --log-error="$state/log/mariadbd.log" --skip-grant-tables --innodb-buffer-pool-size=32M \
    >/dev/null 2>&1 &
  wait_for 60 "MariaDB" grep -q "ready for connections" "$state/log/mariadbd.log"
  say "mariadbd started (pid $(cat "$state/db/mariadbd.pid"), port $db_port)"

  cat >"$state/slurmdbd.conf" <<CONF
AuthType=auth/munge
AuthInfo=socket=$sockets/munge.socket
DbdHost=localhost
DbdAddr=127.0.0.1
DbdPort=$dbd_port
SlurmUser=root
PidFile=$state/slurmdbd.pid
LogFile=$state/log/slurmdbd.log
StorageType=accounting_storage/mysql
StorageHost=127.0.0.1
StoragePort=$db_port
StorageUser=root
StorageLoc=slurm_acct_db
CONF
  chmod 600 "$state/slurmdbd.conf"

  local node_lines="" node_list="node[1-$nodes]" i
  for ((i = 1; i <= nodes; i++)); do
    node_lines+="NodeName=node$i NodeAddr=$subnet_base.$((10 + i)) CPUs=1 RealMemory=4000 State=UNKNOWN"$'\n'
  done
  cat >"$state/slurm.conf" <<CONF
ClusterName=slamkit-test
SlurmctldHost=$(hostname -s)($subnet_base.1)
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
AuthType=auth/munge
CredType=cred/munge
# cred_expire is also how long a requeued job waits before it may start again (default 120 s).
AuthInfo=socket=$sockets/munge.socket,cred_expire=10
StateSaveLocation=$state/slurmstate
SlurmdSpoolDir=$state/spool/%n
SlurmctldPidFile=$state/slurmctld.pid
SlurmdPidFile=$state/slurmd-%n.pid
SlurmctldLogFile=$state/log/slurmctld.log
SlurmdLogFile=$state/log/slurmd-%n.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU_Memory
AccountingStorageType=accounting_storage/slurmdbd
AccountingStorageHost=localhost
AccountingStoragePort=$dbd_port
AccountingStoragePass=$sockets/munge.socket
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
MpiDefault=none
MailProg=/bin/true
# A node that stops answering is DOWN after SlurmdTimeout and its batch jobs are requeued
# (JobRequeue); a node that comes back joins again (ReturnToService=2). Short, for the tests.
SlurmdTimeout=10
JobRequeue=1
ReturnToService=2
KillWait=5
# scontrol forgets a finished job after MinJobAge: an hour, so that sweep status's scontrol
# fallback still sees a cancelled task on a slow machine.
MinJobAge=3600
SchedulerType=sched/backfill
SlurmdParameters=config_overrides
$node_lines
PartitionName=test Nodes=$node_list Default=YES MaxTime=INFINITE State=UP
CONF
  {
    echo "export SLURM_CONF=$state/slurm.conf"
    echo "export PATH=\"\$PATH:/usr/sbin:/sbin\""
  } >"$state/env"
  export SLURM_CONF="$state/slurm.conf"  # slurmdbd reads slurmdbd.conf beside it

  slurmdbd
  wait_for 30 "slurmdbd" sacctmgr -n list cluster
  sacctmgr -i add cluster slamkit-test >/dev/null
  say "slurmdbd started (pid $(cat "$state/slurmdbd.pid"), port $dbd_port)"
  slurmctld -f "$SLURM_CONF"
  wait_for 30 "slurmctld" scontrol ping
  say "slurmctld started (pid $(cat "$state/slurmctld.pid"), $subnet_base.1 port $ctld_port)"
  for ((i = 1; i <= nodes; i++)); do
    start_node "node$i"
  done
  all_idle() { [[ "$(sinfo -h -N -t idle -o %N | sort -u | wc -l)" -eq "$nodes" ]]; }
  wait_for 60 "$nodes idle nodes" all_idle
  say "up: $(sinfo -h -o '%P %D nodes %c CPUs each, %t')"
  trap - EXIT
}

start_node() {
  local node="$1"
  mkdir -p "$state/spool/$node"
  # nsenter, not `ip netns exec`: that mounts a fresh /sys, without the cgroup file system
  # slurmd reads.
  nsenter --net="/run/netns/${namespace_prefix}$node" slurmd -f "$SLURM_CONF" -N "$node"
  wait_for 30 "pid file of slurmd $node" test -s "$state/slurmd-$node.pid"
  say "slurmd $node started (pid $(cat "$state/slurmd-$node.pid"), namespace ${namespace_prefix}$node)"
}

kill_node() {
  local node="${1:?$usage}"
  names
  kill_namespace "${namespace_prefix}$node"
  rm -f "$state/slurmd-$node.pid"
  say "killed $node: SIGKILL to every process in ${namespace_prefix}$node"
}

case "$action" in
  start) start_cluster "${3:-3}" ;;
  stop)
    state="$(cd "$state" 2>/dev/null && pwd || echo "$state")"
    stop_cluster
    ;;
  kill-node)
    state="$(cd "$state" && pwd)"
    kill_node "${3:-}"
    ;;
  start-node)
    state="$(cd "$state" && pwd)"
    names
    export SLURM_CONF="$state/slurm.conf"
    start_node "${3:?$usage}"
    ;;
  *) fail "$usage" ;;
esac
