#!/usr/bin/env bash
# datasets/download_tum.sh against servers on 127.0.0.1 that serve small TUM-layout archives
# built here: a download that breaks off and resumes, a partial file left by an earlier run
# (resumed by a server with byte ranges, started again by plain `python3 -m http.server`), a
# truncated archive, a damaged extracted folder, idempotence and an unknown name.
#   tests/download/download_test.sh [datasets/download_tum.sh]
set -euo pipefail

here="$(cd "$(dirname "$0")" && pwd)"
script="${1:-$here/../../datasets/download_tum.sh}"
python="${SLAMKIT_PYTHON:-/usr/bin/python3}"
# shellcheck source=tests/download/loopback_harness.sh
source "$here/loopback_harness.sh"
new_work_dir slamkit_download_test

# A sequence in the TUM layout: 3 RGB and 3 depth PNGs (with PNG signatures and random bytes,
# so the archive is ~300 kB and does not compress), the lists and a groundtruth.
make_sequence() {
  local dir="$1/rgbd_dataset_$2" i
  mkdir -p "$dir/rgb" "$dir/depth"
  printf '# color images\n# file: test\n# timestamp filename\n' > "$dir/rgb.txt"
  printf '# depth maps\n# file: test\n# timestamp filename\n' > "$dir/depth.txt"
  printf '# ground truth trajectory\n# file: test\n# timestamp tx ty tz qx qy qz qw\n' \
    > "$dir/groundtruth.txt"
  for i in 1 2 3; do
    for kind in rgb depth; do
      { printf '\x89PNG\r\n\x1a\n'; head -c 50000 /dev/urandom; } > "$dir/$kind/100$i.0.png"
      echo "100$i.0 $kind/100$i.0.png" >> "$dir/$kind.txt"
    done
    echo "100$i.0 0.$i 0 0 0 0 0 1" >> "$dir/groundtruth.txt"
  done
  tar -czf "$1/freiburg${2:8:1}/rgbd_dataset_$2.tgz" -C "$1" "rgbd_dataset_$2"
  rm -rf "$dir"
}

run() {  # run DEST NAME...: the script's output in $out, its exit code in $code
  code=0
  out=$(TUM_BASE_URL="$url" TUM_RETRY_DELAY=0 bash "$script" "$@" 2>&1) || code=$?
}

layout_ok() {
  local d="$1"
  [[ -s "$d/groundtruth.txt" && $(ls "$d/rgb" | wc -l) -eq 3 && $(ls "$d/depth" | wc -l) -eq 3 ]]
}

served="$work/served"
mkdir -p "$served/freiburg1" "$served/freiburg2"
make_sequence "$served" freiburg1_xyz
make_sequence "$served" freiburg2_xyz
make_sequence "$served" freiburg1_rpy
archive_size=$(stat -c %s "$served/freiburg1/rgbd_dataset_freiburg1_xyz.tgz")
# A truncated archive on the server: the integrity check must catch it.
head -c $((archive_size / 2)) "$served/freiburg1/rgbd_dataset_freiburg1_xyz.tgz" \
  > "$served/freiburg1/rgbd_dataset_freiburg1_desk.tgz"

# 1. The first transfer breaks off after 100 kB; the script resumes it with a byte range.
start_range_server "$served" 100000
data="$work/data"
run "$data" freiburg1_xyz
echo "$out"
check "broken download exits 0" test "$code" -eq 0
check "broken download resumed" grep -q "resuming at 100000 bytes" <<< "$out"
check "resume asked for the rest" grep -q "rgbd_dataset_freiburg1_xyz.tgz bytes=100000-" "$log"
check "resumed sequence has its layout" layout_ok "$data/rgbd_dataset_freiburg1_xyz"
check "archive removed after extraction" test ! -e "$data/rgbd_dataset_freiburg1_xyz.tgz"

# 2. Idempotent: a whole sequence is checked and left alone, without a request.
requests=$(wc -l < "$log")
run "$data" freiburg1_xyz
check "second run exits 0" test "$code" -eq 0
check "second run says present" grep -q "already present" <<< "$out"
check "second run made no request" test "$(wc -l < "$log")" -eq "$requests"

# 3. A partial file from an interrupted earlier run is resumed (range server, no drop).
start_range_server "$served" 0
head -c 120000 "$served/freiburg2/rgbd_dataset_freiburg2_xyz.tgz" \
  > "$data/rgbd_dataset_freiburg2_xyz.tgz.part"
run "$data" freiburg2_xyz
echo "$out"
check "partial file resumed" grep -q "resuming at 120000 bytes" <<< "$out"
check "partial file: one ranged request" grep -q "freiburg2_xyz.tgz bytes=120000-" "$log"
check "partial file: sequence whole" layout_ok "$data/rgbd_dataset_freiburg2_xyz"

# 4. A truncated archive is refused, removed, and leaves no sequence folder.
run "$data" freiburg1_desk
echo "$out"
check "truncated archive exits 1" test "$code" -eq 1
check "truncated archive reported" grep -q "damaged" <<< "$out"
check "truncated archive removed" test ! -e "$data/rgbd_dataset_freiburg1_desk.tgz"
check "no folder from a truncated archive" test ! -e "$data/rgbd_dataset_freiburg1_desk"

# 5. A damaged extracted folder (a PNG missing) is fetched again.
rm "$data/rgbd_dataset_freiburg2_xyz/depth/1002.0.png"
run "$data" freiburg2_xyz
check "damaged folder noticed" grep -q "incomplete" <<< "$out"
check "damaged folder repaired" layout_ok "$data/rgbd_dataset_freiburg2_xyz"

# 6. Plain `python3 -m http.server` has no byte ranges: a partial file is started again.
"$python" -u -m http.server 0 --bind 127.0.0.1 --directory "$served" > "$work/plain.out" 2>&1 &
servers+=($!)
for _ in $(seq 100); do grep -q "port" "$work/plain.out" 2>/dev/null && break; sleep 0.1; done
url="http://127.0.0.1:$(sed -n 's/.* port \([0-9]*\).*/\1/p' "$work/plain.out" | head -1)"
head -c 50000 "$served/freiburg1/rgbd_dataset_freiburg1_rpy.tgz" \
  > "$data/rgbd_dataset_freiburg1_rpy.tgz.part"
run "$data" freiburg1_rpy
echo "$out"
check "no-range server: started again" grep -q "cannot resume" <<< "$out"
check "no-range server: sequence whole" layout_ok "$data/rgbd_dataset_freiburg1_rpy"

# 7. Names outside the benchmark's list are refused before anything is fetched.
run "$data" freiburg1_dsek
check "unknown name exits 2" test "$code" -eq 2
check "list knows fr3/long_office_household" \
  grep -qx freiburg3_long_office_household <<< "$(bash "$script" --list)"

echo "$failures failure(s)"
[[ $failures -eq 0 ]]
