// ParametricMesher on its own: one tow meshed with the host's constraint polylines (a ring, a
// line over the seam), closed by its caps; geometry checked against the exact surface.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <set>
#include <utility>
#include <vector>

#include "mesh_checks.hpp"
#include "synthetic_tows.hpp"
#include "towgeom/towgeom.hpp"

using namespace towgeom;

namespace {

constexpr double kPi = 3.14159265358979323846;

TowStack scaled(TowStack s, double factor)
{
    for (auto& section : s.sections)
        for (Point3& p : section) p = factor * p;
    return s;
}

/// A ring of 24 points around (u0, v0) and a line at u = u1 over the seam (two pieces).
std::vector<MeshConstraint> ringAndSeamLine(const ParameterRange& r)
{
    MeshConstraint ring;
    ring.closed = true;
    const double u0 = r.uMin + 0.5 * (r.uMax - r.uMin), v0 = r.vMin + 0.5 * r.vPeriod();
    for (int k = 0; k < 24; ++k)
        ring.points.push_back({u0 + 0.05 * (r.uMax - r.uMin) * std::cos(k * kPi / 12), v0 + 0.1 * r.vPeriod() * std::sin(k * kPi / 12)});
    const double u1 = r.uMin + 0.3 * (r.uMax - r.uMin);
    MeshConstraint before{{{u1, r.vMin + 0.8 * r.vPeriod()}, {u1, r.vMax}}, false};
    MeshConstraint after{{{u1, r.vMin}, {u1, r.vMin + 0.2 * r.vPeriod()}}, false};
    return {ring, before, after};
}

std::set<std::pair<std::size_t, std::size_t>> edgesOf(const SurfaceMesh& m)
{
    std::set<std::pair<std::size_t, std::size_t>> e;
    for (const auto& t : m.triangles)
        for (int k = 0; k < 3; ++k) e.emplace(std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]));
    return e;
}

}  // namespace

TEST_CASE("ParametricMesher: a tube with a ring and a line over the seam, closed by its caps", "[mesher]")
{
    testing::Sampling s;
    s.sections = 21;
    s.points = 24;
    const TowSurface tow = TowSurface::fit(testing::tubeAlongX(0.5, 4.0, 0.0, 0.0, 0.0, s, "x"));
    const ParameterRange r = tow.parameterRange();
    const std::vector<MeshConstraint> constraints = ringAndSeamLine(r);
    const ParametricMesher mesher(tow);
    CHECK(mesher.edgeLength() == Approx(0.1 * tow.towSize()));
    const SurfaceMesh m = mesher.mesh(constraints);

    // A closed, consistently oriented surface; its area and volume those of the exact surface.
    const testing::Boundary b = testing::boundaryOf(m.triangles);
    CHECK(b.edges == 0);
    CHECK(b.nonManifoldEdges == 0);
    CHECK(b.misorientedEdges == 0);
    REQUIRE(m.face.size() == m.triangles.size());
    REQUIRE(m.fibreDirection.size() == m.triangles.size());
    TriangleMesh side, closed;
    closed.vertices = side.vertices = m.nodes;
    closed.triangles = m.triangles;
    double sideArea = 0.0;
    for (std::size_t k = 0; k < m.triangles.size(); ++k) {
        const auto& t = m.triangles[k];
        if (m.face[k] == TowFace::Side)
            sideArea += 0.5 * norm(cross(m.nodes[t[1]] - m.nodes[t[0]], m.nodes[t[2]] - m.nodes[t[0]]));
        // The tube runs along x: every fibre direction is +-x, unit.
        CHECK(norm(m.fibreDirection[k]) == Approx(1.0).epsilon(1e-12));
        CHECK(std::abs(m.fibreDirection[k].x) > 0.999);
    }
    // Flat triangles of side h ~ 0.1 x the size on a radius-0.5 tube: about h^2 / (12 R^2) short.
    CHECK(sideArea == Approx(tow.area()).epsilon(3e-3));
    CHECK(enclosedVolume(closed) == Approx(tow.volume()).epsilon(3e-3));

    // Every node with a (u,v) is the surface point there; the constraints are chains of edges.
    std::size_t onSurface = 0;
    for (std::size_t n = 0; n < m.nodes.size(); ++n) {
        if (std::isnan(m.uv[n].u)) continue;
        ++onSurface;
        CHECK(distance(m.nodes[n], tow.point(m.uv[n].u, m.uv[n].v)) <= 1e-12 * tow.towSize());
    }
    CHECK(onSurface < m.nodes.size());  // cap nodes have none
    const auto edges = edgesOf(m);
    REQUIRE(m.constraintNodes.size() == 3);
    CHECK(m.constraintNodes[0].size() >= 24);
    for (std::size_t c = 0; c < 3; ++c) {
        const auto& nodes = m.constraintNodes[c];
        const std::size_t chords = constraints[c].closed ? nodes.size() : nodes.size() - 1;
        for (std::size_t k = 0; k < chords; ++k) {
            const std::size_t a = nodes[k], z = nodes[(k + 1) % nodes.size()];
            CHECK(edges.count({std::min(a, z), std::max(a, z)}) == 1);
        }
    }
    // The line's seam point is one node of both pieces.
    CHECK(m.constraintNodes[1].back() == m.constraintNodes[2].front());
    // The ring's inside: its triangles' (u,v) centroids are not needed; its nodes lie on the
    // ring's ellipse in (u,v) or between two of its points.
    for (std::size_t n : m.constraintNodes[0]) {
        const double du = (m.uv[n].u - 0.5 * (r.uMin + r.uMax)) / (0.05 * (r.uMax - r.uMin));
        const double dv = (m.uv[n].v - (r.vMin + 0.5 * r.vPeriod())) / (0.1 * r.vPeriod());
        CHECK(du * du + dv * dv <= 1.0 + 1e-12);
        CHECK(du * du + dv * dv >= std::cos(kPi / 24) * std::cos(kPi / 24) - 1e-12);  // a chord's middle at worst
    }
}

