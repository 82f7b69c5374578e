#!/usr/bin/env bash
# The main job on the embedded default: sets up (scripts/setup.sh: the packages and the slamkit
# binary alone, not the tests), then runs the whole pipeline on a sequence (tracking with local
# BA, loops, global BA, the fused map.ply) and evaluates it against its groundtruth (ATE, RPE,
# plots; map accuracy on a synthetic sequence).
#   scripts/demo.sh                 # renders the default synthetic sequence and processes it
#   scripts/demo.sh SEQUENCE_DIR    # a TUM sequence folder instead (e.g. from download_tum.sh)
# Output goes to runs/demo/ (override with SLAMKIT_RUN_DIR).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${SLAMKIT_BUILD_DIR:-$root/build}"
run_dir="${SLAMKIT_RUN_DIR:-$root/runs/demo}"
"$root/scripts/setup.sh"
slamkit="$build_dir/bin/slamkit"

sequence="${1:-}"
if [[ -z "$sequence" ]]; then
  sequence="$run_dir/synthetic_desk"
  echo "demo: no sequence given: rendering the synthetic 'desk' sequence into $sequence"
  "$slamkit" synth --preset desk --frames 300 --out "$sequence"
fi
"$slamkit" info "$sequence"
"$slamkit" run "$sequence" --out "$run_dir/run"
echo "demo: trajectory, reports, metrics and plots in $run_dir/run"
echo "demo: map $run_dir/run/map.ply"
echo "demo: open $run_dir/run/report.html in a browser: the run on one page"
