#!/usr/bin/env bash
# Builds slamkit's unit test suites with AddressSanitizer and UndefinedBehaviorSanitizer
# (scripts/sanitizer_build.sh) and runs every `unit` test under them: any report fails the run.
# scripts/test.sh runs it under CI.
#   scripts/sanitize.sh [CTEST_ARGS...]
# The `e2e` tier (the pipeline over whole sequences, the command line, rendering) stays in the
# plain run: under ASan it would take most of CI's time; the parsers it reaches are fuzzed
# (scripts/fuzz.sh).
# Environment: SLAMKIT_SANITIZE_BUILD_DIR (default: build-sanitize/ in the repository).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${SLAMKIT_SANITIZE_BUILD_DIR:-$root/build-sanitize}"
"$root/scripts/sanitizer_build.sh" unit_tests

# halt_on_error and abort_on_error: the first report fails its test. Leaks are findings too.
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:halt_on_error=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
# OpenCV probes for an OpenCL runtime on first use and dlopens the ICD loader (ocl-icd, which
# OpenCV's packages pull in); that loader's dynamic TLS block sends LeakSanitizer's exit-time
# tracer to a bogus address ("Tracer caught signal 11", CvOrbComparison.Freiburg2...). slamkit
# runs on the CPU only, so the probe is switched off here.
export OPENCV_OPENCL_RUNTIME="${OPENCV_OPENCL_RUNTIME:-disabled}"
ctest --test-dir "$build_dir" --output-on-failure -j "$(nproc)" -L '^unit$' "$@"
