#!/usr/bin/env bash
# Installs the Debian packages physdbg needs, skipping what is already there.
# Usage: bash scripts/setup.sh   (as root, or with sudo available)
set -euo pipefail

packages=(
  build-essential cmake pkg-config ccache
  libeigen3-dev nlohmann-json3-dev libgtest-dev
  libosmesa6-dev libglew-dev libstb-dev libpng-dev libegl-dev libegl-mesa0
  libbullet-dev libccd-dev
  libtbb-dev
  libassimp-dev
  clang libclang-rt-14-dev
  parallel
)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
