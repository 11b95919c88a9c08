#!/usr/bin/env python3
"""A mesh-size study: the loops are found once, then the twill is meshed at three sizes from the
same report, and each tow's enclosed volume is compared with the exact surface's.

    PYTHONPATH=build/python python3 examples/python/mesh_size_study.py
"""
import pathlib

import numpy

import towgeom

twill = pathlib.Path(__file__).resolve().parents[1] / "data" / "twill"
tows = [towgeom.TowSurface.fit(towgeom.read_stack(str(path))) for path in sorted(twill.glob("*.stw"))]
report = towgeom.intersect_tows(tows)  # once
exact = numpy.array([tow.volume() for tow in tows])
print(f"{len(report.loops)} loops; volumes of the resolved tows against the exact surfaces' (before resolving)")
print(f"{'size':>6} {'nodes':>8} {'triangles':>10} {'largest volume change':>22}")
for size in (0.2, 0.1, 0.05):
    result = towgeom.resolve_textile(tows, report, edge_length=size)
    meshed = numpy.array([result.mesh.enclosed_volume(k) for k in range(len(tows))])
    triangles = sum(len(tow) for tow in result.mesh.tows)
    print(f"{size:>6} {len(result.mesh.nodes):>8} {triangles:>10} {numpy.abs(meshed / exact - 1).max():>22.2%}")
