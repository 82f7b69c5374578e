#!/usr/bin/env bash
# A sweep on a multi-node Slurm that fails under it (ctest slurm_faults). On the cluster of
# scripts/slurm_cluster.sh (slurmctld, slurmdbd and three nodes, each a slurmd in its own network
# namespace) a sweep of 12 jobs (tests/sweep/faults.yaml) runs while
#   (a) node2 dies (SIGKILL to its slurmd and every process on it) as it runs a task: Slurm
#       requeues the task, `sweep status` says "requeued", the task runs again elsewhere;
#   (b) a running task is cancelled by the user (scancel): `sweep status` says failed (also from
#       scontrol where sacct has no accounting), `sweep collect` refuses to merge and names it;
#   (c) the processes of another running task are SIGKILLed mid-write, leaving a half-written
#       attempt folder;
# then `sweep run --resubmit-missing` runs (b) and (c) again, and (c)'s new attempt removes the
# half-written folder. The sweep must end with every job done exactly once (one "done" line per
# job in the task logs), nothing half-written left, and a merged report equal to that of the same
# plan on the local backend but for times.
#   scripts/slurm_faults.sh SLAMKIT_BINARY STATE_DIR
# Exit 0 passed, 1 failed, 77 skipped: where the cluster cannot run (no root, no network
# namespaces, no packages: scripts/setup.sh --with-slurm) it skips saying why, except under
# CI=true where it fails.
set -euo pipefail
export PATH="$PATH:/usr/sbin:/sbin"

slamkit="${1:?usage: slurm_faults.sh SLAMKIT_BINARY STATE_DIR}"
state="${2:?usage: slurm_faults.sh SLAMKIT_BINARY STATE_DIR}"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
cluster="$here/slurm_cluster.sh"
sweep_file="$here/../tests/sweep/faults.yaml"
say() { echo "faults: $*"; }
fail() { echo "faults: FAIL: $*" >&2; exit 1; }
start=$SECONDS

rm -rf "$state"
mkdir -p "$state"
state="$(cd "$state" && pwd)"
set +e
bash "$cluster" start "$state/cluster" 3
code=$?
set -e
if ((code == 77)); then
  [[ "${CI:-}" == true ]] && fail "the test cluster cannot run here (under CI=true this test must run)"
  echo "faults: SKIP: the test cluster cannot run here"
  exit 77
fi
((code == 0)) || fail "the test cluster did not start"
trap 'bash "$cluster" stop "$state/cluster"' EXIT
source "$state/cluster/env"

source "$(dirname "${BASH_SOURCE[0]}")/wait_for.sh"

# The array job of a sweep's latest submission.
latest_job() { tail -n 1 "$1/slurm/submissions.tsv" | cut -f1; }
queue_empty() { [[ -z "$(squeue -h -j "$1")" ]]; }
# slurmctld reports job ends to slurmdbd asynchronously: wait until accounting has them too.
accounted() {
  local states
  states="$(sacct -n -P -X -j "$1" -o State)"
  ! grep -qE "PENDING|RUNNING|COMPLETING|REQUEUED" <<<"$states"
}
wait_for_end() {
  wait_for 600 "end of array job $1" queue_empty "$1"
  wait_for 60 "accounting of array job $1" accounted "$1"
}
# "INDEX NODE" of a running task of array job $1 (on node $2 if given).
running_task() {
  squeue -h -r -j "$1" -t RUNNING -o '%K %N' | awk -v node="${2:-}" 'node == "" || $2 == node' |
    sort -n | sed -n 1p
}
has_running_task() { [[ -n "$(running_task "$@")" ]]; }
# The run folder of job $1 of the plan in $dir.
run_folder() { awk -F'\t' -v i="$1" '$1 == i {print $5}' "$dir/jobs.tsv"; }
# The attempt folder of a task still alive (the folder is named after its pid) that already
# holds run.json, a run in the middle of writing, and is not one of jobs $2, $3 (already hit).
live_attempt_with_files() {
  local attempt skip_a skip_b
  skip_a="$1/$(run_folder "$2").attempt." skip_b="$1/$(run_folder "$3").attempt."
  for attempt in $(find "$1/runs" -mindepth 3 -maxdepth 3 -type d -name '*.attempt.*'); do
    [[ "$attempt" == "$skip_a"* || "$attempt" == "$skip_b"* ]] && continue
    [[ -f "$attempt/run.json" ]] && kill -0 "${attempt##*.}" 2>/dev/null && echo "$attempt" &&
      return 0
  done
  return 1
}

