#!/usr/bin/env bash
# A real Slurm on this machine only, for the sweep's Slurm backend (ctest slurm_loopback).
# Starts munged, MariaDB with slurmdbd (sacct needs accounting storage), slurmctld and slurmd:
# NodeName localhost, loopback addresses, free ports, CPUs=2, every file under STATE_DIR.
# Then sbatches the tests' tiny sweep (tests/sweep/tiny.yaml: a 40-frame synthetic sequence,
# 2 ORB feature counts x 2 seeds), cancels a running task with scancel, resubmits it with --resubmit-missing,
# collects, and checks that the same sweep run with --backend local gives the same metrics.
# Every daemon it started is stopped by its pid, whatever happens.
#   scripts/slurm_loopback.sh SLAMKIT_BINARY STATE_DIR
# Exit 0 passed, 1 failed, 77 skipped: without root or the packages (scripts/setup.sh
# --with-slurm installs them) it skips saying why, except under CI=true where it fails.
set -euo pipefail
export PATH="$PATH:/usr/sbin:/sbin"

slamkit="${1:?usage: slurm_loopback.sh SLAMKIT_BINARY STATE_DIR}"
state="${2:?usage: slurm_loopback.sh SLAMKIT_BINARY STATE_DIR}"
say() { echo "loopback: $*"; }
fail() { echo "loopback: FAIL: $*" >&2; exit 1; }
skip() {
  if [[ "${CI:-}" == true ]]; then fail "$* (under CI=true this test must run)"; fi
  echo "loopback: SKIP: $*"
  exit 77
}

[[ "$(id -u)" -eq 0 ]] || skip "needs root: the daemons run as root (SlurmUser=root)"
missing=()
for command in munged mungekey mariadb-install-db my_print_defaults mariadbd slurmdbd slurmctld \
  slurmd sacctmgr sbatch squeue sacct scancel sinfo; do
  command -v "$command" >/dev/null || missing+=("$command")
