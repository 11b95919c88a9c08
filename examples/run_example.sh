#!/usr/bin/env bash
# The main job on the bundled example tows: installs what is missing, builds, fits a surface to
# every tow of examples/data (out/fit/NAME.vtk, out/fit.json), then resolves the twill: finds
# where its tows interpenetrate and writes compatible meshes that share a surface there
# (out/resolved/: NAME.vtk for ParaView, NAME.stl, textile.msh, textile.inp, report.json).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/cmake/ensure_packages.sh"
bash "$root/cmake/build.sh" -DTOWGEOM_BUILD_TESTS=OFF -DTOWGEOM_BUILD_BENCHMARKS=OFF
mkdir -p "$root/out"
"$root/build/towgeom" fit "$root"/examples/data/straight_tube.stw "$root"/examples/data/twill/*.stw \
  --out "$root/out/fit" | tee "$root/out/fit.json"
"$root/build/towgeom" resolve "$root"/examples/data/twill/*.stw --out "$root/out/resolved" \
  --formats stl,vtk,msh,inp
echo "towgeom: fitted surfaces in out/fit/*.vtk and out/fit.json; compatible meshes in" \
  "out/resolved/*.vtk (ParaView: colour by region_id), model files out/resolved/textile.msh" \
  "and textile.inp, report out/resolved/report.json" >&2
