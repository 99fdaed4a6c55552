#!/usr/bin/env bash
# The whole test suite: installs missing packages, builds what is stale, runs every test
# (GoogleTest via CTest and the FreeCAD tests via freecadcmd, all registered with CTest).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BISECTMESH_BUILD_DIR:-$root/build}
"$root/scripts/deps.sh"
"$root/scripts/build.sh"
cd "$build"
ctest --output-on-failure -j "$(nproc)" "$@"
