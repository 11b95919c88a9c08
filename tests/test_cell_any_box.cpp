// Issue 39, item 1: a cell cut anywhere (CellCut::Mesh). Checked against oracles independent of
// the clip: the volume of each tow's resolved (uncut) closed mesh inside the box by CGAL's
// corefinement, the tetrahedra's faces counted here (each shared by two, or on the box), their
// volumes against the box's, and CalculiX's reaction against the closed form of a uniform strain.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <towgeom/towgeom.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "cgal_reference.hpp"
#include "cli_runner.hpp"
#include "mesh_checks.hpp"
#include "scan_like.hpp"
#include "synthetic_tows.hpp"

using namespace towgeom;
namespace fs = std::filesystem;

namespace {

/// The box of @p cell as a closed, outward triangle mesh.
TriangleMesh boxMesh(const Cell& cell)
{
    TriangleMesh m;
    for (int k = 0; k < 8; ++k)
        m.vertices.push_back({k & 1 ? cell.max.x : cell.min.x, k & 2 ? cell.max.y : cell.min.y, k & 4 ? cell.max.z : cell.min.z});
    const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    for (const auto& q : quads) {
        m.triangles.push_back({static_cast<std::size_t>(q[0]), static_cast<std::size_t>(q[1]), static_cast<std::size_t>(q[2])});
        m.triangles.push_back({static_cast<std::size_t>(q[0]), static_cast<std::size_t>(q[2]), static_cast<std::size_t>(q[3])});
    }
    return m;
}

/// The tetrahedra counted without towgeom: faces used by more than two tetrahedra, faces used by
/// one that do not lie in a face of the box (a crack), tetrahedra turned the other way from the
/// first, and the sum of their volumes.
struct TetCount {
    std::size_t overShared = 0, cracks = 0, inverted = 0;
    double volume = 0.0;
};

TetCount countTets(const VolumeMesh& v, const Cell& box)
{
    TetCount out;
    std::vector<std::array<std::size_t, 3>> faces;
    double firstSign = 0.0;
    for (const auto& t : v.tetrahedra) {
        const Point3 &a = v.nodes[t[0]], &b = v.nodes[t[1]], &c = v.nodes[t[2]], &d = v.nodes[t[3]];
        const double six = dot(b - a, cross(c - a, d - a));
        if (firstSign == 0.0) firstSign = six > 0.0 ? 1.0 : -1.0;
        if (six * firstSign <= 0.0) ++out.inverted;
        out.volume += std::abs(six) / 6.0;
        for (int skip = 0; skip < 4; ++skip) {
            std::array<std::size_t, 3> f{};
            for (int k = 0, j = 0; k < 4; ++k)
                if (k != skip) f[static_cast<std::size_t>(j++)] = t[static_cast<std::size_t>(k)];
            std::sort(f.begin(), f.end());
            faces.push_back(f);
        }
    }
    std::sort(faces.begin(), faces.end());
    const auto onBox = [&](const std::array<std::size_t, 3>& f) {
        const double lo[3] = {box.min.x, box.min.y, box.min.z}, hi[3] = {box.max.x, box.max.y, box.max.z};
        for (int a = 0; a < 3; ++a) {
            const auto c = [&](std::size_t n) { return a == 0 ? v.nodes[n].x : a == 1 ? v.nodes[n].y : v.nodes[n].z; };
            for (const double plane : {lo[a], hi[a]})
                if (c(f[0]) == plane && c(f[1]) == plane && c(f[2]) == plane) return true;
        }
        return false;
    };
    for (std::size_t i = 0; i < faces.size();) {
        std::size_t j = i;
        while (j < faces.size() && faces[j] == faces[i]) ++j;
        if (j - i > 2) ++out.overShared;
        if (j - i == 1 && !onBox(faces[i])) ++out.cracks;
        i = j;
    }
    return out;
}

/// CalculiX's reaction on XMAX of @p mesh's cell (one isotropic material, E 1000, nu 0.3, in tows
/// and matrix) stretched along x by @p strain, XMIN, YMIN, ZMIN held normal to themselves: a
/// uniform stress E strain, so the reaction is E strain times the face's area exactly for any
/// conforming mesh of the box. NaN when ccx failed.
double cellReaction(const TextileMesh& mesh, const VolumeMesh& v, const fs::path& dir, double strain)
{
    fs::create_directories(dir);
    writeAbaqus(mesh, v, (dir / "cell_volume.inp").string());
    const Cell& box = mesh.cell->box;
    std::ofstream deck(dir / "stretch.inp");
    deck.precision(17);
    deck << "*INCLUDE, INPUT=cell_volume.inp\n*MATERIAL, NAME=ONE\n*ELASTIC\n1000., 0.3\n";
    bool anyTow = false;
    for (std::size_t k = 0; k < v.tow.size() && !anyTow; ++k) anyTow = v.tow[k] < mesh.tows.size();
    if (anyTow) deck << "*SOLID SECTION, ELSET=TEXTILE, MATERIAL=ONE\n";
    deck << "*SOLID SECTION, ELSET=MATRIX, MATERIAL=ONE\n*STEP\n*STATIC\n*BOUNDARY\nXMIN, 1, 1, 0.\nYMIN, 2, 2, 0.\nZMIN, 3, 3, 0.\n"
         << "XMAX, 1, 1, " << strain * (box.max.x - box.min.x) << "\n*NODE PRINT, NSET=XMAX, TOTALS=ONLY\nRF\n*END STEP\n";
    deck.close();
    INFO("ccx not found: install calculix-ccx (bash cmake/ensure_packages.sh, or apt-get install calculix-ccx)");
    REQUIRE(std::system("command -v ccx >/dev/null 2>&1") == 0);
    const testing::Run c = testing::runShell("cd '" + dir.string() + "' && ccx -i stretch 2>&1");
    INFO(c.out);
    CHECK(c.status == 0);
    const std::string dat = testing::slurp(dir / "stretch.dat");
    const auto total = dat.find("total force (fx,fy,fz) for set XMAX ");
    if (c.status != 0 || total == std::string::npos) return std::nan("");
    std::istringstream in(dat.substr(dat.find('\n', total) + 1));
    double fx = std::nan("");
    in >> fx;
    return fx;
}

/// What one cell showed, for the test's summary.
struct CellFigures {
    std::size_t tows = 0, pieces = 0, cutAtEdges = 0, tets = 0;
    double worstVolume = 0.0, fill = 0.0, reaction = 0.0;
};

/// How far a tow's own mesh (before regions) lies from its exact surface (a dense tessellation,
/// closed by its end sections): the volume between them relative to the exact volume, and per
/// unit of area (the mean gap). A clip of the mesh may differ from CGAL's clip of the same mesh
/// by that much: nodes close to a face slide along the exact surface onto it first.
struct MeshDeficit {
    double relative = 0.0, gap = 0.0;
};

std::vector<MeshDeficit> meshDeficits(const std::vector<TowSurface>& tows, const ResolveResult& uncut)
{
    std::vector<MeshDeficit> out;
    for (std::size_t t = 0; t < tows.size(); ++t) {
        const TriangleMesh dense = closedSurface(
            tows[t].tessellate(8 * tows[t].sectionCount() + 1, 4 * tows[t].pointParameters().size()).vertices,
            tows[t].tessellate(8 * tows[t].sectionCount() + 1, 4 * tows[t].pointParameters().size()).triangles);
        const double exact = testing::closedMeshVolume(dense);
        double area = 0.0;
        for (const auto& tri : dense.triangles)
            area += 0.5 * norm(cross(dense.vertices[tri[1]] - dense.vertices[tri[0]], dense.vertices[tri[2]] - dense.vertices[tri[0]]));
        const double between = std::abs(exact - uncut.tows[t].volumeBefore);
        out.push_back({between / exact, between / area});
    }
    return out;
}

/// @p cut (resolved with Cell::cut Mesh) against @p uncut (the same tows and report without the
/// cell): each tow closed, its volume in the box as CGAL's of its uncut mesh within a thousandth
/// of the larger of the two (and of a thousandth of the box's volume) plus twice its mesh's
/// discretisation error @p deficit (meshDeficits()): relative to that volume, and its mean gap
/// over its caps on the box; the tetrahedra conforming, filling the box
/// within 1e-9; CalculiX's reaction within 5e-4 of the closed form.
CellFigures checkCell(const ResolveResult& cut, const ResolveResult& uncut, const Cell& cell, const std::vector<MeshDeficit>& deficit,
                      const fs::path& dir)
{
    CellFigures out;
    REQUIRE(cut.mesh.cell);
    const TriangleMesh box = boxMesh(cell);
    for (std::size_t t = 0; t < cut.mesh.tows.size(); ++t) {
        const TowMesh& m = cut.mesh.tows[t];
        INFO("tow " << m.name);
        const testing::Boundary b = testing::boundaryOf(m.triangles);
        CHECK(b.edges == 0);
        CHECK(b.nonManifoldEdges == 0);
        CHECK(b.misorientedEdges == 0);
        const double expected = testing::intersectionVolume(uncut.mesh.closedTowSurface(t), box);
        const double got = m.triangles.empty() ? 0.0 : cut.tows[t].volumeAfter;
        const double scale = std::max({expected, got, 1e-3 * cell.volume()});
        double caps = 0.0;  // its area on the box's faces
        for (std::size_t k = 0; k < m.triangles.size(); ++k)
            if (m.face[k] == TowFace::Cell) {
                const auto& tri = m.triangles[k];
                caps += 0.5 * norm(cross(cut.mesh.nodes[tri[1]] - cut.mesh.nodes[tri[0]], cut.mesh.nodes[tri[2]] - cut.mesh.nodes[tri[0]]));
            }
        const double bound = 1e-3 * scale + 2.0 * (deficit[t].relative * expected + deficit[t].gap * caps);
        INFO("volume in the box " << got << ", CGAL " << expected << ", mesh's discretisation error " << deficit[t].relative
                                  << ", mean gap " << deficit[t].gap << ", caps' area " << caps);
        CHECK(std::abs(got - expected) <= bound);
        out.worstVolume = std::max(out.worstVolume, std::abs(got - expected) / bound);
        if (m.triangles.empty()) continue;
        ++out.tows;
        out.pieces += cut.tows[t].pieces;
        bool atEdge = false;
        for (std::size_t k = 0; k < m.triangles.size(); ++k) {
            if (m.face[k] != TowFace::Cell) continue;
            for (std::size_t n : m.triangles[k]) {
                const Point3& p = cut.mesh.nodes[n];
                const int planes = (p.x == cell.min.x || p.x == cell.max.x) + (p.y == cell.min.y || p.y == cell.max.y) +
                                   (p.z == cell.min.z || p.z == cell.max.z);
                atEdge = atEdge || planes >= 2;
            }
        }
        out.cutAtEdges += atEdge ? 1 : 0;
    }
    const VolumeMesh v = meshVolumes(cut.mesh);
    out.tets = v.tetrahedra.size();
    // Every node on a face's plane is in that face's set (the boundary conditions' nodes).
    for (int f = 0; f < 6; ++f) {
        const int a = f / 2;
        const double plane = cell.plane(static_cast<CellFace>(f));
        const std::vector<std::size_t>& listed = cut.mesh.cell->faceNodes[static_cast<std::size_t>(f)];
        std::size_t missing = 0;
        for (std::size_t n = 0; n < v.nodes.size(); ++n) {
            const double c = a == 0 ? v.nodes[n].x : a == 1 ? v.nodes[n].y : v.nodes[n].z;
            if (c == plane && !std::binary_search(listed.begin(), listed.end(), n)) ++missing;
        }
        INFO("face " << cellFaceName(static_cast<CellFace>(f)));
        CHECK(missing == 0);
    }
    const TetCount count = countTets(v, cell);
    CHECK(count.overShared == 0);
    CHECK(count.cracks == 0);
    CHECK(count.inverted == 0);
    out.fill = std::abs(count.volume - cell.volume()) / cell.volume();
    CHECK(out.fill <= 1e-9);
    constexpr double strain = 1e-3;
    const double area = (cell.max.y - cell.min.y) * (cell.max.z - cell.min.z);
    const double reaction = cellReaction(cut.mesh, v, dir, strain);
    out.reaction = std::abs(reaction - 1000.0 * strain * area) / (1000.0 * strain * area);
    INFO("CalculiX's reaction " << reaction << ", closed form " << 1000.0 * strain * area);
    // Exact for conforming linear tetrahedra but for rounding: 1e-7 to 3e-7 in 19 of the 20 random
    // boxes; 3.6e-5 to 1.0e-4 (HXT varies run to run) in seed 5's box 1, where HXT leaves
    // near-flat tetrahedra in a thin wedge of matrix (noted as open). Seed 1's box 0 failed here
    // in 1 of 4 runs (3.5 %: a flat tetrahedron of 2.8e-20 left by HXT) until meshVolumes
    // optimised again while any was left (10 of 10 runs since, two at a time).
    CHECK(out.reaction <= 5e-4);
    return out;
}

/// A box at a random place inside @p b, each side 30-70 % of the textile's extent.
Cell randomBox(const BoundingBox& b, std::mt19937& rng)
{
    std::uniform_real_distribution<double> share(0.3, 0.7), place(0.0, 1.0);
    Cell c;
    const double lo[3] = {b.min.x, b.min.y, b.min.z}, hi[3] = {b.max.x, b.max.y, b.max.z};
    double cmin[3], cmax[3];
    for (int a = 0; a < 3; ++a) {
        const double size = share(rng) * (hi[a] - lo[a]);
        cmin[a] = lo[a] + place(rng) * (hi[a] - lo[a] - size);
        cmax[a] = cmin[a] + size;
    }
    c.min = {cmin[0], cmin[1], cmin[2]};
    c.max = {cmax[0], cmax[1], cmax[2]};
    return c;
}

/// Four random boxes in the scan-like textile of @p seed (20 over the five seeds the tests take).
void checkScanBoxes(unsigned seed)
{
    const testing::ScanLikeTextile textile = testing::scanLikeTextile(seed);
    INFO("seed " << seed << ": " << textile.choices.describe());
    const std::vector<TowSurface> tows = testing::fitAll(textile.stacks);
    BoundingBox all;
    for (const TowSurface& t : tows) {
        all.add(t.boundingBox().min);
        all.add(t.boundingBox().max);
    }
    ResolveOptions o;
    o.mesh.relativeEdgeLength = 0.25;
    const IntersectionReport report = intersectTows(tows);
    const ResolveResult uncut = resolveTextile(tows, report, o);
    const std::vector<MeshDeficit> deficit = meshDeficits(tows, uncut);
    std::mt19937 rng(seed);
    CellFigures sum;
    for (int k = 0; k < 4; ++k) {
        Cell cell = randomBox(all, rng);
        INFO("box " << k << ": (" << cell.min.x << ", " << cell.min.y << ", " << cell.min.z << ") to (" << cell.max.x << ", "
                    << cell.max.y << ", " << cell.max.z << ")");
        o.cell = cell;
        const ResolveResult cut = resolveTextile(tows, report, o);
        CHECK(unresolvedPairs(cut).empty());
        const CellFigures f = checkCell(cut, uncut, cell, deficit, fs::temp_directory_path() / ("towgeom_any_box_" + std::to_string(getpid())) /
                                                                   (std::to_string(seed) + "_" + std::to_string(k)));
        sum.tows += f.tows;
        sum.pieces += f.pieces;
        sum.cutAtEdges += f.cutAtEdges;
        sum.tets += f.tets;
        sum.worstVolume = std::max(sum.worstVolume, f.worstVolume);
        sum.fill = std::max(sum.fill, f.fill);
        sum.reaction = std::max(sum.reaction, f.reaction);
    }
    WARN("seed " << seed << ", 4 boxes: " << sum.tows << " tows in them in " << sum.pieces << " pieces, " << sum.cutAtEdges
                 << " cut at an edge of the box; " << sum.tets << " tetrahedra; worst tow volume against CGAL's " << sum.worstVolume << " of the bound"
                 << ", fill " << sum.fill << ", CalculiX's reaction " << sum.reaction);
    CHECK(sum.cutAtEdges > 0);
}

}  // namespace

