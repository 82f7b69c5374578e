#!/usr/bin/env bash
# Sets up (scripts/setup.sh) and runs the whole test suite with ctest.
# Real-data tests read SLAMKIT_DATA (a folder with the TUM sequences and trajectories); without
# it they are skipped with a message, except under CI=true where they fail.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${SLAMKIT_BUILD_DIR:-$root/build}"
"$root/scripts/setup.sh"
if [[ -z "${SLAMKIT_DATA:-}" ]]; then
  echo "test: SLAMKIT_DATA is not set: tests on real TUM data will be skipped"
fi
ctest --test-dir "$build_dir" --output-on-failure -j "$(nproc)" "$@"
