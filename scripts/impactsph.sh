#!/usr/bin/env bash
# One entry point for a fresh machine (Debian 12):
#   bash scripts/impactsph.sh          install what is missing, build, run the main job
#   bash scripts/impactsph.sh test     install what is missing, build, run the tests (what CI runs)
#   bash scripts/impactsph.sh build    install what is missing and build only
# BUILD_DIR (default build) and JOBS (default: cores) can be set in the environment.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
JOBS=${JOBS:-$(nproc)}

# Debian packages the build needs; installed only when one is missing. libthrust-dev (Thrust 1.17) is for
# the gpu port's host build on a machine without the CUDA toolkit; with the toolkit, CMake takes the
# toolkit's own Thrust (CCCL) first. libcgal-dev reads surface meshes (STL, OBJ) and tests points against them
# (shape = "mesh"); python3-vtk9 is VTK's own reader, with which the tests read the VTU/PVD output back.
PACKAGES=(cmake g++ make libeigen3-dev libgsl-dev libtomlplusplus-dev libcli11-dev nlohmann-json3-dev
          libgtest-dev libbenchmark-dev gnuplot-nox libthrust-dev libcgal-dev python3-vtk9)

install_missing() {
  local missing=()
  for p in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "installing: ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

build() {
  cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release
  cmake --build "$BUILD_DIR" -j "$JOBS"
}

install_missing
build
case "${1:-run}" in
  run)
    # The main job: plate perforation (paper F scenario 1) at a coarse spacing that runs in seconds.
    "$BUILD_DIR"/impactsph run cases/plate-8mm/case.toml --spacing 2mm --out runs/plate-8mm
    ;;
  test)
    # Everything but the long validation runs and the GPU tests (labels: unit, analytic, crosscheck).
    ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$JOBS" -LE 'validation|cuda'
    ;;
  build) ;;
  *) echo "usage: bash scripts/impactsph.sh [run|test|build]" >&2; exit 2 ;;
esac
