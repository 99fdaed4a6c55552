#!/usr/bin/env bash
# The README's screenshots, made again: runs the GUI tests that take them (in a real FreeCAD
# window on a virtual display, through CTest) and copies their pictures into docs/images/.
#
#   scripts/screenshots.sh            # after scripts/build.sh (or the README's first command)
#
#   freecad.gui_fem_route  fem_route.png   -> docs/images/fem-route.png   (the FEM workbench route)
#   freecad.gui_mesh       mesh_panel.png  -> docs/images/mesh-panel.png  (the task panel)
# Environment: BISECTMESH_BUILD_DIR (default: build/).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BISECTMESH_BUILD_DIR:-$root/build}
[ -f "$build/CTestTestfile.cmake" ] || { echo "screenshots.sh: no build in $build (run scripts/build.sh)" >&2; exit 2; }
ctest --test-dir "$build" -R '^freecad\.(gui_fem_route|gui_mesh)$' --output-on-failure
copy() {
  [ -s "$build/test-artifacts/$1" ] || { echo "screenshots.sh: $1 was not made" >&2; exit 1; }
  cp "$build/test-artifacts/$1" "$root/docs/images/$2"
  echo "docs/images/$2"
}
copy fem_route.png fem-route.png
copy mesh_panel.png mesh-panel.png
