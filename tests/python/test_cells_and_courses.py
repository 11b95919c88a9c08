"""The cell, the two halves of resolve, and fibre placement from Python: against the command-line
tool's numbers and closed forms."""

import json
import re
import subprocess

import numpy
import pytest

import towgeom
from conftest import CLI


@pytest.fixture(scope="module")
def twill_6x6(tmp_path_factory):
    """A 2/2 twill with a periodic unit cell (6 x 6 yarns), from Python and from the CLI."""
    out = tmp_path_factory.mktemp("twill_6x6")
    textile = towgeom.generate_weave(kind="twill", warps=6, wefts=6, overlap=0.1)
    subprocess.run([CLI, "generate", "--weave", "twill", "--tows", "6x6", "--overlap", "0.1", "--out", str(out), "--quiet"], check=True)
    return textile, out


def test_a_periodic_cell_from_python_as_from_the_cli(twill_6x6):
    textile, out = twill_6x6
    cell = textile.unit_cell()
    written = json.loads((out / "textile.json").read_text())["cell"]
    assert cell.periodic and written["periodic"]
    assert numpy.allclose(cell.min, written["min"], rtol=0, atol=1e-12) and numpy.allclose(cell.max, written["max"], rtol=0, atol=1e-12)
    tows = [towgeom.TowSurface.fit(stack) for stack in textile.stacks()]
    result = towgeom.resolve_textile(tows, edge_length=0.1, cell=cell)
    stacks = sorted(str(p) for p in out.glob("*.stw"))
    subprocess.run([CLI, "resolve", *stacks, "--mesh-size", "0.1", "--cell", str(out / "textile.json"), "--formats", "vtk", "--out",
                    str(out / "resolved"), "--quiet"], check=True)
    report = json.loads((out / "resolved" / "report.json").read_text())
    names = [tow.name for tow in result.mesh.tows]
    assert names == [tow["name"] for tow in report["tows"]]
    assert len(result.mesh.nodes) == report["node_count"]
    assert len(result.mesh.regions) == len(report["regions"])
    # The periodic faces' node pairs lie one period apart, on the same place of both faces.
    faces = result.mesh.cell
    assert faces is not None and len(faces.triangles) > 0
    period = numpy.array(cell.max) - numpy.array(cell.min)
    for axis, pairs in enumerate(faces.periodic_pairs):
        assert len(pairs) > 0
        shift = result.mesh.nodes[pairs[:, 1].astype(numpy.int64)] - result.mesh.nodes[pairs[:, 0].astype(numpy.int64)]
        expected = numpy.zeros(3)
        expected[axis] = period[axis]
        assert numpy.abs(shift - expected).max() < 1e-9 * period.max()
    # Every node inside the box (the cut puts nodes on its faces exactly).
    lo, hi = numpy.array(cell.min), numpy.array(cell.max)
    assert (result.mesh.nodes >= lo - 1e-9 * numpy.abs(hi - lo).max()).all()
    assert (result.mesh.nodes <= hi + 1e-9 * numpy.abs(hi - lo).max()).all()


def test_mesh_tows_then_connect_regions_is_resolve_textile(twill_tows):
    report = towgeom.intersect_tows(twill_tows)
    meshed = towgeom.mesh_tows(twill_tows, report, edge_length=0.2)
    assert len(meshed.mesh.regions) == 0
    connected = towgeom.connect_regions(twill_tows, meshed, edge_length=0.2)
    whole = towgeom.resolve_textile(twill_tows, report, edge_length=0.2)
    assert len(connected.mesh.regions) == len(whole.mesh.regions) == 16
    assert numpy.array_equal(connected.mesh.nodes, whole.mesh.nodes)
    for a, b in zip(connected.mesh.tows, whole.mesh.tows):
        assert numpy.array_equal(a.triangles, b.triangles)


