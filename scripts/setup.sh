#!/usr/bin/env bash
# Installs the Debian packages lrchain needs (only those missing), then configures and
# builds in ./build (Release). Run as root on Debian 12. Usage: scripts/setup.sh [build-dir]
# With LRCHAIN_TEST_TOOLS=1 (scripts/test.sh) it also installs what the tests need: chromium
# (headless browser test of the `lrchain reproduce` report), pytest, h5py and matplotlib (Python tests
# and examples).
# The sanitizer build of scripts/test.sh needs nothing more: g++'s AddressSanitizer and UndefinedBehaviorSanitizer runtimes (libasan8,
# libubsan1) come with build-essential (g++-12 -> libgcc-12-dev) and report through their own
# symbolizer.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${1:-build}

PACKAGES=(build-essential cmake pkg-config git
  libginac-dev libcln-dev ginac-tools
  libeigen3-dev libboost-dev
  doctest-dev libbenchmark-dev libcli11-dev nlohmann-json3-dev libtomlplusplus-dev libfmt-dev
  libomp-dev gnuplot-nox fonts-dejavu-core
  libhdf5-dev libopenmpi-dev openmpi-bin
  python3-dev pybind11-dev python3-pybind11 python3-numpy python3-venv python3-setuptools python3-wheel
  python3-xarray python3-scipy python3-tqdm
  libcmark-gfm-dev libcmark-gfm-extensions-dev libssl-dev)
if [[ "${LRCHAIN_TEST_TOOLS:-0}" == 1 ]]; then
  PACKAGES+=(chromium python3-pytest python3-h5py python3-matplotlib python3-build python3-nbclient
    python3-nbformat python3-ipykernel)
fi

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing missing Debian packages: ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update
  apt-get install -y --no-install-recommends "${missing[@]}"
fi

# A unity build of the libraries (LRCHAIN_UNITY_BUILD): a fresh build takes less time; LRCHAIN_UNITY_BUILD=OFF
# for a build directory you edit and rebuild file by file.
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release -DLRCHAIN_UNITY_BUILD="${LRCHAIN_UNITY_BUILD:-ON}"
cmake --build "$BUILD_DIR" -j "$(nproc)"
