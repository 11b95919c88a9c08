"""Every stage called from Python gives the C++ command-line tool's numbers on the bundled twill,
and the arrays it returns agree with quantities computed here from them alone."""

import numpy
import pytest

import towgeom
from conftest import TWILL_MESH_SIZE


def enclosed_volume(nodes, triangles):
    """Divergence theorem over a closed triangle mesh (independent of the library's own)."""
    a, b, c = (nodes[triangles[:, k]] for k in range(3))
    return numpy.einsum("ij,ij->i", a, numpy.cross(b, c)).sum() / 6.0


@pytest.fixture(scope="module")
def resolved(twill_tows):
    return towgeom.resolve_textile(twill_tows, edge_length=TWILL_MESH_SIZE)


def test_fits_match_the_cli(twill_tows, cli_twill_fit):
    for tow, reported in zip(twill_tows, cli_twill_fit):
        assert tow.name == reported["name"]
        assert tow.volume() == pytest.approx(reported["volume"], rel=1e-12)
        assert tow.area() == pytest.approx(reported["area"], rel=1e-12)
        assert tow.deviation()["max"] == pytest.approx(reported["max_deviation"], rel=1e-9, abs=1e-15)
        # Interpolation: S(u_i, v_j) is point j of section i, on the whole grid at once.
        u, v = numpy.meshgrid(tow.section_parameters, tow.point_parameters, indexing="ij")
        assert numpy.abs(tow.points(u, v) - tow.sections).max() < 1e-12 * tow.tow_size


def test_loops_match_the_cli(twill_tows, resolved, cli_twill_report):
    loops = resolved.intersections.loops
    assert len(loops) == len(cli_twill_report["loops"]) == 16
    for loop, reported in zip(loops, cli_twill_report["loops"]):
        assert loop.closed and reported["closed"]
        assert loop.points.shape == (reported["point_count"], 3)
        assert loop.length() == pytest.approx(reported["length"], rel=1e-12)
        # The curve's points lie on both tows: S_A(uv_a) and S_B(uv_b) are the 3D points.
        tow_a, tow_b = twill_tows[loop.tow_a], twill_tows[loop.tow_b]
        on_a = tow_a.points(loop.uv_a[:, 0], loop.uv_a[:, 1])
        on_b = tow_b.points(loop.uv_b[:, 0], loop.uv_b[:, 1])
        assert numpy.abs(on_a - loop.points).max() < 1e-9
        assert numpy.abs(on_b - loop.points).max() < 1e-9


def test_meshes_match_the_cli(resolved, cli_twill_report):
    mesh = resolved.mesh
    assert mesh.nodes.shape == (cli_twill_report["node_count"], 3)
    assert resolved.crossing_triangle_pairs == cli_twill_report["crossing_triangle_pairs"] == 0
    assert resolved.unresolved == [] and cli_twill_report["unresolved"] == []
    for index, (tow, reported) in enumerate(zip(mesh.tows, cli_twill_report["tows"])):
        assert len(tow) == reported["triangles"]
        volume = enclosed_volume(mesh.nodes, tow.triangles.astype(numpy.int64))
        assert volume == pytest.approx(reported["volume_after"], rel=1e-12)
        assert resolved.tows[index]["volume_after"] == pytest.approx(reported["volume_after"], rel=1e-12)
        assert resolved.tows[index]["volume_before"] == pytest.approx(reported["volume_before"], rel=1e-12)
    assert len(mesh.regions) == len(cli_twill_report["regions"]) == 16
    for region, reported in zip(mesh.regions, cli_twill_report["regions"]):
        assert len(region.triangles) == reported["triangles"]
        assert region.area == pytest.approx(reported["area"], rel=1e-12)
        # A region's triangles are the primary's, and the secondary's mesh holds the same triples.
        primary = mesh.tows[region.primary].triangles[region.triangles.astype(numpy.int64)]
        secondary = {tuple(sorted(t)) for t in mesh.tows[region.secondary].triangles.tolist()}
        assert all(tuple(sorted(t)) in secondary for t in primary.tolist())


def test_report_json_round_trip(twill_tows, resolved, tmp_path):
    report = resolved.intersections
    back = towgeom.IntersectionReport.from_json(report.to_json(twill_tows), twill_tows)
    assert len(back.loops) == len(report.loops)
    for a, b in zip(report.loops, back.loops):
        assert (a.tow_a, a.tow_b) == (b.tow_a, b.tow_b)
        assert numpy.array_equal(a.uv_a, b.uv_a) and numpy.array_equal(a.points, b.points)
    again = towgeom.resolve_textile(twill_tows, back, edge_length=TWILL_MESH_SIZE)
    assert numpy.array_equal(again.mesh.nodes, resolved.mesh.nodes)
    # As a file, named by a pathlib.Path (any os.PathLike is a path).
    path = tmp_path / "report.json"
    report.write(twill_tows, path)
    assert len(towgeom.read_intersection_report(path, twill_tows).loops) == len(report.loops)


def test_generated_weave_as_the_cli_generates_it(tmp_path):
    import subprocess
    from conftest import CLI
    textile = towgeom.generate_weave(kind="twill", warps=4, wefts=4, overlap=0.1)
    subprocess.run([CLI, "generate", "--weave", "twill", "--tows", "4x4", "--overlap", "0.1", "--out", str(tmp_path), "--quiet"],
                   check=True)
    for stack in textile.stacks():
        written = towgeom.read_stack(str(tmp_path / f"{stack.name}.stw"))
        assert numpy.abs(written.sections - stack.sections).max() < 1e-9
