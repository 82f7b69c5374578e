#!/usr/bin/env bash
# datasets/download_tum.sh --pieces against a server on 127.0.0.1 that serves archives laid out
# as TUM's, built here from the pieces in $SLAMKIT_DATA and padded with made-up frames where
# the full sequence is not kept (fr2/desk: frames after the first 50 and one unpaired frame
# before them; fr1/desk: every frame but 18-26, named from rgb_full_sequence.txt and
# depth_full_sequence.txt). What --pieces cuts from them must be byte for byte
# $SLAMKIT_DATA's pieces. Also: a second run makes no request, a damaged piece is made again,
# a sequence or trajectory that differs from the tests' copy is refused, bad usage exits 2.
# Needs $SLAMKIT_DATA: without it the test is skipped (exit 77), under CI=true it fails.
#   tests/download/pieces_test.sh [datasets/download_tum.sh]
set -euo pipefail

here="$(cd "$(dirname "$0")" && pwd)"
script="${1:-$here/../../datasets/download_tum.sh}"
python="${SLAMKIT_PYTHON:-/usr/bin/python3}"
data="${SLAMKIT_DATA:-}"
fr2=rgbd_dataset_freiburg2_desk_first50
fr1=rgbd_dataset_freiburg1_desk_9frames
# Where --pieces gets each trajectory: evo's file name for it, or "" when it is not fetched.
declare -A evo_names=(
  [fr2_desk/orbslam.txt]=fr2_desk_ORB.txt
  [fr2_desk/groundtruth.txt]=""
  [fr1_xyz/groundtruth.txt]=freiburg1_xyz-groundtruth.txt
  [fr1_xyz/rgbdslam.txt]=freiburg1_xyz-rgbdslam.txt
  [fr1_xyz/rgbdslam_drift.txt]=freiburg1_xyz-rgbdslam_drift.txt
)

# The real pieces are the reference: without them there is nothing to compare with.
missing=""
needed=("$fr2/rgb.txt" "$fr1/rgb_full_sequence.txt")
for path in "${!evo_names[@]}"; do needed+=("trajectories/$path"); done
for path in "${needed[@]}"; do
  [[ -n "$data" && -f "$data/$path" ]] || { missing="$path"; break; }
done
if [[ -n "$missing" ]]; then
  why="real data '$missing' not found under SLAMKIT_DATA='$data': set SLAMKIT_DATA to the datasets folder"
  if [[ "${CI:-}" == "true" ]]; then
    echo "FAIL $why" >&2
    exit 1
  fi
  echo "SKIP $why"
  exit 77
fi

# shellcheck source=tests/download/loopback_harness.sh
source "$here/loopback_harness.sh"
new_work_dir slamkit_pieces_test

# A made-up frame: a PNG signature and a line naming it (the script never decodes frames).
made_up_png() { printf '\x89PNG\r\n\x1a\nmade-up frame %s\n' "$2" > "$1"; }

# A made-up accelerometer.txt, as TUM's archives carry one beside the lists.
accelerometer() {
  printf "# accelerometer data\n# file: '%s.bag'\n# timestamp ax ay az\n%s 0.1 -9.8 0.2\n" "$1" "$2"
}

# Adds "STAMP KIND/STAMP.png" to SEQ/KIND.txt for each stamp, each with a made-up PNG.
pad() {
  local seq="$1" kind="$2" stamp
  shift 2
  for stamp in "$@"; do
    echo "$stamp $kind/$stamp.png" >> "$seq/$kind.txt"
    made_up_png "$seq/$kind/$stamp.png" "$stamp"
  done
}

# fr2/desk: the 50 pairs, one RGB frame before them that no depth frame is within 0.02 s of
# (so the cut must follow the association, not the list), and 5 made-up pairs after them.
build_fr2() {
  local seq="$1/rgbd_dataset_freiburg2_desk" kind k
  mkdir -p "$seq"
  cp -r "$data/$fr2/rgb" "$data/$fr2/depth" "$data/$fr2/groundtruth.txt" "$seq/"
  chmod -R u+w "$seq"
  for kind in rgb depth; do
    # TUM's own header: the tests' copies carry a note on the "# file:" line.
    grep '^#' "$data/$fr2/$kind.txt" | sed "s/^\(# file: '[^']*'\) .*/\1/" > "$seq/$kind.txt"
  done
  pad "$seq" rgb 1311868164.331101
  grep -v '^#' "$data/$fr2/rgb.txt" >> "$seq/rgb.txt"
  grep -v '^#' "$data/$fr2/depth.txt" >> "$seq/depth.txt"
  for k in 1 2 3 4 5; do
    pad "$seq" rgb "$(awk -v k="$k" 'BEGIN { printf "%.6f", 1311868166.031120 + k * 0.0333 }')"
    pad "$seq" depth "$(awk -v k="$k" 'BEGIN { printf "%.6f", 1311868166.040650 + k * 0.0333 }')"
  done
  accelerometer rgbd_dataset_freiburg2_desk 1311868164.360000 > "$seq/accelerometer.txt"
}

# fr1/desk: the whole sequence's lists; the 9 frames real, every other one made up.
build_fr1() {
  local seq="$1/rgbd_dataset_freiburg1_desk" kind stamp file
  mkdir -p "$seq/rgb" "$seq/depth"
  cp "$data/$fr1/rgb_full_sequence.txt" "$seq/rgb.txt"
  cp "$data/$fr1/depth_full_sequence.txt" "$seq/depth.txt"
  cp "$data/$fr1/groundtruth.txt" "$seq/groundtruth.txt"
  for kind in rgb depth; do
    while read -r stamp file; do
      if [[ -f "$data/$fr1/$file" ]]; then
        cp "$data/$fr1/$file" "$seq/$file"
      else
        made_up_png "$seq/$file" "$stamp"
      fi
    done < <(grep -v '^#' "$seq/$kind.txt")
  done
  chmod -R u+w "$seq"
  accelerometer rgbd_dataset_freiburg1_desk 1305031452.790000 > "$seq/accelerometer.txt"
}