dir="$state/sweep" dir_local="$state/sweep-local"
"$slamkit" sweep plan "$sweep_file" --out "$dir" >/dev/null
"$slamkit" sweep plan "$sweep_file" --out "$dir_local" >/dev/null
slurm_options=(--backend slurm --cpus 1 --mem 500M --time 00:10:00 --max-running 3)
"$slamkit" sweep run "$dir" "${slurm_options[@]}" | sed 's/^/faults:   /'
grep -q "^#SBATCH --requeue$" "$dir/slurm/sweep.sbatch" || fail "the script does not ask for --requeue"
job="$(latest_job "$dir")"

# The reference: the same plan on this machine, meanwhile.
"$slamkit" sweep run "$dir_local" --backend local --jobs 1 >"$state/sweep-local.log" 2>&1 &
local_pid=$!

# (a) node2 dies while it runs a task.
wait_for 300 "task running on node2" has_running_task "$job" node2
read -r task_a _ < <(running_task "$job" node2)
bash "$cluster" kill-node "$state/cluster" node2 | sed 's/^/faults:   /'
say "(a) node2 killed while it ran task $task_a"

# (b) another running task is cancelled.
other_running_task() { running_task "$job" | awk -v a="$task_a" '$1 != a' | grep -q .; }
wait_for 300 "running task besides $task_a" other_running_task
read -r task_b _ < <(running_task "$job" | awk -v a="$task_a" '$1 != a')
scancel "${job}_${task_b}"
say "(b) scancel ${job}_${task_b}"

# (c) a third task is SIGKILLed mid-write: the task and the `slamkit run` writing there.
wait_for 300 "live attempt folder with files" live_attempt_with_files "$dir" "$task_a" "$task_b"
attempt_c="$(live_attempt_with_files "$dir" "$task_a" "$task_b")"
pid_c="${attempt_c##*.}"
kill -9 "$pid_c" $(pgrep -P "$pid_c") 2>/dev/null || fail "no process $pid_c to kill for $attempt_c"
say "(c) SIGKILL to task process $pid_c and its children, writing $attempt_c"

# (a) Slurm notices the dead node and requeues the task; status says so before it runs again.
# (Outputs are read whole before grep -q: under pipefail a writer cut off by grep fails.)
node_a_failed() {
  local states
  states="$(sacct -n -P -X -D -j "${job}_${task_a}" -o State)"
  grep -q NODE_FAIL <<<"$states"
}
wait_for 120 "NODE_FAIL of ${job}_${task_a} in sacct" node_a_failed
requeued_in_status() {
  local status
  status="$("$slamkit" sweep status "$dir")"
  grep -qE "^requeued +$task_a .*requeued 1 time" <<<"$status"
}
wait_for 30 "requeued task $task_a in sweep status" requeued_in_status
say "(a) sweep status: task $task_a requeued"
bash "$cluster" start-node "$state/cluster" node2 | sed 's/^/faults:   /'
wait_for_end "$job"
say "the first submission ended: $(sacct -n -P -X -D -j "$job" -o State | sort | uniq -c |
  awk '{printf "%s %s; ", $1, $2}')"

# (b) and (c): failed, not merged, resubmitted.
status="$("$slamkit" sweep status "$dir")"
echo "$status" | sed 's/^/faults:   /'
grep -qE "^failed +$task_b .*CANCELLED \(${job}_${task_b}\)" <<<"$status" ||
  fail "status of the cancelled task"
