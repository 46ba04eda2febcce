#!/usr/bin/env bash
# Installs the Debian 12 packages lvslam builds against, only those missing.
# Idempotent and non-interactive; uses sudo when not run as root.
set -euo pipefail

packages=(
  cmake g++ make ccache pkg-config
  libeigen3-dev libopencv-dev libceres-dev
  libnanoflann-dev robin-map-dev libtbb-dev libyaml-cpp-dev
  libspdlog-dev libfmt-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  # ROS1 bag reading (optional component LVSLAM_WITH_ROSBAG, on by default)
  librosbag-storage-dev librcpputils-dev librcutils-dev libament-index-cpp-dev
  libsensor-msgs-dev pluginlib-dev libclass-loader-dev
  libroscpp-core-dev libroslz4-dev libbz2-dev libconsole-bridge-dev
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
