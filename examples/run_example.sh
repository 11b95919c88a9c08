#!/usr/bin/env bash
# The main job on the bundled example tows: installs what is missing, builds, fits a surface to
# every tow of examples/data, writing out/fit/NAME.vtk (open in ParaView) and out/fit.json, then
# finds where the twill's tows interpenetrate, writing out/loops.json.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/cmake/ensure_packages.sh"
bash "$root/cmake/build.sh" -DTOWGEOM_BUILD_TESTS=OFF -DTOWGEOM_BUILD_BENCHMARKS=OFF
mkdir -p "$root/out"
"$root/build/towgeom" fit "$root"/examples/data/straight_tube.stw "$root"/examples/data/twill/*.stw \
  --out "$root/out/fit" | tee "$root/out/fit.json"
"$root/build/towgeom" detect "$root"/examples/data/twill/*.stw --quiet > "$root/out/loops.json"
echo "towgeom: surfaces in out/fit/*.vtk (ParaView), report in out/fit.json," \
  "intersection loops in out/loops.json" >&2
