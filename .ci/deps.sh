#!/usr/bin/env bash
# Installs the Debian packages vdfx needs to build, test and run, only those missing.
# Uses sudo when not root. Safe to run again.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git
  libeigen3-dev nlohmann-json3-dev libcli11-dev
  libopencv-dev
  libavformat-dev libavcodec-dev libavutil-dev libswscale-dev
  libglfw3-dev libglm-dev libepoxy-dev libstb-dev libhidapi-dev
  libx11-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  fonts-dejavu-core blender-data ffmpeg
  gnuplot-nox python3-jsonschema libimage-exiftool-perl
  glslang-tools emscripten chromium
  xvfb xauth libgl1-mesa-dri mesa-utils xdotool
  libopenxr-dev libopenxr-loader1 openxr-layer-corevalidation libopenxr-utils
  clang-14 libclang-rt-14-dev llvm-14 clang-format-14
  universal-ctags
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "vdfx: installing missing packages: ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
