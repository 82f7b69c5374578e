#!/usr/bin/env bash
# Downloads public TUM RGB-D benchmark sequences (Sturm et al., IROS 2012, CC BY 4.0) into a
# folder, in the layout slamkit reads (rgb/ depth/ rgb.txt depth.txt groundtruth.txt).
#   datasets/download_tum.sh DEST freiburg1_desk freiburg2_desk freiburg1_xyz ...
#   datasets/download_tum.sh --list        # every sequence name this script knows
#   datasets/download_tum.sh --pieces DIR  # the real-data pieces the tests read (SLAMKIT_DATA=DIR)
# A broken download resumes where it stopped; the archive (gzip and tar listing) and the
# extracted folder (lists, PNG counts, groundtruth) are checked; a sequence already in place
# and whole is left alone. TUM_BASE_URL replaces the server (the tests use a local one).
# --pieces downloads freiburg2_desk and freiburg1_desk the same way (into DIR/.full_sequences,
# removed once the pieces are made; a few GB while it runs) and cuts from them, byte for byte:
#   rgbd_dataset_freiburg2_desk_first50/  the first 50 RGB/depth pairs of the benchmark's
#                                         association (associate.py, 0.02 s), full groundtruth
#   rgbd_dataset_freiburg1_desk_9frames/  the first 9 pairs (RGB frames 18-26 of 613), full
#                                         groundtruth, the whole lists as rgb_full_sequence.txt
#                                         and depth_full_sequence.txt
# and fills trajectories/: fr2_desk/groundtruth.txt from the sequence, and
# fr1_xyz/groundtruth.txt, fr1_xyz/rgbdslam.txt, fr1_xyz/rgbdslam_drift.txt and
# fr2_desk/orbslam.txt from the test data of the evo project (github.com/MichaelGrupp/evo,
# test/data at a fixed commit; EVO_BASE_URL replaces it). Every file is checked against
# datasets/pieces.sha256, and what is already in DIR and matches is left alone (run again after
# a failure: downloads resume). Not made: trajectories/fr1_xyz/orbslam2_rgbd.txt (no public
# copy is known), so the tests that read it are skipped (and fail under CI=true), nor the data
# folder's README.md.
# Exit codes: 0 done, 1 download or check failed, 2 bad usage or unknown name.
set -euo pipefail

base_url="${TUM_BASE_URL:-https://cvg.cit.tum.de/rgbd/dataset}"
# evo's test data holds byte-identical copies of the estimated trajectories (and fr1/xyz's
# groundtruth) that the evaluator's reference tests use; a fixed commit keeps them unchanged.
evo_commit=9ec1444a9f26a24261e1c126cd4ee2d7877cc395
evo_url="${EVO_BASE_URL:-https://raw.githubusercontent.com/MichaelGrupp/evo/$evo_commit/test/data}"
sums="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/pieces.sha256"
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

