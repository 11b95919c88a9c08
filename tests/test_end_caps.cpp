// Tows as closed solids: resolveTextile() closes every tow by its two end caps (planar meshes of
// its end sections with the tube's end nodes). Checked on the output alone: the caps lie in the
// end sections' planes, face out of the tow, cover the section's exact area, and make each tow a
// closed 2-manifold whose CGAL volume is the reported one; without caps the tubes are open.
#include <catch2/catch.hpp>

#include <towgeom/error.hpp>
#include <towgeom/resolve.hpp>
#include <towgeom/tow_stack.hpp>
#include <towgeom/textile_mesh.hpp>
#include <towgeom/tow_surface.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cgal_reference.hpp"
#include "mesh_checks.hpp"
#include "synthetic_tows.hpp"

using namespace towgeom;

namespace {

std::vector<TowSurface> crossingTubes()
{
    testing::Sampling s;
    s.sections = 41;
    s.points = 48;
    return {TowSurface::fit(testing::tubeAlongX(0.5, 4.0, 0.0, 0.0, 0.0, s, "x")), TowSurface::fit(testing::tubeAlongY(0.4, 0.82, s, "y"))};
}

double smallestAngleDeg(const Point3& a, const Point3& b, const Point3& c)
{
    double best = 180.0;
    const Point3 p[3] = {a, b, c};
    for (int k = 0; k < 3; ++k) {
        const Vector3 u = p[(k + 1) % 3] - p[k], v = p[(k + 2) % 3] - p[k];
        best = std::min(best, std::acos(std::clamp(dot(u, v) / (norm(u) * norm(v)), -1.0, 1.0)) * 180.0 / 3.14159265358979323846);
    }
    return best;
}

}  // namespace

TEST_CASE("every tow is closed by its two end caps: planar, facing out, the section's area", "[resolve][caps]")
{
    const std::vector<TowSurface> tows = crossingTubes();
    const ResolveResult res = resolveTextile(tows);
    REQUIRE(res.mesh.regions.size() == 1);
    CHECK(testing::crossingPairsBetweenTows(res.mesh) == 0);
    // Each tow's axis: x runs along +x from x = 0 to 4, y along +y from y = -2 to 2.
    const Vector3 axes[2] = {{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}};
    for (std::size_t t = 0; t < 2; ++t) {
        INFO("tow " << tows[t].name());
        const TowMesh& m = res.mesh.tows[t];
        REQUIRE(m.face.size() == m.triangles.size());
        const testing::Boundary b = testing::boundaryOf(m.triangles);
        CHECK(b.edges == 0);
        CHECK(b.nonManifoldEdges == 0);
        CHECK(b.misorientedEdges == 0);
        CHECK(res.tows[t].boundaryLoops == 0);
        CHECK(testing::closedMeshVolume(res.mesh.towSurface(t)) == Approx(res.tows[t].volumeAfter).epsilon(1e-9));
        for (const TowFace face : {TowFace::Start, TowFace::End}) {
            INFO((face == TowFace::Start ? "start" : "end") << " cap");
            const double u = face == TowFace::Start ? tows[t].parameterRange().uMin : tows[t].parameterRange().uMax;
            const Point3 centre = tows[t].point(u, 0.0) + 0.5 * (tows[t].point(u, 0.5 * tows[t].parameterRange().vPeriod()) -
                                                               tows[t].point(u, 0.0));
            const Vector3 out = face == TowFace::Start ? -1.0 * axes[t] : axes[t];
            double area = 0.0, worst = 0.0, smallest = 180.0;
            std::size_t triangles = 0;
            for (std::size_t k = 0; k < m.triangles.size(); ++k) {
                if (m.face[k] != face) continue;
                ++triangles;
                const Point3 &a = res.mesh.nodes[m.triangles[k][0]], &p = res.mesh.nodes[m.triangles[k][1]],
                             &c = res.mesh.nodes[m.triangles[k][2]];
                const Vector3 n = cross(p - a, c - a);
                CHECK(dot(n, out) > 0.999999 * norm(n));  // in the section's plane, facing out
                area += 0.5 * norm(n);
                for (const Point3* q : {&a, &p, &c}) worst = std::max(worst, std::abs(dot(*q - centre, out)));
                smallest = std::min(smallest, smallestAngleDeg(a, p, c));
            }
            CHECK(triangles > 10);
            CHECK(worst < 1e-12);  // every cap node in the end section's plane
            // The inscribed polygon of the tube's end nodes (h/2 apart) misses a sliver of the
            // section: within 1 % of its exact area.
            const double exact = tows[t].sectionArea(u);
            CHECK(std::abs(area - exact) <= 0.01 * exact);
            CHECK(area < exact);
            CHECK(smallest >= 20.0);  // CGAL's shape bound holds on the caps
        }
    }

    // Without caps: the same tubes, open at their two ends, the same volumes (the fans that
    // close them for the volume lie in the same planes).
    ResolveOptions o;
    o.mesh.caps = false;
    const ResolveResult open = resolveTextile(tows, o);
    for (std::size_t t = 0; t < 2; ++t) {
        INFO("tow " << tows[t].name());
        CHECK(open.tows[t].boundaryLoops == 2);
        CHECK(testing::boundaryOf(open.mesh.tows[t].triangles).loops == 2);
        CHECK(std::count(open.mesh.tows[t].face.begin(), open.mesh.tows[t].face.end(), TowFace::Side) ==
              static_cast<long>(open.mesh.tows[t].triangles.size()));
        CHECK(open.tows[t].volumeAfter == Approx(res.tows[t].volumeAfter).epsilon(1e-12));
    }
}

