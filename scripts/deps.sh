#!/usr/bin/env bash
# Installs the Debian 12 packages BisectMesh needs, only those that are missing (so a second run
# costs a dpkg query and nothing else). Needs root, or sudo.
set -euo pipefail

PACKAGES=(
  # build
  cmake g++ make pkg-config
  # core library and tests
  libeigen3-dev libgtest-dev googletest libgmp-dev
  # the Python module, built for the interpreter FreeCAD embeds (/usr/bin/python3)
  python3-dev pybind11-dev python3-numpy
  # FreeCAD 0.20 (GUI, console, Python) and the FEM stack it drives
  freecad freecad-python3 python3-matplotlib calculix-ccx
  # OpenCASCADE, for the B-rep front end
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev
  libocct-data-exchange-dev
  # peers the tests and benchmarks compare against
  gmsh tetgen
  # GUI tests in a virtual display
  xvfb xauth
)
# Extra packages a caller needs on top (scripts/fuzz.sh asks for clang 16 this way, so that the
# test command does not install a compiler it never uses).
if [ -n "${BISECTMESH_EXTRA_PACKAGES:-}" ]; then
  read -r -a extra <<< "$BISECTMESH_EXTRA_PACKAGES"
  PACKAGES+=("${extra[@]}")
fi

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO=sudo
  else echo "deps.sh: missing packages (${missing[*]}) and not root; install them or run as root" >&2; exit 1
  fi
fi
echo "deps.sh: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
