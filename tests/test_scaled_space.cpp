// ScaledSpace (mesh/scaled_space.hpp): the plane a tow is meshed in, squared where its sections
// are oblique. Checked on a cylinder sliced at 50 degrees through the surface itself: lines of
// constant x cross the tow square (finite differences of S along them), the map inverts, and the
// seam and the ends are exactly where the linear map puts them.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "mesh/scaled_space.hpp"
#include "towgeom/surface_mesher.hpp"
#include "towgeom/tow_stack.hpp"
#include "towgeom/tow_surface.hpp"

using namespace towgeom;
using namespace towgeom::detail;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// A cylinder of radius 0.5 along x, length 16, 81 sections of 32 points sheared by tan(@p degrees).
TowSurface slicedCylinder(double degrees)
{
    TowStack s;
    s.name = "sliced";
    const double shear = std::tan(degrees * kPi / 180.0);
    for (int i = 0; i < 81; ++i) {
        std::vector<Point3> section;
        for (int j = 0; j < 32; ++j) {
            const double a = 2.0 * kPi * j / 32.0, y = 0.5 * std::cos(a), z = 0.5 * std::sin(a);
            section.push_back({16.0 * i / 80.0 + shear * y, y, z});
        }
        s.sections.push_back(section);
    }
    return TowSurface::fit(s);
}

double cosine(const Vector3& a, const Vector3& b) { return dot(a, b) / (norm(a) * norm(b)); }

}  // namespace

TEST_CASE("ScaledSpace: on an obliquely sliced tow, lines of constant x cross it square, the map inverts, seam and ends stay put",
          "[mesher][oblique]")
{
    const TowSurface tow = slicedCylinder(50.0);
    const ParameterRange r = tow.parameterRange();
    const double su = 16.0 / (r.uMax - r.uMin), sv = kPi / r.vPeriod();
    const ScaledSpace space(tow, su, sv, true);
    REQUIRE(space.corrected());
    std::mt19937 random(7);
    std::uniform_real_distribution<double> along(r.uMin + 0.3 * (r.uMax - r.uMin), r.uMin + 0.7 * (r.uMax - r.uMin));
    std::uniform_real_distribution<double> around(r.vMin, r.vMax);
    double worstBefore = 0.0, worstAfter = 0.0, worstTrip = 0.0, worstSlope = 0.0;
    for (int k = 0; k < 200; ++k) {
        const double u = along(random), v = around(random);
        double x = 0.0, y = 0.0;
        space.toXY(u, v, x, y);
        const UV back = space.toUV(x, y);
        worstTrip = std::max({worstTrip, std::abs(back.u - u) / (r.uMax - r.uMin), std::abs(back.v - v) / r.vPeriod()});
        // The surface along x and along y, by central differences through the map.
        const double e = 1e-5;
        const UV xp = space.toUV(x + e, y), xm = space.toUV(x - e, y), yp = space.toUV(x, y + e), ym = space.toUV(x, y - e);
        const Vector3 sx = tow.point(xp.u, xp.v) - tow.point(xm.u, xm.v), sy = tow.point(yp.u, yp.v) - tow.point(ym.u, ym.v);
        const SurfaceDerivatives d = tow.derivatives(u, v);
        worstBefore = std::max(worstBefore, std::abs(cosine(d.du, d.dv)));
        worstAfter = std::max(worstAfter, std::abs(cosine(sx, sy)));
        // slopes() against differences of toXY.
        double x1 = 0.0, x0 = 0.0, yy = 0.0;
        const double du = 1e-7 * (r.uMax - r.uMin), dv = 1e-7 * r.vPeriod();
        space.toXY(u + du, v, x1, yy);
        space.toXY(u - du, v, x0, yy);
        const ScaledSpace::Slopes s = space.slopes(u, v);
        worstSlope = std::max(worstSlope, std::abs((x1 - x0) / (2.0 * du) - s.xu) / su);
        space.toXY(u, v + dv, x1, yy);
        space.toXY(u, v - dv, x0, yy);
        worstSlope = std::max(worstSlope, std::abs((x1 - x0) / (2.0 * dv) - s.xv) / su);
    }
    WARN("|cos| between the parameter lines: " << worstBefore << " in (u,v), " << worstAfter << " in the plane; round trip "
                                               << worstTrip << ", slopes " << worstSlope);
    CHECK(worstBefore > 0.7);  // the sections' 50 degrees: dS/du and dS/dv at about 40 degrees
    // Square up to the grid's piecewise linear x (64 columns around): 0.074 here.
    CHECK(worstAfter < 0.1);
    CHECK(worstTrip < 1e-12);
    CHECK(worstSlope < 1e-3);
    // The seam: both sides the same x to the bit; the ends: the linear map's x.
    for (int k = 0; k <= 50; ++k) {
        const double u = r.uMin + (r.uMax - r.uMin) * k / 50.0;
        double x0 = 0.0, x1 = 0.0, y = 0.0;
        space.toXY(u, r.vMin, x0, y);
        space.toXY(u, r.vMax, x1, y);
        CHECK(x0 == x1);
    }
    for (int k = 0; k < 16; ++k) {
        const double v = r.vMin + r.vPeriod() * k / 16.0;
        double x = 0.0, y = 0.0;
        space.toXY(r.uMin, v, x, y);
        CHECK(x == 0.0);
        CHECK(space.toUV(x, y).u == r.uMin);
        space.toXY(r.uMax, v, x, y);
        CHECK(x == (r.uMax - r.uMin) * su);
    }
}

