#!/usr/bin/env bash
# Installs the Debian 12 packages the package, its tests and its benchmarks need.
# Run as root (or with sudo available).
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
# libcgal-demo carries CGAL's sample scans and meshes; its recommended Qt
# packages are not needed. clang and libclang-rt-14-dev give libFuzzer;
# cloudcompare, under xvfb-run, checks that the program's output opens.
# pybind11-dev and python3-dev build the Python module; python3-numpy and
# python3-pytest test it, and python3-open3d runs its Open3D example.
# libstb-dev writes the program's --render pictures.
$SUDO apt-get install -y -qq --no-install-recommends \
  ca-certificates cmake make g++ \
  libcgal-dev libeigen3-dev libboost-dev libtbb-dev libgmp-dev libmpfr-dev libcli11-dev libstb-dev \
  catch2 doxygen libcgal-demo gnuplot-nox \
  python3 clang libclang-rt-14-dev bsdutils cloudcompare xvfb xauth \
  pybind11-dev python3-dev python3-numpy python3-pytest python3-open3d >/dev/null