def cylinder_grid(radius=10.0, length=40.0, nu=41, nv=33):
    """Half a cylinder about the x axis: (x, R cos t, R sin t), t in [0, pi]; v fastest."""
    x = numpy.linspace(0.0, length, nu)
    t = numpy.linspace(0.0, numpy.pi, nv)
    grid = numpy.empty((nu, nv, 3))
    grid[..., 0] = x[:, None]
    grid[..., 1] = radius * numpy.cos(t)[None, :]
    grid[..., 2] = radius * numpy.sin(t)[None, :]
    return grid


def test_courses_on_a_cylinder_as_the_cli_lays_them_and_as_the_closed_form(tmp_path):
    grid = cylinder_grid()
    surface = towgeom.fit_placement_surface(grid)
    # The hoop circle x = 20 as reference: geodesic offsets along the axis are the circles
    # x = 20 + k W (the cylinder is developable, its hoops geodesically parallel).
    reference = towgeom.reference_from_plane(surface, (20.0, 0.0, 10.0), (1.0, 0.0, 0.0), points=41)
    plan = towgeom.lay_courses(surface, reference, tow_width=2.0, tows_per_course=3, courses=1, method="geodesic")
    assert [t.name for t in plan.tows] == ["c1_t1", "c1_t2", "c1_t3"]
    offsets = sorted(numpy.median(t.centreline.points[:, 0]) - 20.0 for t in plan.tows)
    assert numpy.allclose(offsets, [-2.0, 0.0, 2.0], rtol=0, atol=1e-6)
    for tow in plan.tows:
        x = tow.centreline.points[:, 0]
        assert numpy.ptp(x) < 1e-6
    for gap in plan.gaps:
        assert abs(gap["min"]) < 1e-6 and abs(gap["max"]) < 1e-6
    # The hoop runs from one straight edge of the half cylinder to the other: so does every tow,
    # its length the half circle's.
    assert plan.off_surface == []
    for tow in plan.tows:
        assert {tow.start_boundary, tow.end_boundary} == {"v_min", "v_max"}
        assert abs(tow.length - numpy.pi * 10.0) < 1e-4
        assert numpy.all(numpy.isfinite(tow.geodesic_curvature))
    # Three tows 2 wide edge to edge across the 40 long half cylinder: 6 / 40 of it once.
    coverage = towgeom.course_coverage(surface, plan, cells=80)
    assert abs(coverage.uncovered + coverage.once + coverage.several - 1.0) < 1e-12
    assert abs(coverage.once - 6.0 / 40.0) < 2.0 / 80.0
    assert coverage.several < 1e-12
    assert coverage.count.shape == (coverage.triangles.shape[0],)
    assert abs(coverage.area.sum() - coverage.total_area) < 1e-9 * coverage.total_area
    # The CLI on the same grid: the same centrelines.
    lines = ["grid 41 33"] + [f"{p[0]!r} {p[1]!r} {p[2]!r}" for p in grid.reshape(-1, 3)]
    (tmp_path / "half.grid").write_text("\n".join(lines) + "\n")
    subprocess.run([CLI, "courses", str(tmp_path / "half.grid"), "--reference", "plane:20,0,10,1,0,0", "--tow-width", "2", "--tows", "3",
                    "--exact", "--out", str(tmp_path / "plan"), "--quiet"], check=True, capture_output=True)
    written = json.loads((tmp_path / "plan" / "courses.json").read_text())
    from_python = json.loads(plan.to_json())
    assert len(written["tows"]) == len(from_python["tows"]) == 3
    for a, b in zip(written["tows"], from_python["tows"]):
        assert a["name"] == b["name"]
        assert numpy.abs(numpy.array(a["centreline"]["points"]) - numpy.array(b["centreline"]["points"])).max() < 1e-12