done
((${#missing[@]} == 0)) ||
  skip "missing ${missing[*]}: scripts/setup.sh --with-slurm installs slurm-wlm, slurmdbd," \
    "munge, mariadb-server-core and mariadb-client-core (mariadb-install-db needs its" \
    "my_print_defaults)"

rm -rf "$state"
mkdir -p "$state"/{munge,db,spool,slurmstate,log}
state="$(cd "$state" && pwd)"
# Unix sockets take at most 107 bytes of path.
sockets="$state/munge"
if ((${#state} > 70)); then sockets="$(mktemp -d /tmp/slamkit-slurm.XXXXXX)"; fi

# Stops every daemon this script started, by the pid it wrote, newest first.
pid_files=()
stop_daemons() {
  local code=$? pid_file pid i
  if [[ -n "${SLURM_CONF:-}" ]] && [[ -f "$state/slurmctld.pid" ]]; then
    scancel --user=root 2>/dev/null || true
  fi
  for ((i = ${#pid_files[@]} - 1; i >= 0; i--)); do
    pid_file="${pid_files[i]}"
    [[ -s "$pid_file" ]] || continue
    pid="$(cat "$pid_file")"
    kill "$pid" 2>/dev/null || continue
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.2; done
    kill -0 "$pid" 2>/dev/null && kill -9 "$pid" 2>/dev/null
    say "stopped $(basename "$pid_file" .pid) (pid $pid)"
  done
  [[ "$sockets" == "$state/munge" ]] || rm -rf "$sockets"
  exit "$code"
}
trap stop_daemons EXIT

# wait_for SECONDS WHAT COMMAND...: polls until COMMAND succeeds.
wait_for() {
  local seconds="$1" what="$2"
  shift 2
  for _ in $(seq $((seconds * 5))); do
    if "$@" >/dev/null 2>&1; then return 0; fi
    sleep 0.2
  done
  fail "no $what after $seconds s"
}

read -r ctld_port slurmd_port dbd_port db_port < <(/usr/bin/python3 -c '
import socket
sockets = [socket.socket() for _ in range(4)]
for s in sockets: s.bind(("127.0.0.1", 0))
print(*[s.getsockname()[1] for s in sockets])')

# munge: a fresh key, its own socket.
mungekey --create --keyfile="$state/munge/munge.key"
chmod 600 "$state/munge/munge.key"
pid_files+=("$state/munge/munged.pid")
munged --key-file="$state/munge/munge.key" --socket="$sockets/munge.socket" \
  --pid-file="$state/munge/munged.pid" --log-file="$state/log/munged.log" \
  --seed-file="$state/munge/munged.seed"
say "munged started (pid $(cat "$state/munge/munged.pid"))"

# MariaDB for slurmdbd: loopback TCP only, no grant tables (nothing but this test reaches it).
mariadb-install-db --no-defaults --datadir="$state/db/data" --user=root \
  --auth-root-authentication-method=normal --skip-test-db >"$state/log/mariadb-install.log" 2>&1 ||
  { tail -n 20 "$state/log/mariadb-install.log"; fail "mariadb-install-db"; }
mariadbd --no-defaults --datadir="$state/db/data" --user=root --bind-address=127.0.0.1 \
  --port="$db_port" --socket="$sockets/mysqld.sock" --pid-file="$state/db/mariadbd.pid" \
  --log-error="$state/log/mariadbd.log" --skip-grant-tables --innodb-buffer-pool-size=32M \
  >/dev/null 2>&1 &
pid_files+=("$state/db/mariadbd.pid")
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

cat >"$state/slurm.conf" <<CONF
ClusterName=loopback
SlurmctldHost=localhost(127.0.0.1)
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$sockets/munge.socket
StateSaveLocation=$state/slurmstate
SlurmdSpoolDir=$state/spool
SlurmctldPidFile=$state/slurmctld.pid
SlurmdPidFile=$state/slurmd.pid
SlurmctldLogFile=$state/log/slurmctld.log
SlurmdLogFile=$state/log/slurmd.log
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
ReturnToService=2
KillWait=5
# scontrol forgets a finished job after MinJobAge: an hour, so the scontrol fallback below still
# sees the cancelled task on a slow machine.
MinJobAge=3600
SchedulerType=sched/backfill
NodeName=localhost NodeAddr=127.0.0.1 CPUs=2 RealMemory=4000 State=UNKNOWN
PartitionName=loopback Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$state/slurm.conf"  # slurmdbd reads slurmdbd.conf beside it

pid_files+=("$state/slurmdbd.pid")
slurmdbd
wait_for 30 "slurmdbd" sacctmgr -n list cluster
sacctmgr -i add cluster loopback >/dev/null
say "slurmdbd started (pid $(cat "$state/slurmdbd.pid"), port $dbd_port)"
pid_files+=("$state/slurmctld.pid")
slurmctld -f "$SLURM_CONF"
pid_files+=("$state/slurmd.pid")
slurmd -f "$SLURM_CONF" -N localhost
node_idle() { [[ "$(sinfo -h -n localhost -o %t)" == idle ]]; }
wait_for 60 "idle node" node_idle
say "slurmctld (pid $(cat "$state/slurmctld.pid"), port $ctld_port) and slurmd (pid" \
  "$(cat "$state/slurmd.pid"), port $slurmd_port) up: $(sinfo -h -o '%P %D node(s) %c CPUs %t')"

sweep_file="$(dirname "${BASH_SOURCE[0]}")/../tests/sweep/tiny.yaml"
slurm_dir="$state/sweep-slurm"
local_dir="$state/sweep-local"
slurm_options=(--backend slurm --cpus 1 --mem 1G --time 00:10:00 --max-running 2)

"$slamkit" sweep plan "$sweep_file" --out "$slurm_dir"
submitted="$("$slamkit" sweep run "$slurm_dir" "${slurm_options[@]}")"
echo "$submitted"
job="$(sed -n 's/.*submitted array job \([0-9][0-9]*\).*/\1/p' <<<"$submitted")"
[[ -n "$job" ]] || fail "no array job id in the output of sweep run"
say "array job $job submitted"
grep -q "^#SBATCH --array=0-3%2$" "$slurm_dir/slurm/sweep.sbatch" || fail "the script's --array"

# Task 0 is cancelled while it runs; the others finish.
task_running() { squeue -h -r -j "$job" -o '%K %T' | grep -qx "0 RUNNING"; }
wait_for 120 "running task 0" task_running
scancel "${job}_0"
say "scancel ${job}_0 while it ran"
queue_empty() { [[ -z "$(squeue -h -j "$1")" ]]; }
# slurmctld reports job ends to slurmdbd asynchronously: a loaded machine showed an empty queue
# while sacct still had a task RUNNING. Wait until accounting has every end too.
accounted() { ! sacct -n -P -X -j "$1" -o State | grep -qE "PENDING|RUNNING|COMPLETING"; }
wait_for 300 "end of array job $job" queue_empty "$job"
wait_for 60 "accounting of array job $job" accounted "$job"
sacct_states="$(sacct -n -P -X -j "$job" -o JobID,State,ExitCode)"
say "sacct after the first submission:"
sed 's/^/loopback:   /' <<<"$sacct_states"
grep -q "^${job}_0|CANCELLED" <<<"$sacct_states" || fail "sacct does not show ${job}_0 cancelled"
[[ "$(grep -c "|COMPLETED|" <<<"$sacct_states")" -eq 3 ]] || fail "sacct: 3 tasks COMPLETED"

status="$("$slamkit" sweep status "$slurm_dir")"
echo "$status"
grep -q "3 done, 0 pending, 0 running, 1 failed, 0 missing" <<<"$status" || fail "sweep status"
grep -q "^failed  *0 .*CANCELLED (${job}_0)" <<<"$status" || fail "status of the cancelled task"
# Without accounting storage sacct refuses; status falls back to scontrol show job.
sed 's#^AccountingStorageType=.*#AccountingStorageType=accounting_storage/none#' "$SLURM_CONF" \
  >"$state/slurm-no-accounting.conf"
status="$(SLURM_CONF="$state/slurm-no-accounting.conf" "$slamkit" sweep status "$slurm_dir")"
echo "$status"
grep -q "Slurm states from squeue and scontrol" <<<"$status" || fail "no fallback to scontrol"
grep -q "^failed  *0 .*CANCELLED (${job}_0)" <<<"$status" || fail "scontrol: the cancelled task"
set +e
collected="$("$slamkit" sweep collect "$slurm_dir")"
code=$?
set -e
echo "$collected"
[[ $code -eq 1 ]] || fail "sweep collect with a cancelled task exited $code, not 1"
grep -q "CANCELLED (${job}_0)" "$slurm_dir/report.md" || fail "the report lists the cancelled task"

resubmitted="$("$slamkit" sweep run "$slurm_dir" "${slurm_options[@]}" --resubmit-missing)"
echo "$resubmitted"
job2="$(sed -n 's/.*submitted array job \([0-9][0-9]*\): 1 tasks (--array=0%2).*/\1/p' \
  <<<"$resubmitted")"
[[ -n "$job2" ]] || fail "--resubmit-missing did not submit task 0 alone"
say "task 0 resubmitted as array job $job2"
wait_for 300 "end of array job $job2" queue_empty "$job2"
wait_for 60 "accounting of array job $job2" accounted "$job2"
sacct_states="$(sacct -n -P -X -j "$job,$job2" -o JobID,State,ExitCode)"
say "sacct after the resubmission:"
sed 's/^/loopback:   /' <<<"$sacct_states"
# A one-task array can be accounted under the array's own id ("5", not "5_0"): seen once when
# the task ended before slurmdbd had its task id. `sweep status` below checks the run itself.
grep -qE "^${job2}(_0)?\|COMPLETED" <<<"$sacct_states" || fail "resubmitted task 0 did not complete"
status="$("$slamkit" sweep status "$slurm_dir")"
echo "$status"
grep -q "4 done, 0 pending, 0 running, 0 failed, 0 missing" <<<"$status" || fail "sweep status"
"$slamkit" sweep collect "$slurm_dir"

# The same sweep on this machine: the same numbers, timing aside.
"$slamkit" sweep plan "$sweep_file" --out "$local_dir" >/dev/null
"$slamkit" sweep run "$local_dir" --backend local --jobs 2
"$slamkit" sweep collect "$local_dir" >/dev/null
metrics_without_timing() {
  /usr/bin/python3 -c '
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
keep = [k for k in rows[0] if k not in ("run_seconds", "frames_per_second")]
print(",".join(keep))
for r in rows: print(",".join(r[k] for k in keep))' "$1"
}
if ! diff <(metrics_without_timing "$slurm_dir/runs.csv") \
  <(metrics_without_timing "$local_dir/runs.csv") >"$state/metrics.diff"; then
  cat "$state/metrics.diff"
  fail "the slurm and local backends measured differently"
fi
say "identical metrics from the slurm and local backends (runs.csv, timing aside):"
metrics_without_timing "$slurm_dir/runs.csv" | cut -d, -f1-9 | sed 's/^/loopback:   /'
say "PASS"
