#!/usr/bin/env bash
# Installs the Debian packages rmfx needs. Idempotent: silent when everything is present.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libtinyxml2-dev libglfw3-dev libglm-dev glslang-dev glslang-tools
  libopenimageio-dev openimageio-tools
  libegl-dev libepoxy-dev libegl-mesa0 libgl1-mesa-dri
  libimgui-dev libassimp-dev
  libspirv-cross-c-shared-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  clang libclang-rt-14-dev
  xvfb xauth
  # The Python module (python/, import rmfx) and its tests; python3-openimageio reads the rmfx
  # command's images back in those tests; python3-distributed (Dask) is for frame ranges to come
  pybind11-dev python3-numpy python3-pytest python3-openimageio python3-distributed
  # For the tests only: the replay report is loaded in a real, headless browser (rmfx does not need it)
  chromium
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "setup: installing ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
