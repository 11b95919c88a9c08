// ScaledSpace (mesh/scaled_space.hpp): the plane a tow is meshed in, squared where its sections
// are oblique. Checked on a cylinder sliced at 50 degrees through the surface itself: lines of
// constant x cross the tow square (finite differences of S along them), the map inverts, and the
// seam and the ends are exactly where the linear map puts them.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "mesh/scaled_space.hpp"
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