usage() {  # the header above, without its comment marks
  awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"
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

# Fetches, checks and extracts sequence NAME into DEST/rgbd_dataset_NAME, unless it is whole there.
get_sequence() {
  local dest="$1" name="$2" folder target problem archive url staging
  folder="rgbd_dataset_${name}"
  target="$dest/$folder"
  if [[ -d "$target" ]]; then
    if problem=$(check_layout "$target"); then
      say "$folder already present (layout checked)"
      return 0
    fi
    say "$folder is incomplete ($problem); fetching it again"
  fi
  command -v curl >/dev/null || fail "needs curl (apt-get install curl)"
  mkdir -p "$dest"
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
}

# --- --pieces -------------------------------------------------------------------------------

# The benchmark's association of RGB_LIST and DEPTH_LIST as associate.py makes it (pairs closer
# than 0.02 s, the closest pair first, each frame used once; ties by RGB then depth time), one
# "rgb_time rgb_file depth_time depth_file" line per pair in RGB time order. Stamps are
# compared as numbers but written as the lists have them, so the lines are the lists' text.
associate() {
  local rgb="$1" depth="$2"
  # Both lists sorted by time, so each RGB stamp scans only the depth stamps near it.
  LC_ALL=C awk '
    FNR == 1 { file++ }
    /^[[:space:]]*(#|$)/ { next }
    file == 1 { n++; t[n] = $1 + 0; stamp[n] = $1; name[n] = $2; next }
    {
      a = $1 + 0
      while (lo < n && t[lo + 1] < a - 0.021) lo++
      for (j = lo + 1; j <= n && t[j] < a + 0.021; j++) {
        d = a - t[j]
        if (d < 0) d = -d
        if (d < 0.02) printf "%.17g %s %s %s %s\n", d, $1, $2, stamp[j], name[j]
      }
    }' <(LC_ALL=C sort -g -k1,1 "$depth") <(LC_ALL=C sort -g -k1,1 "$rgb") |
    LC_ALL=C sort -g -k1,1 -k2,2 -k4,4 |
    awk '!($2 in rgb_used) && !($4 in depth_used) {
           rgb_used[$2]; depth_used[$4]; print $2, $3, $4, $5 }' |
    LC_ALL=C sort -g -k1,1
}

# The comment lines heading LIST; NOTE (if any) is appended to its "# file:" line, as the
# tests' copies of the fr2/desk lists carry a note on where they were cut.
list_header() {
  awk -v note="$2" '/^#/ { if (note != "" && index($0, "# file:") == 1) $0 = $0 " " note; print; next }
                    { exit }' "$1"
}

# Cuts PIECE (a new folder, as an absolute path) from the full sequence FULL: the first N
# associated pairs, their PNGs, rgb.txt and depth.txt headed as FULL's lists (plus RGB_NOTE and
# DEPTH_NOTE), associate.txt and the full groundtruth.txt.
cut_piece() {
  local full="$1" piece="$2" n="$3" rgb_note="$4" depth_note="$5"
  mkdir -p "$piece/rgb" "$piece/depth"
  associate "$full/rgb.txt" "$full/depth.txt" > "$piece/.pairs"
  head -n "$n" "$piece/.pairs" > "$piece/associate.txt"
  rm "$piece/.pairs"
  [[ $(wc -l < "$piece/associate.txt") -eq $n ]] ||
    fail "$full: fewer than $n RGB/depth pairs within 0.02 s"
  # The names become paths: only TUM's own form is let through.
  grep -qvE '^[0-9.]+ rgb/[0-9.]+\.png [0-9.]+ depth/[0-9.]+\.png$' "$piece/associate.txt" &&
    fail "$full: a list names a file outside rgb/ or depth/"
  { list_header "$full/rgb.txt" "$rgb_note"; awk '{ print $1, $2 }' "$piece/associate.txt"; } \
    > "$piece/rgb.txt"
  { list_header "$full/depth.txt" "$depth_note"; awk '{ print $3, $4 }' "$piece/associate.txt"; } \
    > "$piece/depth.txt"
  cp "$full/groundtruth.txt" "$piece/groundtruth.txt"
  # One cp for all the frames (--parents keeps their rgb/ and depth/ paths; PIECE is absolute).
  awk '{ print $2; print $4 }' "$piece/associate.txt" |
    (cd "$full" && xargs cp --parents -t "$piece")
}

# The lines of pieces.sha256 for PATH: the file itself, or every file under the folder.
sums_for() {
  awk -v p="$1" '!/^#/ { f = substr($0, 67); if (f == p || index(f, p "/") == 1) print }' "$sums"
}

# Whether ROOT/PATH is exactly what pieces.sha256 lists for PATH: each file with its checksum,
# no file missing and none more. Prints what differs and returns 1 otherwise.
matches_sums() {
  local root="$1" path="$2" expected found report
  expected=$(sums_for "$path" | wc -l)
  [[ -e "$root/$path" ]] || { echo "$path is missing"; return 1; }
  found=$(cd "$root" && find "$path" -type f | wc -l)
  [[ "$found" -eq "$expected" ]] ||
    { echo "$path holds $found files, the tests' copy $expected"; return 1; }
  report=$(cd "$root" && sums_for "$path" | sha256sum --quiet --strict -c - 2>&1) && return 0
  head -n 5 <<< "$report"  # the files that differ, and sha256sum's count of them
  return 1
}

# Downloads the evo file NAME into DIR/trajectories/PATH and checks it.
fetch_trajectory() {
  local dir="$1" path="$2" name="$3" work="$1/.cutting/trajectories/$2" problem
  mkdir -p "$(dirname "$work")" "$(dirname "$dir/trajectories/$path")"
  # A few hundred kB: a leftover part file is not worth resuming (and a whole one would get an
  # HTTP 416, which fetch recognises only for archives).
  rm -f "$work" "$work.part"
  say "$evo_url/$name"
  fetch "$evo_url/$name" "$work"
  problem=$(matches_sums "$dir/.cutting" "trajectories/$path") ||
    { rm -f "$work"; fail "$evo_url/$name is not the file the tests use: $problem"; }
  mv "$work" "$dir/trajectories/$path"
}

# What --pieces makes, as paths in DIR.
piece_paths=(
  rgbd_dataset_freiburg2_desk_first50 rgbd_dataset_freiburg1_desk_9frames
  trajectories/fr2_desk/groundtruth.txt trajectories/fr2_desk/orbslam.txt
  trajectories/fr1_xyz/groundtruth.txt trajectories/fr1_xyz/rgbdslam.txt
  trajectories/fr1_xyz/rgbdslam_drift.txt
)
# evo's names for the trajectories fetched from it.
declare -A evo_names=(
  [fr2_desk/orbslam.txt]=fr2_desk_ORB.txt
  [fr1_xyz/groundtruth.txt]=freiburg1_xyz-groundtruth.txt
  [fr1_xyz/rgbdslam.txt]=freiburg1_xyz-rgbdslam.txt
  [fr1_xyz/rgbdslam_drift.txt]=freiburg1_xyz-rgbdslam_drift.txt
)

# Cuts PIECE from sequence NAME (downloaded into FULL if needed) into DIR, checked before it is
# moved into place.
make_piece() {
  local dir="$1" full="$2" name="$3" piece="$4" n="$5" rgb_note="${6:-}" depth_note="${7:-}"
  local sequence="$full/rgbd_dataset_$name" problem
  get_sequence "$full" "$name"
  rm -rf "$dir/.cutting/$piece"
  cut_piece "$sequence" "$dir/.cutting/$piece" "$n" "$rgb_note" "$depth_note"
  if [[ "$piece" == rgbd_dataset_freiburg1_desk_9frames ]]; then
    # The whole sequence's lists, for the tests on stream timing and missing frames.
    cp "$sequence/rgb.txt" "$dir/.cutting/$piece/rgb_full_sequence.txt"
    cp "$sequence/depth.txt" "$dir/.cutting/$piece/depth_full_sequence.txt"
  fi
  problem=$(matches_sums "$dir/.cutting" "$piece") ||
    fail "$piece cut from $sequence differs from the tests' copy" \
      "(the server's sequence changed?): $problem"
  rm -rf "${dir:?}/$piece"
  mv "$dir/.cutting/$piece" "$dir/$piece"
  say "$piece ready (checksums match)"
}

make_pieces() {
  local dir full path missing=() problem
  dir=$(realpath -m -- "$1")
  full="$dir/.full_sequences"
  [[ -s "$sums" ]] || fail "$sums is missing: it comes with this script"
  mkdir -p "$dir"
  for path in "${piece_paths[@]}"; do
    if problem=$(matches_sums "$dir" "$path"); then
      say "$path already present (checksums match)"
    else
      [[ -e "$dir/$path" ]] && say "$path differs from the tests' copy ($problem); making it again"
      missing+=("$path")
    fi
  done
  for path in "${missing[@]}"; do
    case "$path" in
      rgbd_dataset_freiburg2_desk_first50)  # its lists' "# file:" lines carry these notes
        make_piece "$dir" "$full" freiburg2_desk "$path" 50 \
          "(first 50 associated frames, from Yang-L1/direct-bundle-adjustment-tensorflow test_data)" \
          "(first 50 associated frames)" ;;
      rgbd_dataset_freiburg1_desk_9frames)
        make_piece "$dir" "$full" freiburg1_desk "$path" 9 ;;
      trajectories/fr2_desk/groundtruth.txt)  # TUM's own, as in the sequence's archive
        get_sequence "$full" freiburg2_desk
        mkdir -p "$dir/.cutting/trajectories/fr2_desk" "$dir/trajectories/fr2_desk"
        cp "$full/rgbd_dataset_freiburg2_desk/groundtruth.txt" "$dir/.cutting/$path"
        problem=$(matches_sums "$dir/.cutting" "$path") ||
          fail "freiburg2_desk's groundtruth.txt is not the tests' copy: $problem"
        mv "$dir/.cutting/$path" "$dir/$path" ;;
      trajectories/*)
        fetch_trajectory "$dir" "${path#trajectories/}" "${evo_names[${path#trajectories/}]}" ;;
    esac
  done
  # Every piece is made and checked: the full sequences and the scratch space go. (On a
  # failure they stay, so that running again resumes rather than downloads anew.)
  rm -rf "$dir/.cutting" "$full"
  say "pieces ready in $dir (SLAMKIT_DATA=$dir)"
  say "not made: trajectories/fr1_xyz/orbslam2_rgbd.txt (no public copy known);" \
    "the tests that read it skip, and fail under CI=true"
}

[[ $# -ge 1 ]] || usage
if [[ "$1" == "--list" || ( $# -ge 2 && "$2" == "--list" ) ]]; then
  printf '%s\n' "${known[@]}"
  exit 0
fi
if [[ "$1" == "--pieces" ]]; then
  if [[ $# -ne 2 || -z "$2" || "$2" == -* ]]; then
    echo "download_tum: error: --pieces takes one folder: datasets/download_tum.sh --pieces DIR" >&2
    exit 2
  fi
  make_pieces "$2"
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
  get_sequence "$dest" "$name"
done
