#!/usr/bin/env bash
# Configures and builds the instrumented tree that scripts/sanitize.sh and scripts/fuzz.sh share:
# clang 14 with ASan + UBSan and libFuzzer's coverage hooks (cmake/sanitizers.cmake), the test
# suites and the fuzz targets, no benchmarks. One tree for both, so that the library is compiled
# once for the sanitizer suites and the fuzzers (CI runs both).
#   scripts/sanitizer_build.sh TARGET...
# Environment: SLAMKIT_SANITIZE_BUILD_DIR (default: build-sanitize/ in the repository).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${SLAMKIT_SANITIZE_BUILD_DIR:-$root/build-sanitize}"

"$root/scripts/setup.sh" --test-tools --packages-only

mkdir -p "$build_dir"
log="$build_dir/build.log"
# No Python module here: an ASan-instrumented module cannot load into an uninstrumented python3.
if ! { CC=clang-14 CXX=clang++-14 cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release \
         -DSLAMKIT_SANITIZE=ON -DSLAMKIT_FUZZ=ON -DSLAMKIT_BUILD_BENCHMARKS=OFF \
         -DSLAMKIT_BUILD_PYTHON=OFF &&
       cmake --build "$build_dir" -j "$(nproc)" --target "$@"; } >"$log" 2>&1; then
  tail -n 40 "$log" >&2
  echo "sanitizer build: failed; full log in $log" >&2
  exit 1
fi
echo "sanitizer build: $* built in $SECONDS s"
