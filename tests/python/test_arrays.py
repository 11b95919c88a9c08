"""Arrays in and out: stacks from NumPy, vectorised evaluation, read-only views of the meshes
that keep their owner alive, and the meshio round trip."""

import gc

import numpy
import pytest

import towgeom


def circle_stack(name, sections=6, points=12, radius=0.5):
    """A straight tube along x: closed form for everything below."""
    t = numpy.linspace(0.0, 2.0 * numpy.pi, points, endpoint=False)
    x = numpy.linspace(0.0, 5.0, sections)
    array = numpy.empty((sections, points, 3))
    array[:, :, 0] = x[:, None]
    array[:, :, 1] = radius * numpy.cos(t)[None, :]
    array[:, :, 2] = radius * numpy.sin(t)[None, :]
    return towgeom.Stack(name, array), array


def test_a_stack_from_an_array_round_trips(tmp_path):
    stack, array = circle_stack("tube")
    assert (stack.section_count, stack.points_per_section) == (6, 12)
    assert numpy.array_equal(stack.sections, array)
    stack.write(tmp_path / "tube.stw")  # str or any os.PathLike
    assert numpy.array_equal(towgeom.read_stack(tmp_path / "tube.stw").sections, array)
    with pytest.raises(ValueError):
        towgeom.Stack("flat", numpy.zeros((6, 12)))


def test_evaluation_broadcasts_and_matches_the_closed_form():
    stack, _ = circle_stack("tube", points=24)
    tow = towgeom.TowSurface.fit(stack)
    u, v = numpy.meshgrid(numpy.linspace(0.0, 1.0, 7), numpy.linspace(0.0, 1.0, 9), indexing="ij")
    points = tow.points(u, v)
    assert points.shape == (7, 9, 3)
    # A periodic cubic through 24 points of a circle of radius 0.5: radius within 1e-4.
    assert numpy.abs(numpy.hypot(points[..., 1], points[..., 2]) - 0.5).max() < 1e-4
    normals = tow.normals(u, v)
    radial = points.copy()
    radial[..., 0] = 0.0
    radial /= numpy.linalg.norm(radial, axis=-1, keepdims=True)
    assert numpy.abs(numpy.einsum("...k,...k", normals, radial) - 1.0).max() < 1e-6  # outward
    assert tow.volume() == pytest.approx(numpy.pi * 0.25 * 5.0, rel=1e-4)
    vertices, triangles = tow.tessellate(10, 16)
    assert triangles.max() < len(vertices)


def test_first_arrays_made_on_several_threads_at_once_do_not_deadlock():
    import subprocess
    import sys

    # A fresh interpreter (NumPy not imported by the test) whose threads make their first arrays
    # together: pybind11 sets NumPy up lazily unless the module does it at import.
    script = (
        "import threading, towgeom\n"
        "stacks = towgeom.generate_weave(kind='plain', warps=2, wefts=2).stacks()\n"
        "threads = [threading.Thread(target=lambda: [s.sections for s in stacks]) for _ in range(4)]\n"
        "[t.start() for t in threads]; [t.join() for t in threads]; print('done')\n")
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=60)
    assert done.stdout.strip() == "done"


def test_mesh_arrays_are_read_only_views_that_keep_the_result_alive(twill_tows):
    result = towgeom.resolve_textile(twill_tows, edge_length=0.2)
    nodes = result.mesh.nodes
    triangles = result.mesh.tows[0].triangles
    again = result.mesh.nodes
    assert numpy.shares_memory(nodes, again)  # a view of the library's vector, not a copy
    assert not nodes.flags.writeable and not triangles.flags.writeable
    with pytest.raises(ValueError):
        nodes[0, 0] = 1.0
    expected = nodes.copy(), triangles.copy()
    del result, again
    gc.collect()
    assert numpy.array_equal(nodes, expected[0]) and numpy.array_equal(triangles, expected[1])


def test_meshio_round_trip_keeps_nodes_and_cells(twill_tows, tmp_path):
    import meshio

    mesh = towgeom.resolve_textile(twill_tows, edge_length=0.2).mesh
    written = tmp_path / "textile.vtu"
    meshio.write(str(written), mesh.to_meshio())
    read = meshio.read(str(written))
    back = towgeom.TextileMesh.from_meshio(read, names=[tow.name for tow in mesh.tows])
    assert numpy.array_equal(back.nodes, mesh.nodes)
    assert [tow.name for tow in back.tows] == [tow.name for tow in mesh.tows]
    for a, b in zip(mesh.tows, back.tows):
        assert numpy.array_equal(a.triangles, b.triangles)
        assert numpy.array_equal(a.region, b.region) and numpy.array_equal(a.face, b.face)
    assert any((tow.region >= 0).any() for tow in back.tows)  # the regions came back, not all -1
    for k in range(len(mesh.tows)):
        assert back.enclosed_volume(k) == pytest.approx(mesh.enclosed_volume(k), rel=1e-12)
    with pytest.raises(ValueError, match="node"):
        towgeom.TextileMesh.from_arrays(numpy.zeros((3, 3)), [("t", numpy.array([[0, 1, 3]]))])
    with pytest.raises(TypeError, match="integer"):  # no silent truncation of float indices
        towgeom.TextileMesh.from_arrays(numpy.zeros((3, 3)), [("t", numpy.array([[0.2, 1.7, 2.9]]))])


def test_a_stack_from_a_texgen_style_list_of_sections():
    class XYZ:  # TexGen's point type: attributes x, y, z
        def __init__(self, x, y, z):
            self.x, self.y, self.z = x, y, z

    radius, length = 0.5, 4.0
    sections = []
    for i, x in enumerate(numpy.linspace(0.0, length, 9)):
        n = 48 + 8 * (i % 3)  # 48, 56 or 64 points: different in neighbouring sections
        t = numpy.linspace(0.0, 2.0 * numpy.pi, n, endpoint=False)
        sections.append([XYZ(x, radius * numpy.cos(a), radius * numpy.sin(a)) for a in t])
    with pytest.raises(ValueError, match="points=N"):
        towgeom.stack_from_sections("yarn", sections)
    stack = towgeom.stack_from_sections("yarn", sections, points=48)
    assert (stack.section_count, stack.points_per_section) == (9, 48)
    tow = towgeom.TowSurface.fit(stack)
    # Resampled points lie on the input polygons' chords, at most r (1 - cos(pi / 48)) inside the
    # circle: the volume at most 2 (1 - cos(pi / 48)) = 4.3e-3 below pi r^2 L, and not above it.
    exact = numpy.pi * radius**2 * length
    assert 1.0 - 2.0 * (1.0 - numpy.cos(numpy.pi / 48)) < tow.volume() / exact < 1.0
    same = towgeom.stack_from_sections("yarn", [[(p.x, p.y, p.z) for p in sections[0]]] * 2)
    assert same.sections.shape == (2, 48, 3)