TEST_CASE("ParametricMesher: the same mesh in any units, a tube without caps, bad input refused", "[mesher]")
{
    testing::Sampling s;
    s.sections = 21;
    s.points = 24;
    const TowStack stack = testing::tubeAlongX(0.5, 4.0, 0.0, 0.0, 0.0, s, "x");
    const TowSurface tow = TowSurface::fit(stack);
    const SurfaceMesh m = ParametricMesher(tow).mesh(ringAndSeamLine(tow.parameterRange()));
    for (double factor : {1024.0, 1.0 / 1024.0, 1000.0}) {
        INFO(factor);
        const TowSurface big = TowSurface::fit(scaled(stack, factor));
        const SurfaceMesh mb = ParametricMesher(big).mesh(ringAndSeamLine(big.parameterRange()));
        if (factor == 1000.0) {  // not a power of two: rounding may move a refinement step
            CHECK(mb.triangles.size() == Approx(m.triangles.size()).epsilon(0.02));
        } else {
            CHECK(mb.triangles == m.triangles);
            for (std::size_t n = 0; n < m.nodes.size(); ++n) CHECK(distance(factor * m.nodes[n], mb.nodes[n]) <= 1e-12 * factor);
        }
    }
    SurfaceMeshOptions open;
    open.caps = false;
    const SurfaceMesh tube = ParametricMesher(tow, open).mesh();
    CHECK(testing::boundaryOf(tube.triangles).loops == 2);
    for (const TowFace f : tube.face) CHECK(f == TowFace::Side);

    const auto code = [](const std::function<void()>& f) {
        try {
            f();
        } catch (const Error& e) {
            return e.code();
        }
        return ErrorCode::Internal;  // nothing thrown: fails the checks below
    };
    const ParameterRange r = tow.parameterRange();
    CHECK(code([&] { ParametricMesher(tow).mesh({{{{r.uMin, r.vMin + 0.5}, {r.uMax + 0.1, r.vMin + 0.5}}, false}}); }) ==
          ErrorCode::InvalidArgument);                                                       // off the rectangle
    CHECK(code([&] { ParametricMesher(tow).mesh({{{{0.5, 0.5}, {0.5, 0.5}}, false}}); }) == ErrorCode::InvalidArgument);  // repeated
    CHECK(code([&] { ParametricMesher(tow).mesh({{{{0.5, 0.5}, {0.6, 0.5}}, true}}); }) == ErrorCode::InvalidArgument);   // 2 closed
    SurfaceMeshOptions coarse;
    coarse.relativeEdgeLength = 1.0;  // over pi / 4
    CHECK(code([&] { ParametricMesher(tow, coarse); }) == ErrorCode::InvalidArgument);
    SurfaceMeshOptions fine;
    fine.relativeEdgeLength = 0.002;  // about 7 million triangles
    fine.maxTriangles = 1'000'000;
    CHECK(code([&] { ParametricMesher(tow, fine).mesh(); }) == ErrorCode::TooLarge);

    // Constraints meet only at points they share: crossing, ending on a chord, or running along
    // the seam or an end is refused; a shared point is one node of both.
    const auto at = [&](double u, double v) { return UV{r.uMin + u * (r.uMax - r.uMin), r.vMin + v * r.vPeriod()}; };
    const MeshConstraint a{{at(0.3, 0.3), at(0.7, 0.7)}, false};
    CHECK(code([&] { ParametricMesher(tow).mesh({a, {{at(0.3, 0.7), at(0.7, 0.3)}, false}}); }) == ErrorCode::InvalidArgument);
    CHECK(code([&] { ParametricMesher(tow).mesh({a, {{at(0.3, 0.7), at(0.5, 0.5)}, false}}); }) == ErrorCode::InvalidArgument);
    CHECK(code([&] { ParametricMesher(tow).mesh({{{at(0.3, 0.0), at(0.6, 0.0)}, false}}); }) == ErrorCode::InvalidArgument);
    const SurfaceMesh shared = ParametricMesher(tow).mesh({{{at(0.3, 0.3), at(0.5, 0.5)}, false}, {{at(0.5, 0.5), at(0.7, 0.3)}, false}});
    CHECK(shared.constraintNodes[0].back() == shared.constraintNodes[1].front());
}

