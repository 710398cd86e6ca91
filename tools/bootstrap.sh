#!/usr/bin/env bash
# One-command set-up for a fresh Debian 12 machine:
#   tools/bootstrap.sh render   install missing packages, build Release, render the default shot
#   tools/bootstrap.sh test     install missing packages, build Release, run the whole test suite
# Environment: BUILD_DIR (default build), JOBS (default: number of cores), FRAMES (render: which frames),
# HARDENING=0 (test: skip the sanitizer and fuzz stage, tools/hardening.sh).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
mode="${1:-}"
case "$mode" in
  render|test|build) ;;
  *) echo "usage: tools/bootstrap.sh render|test|build" >&2; exit 2 ;;
esac

packages=(cmake ninja-build g++ pkg-config
  libembree-dev libtbb-dev libopenimageio-dev openimageio-tools libopenexr-dev libopencolorio-dev
  libtinygltf-dev libeigen3-dev nlohmann-json3-dev libcli11-dev libfmt-dev libtet1.5-dev libopenvdb-dev libboost-dev
  libgtest-dev libgmock-dev libbenchmark-dev)

# The farm test brings up a single-node Slurm cluster (tools/slurm/cluster.sh).
[ "$mode" = test ] && packages+=(slurm-wlm munge)
# The hardening stage (tools/hardening.sh) builds with clang: ASan/UBSan and libFuzzer.
[ "$mode" = test ] && packages+=(clang)

install_missing_packages() {
  local missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "bootstrap: installing ${missing[*]}" >&2
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

build_dir="${BUILD_DIR:-build}"
jobs="${JOBS:-$(nproc)}"

install_missing_packages
cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build_dir" -j "$jobs"

case "$mode" in
  render)
    # FRAMES (optional): which frames, as --frames takes them; --resume continues a stopped run.
    "$build_dir/tools/lacrima" render scenes/shots/tear_closeup.json --preview --resume ${FRAMES:+--frames "$FRAMES"}
    ;;
  test)
    ctest --test-dir "$build_dir" --output-on-failure -j "$jobs"
    # Sanitizers and fuzzing (docs/hardening.md); HARDENING=0 skips them.
    [ "${HARDENING:-1}" = 0 ] || JOBS="$jobs" tools/hardening.sh
    ;;
esac
