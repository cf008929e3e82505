#!/usr/bin/env bash
# Installs every dependency geomesh needs from Debian's packages (when one is missing), then
# configures and builds geomesh into build/. Safe to run again: it only does what is missing.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${GEOMESH_BUILD_DIR:-$root/build}

packages=(
  build-essential cmake ninja-build ccache pkg-config
  re2c bison
  libcgal-dev libgmp-dev libmpfr-dev
  libtet1.5-dev
  liblemon-dev
  libmetis-dev libcgns-dev libeigen3-dev
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev
  libocct-visualization-dev libocct-data-exchange-dev
  libgtest-dev
  clang libclang-rt-14-dev
  pybind11-dev python3-dev python3-numpy python3-pytest python3-venv python3-pil
  libpng-dev
  chromium
)
# The viewer's page is bundled from the npm registry at build time: Node.js and npm from Debian
# unless the machine already has them.
command -v node >/dev/null 2>&1 || packages+=(nodejs)
command -v npm >/dev/null 2>&1 || packages+=(npm)

missing_packages() {
  local p
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || echo "$p"
  done
}

install_packages() {
  local missing
  missing=$(missing_packages)
  [ -z "$missing" ] && return 0
  echo "setup: installing Debian packages:" $missing
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  # shellcheck disable=SC2086
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends $missing
}

configure_and_build() {
  if [ ! -f "$build/build.ninja" ]; then
    cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DGEOMESH_WERROR=ON \
      ${GEOMESH_CMAKE_ARGS:-}
  fi
  cmake --build "$build"
}

install_packages
configure_and_build
