#!/usr/bin/env bash
# Installs the Debian 12 packages slamkit needs (only those missing) and builds it.
# Idempotent and quiet when everything is already in place. Works as root or through sudo.
#   scripts/setup.sh            # install what is missing, configure, build (Release)
#   --test-tools                # also clang 14, libFuzzer and OpenMP for clang, for scripts/fuzz.sh and the
#                               # sanitizer build (scripts/test.sh asks for them under CI)
#   --with-slurm                # also Slurm, slurmdbd, munge and MariaDB's server binary, for
#                               # the loopback Slurm test (scripts/slurm_loopback.sh; asked
#                               # for by scripts/test.sh under CI)
#   --packages-only             # install, do not build
# Environment: SLAMKIT_BUILD_DIR (default: build/ in the repository).
set -euo pipefail

test_tools=false
with_slurm=false
build=true
for arg in "$@"; do
  case "$arg" in
    --test-tools) test_tools=true ;;
    --with-slurm) with_slurm=true ;;
    --packages-only) build=false ;;
    *)
      echo "setup: unknown option '$arg' (--test-tools, --with-slurm, --packages-only)" >&2
      exit 2
      ;;
  esac
done

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${SLAMKIT_BUILD_DIR:-$root/build}"

# Build tools, the libraries of the stack, the test framework, and matplotlib for the plots.
packages=(
  g++ cmake make pkg-config
  libeigen3-dev libopencv-dev libceres-dev libpcl-dev libyaml-cpp-dev libpng-dev zlib1g-dev
  liblodepng-dev libisal-dev
  libcli11-dev nlohmann-json3-dev libgtest-dev
  python3-matplotlib
)
if $test_tools; then
  packages+=(clang-14 libclang-rt-14-dev libfuzzer-14-dev libomp-14-dev)
fi
if $with_slurm; then
  # A whole Slurm on this machine: controller, node daemon, accounting daemon (sacct needs it)
  # with the MariaDB server it stores into, and munge for authentication.
  packages+=(slurm-wlm slurmdbd munge mariadb-server-core mariadb-client-core)
fi

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

if ((${#missing[@]} > 0)); then
  if [[ "$(id -u)" -eq 0 ]]; then
    sudo=()
  elif command -v sudo >/dev/null; then
    sudo=(sudo)
  else
    echo "setup: need root or sudo to install: ${missing[*]}" >&2
    exit 1
  fi
  echo "setup: installing ${#missing[@]} Debian packages: ${missing[*]}"
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" >/dev/null
fi

$build || exit 0
mkdir -p "$build_dir"
log="$build_dir/setup.log"
if ! { cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release &&
       cmake --build "$build_dir" -j "$(nproc)"; } >"$log" 2>&1; then
  tail -n 40 "$log" >&2
  echo "setup: build failed; full log in $log" >&2
  exit 1
fi
if grep -q "warning:" "$log"; then
  grep "warning:" "$log" | sort -u | head -n 20 >&2
fi
echo "setup: built $build_dir/bin/slamkit"
