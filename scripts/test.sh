#!/usr/bin/env bash
# The whole test suite: installs missing packages, builds what is stale, runs every test
# (GoogleTest via CTest and the FreeCAD tests via freecadcmd, all registered with CTest), then
# the sanitizer job (scripts/sanitize.sh: the C++ tests and the fuzz corpus replays under
# AddressSanitizer and UBSan, in build-asan/). Arguments go to the first ctest and skip the
# sanitizer job (a chosen subset of tests); so does BISECTMESH_SANITIZE=0.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BISECTMESH_BUILD_DIR:-$root/build}
"$root/scripts/deps.sh"
"$root/scripts/build.sh"
cd "$build"
ctest --output-on-failure -j "$(nproc)" "$@"
if [ $# -eq 0 ] && [ "${BISECTMESH_SANITIZE:-1}" != 0 ]; then
  "$root/scripts/sanitize.sh"
fi