TEST_CASE("ParametricMesher: a size function grades the mesh where the host asks", "[mesher][size]")
{
    testing::Sampling s;
    s.sections = 21;
    s.points = 24;
    const TowSurface tow = TowSurface::fit(testing::tubeAlongX(0.5, 4.0, 0.0, 0.0, 0.0, s, "x"));
    const ParameterRange r = tow.parameterRange();
    const double uMid = 0.5 * (r.uMin + r.uMax);
    SurfaceMeshOptions uniform;
    uniform.caps = false;
    SurfaceMeshOptions graded = uniform;
    const double h = 0.1 * tow.towSize();
    graded.size = [&](const UV& at) { return at.u < uMid ? h / 3.0 : h; };  // 3x finer on the first half
    const SurfaceMesh a = ParametricMesher(tow, uniform).mesh(), b = ParametricMesher(tow, graded).mesh();
    const auto trianglesBefore = [&](const SurfaceMesh& m) {
        std::size_t n = 0;
        for (const auto& t : m.triangles) n += (m.nodes[t[0]].x + m.nodes[t[1]].x + m.nodes[t[2]].x) / 3.0 < 2.0;
        return n;
    };
    // The first half: about 9x the triangles (h/3); the second: about the same as uniform.
    const double firstHalf = double(trianglesBefore(b)) / double(trianglesBefore(a));
    const double secondHalf = double(b.triangles.size() - trianglesBefore(b)) / double(a.triangles.size() - trianglesBefore(a));
    WARN("graded / uniform triangles: first half " << firstHalf << ", second half " << secondHalf);
    CHECK(firstHalf > 6.0);
    CHECK(firstHalf < 12.0);
    CHECK(secondHalf < 1.5);
    CHECK(testing::boundaryOf(b.triangles).loops == 2);
    // The edges: about h/3 long on the first half, about h on the second (means, 3D).
    double sum[2] = {0.0, 0.0};
    std::size_t count[2] = {0, 0};
    for (const auto& t : b.triangles)
        for (int k = 0; k < 3; ++k) {
            const Point3 &p = b.nodes[t[k]], &q = b.nodes[t[(k + 1) % 3]];
            const double x = 0.5 * (p.x + q.x);
            if (x > 1.8 && x < 2.2) continue;  // the grading between them
            sum[x > 2.0] += distance(p, q);
            ++count[x > 2.0];
        }
    const double fine = sum[0] / double(count[0]), coarse = sum[1] / double(count[1]);
    WARN("mean edge: " << fine << " (h/3 = " << h / 3.0 << "), " << coarse << " (h = " << h << ")");
    CHECK(fine < 0.45 * coarse);
    CHECK(fine < 1.1 * h / 3.0);
    CHECK(coarse < 1.1 * h);

    SurfaceMeshOptions bad = uniform;
    bad.size = [](const UV&) { return -1.0; };
    try {
        ParametricMesher(tow, bad).mesh();
        FAIL("a negative size was taken");
    } catch (const Error& e) {
        CHECK(e.code() == ErrorCode::InvalidArgument);
    }
}

