"""towgeom: exact geometry for composite tows, from Python.

The C++ library's stages on NumPy arrays::

    import towgeom
    stacks = [towgeom.read_stack(p) for p in paths]          # or towgeom.Stack(name, array)
    tows = [towgeom.TowSurface.fit(s) for s in stacks]
    report = towgeom.intersect_tows(tows)                    # every interpenetration as loops
    result = towgeom.resolve_textile(tows, report, edge_length=0.1)
    result.mesh.write_gmsh("textile.msh")
    mesh = result.mesh.to_meshio()                           # meshio.Mesh, one triangle block per tow

Long calls (intersect_tows, resolve_textile) take progress=callable(stage, done, total) and stop
on Ctrl-C with KeyboardInterrupt. Errors of the library raise towgeom.Error, whose code, file and
line say what and where.
"""

from ._towgeom import *  # noqa: F401,F403
from ._towgeom import TextileMesh, __version__  # noqa: F401

__all__ = [name for name in dir() if not name.startswith("_")]


def _to_meshio(self):
    """The mesh as a meshio.Mesh: one "triangle" cell block per tow, cell data "tow" (the tow's
    index), "region" (connected region or -1) and "face" (FACE_NAMES), field data "tow_names"."""
    import meshio
    import numpy

    blocks, tows, regions, faces = [], [], [], []
    for index, tow in enumerate(self.tows):
        blocks.append(("triangle", numpy.asarray(tow.triangles, dtype=numpy.int64)))
        tows.append(numpy.full(len(tow), index, dtype=numpy.int64))
        regions.append(numpy.asarray(tow.region, dtype=numpy.int64))
        faces.append(numpy.asarray(tow.face, dtype=numpy.int64))
    mesh = meshio.Mesh(numpy.array(self.nodes), blocks, cell_data={"tow": tows, "region": regions, "face": faces})
    mesh.field_data["tow_names"] = numpy.array([tow.name for tow in self.tows])
    return mesh


def _from_meshio(mesh, names=None):
    """A TextileMesh from a meshio.Mesh: each "triangle" block one tow, named by NAMES, the
    mesh's field data "tow_names" (as to_meshio() writes it) or tow_0, tow_1, ..."""
    import numpy

    blocks = [block for block in mesh.cells if block.type == "triangle"]
    if names is None:
        stored = mesh.field_data.get("tow_names") if mesh.field_data else None
        names = [str(n) for n in stored] if stored is not None and len(stored) == len(blocks) else [f"tow_{k}" for k in range(len(blocks))]
    if len(names) != len(blocks):
        raise ValueError(f"{len(names)} names for {len(blocks)} triangle blocks")
    return TextileMesh.from_arrays(numpy.asarray(mesh.points, dtype=numpy.float64),
                                   [(name, block.data) for name, block in zip(names, blocks)])


TextileMesh.to_meshio = _to_meshio
TextileMesh.from_meshio = staticmethod(_from_meshio)
