// Tows as closed solids: resolveTextile() closes every tow by its two end caps (planar meshes of
// its end sections with the tube's end nodes). Checked on the output alone: the caps lie in the
// end sections' planes, face out of the tow, cover the section's exact area, and make each tow a
// closed 2-manifold whose CGAL volume is the reported one; without caps the tubes are open.
#include <catch2/catch.hpp>

#include <towgeom/resolve.hpp>
#include <towgeom/textile_mesh.hpp>
#include <towgeom/tow_surface.hpp>

#include <algorithm>
#include <cmath>
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
