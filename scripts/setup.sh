#!/usr/bin/env bash
# One command for a fresh Debian 12 machine: installs the missing packages, builds in Release,
# installs the FreeCAD workbench into FreeCAD's user Mod folder and bisect-mesh into
# ~/.local/bin (or $PREFIX/bin), then runs bisect-mesh on the bundled examples.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BISECTMESH_BUILD_DIR:-$root/build}
prefix=${PREFIX:-$HOME/.local}

"$root/scripts/deps.sh"
"$root/scripts/build.sh"
cmake --install "$build" --prefix "$prefix"

mod_dir=$(sed -n 's/^BISECTMESH_MOD_DIR:PATH=//p' "$build/CMakeCache.txt")
echo
echo "Installed: $prefix/bin/bisect-mesh and the FreeCAD workbench in $mod_dir/BisectMesh"
# Checks that a plain FreeCAD console session finds the installed workbench.
freecadcmd -c "import bisectmesh, os; print('FreeCAD imports bisectmesh from ' + os.path.dirname(bisectmesh.__file__))" \
  2>/dev/null | grep "FreeCAD imports"
echo
echo "\$ bisect-mesh info examples/cube-cavity-adjacent-cube.poly"
"$prefix/bin/bisect-mesh" info "$root/examples/cube-cavity-adjacent-cube.poly"
echo
echo "\$ bisect-mesh quality examples/box-minus-cylinder.msh"
"$prefix/bin/bisect-mesh" quality "$root/examples/box-minus-cylinder.msh"
echo
# The main job: the thesis's cube with a cavity beside a second cube, meshed into tetrahedra.
out=$(mktemp -d)
echo "\$ bisect-mesh examples/cube-cavity-adjacent-cube.poly -n 10000 -o cube.vtu --stats cube.json"
"$prefix/bin/bisect-mesh" "$root/examples/cube-cavity-adjacent-cube.poly" -n 10000 -o "$out/cube.vtu" --stats "$out/cube.json" 2>&1 | sed "s|$out/||"
cat "$out/cube.json"; echo
rm -rf "$out"
echo
# The FreeCAD user's job: a CSG solid (a box minus a cylinder) meshed in-process by the workbench.
echo "\$ freecadcmd: bisectmesh.mesh_shape(box minus cylinder, elements=5000, order=2)"
freecadcmd -c "import Part, FreeCAD, bisectmesh
s = Part.makeBox(20, 10, 10).cut(Part.makeCylinder(3, 10, FreeCAD.Vector(10, 0, 5), FreeCAD.Vector(0, 1, 0)))
r = {}
m = bisectmesh.mesh_shape(s, elements=5000, order=2, report=r)
print('A FreeCAD solid meshed in-process: %d tetra10, %d nodes, smallest dihedral %.1f deg, %.2f s' % (m.VolumeCount, m.NodeCount, r['stats']['quality']['dihedral_min'], r['stats']['times']['total']))" \
  2>/dev/null | grep "in-process"
