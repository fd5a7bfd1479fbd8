#!/usr/bin/env bash
# Installs the Debian packages Blaze needs, if missing. As root it runs apt-get; otherwise it prints
# the exact command and fails. Usage: tools/ensure_deps.sh [run|test]
set -euo pipefail
if [ -n "${BLAZE_SKIP_DEPS:-}" ]; then
  echo "blaze: BLAZE_SKIP_DEPS is set: not checking Debian packages (machines without a package registry)"
  exit 0
fi
pkgs=(g++ make libeigen3-dev libboost-test-dev libgsl-dev gnuplot-nox libgnuplot-iostream-dev
      libboost-iostreams-dev libboost-filesystem-dev libboost-system-dev python3 python3-meshio libgomp1
      libtomlplusplus-dev python3-vtk9 libopenmpi-dev openmpi-bin)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "blaze: missing Debian packages: ${missing[*]}"
if [ "$(id -u)" -ne 0 ]; then
  echo "blaze: not root, so not installing. Run:"
  echo "  sudo apt-get update && sudo apt-get install -y ${missing[*]}"
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}"
