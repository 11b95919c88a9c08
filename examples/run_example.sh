#!/usr/bin/env bash
# The main job on the bundled example tows: installs what is missing, builds, and fits a surface
# to every tow of examples/data, writing out/fit/NAME.vtk (open in ParaView) and out/fit.json.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/cmake/ensure_packages.sh"
bash "$root/cmake/build.sh" -DTOWGEOM_BUILD_TESTS=OFF -DTOWGEOM_BUILD_BENCHMARKS=OFF
mkdir -p "$root/out"
"$root/build/towgeom" fit "$root"/examples/data/straight_tube.stw "$root"/examples/data/twill/*.stw \
  --out "$root/out/fit" | tee "$root/out/fit.json"
echo "towgeom: surfaces in out/fit/*.vtk (ParaView), report in out/fit.json" >&2