TEST_CASE("ParametricMesher: a tube sliced obliquely (sections at 50 degrees to its axis) gets triangles of at least 15 degrees away from its ends",
          "[mesher][oblique]")
{
    // A scan slices a binder that crosses the thickness at an angle: its sections lie in planes
    // oblique to it, and dS/du meets dS/dv at 40 degrees. The same cylinder (radius 0.5, length
    // 16 along x) with its sections sheared: x += y tan(50 deg) keeps every point on it.
    testing::Sampling s;
    s.sections = 81;
    s.points = 32;
    TowStack stack = testing::tubeAlongX(0.5, 16.0, 0.0, 0.0, 0.0, s, "oblique");
    const double shear = std::tan(50.0 * kPi / 180.0);
    for (auto& section : stack.sections)
        for (Point3& p : section) p.x += shear * p.y;
    const TowSurface tow = TowSurface::fit(stack);
    // Triangles under h/8 (those of a loop's surroundings) are shaped in the plane alone: the
    // middle is meshed at h/12.
    const ParameterRange r = tow.parameterRange();
    SurfaceMeshOptions o;
    const double h = 0.1 * tow.towSize(), uMid = 0.5 * (r.uMin + r.uMax), reach = 0.0625 * (r.uMax - r.uMin);
    o.size = [&](const UV& at) { return std::abs(at.u - uMid) < reach ? h / 12.0 : h; };
    const SurfaceMesh m = ParametricMesher(tow, o).mesh({});
    double sideArea = 0.0, middleWorst = 180.0;
    std::size_t side = 0, below15 = 0;
    for (std::size_t k = 0; k < m.triangles.size(); ++k) {
        if (m.face[k] != TowFace::Side) continue;
        const auto& t = m.triangles[k];
        const Point3 &a = m.nodes[t[0]], &b = m.nodes[t[1]], &c = m.nodes[t[2]];
        sideArea += 0.5 * norm(cross(b - a, c - a));
        const auto angle = [](const Point3& p, const Point3& q, const Point3& r) {
            return std::atan2(norm(cross(q - p, r - p)), dot(q - p, r - p)) * 180.0 / kPi;
        };
        const double smallest = std::min({angle(a, b, c), angle(b, c, a), angle(c, a, b)});
        ++side;
        below15 += smallest < 15.0;
        // Inside the fine middle (u within a sixteenth of the length of its middle: x within
        // 7-9 +-0.6), far from the oblique ends, where the plane is not squared.
        if (std::min({a.x, b.x, c.x}) > 7.7 && std::max({a.x, b.x, c.x}) < 8.3) middleWorst = std::min(middleWorst, smallest);
    }
    // The lateral area between two parallel planes, whatever their slope: 2 pi r L.
    CHECK(sideArea == Approx(2.0 * kPi * 0.5 * 16.0).epsilon(3e-3));
    INFO(below15 << " of " << side << " triangles under 15 degrees");
    CHECK(middleWorst >= 15.0);
    CHECK(static_cast<double>(below15) <= 1e-3 * static_cast<double>(side));
}
