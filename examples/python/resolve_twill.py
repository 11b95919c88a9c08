#!/usr/bin/env python3
"""The README's main job from Python: fit the bundled twill's tows, find every interpenetration,
resolve it into compatible meshes and write them (Gmsh .msh, Abaqus .inp, meshio's .vtu).

    PYTHONPATH=build/python python3 examples/python/resolve_twill.py [OUT_DIR]
"""
import pathlib
import sys

import towgeom

twill = pathlib.Path(__file__).resolve().parents[1] / "data" / "twill"
out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "twill_out")
out.mkdir(parents=True, exist_ok=True)

tows = [towgeom.TowSurface.fit(towgeom.read_stack(str(path))) for path in sorted(twill.glob("*.stw"))]
report = towgeom.intersect_tows(tows)
result = towgeom.resolve_textile(tows, report, edge_length=0.1, progress=lambda stage, done, total: print(f"  {stage} {done}/{total}"))
result.mesh.write_gmsh(str(out / "textile.msh"))
result.mesh.write_abaqus(str(out / "textile.inp"))
result.mesh.to_meshio().write(str(out / "textile.vtu"))
print(f"{len(report.loops)} loops, {len(result.mesh.regions)} shared regions, {len(result.mesh.nodes)} nodes, "
      f"{len(result.unresolved)} pairs unresolved, {result.crossing_triangle_pairs} crossing triangle pairs -> {out}")
