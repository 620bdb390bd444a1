#!/usr/bin/env bash
# Installs the Debian packages creaturelab needs, only those missing. Idempotent; silent when
# everything is present. Uses sudo when not root.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git lld
  clang libclang-rt-14-dev  # the sanitizer tree (make test-asan)
  libeigen3-dev libceres-dev libhdf5-dev hdf5-tools
  libbenchmark-dev libbenchmark-tools libgtest-dev libgmock-dev
  libcli11-dev libtomlplusplus-dev nlohmann-json3-dev
  libboost-dev  # Boost.Math's Student-t quantile (header-only) for the checks' intervals
  libopenmpi-dev openmpi-bin
  zlib1g-dev
  libtinygltf-dev povray povray-includes
  libmujoco-dev libmujoco-samples
  libssl-dev
  libcairo2-dev libpango1.0-dev fonts-dejavu-core
  python3-h5py python3-numpy python3-matplotlib
  python3-meshio  # an XDMF reader for the cli_xdmf_readers test (ParaView's pvbatch is optional)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

sudo=""
[ "$(id -u)" -ne 0 ] && sudo="sudo"
echo "deps: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -q >&2
$sudo apt-get install -y -q --no-install-recommends "${missing[@]}" >&2