def test_courses_on_a_trimmed_face_written_by_gmsh_end_on_its_edges(tmp_path):
    # A disk of radius 10 with the part x > 6 cut off (Gmsh's OpenCASCADE kernel): a plane face
    # trimmed by an arc and a line, its (u,v) box larger than the face.
    (tmp_path / "d.geo").write_text('SetFactory("OpenCASCADE");\nDisk(1) = {0, 0, 0, 10};\nRectangle(2) = {6, -20, 0, 20, 40};\n'
                                    "BooleanDifference{ Surface{1}; Delete; }{ Surface{2}; Delete; }\n")
    subprocess.run(["gmsh", str(tmp_path / "d.geo"), "-0", "-o", str(tmp_path / "d.step"), "-format", "step"], check=True, capture_output=True)
    surface = towgeom.read_placement_surface(str(tmp_path / "d.step"), 0)
    assert surface.trim_edges == 2
    reference = towgeom.reference_from_plane(surface, (0.0, 0.0, 0.0), (0.0, 1.0, 0.0), points=41)
    plan = towgeom.lay_courses(surface, reference, tow_width=2.0, tows_per_course=4, courses=1, method="geodesic")
    assert len(plan.tows) == 4
    for tow in plan.tows:
        points = tow.centreline.points
        y = points[0, 1]
        assert numpy.abs(points[:, 1] - y).max() < 1e-9
        # From the arc (x = -sqrt(100 - y^2)) to the line x = 6, the edge each end lies on named.
        left, right = sorted([points[0, 0], points[-1, 0]])
        assert abs(left + numpy.sqrt(100.0 - y * y)) < 2e-8 and abs(right - 6.0) < 2e-8
        assert tow.start_boundary.startswith("edge ") and tow.end_boundary.startswith("edge ")
        assert tow.start_boundary != tow.end_boundary
        assert abs(tow.length - (6.0 + numpy.sqrt(100.0 - y * y))) < 1e-7
    # Coverage of the face alone: the strip |y| <= 4 of the D once (its area by the trapezoid rule).
    y = numpy.linspace(-10.0, 10.0, 200001)
    width = numpy.sqrt(100.0 - y * y) + numpy.minimum(6.0, numpy.sqrt(100.0 - y * y))
    area, strip = numpy.trapz(width, y), numpy.trapz(numpy.where(numpy.abs(y) <= 4.0, width, 0.0), y)
    coverage = towgeom.course_coverage(surface, plan, cells=100)
    assert abs(coverage.total_area - area) < 2e-3 * area
    assert abs(coverage.once - strip / area) < 1e-3
    # The command-line tool on the same file: its coverage.vtk as meshio reads it, its courses.step
    # as Gmsh reads it (each tow's centreline and edges a curve, their ends on the D's boundary).
    subprocess.run([CLI, "courses", str(tmp_path / "d.step"), "--reference", "plane:0,0,0,0,1,0", "--tow-width", "2", "--tows", "4", "--exact",
                    "--coverage-cells", "100", "--out", str(tmp_path / "plan"), "--quiet"], check=True, capture_output=True)
    import meshio
    mesh = meshio.read(str(tmp_path / "plan" / "coverage.vtk"))
    assert mesh.cells[0].type == "triangle"
    assert abs(mesh.cell_data["area"][0].sum() - coverage.total_area) < 1e-9 * coverage.total_area
    assert set(numpy.unique(mesh.cell_data["coverage"][0])) <= {0, 1}
    subprocess.run(["gmsh", str(tmp_path / "plan" / "courses.step"), "-0", "-o", str(tmp_path / "read.geo_unrolled")], check=True,
                   capture_output=True)
    text = (tmp_path / "read.geo_unrolled").read_text()
    assert text.count("Spline(") == 12
    # The curves' end points are Gmsh's numbered points (their inner points are "p1 + k").
    ends = [[float(x) for x in line.split("{")[1].split("}")[0].split(",")[:3]] for line in text.splitlines()
            if re.match(r"Point\(\d+\)", line)]
    assert len(ends) == 24
    for x, y, z in ends:
        on_arc = abs(numpy.hypot(x, y) - 10.0) if x <= 6.0 + 1e-9 else 1e300
        on_line = abs(x - 6.0) if abs(y) <= 8.0 + 1e-9 else 1e300
        assert min(on_arc, on_line) < 1e-6 and abs(z) < 1e-9
