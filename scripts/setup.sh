#!/usr/bin/env bash
# Installs finseg's build and run dependencies from Debian (see README, "Dependencies").
set -euo pipefail
packages=(
  cmake ninja-build g++ clang-format
  libeigen3-dev libsuitesparse-dev libopenblas0-serial libyaml-cpp-dev libcli11-dev libfmt-dev libboost-dev nlohmann-json3-dev zlib1g-dev libssl-dev
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
# CHOLMOD's BLAS is libblas.so.3's alternative: OpenBLAS serial (priority 90) unless the
# alternative was set by hand (README, "Dependencies").
blas=$(update-alternatives --query libblas.so.3-x86_64-linux-gnu 2>/dev/null | sed -n 's/^Value: //p')
case "$blas" in
  */openblas-serial/*) ;;
  *) echo "finseg setup: note: libblas.so.3 is ${blas:-unknown}, not OpenBLAS serial (slower sparse factorizations)" ;;
esac