namespace {

/// A round tube along x, length 8, whose radius swells and shrinks threefold along it:
/// r(x) = 0.5 (1 + 0.5 sin(2 pi x / 8)), 81 sections of 32 points.
double swellingRadius(double x) { return 0.5 * (1.0 + 0.5 * std::sin(2.0 * kPi * x / 8.0)); }
TowSurface swellingTube()
{
    TowStack s;
    s.name = "swelling";
    for (int i = 0; i < 81; ++i) {
        const double x = 8.0 * i / 80.0, r = swellingRadius(x);
        std::vector<Point3> section;
        for (int j = 0; j < 32; ++j) section.push_back({x, r * std::cos(2.0 * kPi * j / 32.0), r * std::sin(2.0 * kPi * j / 32.0)});
        s.sections.push_back(section);
    }
    return TowSurface::fit(s);
}

}  // namespace

/// |S_x| / |S_y| (by central differences through @p space) at 300 random points of @p tow,
/// away from the end cells: the smallest, the largest, and that of their sums (the plane's
/// scale along x against that across).
struct LengthRatios {
    double lo = 1e300, hi = 0.0, mean = 0.0;
};
LengthRatios lengthRatios(const TowSurface& tow, const ScaledSpace& space)
{
    const ParameterRange r = tow.parameterRange();
    std::mt19937 random(11);
    std::uniform_real_distribution<double> along(r.uMin + 0.1 * (r.uMax - r.uMin), r.uMin + 0.9 * (r.uMax - r.uMin));
    std::uniform_real_distribution<double> around(r.vMin, r.vMax);
    LengthRatios out;
    double sumX = 0.0, sumY = 0.0;
    for (int k = 0; k < 300; ++k) {
        double x = 0.0, y = 0.0;
        space.toXY(along(random), around(random), x, y);
        const double e = 1e-5;
        const UV xp = space.toUV(x + e, y), xm = space.toUV(x - e, y), yp = space.toUV(x, y + e), ym = space.toUV(x, y - e);
        const double sx = norm(tow.point(xp.u, xp.v) - tow.point(xm.u, xm.v)), sy = norm(tow.point(yp.u, yp.v) - tow.point(ym.u, ym.v));
        const double ratio = sx / sy;
        sumX += sx;
        sumY += sy;
        out.lo = std::min(out.lo, ratio);
        out.hi = std::max(out.hi, ratio);
    }
    out.mean = sumX / sumY;
    return out;
}

TEST_CASE("ScaledSpace: on a tow sliced obliquely, the conformal length makes the squared plane as long across as along", "[mesher][conformal]")
{
    // Lines of constant x are the sections square to the tow once the plane is squared: the
    // length per unit u is |S_u| over their girth (2 pi r), not over the oblique sections'.
    const TowSurface tow = slicedCylinder(50.0);
    const ParameterRange r = tow.parameterRange();
    const double ly = kPi * tow.towSize();
    const double su = ScaledSpace::conformalLength(tow, ly) / (r.uMax - r.uMin), sv = ly / r.vPeriod();
    // The closed form: x runs 16 / (2 pi 0.5) ly along the cylinder.
    CHECK(su * (r.uMax - r.uMin) == Approx(16.0 / kPi * ly).epsilon(1e-3));
    // Across, y is linear in v, and the fit's v runs unevenly along the oblique sections: the
    // ratio varies around the tow (0.77 .. 1.20); the lengths' sums are the same.
    const LengthRatios q = lengthRatios(tow, ScaledSpace(tow, su, sv, true));
    WARN("sliced at 50 degrees: |S_x| / |S_y| " << q.lo << " .. " << q.hi << ", mean " << q.mean);
    CHECK(q.mean == Approx(1.0).epsilon(0.02));
}

