#!/usr/bin/env bash
# Sets up (scripts/setup.sh) and runs the whole test suite with ctest.
# Real-data tests read SLAMKIT_DATA (a folder with the TUM sequences and trajectories); without
# it they are skipped with a message, except under CI=true where they fail. The same goes for the
# loopback Slurm test: under CI=true setup installs Slurm for it (setup.sh --with-slurm).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${SLAMKIT_BUILD_DIR:-$root/build}"
setup_options=()
if [[ "${CI:-}" == true ]]; then setup_options+=(--with-slurm); fi
"$root/scripts/setup.sh" "${setup_options[@]}"
if [[ -z "${SLAMKIT_DATA:-}" ]]; then
  echo "test: SLAMKIT_DATA is not set: tests on real TUM data will be skipped"
fi
ctest --test-dir "$build_dir" --output-on-failure -j "$(nproc)" "$@"