TEST_CASE("caps close bent tows and tows given clockwise, facing out", "[resolve][caps]")
{
    testing::Sampling cw;
    cw.sections = 41;
    cw.points = 32;
    cw.counterClockwise = false;  // sections given clockwise: the fit reverses them
    const std::vector<TowSurface> tows{TowSurface::fit(testing::growingBentTube(0.3, 0.5, 3.0, 1.5, cw, "bent")),
                                       TowSurface::fit(testing::tubeAlongX(0.4, 3.0, 0.0, 5.0, 0.0, cw, "straight"))};
    const ResolveResult res = resolveTextile(tows);
    for (std::size_t t = 0; t < tows.size(); ++t) {
        INFO("tow " << tows[t].name());
        const TowMesh& m = res.mesh.tows[t];
        const testing::Boundary b = testing::boundaryOf(m.triangles);
        CHECK(b.edges == 0);
        CHECK(b.misorientedEdges == 0);
        // Outward: a positive volume, the exact one within the faceting (inscribed polygons).
        const double exact = tows[t].volume();
        CHECK(res.tows[t].volumeAfter > 0.97 * exact);
        CHECK(res.tows[t].volumeAfter < exact);
        // Each cap faces away from the tow: along -dS/du at its start, +dS/du at its end.
        for (const TowFace face : {TowFace::Start, TowFace::End}) {
            const double u = face == TowFace::Start ? tows[t].parameterRange().uMin : tows[t].parameterRange().uMax;
            Vector3 along = tows[t].derivatives(u, 0.0).du;
            if (face == TowFace::Start) along = -1.0 * along;
            std::size_t facing = 0, total = 0;
            for (std::size_t k = 0; k < m.triangles.size(); ++k) {
                if (m.face[k] != face) continue;
                ++total;
                const Point3 &a = res.mesh.nodes[m.triangles[k][0]], &p = res.mesh.nodes[m.triangles[k][1]],
                             &c = res.mesh.nodes[m.triangles[k][2]];
                facing += dot(cross(p - a, c - a), along) > 0.0;
            }
            CHECK(total > 0);
            CHECK(facing == total);
        }
    }
}

TEST_CASE("a mesh size too coarse for a concave end section is refused, naming the tow and end", "[resolve][caps]")
{
    // A C-shaped section (radius 1, 0.1 thick, from -150 to 150 degrees) along x: at h = 2 the
    // tube's end nodes, about h apart, cut across the C (at 1.5 and below they do not).
    TowStack c;
    c.name = "crescent";
    const double pi = 3.14159265358979323846;
    for (std::size_t i = 0; i < 11; ++i) {
        std::vector<Point3> section;
        const double x = 0.4 * static_cast<double>(i);
        for (std::size_t k = 0; k < 64; ++k) {
            const double s = static_cast<double>(k) / 64.0;  // outer arc, then inner arc back
            const double angle = s < 0.5 ? -150.0 + 600.0 * s : 150.0 - 600.0 * (s - 0.5);
            const double r = s < 0.5 ? 1.0 : 0.9;
            section.push_back({x, r * std::cos(angle * pi / 180.0), r * std::sin(angle * pi / 180.0)});
        }
        c.sections.push_back(section);
    }
    const std::vector<TowSurface> tows{TowSurface::fit(c)};
    ResolveOptions o;
    o.mesh.edgeLength = 0.1;
    const ResolveResult fine = resolveTextile(tows, o);
    CHECK(fine.tows[0].boundaryLoops == 0);
    CHECK(testing::boundaryOf(fine.mesh.tows[0].triangles).misorientedEdges == 0);
    o.mesh.edgeLength = 2.0;  // below the cap of a quarter of the circumference (pi x 3.18 / 4)
    try {
        resolveTextile(tows, o);
        FAIL("a cap across the C was made");
    } catch (const Error& e) {
        CHECK(e.code() == ErrorCode::InvalidArgument);
        CHECK(std::string(e.what()).find("tow 'crescent'") != std::string::npos);
        CHECK(e.message().find("cap cannot be meshed") != std::string::npos);
        CHECK(e.message().find("--no-caps") != std::string::npos);
    }
    o.mesh.caps = false;
    CHECK(resolveTextile(tows, o).tows[0].boundaryLoops == 2);
}
