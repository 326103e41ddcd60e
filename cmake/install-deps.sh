#!/bin/sh
# Installs the Debian 12 packages raylab needs to build and test, if any are missing.
# Run as root on a fresh machine (the README's quick start does). Installs nothing else.
# libembree-dev is for one benchmark (raylab-bench rays): raylab builds and runs without it.
# python3-dev, pybind11-dev and python3-numpy build the Python module (python/); matplotlib,
# nbconvert and ipykernel run the notebooks (notebooks/) in the test suite.
set -eu
PACKAGES="cmake g++ make pkg-config python3-glad
  libglm-dev libopenimageio-dev openimageio-tools libosmesa6-dev libegl-dev libegl-mesa0
  nlohmann-json3-dev libcli11-dev libgtest-dev libmd4c-dev libtinyobjloader-dev libtinygltf-dev
  libglfw3-dev libimgui-dev xvfb fonts-dejavu-core
  clang-16 libclang-rt-16-dev llvm-16
  python3-dev pybind11-dev python3-numpy python3-matplotlib python3-nbconvert python3-ipykernel
  libembree-dev"
missing=""
for p in $PACKAGES; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
  echo "raylab: installing:$missing" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  # shellcheck disable=SC2086
  apt-get install -y -qq --no-install-recommends $missing >/dev/null
fi