TEST_CASE("a crimped tow cut by a box at its crests, along its length, at an edge and a corner: pieces closed, volumes as CGAL's",
          "[cell][any-box]")
{
    // Centre line z = 0.6 cos(2 pi x / 2) from x = 0 to 4, half thickness 0.15: above z = 0.2 the
    // crests at x = 0, 2 and 4 leave the box whole (their lower side is at 0.45), the troughs
    // stay in it: two pieces.
    testing::Sampling s;
    s.sections = 81;
    s.points = 32;
    const std::vector<TowSurface> tows{TowSurface::fit(testing::crimpedTow(0.4, 0.15, 4.0, 0.6, 2.0, s, "binder"))};
    ResolveOptions o;
    o.mesh.relativeEdgeLength = 0.15;
    const IntersectionReport report = intersectTows(tows);
    const ResolveResult uncut = resolveTextile(tows, report, o);
    const std::vector<MeshDeficit> deficit = meshDeficits(tows, uncut);
    struct Case {
        const char* what;
        Cell cell;
        std::size_t pieces;
    };
    const auto box = [](Point3 lo, Point3 hi) {
        Cell c;
        c.min = lo;
        c.max = hi;
        return c;
    };
    const std::vector<Case> cases{
        {"crests out above z = 0.2", box({-1.0, -1.0, -1.0}, {5.0, 1.0, 0.2}), 2},
        {"along its length at y = 0.1, crests out", box({-1.0, -1.0, -1.0}, {5.0, 0.1, 0.2}), 2},
        // The troughs at x = 1 and 3 dip below z = -0.6 (their lower side at -0.75): two pieces.
        {"an edge of the box along x through both troughs", box({0.5, 0.05, -1.0}, {3.5, 1.0, -0.6}), 2},
        {"a corner of the box inside it", box({0.9, 0.1, -0.7}, {1.3, 1.0, 0.0}), 1},
    };
    for (std::size_t k = 0; k < cases.size(); ++k) {
        INFO(cases[k].what);
        o.cell = cases[k].cell;
        const ResolveResult cut = resolveTextile(tows, report, o);
        CHECK(cut.tows[0].pieces == cases[k].pieces);
        checkCell(cut, uncut, cases[k].cell, deficit, fs::temp_directory_path() / ("towgeom_crimped_box_" + std::to_string(getpid())) / std::to_string(k));
    }
}

