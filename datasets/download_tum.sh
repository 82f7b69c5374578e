#!/usr/bin/env bash
# Downloads public TUM RGB-D benchmark sequences (Sturm et al., IROS 2012, CC BY 4.0) into a
# folder, in the layout slamkit reads (rgb/ depth/ rgb.txt depth.txt groundtruth.txt).
#   datasets/download_tum.sh DEST freiburg1_desk freiburg2_desk freiburg1_xyz ...
#   datasets/download_tum.sh DEST --list     # the sequence names this script knows
# Then: export SLAMKIT_DATA=DEST; slamkit track DEST/rgbd_dataset_freiburg1_desk --out runs/fr1_desk
set -euo pipefail

base_url="${TUM_BASE_URL:-https://cvg.cit.tum.de/rgbd/dataset}"
known=(
  freiburg1_xyz freiburg1_rpy freiburg1_desk freiburg1_desk2 freiburg1_room freiburg1_360
  freiburg1_floor freiburg1_plant freiburg1_teddy
  freiburg2_xyz freiburg2_rpy freiburg2_desk freiburg2_large_with_loop freiburg2_pioneer_360
  freiburg3_long_office_household freiburg3_nostructure_texture_far
  freiburg3_structure_notexture_far freiburg3_structure_texture_near
)

if [[ $# -lt 2 ]]; then
  sed -n '2,7p' "$0" | sed 's/^# \{0,1\}//'
  exit 2
fi
dest="$1"
shift
if [[ "$1" == "--list" ]]; then
  printf '%s\n' "${known[@]}"
  exit 0
fi
command -v curl >/dev/null || { echo "download_tum: needs curl (apt-get install curl)" >&2; exit 1; }
mkdir -p "$dest"
for name in "$@"; do
  folder="rgbd_dataset_${name}"
  if [[ -f "$dest/$folder/groundtruth.txt" ]]; then
    echo "download_tum: $folder already present"
    continue
  fi
  camera="${name%%_*}"  # freiburg1, freiburg2, freiburg3
  url="$base_url/$camera/$folder.tgz"
  echo "download_tum: $url"
  curl -fL --retry 3 -o "$dest/$folder.tgz" "$url"
  tar -xzf "$dest/$folder.tgz" -C "$dest"
  rm -f "$dest/$folder.tgz"
done
