#!/usr/bin/env bash
# Installs finseg's build and run dependencies from Debian (see README, "Dependencies").
set -euo pipefail
packages=(
  cmake ninja-build g++ clang-format
  libeigen3-dev libsuitesparse-dev libyaml-cpp-dev libcli11-dev libfmt-dev libboost-dev nlohmann-json3-dev zlib1g-dev libssl-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  gnuplot-nox libjs-three libjs-chart.js chromium
  libceres-dev libopenmpi-dev openmpi-bin
  pybind11-dev python3-dev python3-numpy python3-pytest python3-matplotlib
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "finseg setup: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