grep -qE "^failed .*FAILED" <<<"$status" || fail "status of the killed task"
sed 's#^AccountingStorageType=.*#AccountingStorageType=accounting_storage/none#' "$SLURM_CONF" \
  >"$state/slurm-no-accounting.conf"
status="$(SLURM_CONF="$state/slurm-no-accounting.conf" "$slamkit" sweep status "$dir")"
grep -q "Slurm states from squeue and scontrol" <<<"$status" || fail "no fallback to scontrol"
grep -qE "^failed +$task_b .*CANCELLED" <<<"$status" || fail "scontrol: the cancelled task"
set +e
collected="$("$slamkit" sweep collect "$dir")"
code=$?
set -e
[[ $code -eq 1 ]] || fail "sweep collect of an incomplete sweep exited $code, not 1"
grep -q "nothing merged" <<<"$collected" && grep -qE "^failed +$task_b " <<<"$collected" ||
  { echo "$collected"; fail "collect does not name the missing job"; }
[[ ! -e "$dir/report.md" ]] || fail "collect merged an incomplete sweep"
[[ -d "$attempt_c" ]] || fail "the killed attempt left no folder: the test did not kill mid-run"
"$slamkit" sweep run "$dir" "${slurm_options[@]}" --resubmit-missing | sed 's/^/faults:   /'
job2="$(latest_job "$dir")"
wait_for_end "$job2"
[[ ! -e "$attempt_c" ]] || fail "the half-written attempt $attempt_c is still there"

wait "$local_pid" || { cat "$state/sweep-local.log"; fail "the local sweep failed"; }
"$slamkit" sweep collect "$dir_local" >/dev/null

# Everything is in the report, each job once, nothing half-written.
without_times() {
  /usr/bin/python3 - "$1" <<'PY'
import csv, re, sys
folder = sys.argv[1]
rows = list(csv.DictReader(open(folder + "/runs.csv")))
keep = [k for k in rows[0] if k not in ("run_seconds", "frames_per_second")]
print(",".join(keep))
for r in rows:
    print(",".join(r[k] for k in keep))
for line in open(folder + "/report.md"):
    if line.startswith("Sweep "):  # slamkit's version, the machine and the time of the merge
        continue
    print(re.sub(r"\| [0-9.]+ s \| [0-9.]+ frames/s \|$", "| T |", line.rstrip("\n")))
print(open(folder + "/ate_table.csv").read())
PY
}
status="$("$slamkit" sweep status "$dir")"
grep -q ": 12 jobs: 12 done, 0 pending, 0 running, 0 requeued, 0 failed, 0 missing" <<<"$status" ||
  { echo "$status"; fail "not every job done"; }
"$slamkit" sweep collect "$dir" >"$state/collect.log" || fail "collect failed"
without_times "$dir_local" >"$state/local.txt"
without_times "$dir" >"$state/slurm.txt"
diff "$state/local.txt" "$state/slurm.txt" >"$state/report.diff" ||
  { cat "$state/report.diff"; fail "the merged report differs from the local backend's"; }
done_lines="$(cat "$dir"/slurm/logs/*.log | grep "^done ")"
[[ "$(wc -l <<<"$done_lines")" -eq 12 && -z "$(awk '{print $2}' <<<"$done_lines" | sort | uniq -d)" ]] ||
  { echo "$done_lines"; fail "not each of the 12 runs published once"; }
leftovers="$(find "$dir" \( -name '*.attempt.*' -o -name '*.failed' -o -name '*.removing.*' \
  -o -name '*.tmp' -o -name '*.tmp.*' \) -print)"
[[ -z "$leftovers" ]] || fail "left behind: $leftovers"
say "12 of 12 jobs done once each, nothing half-written, report equal to the local backend's"
say "sacct of every attempt:"
sacct -n -P -X -D -j "$job,$job2" -o JobID,State,NodeList | sed 's/^/faults:   /'
say "PASS in $((SECONDS - start)) s"