# Packs BUILD/rgbd_dataset_NAME into SERVED/freiburgN/ as TUM names it (gzip -1: the PNGs do
# not compress anyway).
pack() {
  local build="$1" served="$2" name="$3"
  mkdir -p "$served/${name%%_*}"
  tar -C "$build" -cf - "rgbd_dataset_$name" | gzip -1 > "$served/${name%%_*}/rgbd_dataset_$name.tgz"
}

run() {  # run ARGS...: the script's output in $out, its exit code in $code
  code=0
  out=$(TUM_BASE_URL="$url" EVO_BASE_URL="$url/evo" TUM_RETRY_DELAY=0 bash "$script" "$@" 2>&1) ||
    code=$?
}

same_pieces() {  # same_pieces OUT: OUT's pieces and trajectories are byte for byte $SLAMKIT_DATA's
  local dir="$1" path
  diff -r "$dir/$fr2" "$data/$fr2" && diff -r "$dir/$fr1" "$data/$fr1" || return 1
  for path in "${!evo_names[@]}"; do
    cmp "$dir/trajectories/$path" "$data/trajectories/$path" || return 1
  done
}

build="$work/build"
served="$work/served"
mkdir -p "$build" "$served/evo"
build_fr2 "$build"
build_fr1 "$build"
pack "$build" "$served" freiburg2_desk
pack "$build" "$served" freiburg1_desk
for path in "${!evo_names[@]}"; do
  [[ -n "${evo_names[$path]}" ]] && cp "$data/trajectories/$path" "$served/evo/${evo_names[$path]}"
done
start_range_server "$served"

# 1. The pieces cut from the served sequences are the tests' pieces.
out_dir="$work/out"
run --pieces "$out_dir"
echo "$out"
check "--pieces exits 0" test "$code" -eq 0
check "pieces and trajectories byte for byte SLAMKIT_DATA's" same_pieces "$out_dir"
check "both sequences downloaded" grep -q "freiburg1_desk.tgz" "$log"
check "the full sequences removed" test ! -e "$out_dir/.full_sequences"
check "no scratch folder left" test ! -e "$out_dir/.cutting"
check "says which trajectory it does not make" grep -q "not made: trajectories/fr1_xyz/orbslam2_rgbd.txt" <<< "$out"

# 2. A second run checks what is there and makes no request.
requests=$(wc -l < "$log")
run --pieces "$out_dir"
check "second run exits 0" test "$code" -eq 0
check "second run says present" grep -q "$fr2 already present" <<< "$out"
check "second run made no request" test "$(wc -l < "$log")" -eq "$requests"

# 3. A damaged piece (a PNG gone, a list edited) is made again; the whole one is left alone.
# (fr1/desk's: its archive is the small one.)
rm "$out_dir/$fr1/depth/1305031453.374112.png"
echo "1 rgb/1.png" >> "$out_dir/$fr1/rgb.txt"
: > "$log"
run --pieces "$out_dir"
echo "$out"
check "damaged piece: exits 0" test "$code" -eq 0
check "damaged piece noticed" grep -q "$fr1 differs from the tests' copy" <<< "$out"
check "damaged piece: only its sequence fetched" \
  test "$(grep -c '\.tgz' "$log")" -eq 1 -a "$(grep -c freiburg1_desk.tgz "$log")" -eq 1
check "damaged piece made again" same_pieces "$out_dir"

# 4. A sequence whose frames differ from the tests' copy is refused: no piece is left.
bad_dir="$work/bad"
cp -al "$out_dir" "$bad_dir"  # links: the script replaces files, never writes into them
rm -rf "${bad_dir:?}/$fr1"
printf 'X' | dd of="$build/rgbd_dataset_freiburg1_desk/depth/1305031453.404816.png" bs=1 seek=100 \
  conv=notrunc status=none
pack "$build" "$served" freiburg1_desk
run --pieces "$bad_dir"
echo "$out"
check "changed sequence exits 1" test "$code" -eq 1
check "changed sequence reported" grep -q "differs from the tests' copy" <<< "$out"
check "changed sequence names the file" grep -q "depth/1305031453.404816.png: FAILED" <<< "$out"
check "no piece from a changed sequence" test ! -e "$bad_dir/$fr1"

# 5. A trajectory that is not the tests' copy is refused and not left in place.
echo "1 0 0 0 0 0 0 1" >> "$served/evo/fr2_desk_ORB.txt"
rm "$out_dir/trajectories/fr2_desk/orbslam.txt"
run --pieces "$out_dir"
echo "$out"
check "changed trajectory exits 1" test "$code" -eq 1
check "changed trajectory reported" grep -q "fr2_desk_ORB.txt is not the file the tests use" <<< "$out"
check "changed trajectory not in place" test ! -e "$out_dir/trajectories/fr2_desk/orbslam.txt"

# 6. Bad usage: a clear message and exit code 2, before anything is fetched.
run --pieces
check "--pieces without a folder exits 2" test "$code" -eq 2
check "--pieces without a folder says how" grep -q -- "--pieces takes one folder" <<< "$out"
run --pieces "$work/a" "$work/b"
check "--pieces with two folders exits 2" test "$code" -eq 2
check "nothing made on bad usage" test ! -e "$work/a"

echo "$failures failure(s)"
[[ $failures -eq 0 ]]
