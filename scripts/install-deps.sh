#!/usr/bin/env bash
# Installs the Debian 12 packages glint builds, tests and benchmarks with.
# Idempotent: packages already present are skipped, and apt-get is only run when something is missing.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config clang-format
  python3  # the layer check (scripts/check_layers.py, run by make test)
  python3-numpy  # make bench-peers (bench/peers.py), the Python module's tests
  pybind11-dev python3-dev python3-pytest  # the Python module glint (python/) and its tests (tests/python)
  libtbb-dev libyaml-dev libcli11-dev libfmt-dev
  libstb-dev libjpeg62-turbo-dev libtinyexr-dev libpng-dev libtinyobjloader-dev libtinygltf-dev libembree-dev
  nlohmann-json3-dev libcpp-httplib-dev
  zlib1g-dev  # deflate and CRC-32 for glint's PNG writer
  libopenmpi-dev openmpi-bin  # mpirun glint render (optional at build time; docs/distributed.md)
  libgtest-dev libgmock-dev libbenchmark-dev
  clang libclang-rt-14-dev llvm  # make fuzz: clang with libFuzzer and the sanitizers' runtimes, llvm-symbolizer
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  sudo="sudo"
fi
echo "install-deps: installing ${missing[*]}" >&2
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
