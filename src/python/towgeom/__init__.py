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

import numpy  # noqa: F401  (before the extension: its arrays need NumPy set up on this thread)

from ._towgeom import *  # noqa: F401,F403
from ._towgeom import TextileMesh, __version__  # noqa: F401


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
    """A TextileMesh from a meshio.Mesh: its triangles split into tows by the cell data "tow"
    (as to_meshio() writes it; writers such as VTU's merge the blocks) or else one tow per
    "triangle" block, with the cell data "region" and "face" where present. Named by NAMES, the
    field data "tow_names" (kept by meshio's own formats, lost by VTU and VTK), or tow_0, ...
    Other cell types (a Gmsh file's lines and tetrahedra) are ignored."""
    import numpy

    indices = [k for k, block in enumerate(mesh.cells) if block.type == "triangle"]

    def gathered(key):
        if key not in mesh.cell_data:
            return None
        return numpy.concatenate([numpy.asarray(mesh.cell_data[key][k]).ravel() for k in indices]).astype(numpy.int64)

    blocks = [numpy.asarray(mesh.cells[k].data, dtype=numpy.int64) for k in indices]
    every = numpy.concatenate(blocks) if blocks else numpy.zeros((0, 3), dtype=numpy.int64)
    tow_of = gathered("tow")
    if tow_of is None:
        tow_of = numpy.concatenate([numpy.full(len(b), k, dtype=numpy.int64) for k, b in enumerate(blocks)]) if blocks else numpy.zeros(0, numpy.int64)
    count = int(tow_of.max()) + 1 if len(tow_of) else 0
    region, face = gathered("region"), gathered("face")
    if names is None:
        stored = mesh.field_data.get("tow_names") if mesh.field_data else None
        names = [str(n) for n in stored] if stored is not None and len(stored) == count else [f"tow_{k}" for k in range(count)]
    if len(names) != count:
        raise ValueError(f"{len(names)} names for {count} tows")
    tows = []
    for k, name in enumerate(names):
        mine = tow_of == k
        entry = [name, every[mine]]
        if region is not None:
            entry.append(region[mine])
            if face is not None:
                entry.append(face[mine])
        tows.append(tuple(entry))
    return TextileMesh.from_arrays(numpy.asarray(mesh.points, dtype=numpy.float64), tows)


def _as_xyz(point):
    """(x, y, z) of a point given as a sequence or as an object with x, y, z (TexGen's XYZ)."""
    if hasattr(point, "x"):
        return (float(point.x), float(point.y), float(point.z))
    return tuple(float(c) for c in point)


def _resample_closed(polygon, count):
    """COUNT points equally spaced by arc length around a closed polygon, from its first point."""
    import numpy

    closed = numpy.vstack([polygon, polygon[:1]])
    along = numpy.concatenate([[0.0], numpy.cumsum(numpy.linalg.norm(numpy.diff(closed, axis=0), axis=1))])
    at = numpy.linspace(0.0, along[-1], count, endpoint=False)
    return numpy.column_stack([numpy.interp(at, along, closed[:, k]) for k in range(3)])


def stack_from_sections(name, sections, points=None):
    """A Stack from a list of yarn sections, as textile modellers give them (TexGen's slave
    nodes' section points, a micro-CT tool's contours): each section a sequence of 3D points
    (tuples, arrays, or objects with x, y, z), in order around the yarn, not repeating the
    first point at the end.

    Sections with different numbers of points need POINTS: each closed polygon is then resampled
    to POINTS points equally spaced by arc length from its first point (corners between samples
    are cut). Without it they must all have the same number, or ValueError says how many each has.
    """
    import numpy

    polygons = [numpy.array([_as_xyz(p) for p in section], dtype=numpy.float64) for section in sections]
    counts = sorted({len(p) for p in polygons})
    if points is not None:
        polygons = [_resample_closed(p, int(points)) for p in polygons]
    elif len(counts) > 1:
        raise ValueError(f"the sections of '{name}' have {counts} points: give points=N to resample each to N")
    return Stack(name, numpy.stack(polygons) if polygons else numpy.zeros((0, 0, 3)))


TextileMesh.to_meshio = _to_meshio
TextileMesh.from_meshio = staticmethod(_from_meshio)

__all__ = [name for name in dir() if not name.startswith("_") and name != "numpy"]
