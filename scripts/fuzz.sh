#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz, clang with ASan+UBSan, in the tree of
# scripts/sanitizer_build.sh) and runs each for a bounded time. Every crash, hang or
# out-of-memory input found is copied to tests/fuzz_regressions/<target>/, which an ordinary
# ctest test replays on every run; the script then exits 1.
#   scripts/fuzz.sh [SECONDS] [TARGET...]   # SECONDS per target (default 60); all targets
# Seeds: tests/fuzz/seeds/<target>/, the regression suites in results/, and the real files
# under SLAMKIT_DATA (gathered at run time, cut to 4 KB). The corpus grows in
# <build>/corpus/<target>/ from run to run.
# Environment: SLAMKIT_SANITIZE_BUILD_DIR (default: build-sanitize/ in the repository).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${SLAMKIT_SANITIZE_BUILD_DIR:-$root/build-sanitize}"
seconds="${1:-60}"
(($# > 0)) && shift
targets=(tum_list association trajectory kitti euroc trajectory_format settings calibration png suite sweep)  # as tests/fuzz
(($# > 0)) && targets=("$@")

"$root/scripts/sanitizer_build.sh" fuzzers

# Seeds from the real data: lists, associations and trajectories of every sequence there.
gather_seeds() {
  local target="$1" dir="$2" data="${SLAMKIT_DATA:-}"
  mkdir -p "$dir"
  [[ -n "$data" && -d "$data" ]] || return 0
  local -a files=()
  case "$target" in
    tum_list) mapfile -t files < <(find "$data" -name 'rgb*.txt' -o -name 'depth*.txt') ;;
    association) mapfile -t files < <(find "$data" -name 'associat*.txt') ;;
    trajectory) mapfile -t files < <(find "$data" -name '*.txt' ! -name 'rgb*' ! -name 'depth*' \
                                       ! -name 'associat*') ;;
    kitti) mapfile -t files < <(find "$data" -path '*poses*' -name '*.txt' -o -name 'times.txt') ;;
    euroc | trajectory_format) mapfile -t files < <(find "$data" -name 'data.csv' -path '*mav0*') ;;
    png) mapfile -t files < <(find "$data" -name '*.png' | sort | head -n 2) ;;
  esac
  local file
  for file in "${files[@]}"; do
    # Cut: libFuzzer mutates small inputs far faster, and a prefix keeps every line kind.
    head -c 4096 "$file" >"$dir/$(echo "$file" | tr '/' '_')"
  done
  if [[ "$target" == suite ]]; then cp "$root"/results/*.yaml "$dir/"; fi
  if [[ "$target" == sweep ]]; then cp "$root"/tests/sweep/*.yaml "$dir/"; fi
}

# TMPDIR: the targets write each input to a file; memory is faster than disk for that.
scratch_base="${TMPDIR:-/tmp}"
[[ -d /dev/shm && -w /dev/shm ]] && scratch_base=/dev/shm
scratch="$(mktemp -d "$scratch_base/slamkit_fuzz.XXXXXX")"
trap 'rm -rf "$scratch"' EXIT

# One target: fuzz it, move its findings into tests/fuzz_regressions/<target>/, and leave its
# summary line and finding count in the scratch folder.
fuzz_target() {
  local target="$1"
  local corpus="$build_dir/corpus/$target" findings="$build_dir/findings/$target"
  local seeds="$build_dir/seeds/$target" fuzz_log="$build_dir/fuzz-$target.log"
  local temporary="$scratch/$target" status=0 new=0 runs artifact
  mkdir -p "$corpus" "$findings" "$temporary"
  rm -rf "$seeds"
  gather_seeds "$target" "$seeds"
  local -a inputs=("$corpus" "$seeds")
  [[ -d "$root/tests/fuzz/seeds/$target" ]] && inputs+=("$root/tests/fuzz/seeds/$target")
  # -timeout: a single input taking 10 s is a hang; -rss_limit_mb also caps any one allocation.
  TMPDIR="$temporary" "$build_dir/tests/fuzz/${target}_fuzzer" \
    -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=8192 \
    -dict="$root/tests/fuzz/dict/$target.dict" -artifact_prefix="$findings/" \
    -print_final_stats=1 "${inputs[@]}" \
    >"$fuzz_log" 2>&1 || status=$?
  runs="$(sed -n 's/^stat::number_of_executed_units: *//p' "$fuzz_log" | tail -n 1)"
  {
    for artifact in "$findings"/*; do
      [[ -e "$artifact" ]] || continue
      mkdir -p "$root/tests/fuzz_regressions/$target"
      cp "$artifact" "$root/tests/fuzz_regressions/$target/"
      rm "$artifact"
      echo "fuzz: $target: FINDING $(basename "$artifact") -> tests/fuzz_regressions/$target/"
      new=$((new + 1))
    done
    if ((status != 0 && new == 0)); then
      echo "fuzz: $target: the fuzzer failed (exit $status) without a finding; see $fuzz_log"
      new=1
    fi
    echo "fuzz: $target: ${seconds} s, ${runs:-0} executions, $(ls "$corpus" | wc -l) corpus" \
      "inputs, $new finding(s)"
  } >"$scratch/$target.summary"
  echo "$new" >"$scratch/$target.found"
}

# The targets run side by side, one per core: each fuzzer is one process, and CI's time is
# what they add up to.
jobs_at_once="$(nproc)"
for target in "${targets[@]}"; do
  while (($(jobs -rp | wc -l) >= jobs_at_once)); do wait -n || true; done
  fuzz_target "$target" &
done
wait
found=0
for target in "${targets[@]}"; do
  cat "$scratch/$target.summary"
  found=$((found + $(cat "$scratch/$target.found")))
done

if ((found > 0)); then
  echo "fuzz: $found finding(s); see the logs in $build_dir (fuzz-<target>.log)" >&2
  exit 1
fi
echo "fuzz: no findings"
