#!/usr/bin/env bash
# Configures (once) and builds BisectMesh in Release into build/ (or $BISECTMESH_BUILD_DIR).
# Rebuilds only what is stale.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BISECTMESH_BUILD_DIR:-$root/build}

# FreeCAD's user Mod folder, asked of FreeCAD itself (it differs between versions and setups).
mod_dir=""
if command -v freecadcmd >/dev/null 2>&1; then
  mod_dir=$(freecadcmd -c "import FreeCAD; print('MODDIR=' + FreeCAD.getUserAppDataDir() + 'Mod')" 2>/dev/null \
            | sed -n 's/^MODDIR=//p' | tail -n 1)
fi

if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DBISECTMESH_MOD_DIR="$mod_dir"
elif [ -n "$mod_dir" ]; then
  cmake "$build" -DBISECTMESH_MOD_DIR="$mod_dir" >/dev/null
fi
cmake --build "$build" -j "$(nproc)"
