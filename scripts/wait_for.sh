# Sourced by the Slurm scripts (slurm_cluster.sh, slurm_faults.sh), which define fail().
# wait_for SECONDS WHAT COMMAND...: polls COMMAND five times a second until it succeeds; fails
# with "no WHAT after SECONDS s" if it never does.
wait_for() {
  local seconds="$1" what="$2"
  shift 2
  for _ in $(seq $((seconds * 5))); do
    if "$@" >/dev/null 2>&1; then return 0; fi
    sleep 0.2
  done
  fail "no $what after $seconds s"
}
