#!/usr/bin/env bash
# Downloads public TUM RGB-D benchmark sequences (Sturm et al., IROS 2012, CC BY 4.0) into a
# folder, in the layout slamkit reads (rgb/ depth/ rgb.txt depth.txt groundtruth.txt).
#   datasets/download_tum.sh DEST freiburg1_desk freiburg2_desk freiburg1_xyz ...
#   datasets/download_tum.sh --list        # every sequence name this script knows
# A broken download resumes where it stopped; the archive (gzip and tar listing) and the
# extracted folder (lists, PNG counts, groundtruth) are checked; a sequence already in place
# and whole is left alone. TUM_BASE_URL replaces the server (the tests use a local one).
# Exit codes: 0 done, 1 download or check failed, 2 bad usage or unknown name.
set -euo pipefail

base_url="${TUM_BASE_URL:-https://cvg.cit.tum.de/rgbd/dataset}"
# The benchmark's sequences with public groundtruth, by the site's categories.
known=(
  freiburg1_xyz freiburg1_rpy freiburg2_xyz freiburg2_rpy
  freiburg1_360 freiburg1_floor freiburg1_desk freiburg1_desk2 freiburg1_room
  freiburg2_360_hemisphere freiburg2_360_kidnap freiburg2_desk freiburg2_large_no_loop
  freiburg2_large_with_loop freiburg3_long_office_household
  freiburg2_pioneer_360 freiburg2_pioneer_slam freiburg2_pioneer_slam2 freiburg2_pioneer_slam3
  freiburg3_nostructure_notexture_far freiburg3_nostructure_notexture_near_withloop
  freiburg3_nostructure_texture_far freiburg3_nostructure_texture_near_withloop
  freiburg3_structure_notexture_far freiburg3_structure_notexture_near
  freiburg3_structure_texture_far freiburg3_structure_texture_near
  freiburg2_desk_with_person freiburg3_sitting_static freiburg3_sitting_xyz
  freiburg3_sitting_halfsphere freiburg3_sitting_rpy freiburg3_walking_static
  freiburg3_walking_xyz freiburg3_walking_halfsphere freiburg3_walking_rpy
  freiburg1_plant freiburg1_teddy freiburg2_coke freiburg2_dishes freiburg2_flowerbouquet
  freiburg2_flowerbouquet_brownbackground freiburg2_metallic_sphere freiburg2_metallic_sphere2
  freiburg3_cabinet freiburg3_large_cabinet freiburg3_teddy
)

say() { echo "download_tum: $*"; }
fail() { echo "download_tum: error: $*" >&2; exit 1; }

usage() {
  sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//'
  exit 2
}

# Data lines (not comments, not blank) of a TUM list file.
data_lines() { grep -cv '^[[:space:]]*\(#\|$\)' "$1" || true; }

# Checks an extracted sequence folder; prints what is wrong and returns 1, or returns 0.
check_layout() {
  local dir="$1" list kind listed files
  for list in rgb.txt depth.txt groundtruth.txt; do
    [[ -s "$dir/$list" ]] || { echo "$dir/$list missing or empty"; return 1; }
  done
  for kind in rgb depth; do
    listed=$(data_lines "$dir/$kind.txt")
    files=$(find "$dir/$kind" -maxdepth 1 -name '*.png' 2>/dev/null | wc -l)
    [[ "$listed" -gt 0 && "$listed" -eq "$files" ]] ||
      { echo "$dir/$kind.txt lists $listed images, $kind/ holds $files PNG files"; return 1; }
  done
  # Every groundtruth line: a stamp, a position and a quaternion.
  if grep -v '^[[:space:]]*\(#\|$\)' "$dir/groundtruth.txt" | awk 'NF != 8 { bad = 1 } END { exit !bad }'; then
    echo "$dir/groundtruth.txt has lines without 8 fields"
    return 1
  fi
  [[ $(data_lines "$dir/groundtruth.txt") -gt 0 ]] || { echo "$dir/groundtruth.txt has no poses"; return 1; }
}

# Downloads URL into FILE, resuming FILE.part; up to 5 attempts.
fetch() {
  local url="$1" file="$2" part="$2.part" attempt code
  for attempt in 1 2 3 4 5; do
    if [[ -s "$part" ]]; then
      say "resuming at $(stat -c %s "$part") bytes"
    fi
    code=0
    curl -fL --connect-timeout 30 --speed-limit 1000 --speed-time 60 -sS -C - -o "$part" "$url" ||
      code=$?
    case "$code" in
      0) mv "$part" "$file"; return 0 ;;
      33) say "the server cannot resume; starting again"; rm -f "$part" ;;  # no byte ranges
      22) # HTTP error; a 416 means the part file already holds the whole archive
        if [[ -s "$part" ]] && gzip -t "$part" 2>/dev/null; then mv "$part" "$file"; return 0; fi
        [[ $attempt -ge 2 ]] && fail "$url: the server refused the download" ;;
      *) say "transfer broke off (curl exit code $code); attempt $attempt of 5" ;;
    esac
    sleep "${TUM_RETRY_DELAY:-2}"
  done
  fail "$url: download failed after 5 attempts ($part kept: run again to resume)"
}

# Checks the archive: whole gzip stream, a tar listing under the sequence folder only.
check_archive() {
  local archive="$1" folder="$2"
  gzip -t "$archive" 2>/dev/null || return 1
  tar -tzf "$archive" | awk -v f="$folder" 'index($0, f "/") != 1 && $0 != f { bad = 1 } END { exit bad }'
}

[[ $# -ge 1 ]] || usage
if [[ "$1" == "--list" || ( $# -ge 2 && "$2" == "--list" ) ]]; then
  printf '%s\n' "${known[@]}"
  exit 0
fi
[[ $# -ge 2 ]] || usage
dest="$1"
shift
for name in "$@"; do
  printf '%s\n' "${known[@]}" | grep -qx -- "$name" ||
    { echo "download_tum: error: unknown sequence '$name' (--list shows the names)" >&2; exit 2; }
done

mkdir -p "$dest"
for name in "$@"; do
  folder="rgbd_dataset_${name}"
  target="$dest/$folder"
  if [[ -d "$target" ]]; then
    if problem=$(check_layout "$target"); then
      say "$folder already present (layout checked)"
      continue
    fi
    say "$folder is incomplete ($problem); fetching it again"
  fi
  command -v curl >/dev/null || fail "needs curl (apt-get install curl)"
  archive="$dest/$folder.tgz"
  url="$base_url/${name%%_*}/$folder.tgz"  # freiburg1/, freiburg2/, freiburg3/
  if [[ ! -f "$archive" ]]; then
    say "$url"
    fetch "$url" "$archive"
  fi
  if ! check_archive "$archive" "$folder"; then
    rm -f "$archive"
    fail "$archive is damaged (truncated or not the sequence's archive); removed it: run again to download it anew"
  fi
  # Extracted beside the target and moved in whole, so an interrupted extraction never
  # leaves a folder that looks finished.
  staging="$dest/.extracting_$folder"
  rm -rf "$staging"
  mkdir -p "$staging"
  tar -xzf "$archive" -C "$staging"
  problem=$(check_layout "$staging/$folder") || { rm -rf "$staging"; fail "$archive: $problem"; }
  rm -rf "$target"
  mv "$staging/$folder" "$target"
  rmdir "$staging"
  rm -f "$archive"
  say "$folder ready ($(data_lines "$target/rgb.txt") RGB frames, $(data_lines "$target/groundtruth.txt") groundtruth poses)"
done