TEST_CASE("ScaledSpace: on a tow whose girth changes threefold, x runs conformally (as long across as along)", "[mesher][conformal]")
{
    const TowSurface tow = swellingTube();
    const ParameterRange r = tow.parameterRange();
    const double ly = kPi * tow.towSize();
    // The closed form: ly times the integral of sqrt(1 + r'^2) / (2 pi r) over x (Simpson, 4000 steps).
    double exact = 0.0;
    const int n = 4000;
    for (int k = 0; k <= n; ++k) {
        const double x = 8.0 * k / n, dr = 0.5 * 0.5 * (2.0 * kPi / 8.0) * std::cos(2.0 * kPi * x / 8.0);
        const double w = k == 0 || k == n ? 1.0 : k % 2 ? 4.0 : 2.0;
        exact += w * std::sqrt(1.0 + dr * dr) / (2.0 * kPi * swellingRadius(x)) * (8.0 / n) / 3.0;
    }
    exact *= ly;
    const double length = ScaledSpace::conformalLength(tow, ly);
    // (The grid's end cells take their share at the mean rate: 8e-4 off.)
    CHECK(length == Approx(exact).epsilon(1.5e-3));
    const double su = length / (r.uMax - r.uMin), sv = ly / r.vPeriod();
    const ScaledSpace conformal(tow, su, sv, true), linear(tow, su, sv, false);
    REQUIRE(conformal.corrected());
    const LengthRatios c = lengthRatios(tow, conformal), l = lengthRatios(tow, linear);
    const double cLo = c.lo, cHi = c.hi, lLo = l.lo, lHi = l.hi;
    WARN("conformal length " << length << " (closed form " << exact << "); |S_x| / |S_y| " << cLo << " .. " << cHi
                             << " conformal, " << lLo << " .. " << lHi << " linear");
    CHECK(lHi / lLo > 2.5);  // the linear map: the girth's threefold change
    CHECK(cLo > 0.99);  // 0.9955 .. 1.0061 measured
    CHECK(cHi < 1.01);
}

TEST_CASE("ParametricMesher: a tow whose girth changes threefold is meshed at its size, its triangles at least 15 degrees",
          "[mesher][conformal]")
{
    // In a plane that is not conformal (three times too short across the tow where it is
    // thickest, next to the one that is), the plane's good triangles are poor on the surface;
    // refining them in the plane does not end until they are an eighth of the mesh size.
    const TowSurface tow = swellingTube();
    const SurfaceMesh m = ParametricMesher(tow).mesh({});
    const double h = 0.1 * tow.towSize();
    double sideArea = 0.0;
    std::size_t side = 0, below15 = 0;
    for (std::size_t k = 0; k < m.triangles.size(); ++k) {
        if (m.face[k] != TowFace::Side) continue;
        const auto& t = m.triangles[k];
        const Point3 &a = m.nodes[t[0]], &b = m.nodes[t[1]], &c = m.nodes[t[2]];
        sideArea += 0.5 * norm(cross(b - a, c - a));
        const auto angle = [](const Point3& p, const Point3& q, const Point3& o) {
            return std::atan2(norm(cross(q - p, o - p)), dot(q - p, o - p)) * 180.0 / kPi;
        };
        ++side;
        below15 += std::min({angle(a, b, c), angle(b, c, a), angle(c, a, b)}) < 15.0;
    }
    // The lateral area: the integral of 2 pi r sqrt(1 + r'^2) over x (Simpson, 4000 steps).
    double area = 0.0;
    const int n = 4000;
    for (int k = 0; k <= n; ++k) {
        const double x = 8.0 * k / n, dr = 0.5 * 0.5 * (2.0 * kPi / 8.0) * std::cos(2.0 * kPi * x / 8.0);
        const double w = k == 0 || k == n ? 1.0 : k % 2 ? 4.0 : 2.0;
        area += w * 2.0 * kPi * swellingRadius(x) * std::sqrt(1.0 + dr * dr) * (8.0 / n) / 3.0;
    }
    // Triangles per equilateral triangle of side h in the area (about 3 for a mesher that keeps
    // every edge under h).
    const double perIdeal = static_cast<double>(side) / (area / (std::sqrt(3.0) / 4.0 * h * h));
    WARN(side << " side triangles, " << perIdeal << " per equilateral triangle of side h; " << below15 << " under 15 degrees");
    CHECK(sideArea == Approx(area).epsilon(3e-3));
    CHECK(perIdeal < 4.0);
    CHECK(below15 == 0);
}
