#!/usr/bin/env bash
# Sets up (scripts/setup.sh --all --browser: every test suite and benchmark, and Chromium for the
# report page's browser test) and runs the whole test suite
# with ctest: both tiers, `unit` and `e2e` (docs/usage.md#tests). Extra arguments go to ctest,
# e.g. `scripts/test.sh -L unit`.
# Real-data tests read SLAMKIT_DATA (a folder with the TUM sequences and trajectories); without
# it they are skipped with a message, except under CI=true where they fail. The same goes for the
# Slurm fault test.
# Under CI=true setup also installs the test tools (clang and libFuzzer, Slurm) and builds with
# warnings as errors, and after ctest every unit test runs under ASan+UBSan (scripts/sanitize.sh)
# and a short fuzz pass goes over every parser (scripts/fuzz.sh, SLAMKIT_CI_FUZZ_SECONDS per
# target, default 15).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${SLAMKIT_BUILD_DIR:-$root/build}"
ci=false
[[ "${CI:-}" == "true" ]] && ci=true
# A full disk makes some test fail far from the cause: say so first (docs/usage.md#tests).
df -Pm -- "$root" "${TMPDIR:-/tmp}" | awk 'NR > 1 && !seen[$6]++ && $4 < 4096 {
  printf "test: warning: only %d MB free on %s; a whole test run needs about 4 GB\n", $4, $6 }' || true
if $ci; then
  "$root/scripts/setup.sh" --all --browser --werror --test-tools --with-slurm
else
  "$root/scripts/setup.sh" --all --browser
fi
if [[ -z "${SLAMKIT_DATA:-}" ]]; then
  echo "test: SLAMKIT_DATA is not set: tests on real TUM data will be skipped"
else
  # ctest runs each test in its own folder: a relative path would find no data there.
  export SLAMKIT_DATA="$(realpath -m -- "$SLAMKIT_DATA")"
fi
# Each phase says how long it took, so that a slow CI shows where its time went.
phase() {
  local name="$1" start=$SECONDS
  shift
  "$@"
  echo "test: $name took $((SECONDS - start)) s"
}
phase "ctest" ctest --test-dir "$build_dir" --output-on-failure -j "$(nproc)" "$@"
if $ci; then
  phase "the sanitizer build and its unit tests" "$root/scripts/sanitize.sh"
  phase "the fuzz pass" "$root/scripts/fuzz.sh" "${SLAMKIT_CI_FUZZ_SECONDS:-15}"
fi
echo "test: all passed in $SECONDS s"
