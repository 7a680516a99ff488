#!/usr/bin/env bash
# Set-up of a Debian 12 machine for cairn, then a Release build in build/ (or $CAIRN_BUILD_DIR).
# Idempotent: installs only the Debian packages that are missing, and says nothing when all are there.
set -euo pipefail
cd "$(dirname "$0")/.."

# what the build, the tests and the report need
packages=(
  g++ cmake make pkg-config          # compiler and build
  libeigen3-dev                      # linear algebra
  libtomlplusplus-dev                # scene files
  libcli11-dev                       # command line
  nlohmann-json3-dev                 # run records
  libfccp-dev                        # reading CSV
  catch2                             # tests (v2)
  libbenchmark-dev                   # benchmarks of kernels
  libglpk-dev                        # linear programmes: the block limit analysis
  gnuplot-nox                        # figures of the report
  libbullet-dev libode-dev libmujoco-dev   # reference engines
  libsiconos-mechanics-dev           # the non-smooth contact dynamics engine (Siconos)
  python3-meshio                     # test: VTK files read back by an independent reader
  chromium                           # test: the 3-D replay rendered headless
  clang-14 libclang-rt-14-dev libfuzzer-14-dev   # the clang build and the fuzzer (docs/development.md)
)
# the 3-D replay bundles three.js from the npm registry at build time: node and npm, from Debian
# unless a node with its own npm is already there (Debian's npm conflicts with such a node)
if ! command -v npm >/dev/null 2>&1; then
  packages+=(nodejs npm)
fi
# OpenMP comes with g++ (libgomp); no other package is needed for it.

missing=()
for p in "${packages[@]}"; do
  if [[ "$(dpkg-query -W -f='${db:Status-Abbrev}' "$p" 2>/dev/null)" != ii* ]]; then
    missing+=("$p")
  fi
done

if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  install=(bash -c 'apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "$@"' _ "${missing[@]}")
  if [[ $(id -u) -eq 0 ]]; then
    "${install[@]}" >/dev/null
  elif command -v sudo >/dev/null 2>&1; then
    sudo "${install[@]}" >/dev/null
  else
    echo "setup: these Debian packages are missing and I am neither root nor able to sudo:" >&2
    echo "  ${missing[*]}" >&2
    echo "install them with: apt-get install ${missing[*]}" >&2
    exit 1
  fi
fi

# the build directory: build/ unless CAIRN_BUILD_DIR says otherwise
build="${CAIRN_BUILD_DIR:-build}"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j"$(nproc)" >/dev/null
