#!/usr/bin/env bash
# Installs the Debian 12 packages lvslam builds against, only those missing,
# then the report's pinned JavaScript libraries (npm ci in web/, from its
# package-lock.json). Idempotent and non-interactive; uses sudo when not run
# as root.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  cmake g++ make ccache pkg-config
  libeigen3-dev libopencv-dev libceres-dev
  libnanoflann-dev robin-map-dev libtbb-dev libyaml-cpp-dev
  libspdlog-dev libfmt-dev libcli11-dev nlohmann-json3-dev zlib1g-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  # ROS1 bag reading (optional component LVSLAM_WITH_ROSBAG, on by default)
  librosbag-storage-dev librcpputils-dev librcutils-dev libament-index-cpp-dev
  libsensor-msgs-dev pluginlib-dev libclass-loader-dev
  libroscpp-core-dev libroslz4-dev libbz2-dev libconsole-bridge-dev
  # lvslam_node (optional component LVSLAM_WITH_ROS, on when these are found):
  # roscpp and the message headers it publishes; roscore, rosparam and
  # rosbag play for its tests (tests/ros) and for replaying bags into it
  libroscpp-dev libnav-msgs-dev libvisualization-msgs-dev libdiagnostic-msgs-dev libtf2-msgs-dev
  python3-roslaunch python3-rosparam python3-rosbag
  # HTML reports: the test opens them in headless Chromium
  chromium
)
# Node and npm for the report's libraries, unless a node is already there
# (Debian's npm would not install beside another vendor's nodejs).
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then packages+=(nodejs npm); fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
else
  sudo_cmd=()
  if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
  echo "install-deps: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# The lock file pins every version; npm ci installs exactly those, and only
# when node_modules is older than the lock file.
if [ ! -f web/node_modules/.package-lock.json ] || [ web/package-lock.json -nt web/node_modules/.package-lock.json ]; then
  echo "install-deps: npm ci in web/ (three.js, Chart.js, puppeteer-core)"
  (cd web && npm ci --no-audit --no-fund --loglevel=error)
else
  echo "install-deps: web/node_modules up to date"
fi
