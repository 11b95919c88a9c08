"""Volumes and exports from Python, checked in numpy and in the programs that read them."""

import re
import subprocess

import numpy
import pytest

import towgeom


@pytest.fixture(scope="module")
def resolved(twill_tows):
    return towgeom.resolve_textile(twill_tows, edge_length=0.2)


def test_tetrahedra_fill_each_closed_tow(resolved, tmp_path):
    volumes = towgeom.mesh_volumes(resolved, threads=1)
    nodes, tets, tow = volumes.nodes, volumes.tetrahedra.astype(numpy.int64), volumes.tow
    a, b, c, d = (nodes[tets[:, k]] for k in range(4))
    signed = numpy.einsum("ij,ij->i", b - a, numpy.cross(c - a, d - a)) / 6.0
    assert (signed > 0).all()
    for k in range(len(resolved.mesh.tows)):
        assert signed[tow == k].sum() == pytest.approx(resolved.mesh.enclosed_volume(k), rel=1e-9)
    path = tmp_path / "volumes.msh"
    resolved.mesh.write_gmsh_volumes(volumes, str(path))
    checked = subprocess.run(["gmsh", "-check", str(path)], capture_output=True, text=True)
    assert checked.returncode == 0 and "Error" not in checked.stdout + checked.stderr
    assert f"Info    : {len(nodes)} nodes" in checked.stdout


def test_a_tow_as_stl_reads_back_with_meshio(resolved, tmp_path):
    import meshio

    resolved.mesh.write_tow_stl(0, str(tmp_path / "warp_0.stl"))
    read = meshio.read(str(tmp_path / "warp_0.stl"))
    points, triangles = read.points.astype(numpy.float64), read.cells_dict["triangle"]
    a, b, c = (points[triangles[:, k]] for k in range(3))
    volume = numpy.einsum("ij,ij->i", a, numpy.cross(b, c)).sum() / 6.0
    assert volume == pytest.approx(resolved.mesh.enclosed_volume(0), rel=1e-6)  # STL stores float32


def test_the_trimmed_brep_keeps_the_primaries_exact_and_gmsh_reads_its_step(twill_tows, resolved, tmp_path):
    brep = towgeom.trimmed_brep(twill_tows, resolved)
    assert [s.name for s in brep.solids] == [t.name for t in twill_tows]
    assert all(s.valid for s in brep.solids)
    assert brep.shared_face_count == 16
    for tow, solid, role in zip(twill_tows, brep.solids, resolved.tows):
        if role["role"] == "primary":  # the warps keep their own exact surface
            assert solid.volume == pytest.approx(tow.volume(), rel=1e-9)
        else:
            assert solid.volume < tow.volume()
    path = tmp_path / "twill.step"
    brep.write_step(str(path))
    # Gmsh's OpenCASCADE kernel reads it (-0: the model as read, written back as OCCT's .brep,
    # whose shapes are listed one per line, a solid's starting with "So").
    written = tmp_path / "gmsh.brep"
    read = subprocess.run(["gmsh", str(path), "-0", "-o", str(written)], capture_output=True, text=True)
    assert read.returncode == 0 and "Error" not in read.stdout + read.stderr
    assert len(re.findall(r"^So", written.read_text(), flags=re.M)) == len(twill_tows)


def test_quadratic_tetrahedra_have_their_middle_nodes_on_straight_edges(twill_tows):
    resolved = towgeom.resolve_textile(twill_tows[:1] + twill_tows[4:5], edge_length=0.3)
    volumes = towgeom.mesh_volumes(resolved, order=2, threads=1)
    tets, middles, nodes = volumes.tetrahedra.astype(numpy.int64), volumes.edge_nodes.astype(numpy.int64), volumes.nodes
    assert middles.shape == (len(tets), 6)
    edges = [(0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)]  # Abaqus C3D10's order
    for k, (a, b) in enumerate(edges):
        midpoint = 0.5 * (nodes[tets[:, a]] + nodes[tets[:, b]])
        assert numpy.abs(nodes[middles[:, k]] - midpoint).max() < 1e-12 * numpy.ptp(nodes, axis=0).max()
    towgeom.add_fibre_directions(volumes, twill_tows[:1] + twill_tows[4:5])
    assert numpy.allclose(numpy.linalg.norm(volumes.fibre_direction, axis=1), 1.0, rtol=0, atol=1e-12)
