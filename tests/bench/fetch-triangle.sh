#!/usr/bin/env bash
# Fetches Shewchuk's Triangle (Debian's triangle-bin) for bench_mesh2d, the 2D peer of the planar
# mesher. Triangle is in Debian's non-free section (its licence forbids commercial use), so
# BisectMesh never installs it: this script downloads the package into the build tree with a
# private apt state, without touching the system's apt sources, and extracts the `triangle`
# program to $BUILD/bench/tools/triangle, where bench_mesh2d looks first. No root needed.
#
#   tests/bench/fetch-triangle.sh [BUILD_DIR]   (default: build, or $BISECTMESH_BUILD_DIR)
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD="${1:-${BISECTMESH_BUILD_DIR:-build}}"
TOOLS="$BUILD/bench/tools"
STATE="$(mktemp -d)"
trap 'rm -rf "$STATE"' EXIT
mkdir -p "$TOOLS" "$STATE/lists/partial" "$STATE/cache/archives/partial"
echo "deb http://deb.debian.org/debian bookworm non-free" > "$STATE/sources.list"
APT=(-o Dir::Etc::SourceList="$STATE/sources.list" -o Dir::Etc::SourceParts=/dev/null
     -o Dir::State::Lists="$STATE/lists" -o Dir::Cache="$STATE/cache" -o Debug::NoLocking=1 -o APT::Sandbox::User="$(id -un)")
apt-get "${APT[@]}" update -qq
(cd "$STATE" && apt-get "${APT[@]}" download -qq triangle-bin)
dpkg-deb -x "$STATE"/triangle-bin_*.deb "$STATE/x"
cp "$STATE/x/usr/bin/triangle" "$TOOLS/triangle"
echo "fetch-triangle: $TOOLS/triangle ($(dpkg-deb -f "$STATE"/triangle-bin_*.deb Version))"