TEST_CASE("cells at random places in scan-like textiles, seeds 1-2: every cell meshes, conforms, fills its box, CalculiX solves it",
          "[volume][cell][scan][any-box][ccx]")
{
    checkScanBoxes(1);
    checkScanBoxes(2);
}

TEST_CASE("cells at random places in scan-like textiles, seeds 3-4: every cell meshes, conforms, fills its box, CalculiX solves it",
          "[volume][cell][scan][any-box][ccx]")
{
    checkScanBoxes(3);
    checkScanBoxes(4);
}

TEST_CASE("cells at random places in scan-like textiles, seed 5: every cell meshes, conforms, fills its box, CalculiX solves it",
          "[volume][cell][scan][any-box][ccx]")
{
    checkScanBoxes(5);
}

TEST_CASE("towgeom resolve --cell through the bundled twill's crossings: the mesh cut by default, --cell-cut checked", "[cli][cell][any-box]")
{
    const fs::path dir = fs::temp_directory_path() / ("towgeom_cli_any_box_" + std::to_string(getpid()));
    fs::remove_all(dir);
    std::string files;
    for (const auto& e : fs::directory_iterator(std::string(TOWGEOM_EXAMPLE_DATA) + "/twill"))
        if (e.path().extension() == ".stw") files += " '" + e.path().string() + "'";
    // Faces through the crossings at x = 1 and y = 2 (the parametric cut refuses them: they run
    // along tows there) and a top face through the tows' thickness.
    const std::string box = " --cell 1,-0.5,-0.5,3.5,2,0.05";
    const testing::Run parametric = testing::cli("resolve" + files + box + " --cell-cut parametric --quiet --out '" + (dir / "p").string() + "'");
    CHECK(parametric.status == 2);
    const testing::Run r = testing::cli("resolve" + files + box + " --volume --quiet --out '" + (dir / "m").string() + "'");
    INFO(r.err);
    REQUIRE(r.status == 0);
    const nlohmann::json report = nlohmann::json::parse(testing::slurp(dir / "m" / "report.json"));
    CHECK(report["cell"]["cut"] == "mesh");
    std::size_t pieces = 0;
    for (const auto& t : report["tows"]) pieces += t["pieces"].get<std::size_t>();
    CHECK(pieces > 0);
    CHECK(report["volume_mesh"]["tetrahedra"].get<std::size_t>() > 0);
    // Usage errors: exit 2, nothing written.
    const testing::Run unknown = testing::cli("resolve" + files + box + " --cell-cut sideways --quiet --out '" + (dir / "u").string() + "'");
    CHECK(unknown.status == 2);
    CHECK(unknown.err.find("--cell-cut takes auto, parametric or mesh") != std::string::npos);
    const testing::Run periodic = testing::cli("resolve" + files + box + " --periodic --cell-cut mesh --quiet --out '" + (dir / "q").string() + "'");
    CHECK(periodic.status == 2);
    CHECK(periodic.err.find("not periodic") != std::string::npos);
    const testing::Run noCell = testing::cli("resolve" + files + " --cell-cut mesh --quiet --out '" + (dir / "n").string() + "'");
    CHECK(noCell.status == 2);
    CHECK(!fs::exists(dir / "u"));
    fs::remove_all(dir);
}
