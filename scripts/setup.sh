#!/usr/bin/env bash
# Installs the Debian 12 packages slamkit needs (only those missing) and builds it.
# Idempotent and quiet when everything is already in place. Works as root or through sudo.
#   scripts/setup.sh            # install what is missing, configure, build the slamkit binary
#   --all                       # build every target: the test suites and benchmarks too
#   --werror                    # warnings are errors on the project's own code (CI)
#   --test-tools                # also clang 14, libFuzzer and OpenMP for clang, for scripts/fuzz.sh and the
#                               # sanitizer build (scripts/test.sh asks for them under CI)
#   --browser                   # also Chromium, for the browser test of the report page
#                               # (tests/report; asked for by scripts/test.sh)
#   --with-slurm                # also Slurm, slurmdbd, munge, MariaDB's server binary and
#                               # iproute2, for the Slurm test cluster (scripts/slurm_cluster.sh,
#                               # scripts/slurm_faults.sh; asked for by scripts/test.sh under CI)
#   --packages-only             # install, do not build
# Environment: SLAMKIT_BUILD_DIR (default: build/ in the repository).
set -euo pipefail

test_tools=false
browser=false
with_slurm=false
build=true
targets=(--target slamkit)
werror=OFF
for arg in "$@"; do
  case "$arg" in
    --all) targets=() ;;
    --werror) werror=ON ;;
    --test-tools) test_tools=true ;;
    --browser) browser=true ;;
    --with-slurm) with_slurm=true ;;
    --packages-only) build=false ;;
    *)
      echo "setup: unknown option '$arg' (--all, --werror, --test-tools, --browser, --with-slurm," \
        "--packages-only)" >&2
      exit 2
      ;;
  esac
done

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${SLAMKIT_BUILD_DIR:-$root/build}"

# Build tools (dpkg-dev and file for `cpack -G DEB`: dpkg-shlibdeps finds the .deb's
# dependencies), the libraries of the stack, the test frameworks, matplotlib for the plots,
# three.js, which the build inlines into the report page, and pybind11 and numpy for the Python
# module (bin/python).
packages=(
  g++ cmake make pkg-config dpkg-dev file
  libeigen3-dev libopencv-dev libceres-dev libpcl-dev libyaml-cpp-dev libpng-dev zlib1g-dev
  liblodepng-dev libisal-dev
  libcli11-dev nlohmann-json3-dev libgtest-dev python3-pytest
  python3-matplotlib libjs-three pybind11-dev python3-numpy python3-dev
)
if $test_tools; then
  packages+=(clang-14 libclang-rt-14-dev libfuzzer-14-dev libomp-14-dev)
fi
if $browser; then
  packages+=(chromium)
fi
if $with_slurm; then
  # A whole Slurm on this machine: controller, node daemon, accounting daemon (sacct needs it)
  # with the MariaDB server it stores into, munge for authentication, and iproute2 for the
  # test cluster's nodes (network namespaces).
  packages+=(slurm-wlm slurmdbd munge mariadb-server-core mariadb-client-core iproute2)
fi

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

mkdir -p "$build_dir"
started=$SECONDS
elapsed() { printf '%d min %02d s' $(((SECONDS - started) / 60)) $(((SECONDS - started) % 60)); }

# Shows a long step's progress on one line: `count` lines of its log matching `pattern` out of
# `total` (a terminal redraws the line; a log gets a line every 10 %).
show_progress() {
  local label="$1" pattern="$2" total="$3" log="$4" done=0 shown=-10 line percent
  : >"$log"
  while IFS= read -r line; do
    printf '%s\n' "$line" >>"$log"
    [[ "$line" =~ $pattern ]] || continue
    if [[ -n "${BASH_REMATCH[1]:-}" ]]; then percent="${BASH_REMATCH[1]}"; else
      done=$((done + 1)); percent=$((100 * done / total)); fi
    ((percent > 100)) && percent=100
    if [[ -t 1 ]]; then
      printf '\rsetup: %s: %3d %% (%s)' "$label" "$percent" "$(elapsed)"
    elif ((percent >= shown + 10)); then
      shown=$percent
      echo "setup: $label: $percent % ($(elapsed))"
    fi
  done
  [[ -t 1 ]] && echo
  return 0
}

if ((${#missing[@]} > 0)); then
  if [[ "$(id -u)" -eq 0 ]]; then
    sudo=()
  elif command -v sudo >/dev/null; then
    sudo=(sudo)
  else
    echo "setup: need root or sudo to install: ${missing[*]}" >&2
    exit 1
  fi
  apt_log="$build_dir/apt.log"
  echo "setup: installing ${#missing[@]} Debian packages and what they need: ${missing[*]}"
  echo "setup: this takes a few minutes on a fresh machine; log: $apt_log"
  "${sudo[@]}" apt-get update -qq
  # apt's own count of the packages it will fetch, unpack and set up: three steps each.
  total="$(DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -s --no-install-recommends \
             "${missing[@]}" 2>/dev/null | grep -c '^Conf ' || true)"
  if ! DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y --no-install-recommends \
         "${missing[@]}" 2>&1 |
       show_progress "packages" '^Get:|^Unpacking |^Setting up ' "$((total > 0 ? 3 * total : 1))" \
         "$apt_log"; then
    tail -n 20 "$apt_log" >&2
    echo "setup: installing packages failed; full log in $apt_log" >&2
    exit 1
  fi
  echo "setup: packages installed ($(elapsed))"
fi

$build || exit 0
log="$build_dir/setup.log"
what="slamkit"
((${#targets[@]} == 0)) && what="slamkit, tests and benchmarks"
echo "setup: building $what in $build_dir (Release); log: $log"
if ! { cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DSLAMKIT_WERROR="$werror" &&
       cmake --build "$build_dir" -j "$(nproc)" "${targets[@]}"; } 2>&1 |
     show_progress "build" '^\[ *([0-9]+)%\]' 100 "$log"; then
  tail -n 40 "$log" >&2
  echo "setup: build failed; full log in $log" >&2
  exit 1
fi
if grep -q "warning:" "$log"; then
  grep "warning:" "$log" | sort -u | head -n 20 >&2
fi
echo "setup: built $build_dir/bin/slamkit ($(elapsed))"
