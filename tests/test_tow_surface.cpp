// TowSurface: accuracy of the fits against closed forms, orientation, seam continuity, queries.
#include <catch2/catch.hpp>

#include <towgeom/towgeom.hpp>

#include <cmath>
#include <random>

#include "analytic_reference.hpp"
#include "synthetic_tows.hpp"

using namespace towgeom;
using testing::Sampling;

namespace {

constexpr double kPi = 3.14159265358979323846;

double relative(double value, double exact) { return std::fabs(value - exact) / std::fabs(exact); }

/// Checks that normals point away from the x axis (for tubes along x) at a grid of (u,v).
void checkOutwardAboutXAxis(const TowSurface& s)
{
    const ParameterRange r = s.parameterRange();
    for (int i = 0; i <= 10; ++i)
        for (int j = 0; j < 16; ++j) {
            const double u = r.uMin + (r.uMax - r.uMin) * i / 10.0, v = r.vMin + r.vPeriod() * j / 16.0;
            const Point3 p = s.point(u, v);
            const Vector3 n = s.normal(u, v);
            const Vector3 radial{0.0, p.y, p.z};
            REQUIRE(dot(n, radial) > 0.5 * norm(radial));
            REQUIRE(std::fabs(norm(n) - 1.0) < 1e-12);
        }
}

using testing::BSplineCircle;
using testing::interpolatingControlRadius;
using testing::uniformBSplineCircle;

}  // namespace

TEST_CASE("straight circular tube r=0.5 L=4, 21x24: interpolation keeps the volume", "[surface][accuracy]")
{
    const double r = 0.5, length = 4.0, exact = kPi * r * r * length;
    const TowStack stack = testing::ellipticalTube(r, r, length, {21, 24});
    const TowSurface interp = TowSurface::fit(stack);
    const TowSurface net = TowSurface::fit(stack, {FitMode::ControlNet});
    const Deviation dev = interp.deviation();
    // A straight tube of identical sections: volume = section area x length, area = perimeter x
    // length, with the sections' B-splines known exactly (testing::uniformBSplineCircle: the
    // periodic cubic B-spline with knots at the samples' parameters, uniform here).
    const BSplineCircle interpSection = uniformBSplineCircle(24, interpolatingControlRadius(24, r));
    const BSplineCircle netSection = uniformBSplineCircle(24, r);

    WARN("interpolate volume " << interp.volume() << " (" << 100 * (interp.volume() / exact - 1) << " % from the cylinder, "
                               << relative(interp.volume(), interpSection.area * length) << " from the B-spline reference), faceted "
                               << interp.facetedVolume() << " (" << 100 * (interp.facetedVolume() / exact - 1)
                               << " %), controlnet " << net.volume() << " (" << 100 * (net.volume() / exact - 1)
                               << " %), max deviation " << dev.max);
    // Interpolation: 1.3e-5 below the cylinder, exactly the reference B-spline's section area.
    CHECK(relative(interp.volume(), interpSection.area * length) < 1e-12);
    CHECK(relative(interp.volume(), exact) == Approx(1.326307e-5).epsilon(1e-6));
    CHECK(dev.max <= 5e-15);
    CHECK(dev.rms <= dev.max);
    // The faceted input: a prism over the inscribed 24-gon, (12 / pi) sin(pi / 12) - 1 = -1.138 %.
    CHECK(std::fabs(interp.facetedVolume() / exact - (12.0 / kPi * std::sin(kPi / 12.0))) < 1e-13);
    // The control-net surface is the reference B-spline on the samples: 2.26 % low.
    CHECK(relative(net.volume(), netSection.area * length) < 1e-12);
    CHECK(net.volume() < interp.facetedVolume());
    // Where a control point sits, the curve is at (P[j-1] + 4 P[j] + P[j+1]) / 6: r (4 + 2 cos 15deg) / 6.
    CHECK(net.deviation().max == Approx(r * (1 - (4 + 2 * std::cos(kPi / 12)) / 6)).epsilon(1e-12));
    // Section area and surface area against the reference B-spline's area and perimeter.
    CHECK(relative(interp.sectionArea(0.37), interpSection.area) < 1e-12);
    CHECK(relative(interp.area(), interpSection.perimeter * length) < 1e-12);
    CHECK(interp.mode() == FitMode::Interpolate);
    CHECK(interp.controlPointCount(true) == 21);
    CHECK(interp.controlPointCount(false) == 24);
}

TEST_CASE("control-net fit loses about half a percent at 48 points around", "[surface][accuracy]")
{
    const double r = 0.5, length = 4.0, exact = kPi * r * r * length;
    const TowSurface net = TowSurface::fit(testing::ellipticalTube(r, r, length, {21, 48}), {FitMode::ControlNet});
    const double loss = 1.0 - net.volume() / exact;
    // The uniform B-spline on the 48 samples: 1 - area / (pi r^2) = 0.5696 %.
    const double expected = 1.0 - uniformBSplineCircle(48, r).area / (kPi * r * r);
    WARN("controlnet volume loss at 21x48: " << 100 * loss << " %, reference " << 100 * expected << " %");
    CHECK(loss == Approx(expected).epsilon(1e-10));
    CHECK(loss == Approx(5.696108e-3).epsilon(1e-6));
}

TEST_CASE("elliptical tube with its start rotated by 90 degrees, both orientations", "[surface][accuracy]")
{
    const double a = 0.6, b = 0.2, length = 3.0, exact = kPi * a * b * length;
    for (const bool ccw : {true, false}) {
        DYNAMIC_SECTION((ccw ? "counter-clockwise" : "clockwise") << " input")
        {
            Sampling s{21, 24, kPi / 2, ccw};
            const TowSurface surface = TowSurface::fit(testing::ellipticalTube(a, b, length, s));
            CHECK(surface.inputReversed() == ccw);
            CHECK(surface.startShifts() == std::vector<std::size_t>(21, 0));  // consistent starts stay
            // Observed 9.23e-5 (24 points around a 3:1 ellipse, started at its flat side).
            CHECK(relative(surface.volume(), exact) < 2e-4);
            CHECK(surface.volume() > 0.0);
            CHECK(surface.deviation().max <= 5e-15);  // observed 1.4e-15
            checkOutwardAboutXAxis(surface);
            // The seam runs through the first input point of every section: (0, 0, b) here.
            const Point3 seam = surface.point(0.5, 0.0);
            CHECK(std::fabs(seam.y) < 1e-12);
            CHECK(seam.z == Approx(b).epsilon(1e-12));
            // C2 across the seam: both sides evaluated on their own knot spans.
            for (const double u : {0.0, 0.3, 0.71, 1.0}) {
                const SeamJump j = surface.seamJump(u);
                // C2 to rounding: observed at most 1.6e-14 (second derivative, of size ~10).
                CHECK(j.position <= 1e-15);
                CHECK(j.first <= 1e-14);
                CHECK(j.second <= 5e-14);
            }
        }
    }
}

TEST_CASE("bent tube: volume by Pappus, closest points, iso-curves", "[surface][accuracy]")
{
    const double r = 0.3, bend = 2.0, sweep = kPi / 2;
    const TowSurface s = TowSurface::fit(testing::bentTube(r, bend, sweep, {41, 32}));
    const double exact = kPi * r * r * bend * sweep;
    CHECK(relative(s.volume(), exact) < 1e-5);  // observed 4.2e-6

    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int k = 0; k < 40; ++k) {
        const double u = 0.05 + 0.9 * unit(rng), v = unit(rng);
        const Point3 p = s.point(u, v);
        const Vector3 n = s.normal(u, v);
        const double offset = 0.05 * r;
        const Point3 q = p + offset * n;
        const UV found = s.closestParameters(q);
        CHECK(distance(s.point(found.u, found.v), p) < 1e-12);  // observed 5e-16
        const UV local = s.closestParameters(q, {u + 0.01, v - 0.01});
        CHECK(distance(s.point(local.u, local.v), p) < 1e-12);
        // Normals point away from the centre line.
        const double phi = std::atan2(p.y, p.x);
        const Point3 centre{bend * std::cos(phi), bend * std::sin(phi), 0.0};
        CHECK(dot(n, p - centre) > 0.9 * r);
    }

    const Curve3 section = s.isoU(0.5);
    CHECK(section.closed());
    CHECK(section.length() == Approx(2 * kPi * r).epsilon(5e-6));  // observed 2.1e-6
    const double tol = 1e-4 * r;
    const std::vector<Point3> poly = section.polyline(tol);
    CHECK(poly.size() >= 8);
    // The closing point is not repeated: the last point is one chord before the first.
    CHECK(distance(poly.front(), poly.back()) > 0.5 * 2 * kPi * r / static_cast<double>(poly.size()));
    for (const Point3& p : poly) {
        const double rho = std::hypot(std::hypot(p.x, p.y) - bend, p.z);
        CHECK(rho == Approx(r).epsilon(1e-5));  // the fit's own error: observed 3.9e-6
    }
    const std::vector<Point3> spaced = section.polylineBySpacing(0.1 * r);
    CHECK(spaced.size() >= static_cast<std::size_t>(2 * kPi * 10));
    for (std::size_t i = 0; i < spaced.size(); ++i)
        CHECK(distance(spaced[i], spaced[(i + 1) % spaced.size()]) <= 0.1 * r * 1.001);
}

TEST_CASE("a tow bent through 350 degrees, growing along it, keeps outward normals", "[surface][accuracy]")
{
    const double r0 = 0.2, r1 = 0.45, bend = 2.0, sweep = 350.0 / 180.0 * kPi;
    for (const bool ccw : {true, false}) {
        Sampling sampling{121, 32, 0.0, ccw};
        const TowSurface s = TowSurface::fit(testing::growingBentTube(r0, r1, bend, sweep, sampling));
        const double exact = kPi * bend * sweep * (r0 * r0 + r0 * r1 + r1 * r1) / 3;
        INFO((ccw ? "counter-clockwise" : "clockwise") << " input, volume " << s.volume() << ", exact " << exact);
        CHECK(s.inputReversed() == ccw);
        CHECK(s.startShifts() == std::vector<std::size_t>(121, 0));
        CHECK(relative(s.volume(), exact) < 1e-5);  // observed 4.2e-6
        for (const double u : {0.0, 0.25, 0.5, 0.75, 1.0})
            for (const double v : {0.0, 0.3, 0.6}) {
                const Point3 p = s.point(u, v);
                const double phi = std::atan2(p.y, p.x);
                const Point3 centre{bend * std::cos(phi), bend * std::sin(phi), 0.0};
                CHECK(dot(s.normal(u, v), p - centre) > 0.9 * distance(p, centre));
            }
    }
}

TEST_CASE("derivatives agree with finite differences", "[surface]")
{
    const TowSurface s = TowSurface::fit(testing::crimpedTow(0.5, 0.12, 4.0, 0.1, 2.0, {60, 32}));
    const double h = 1e-6;
    for (const double u : {0.1, 0.5, 0.93})
        for (const double v : {0.0, 0.25, 0.999}) {
            const SurfaceSecondDerivatives d = s.secondDerivatives(u, v);
            const Vector3 du = (1 / (2 * h)) * (s.point(u + h, v) - s.point(u - h, v));
            const Vector3 dv = (1 / (2 * h)) * (s.point(u, v + h) - s.point(u, v - h));
            CHECK(distance(du, d.du) < 1e-5 * norm(d.du));
            CHECK(distance(dv, d.dv) < 1e-5 * norm(d.dv));
            const SurfaceDerivatives a = s.derivatives(u + h, v), b = s.derivatives(u - h, v);
            const Vector3 duu = (1 / (2 * h)) * (a.du - b.du);
            CHECK(distance(duu, d.duu) < 1e-4 * std::max(1.0, norm(d.duu)));
        }
    // v wraps: v and v + 1 are the same point.
    CHECK(distance(s.point(0.4, 0.2), s.point(0.4, 1.2)) < 1e-12);
    CHECK(distance(s.point(0.4, -0.3), s.point(0.4, 0.7)) < 1e-12);
}

TEST_CASE("approximation meets its tolerance with fewer control points", "[surface]")
{
    const TowStack stack = testing::crimpedTow(0.5, 0.2, 4.0, 0.1, 2.0, {80, 48});
    const double tolerance = 1e-3;
    const TowSurface approx = TowSurface::fit(stack, {FitMode::Approximate, tolerance});
    const TowSurface interp = TowSurface::fit(stack);
    CHECK(approx.deviation().max <= tolerance);
    CHECK(approx.deviation().max > 1e-9);  // it really approximated
    CHECK(approx.controlPointCount(true) * approx.controlPointCount(false) <
          interp.controlPointCount(true) * interp.controlPointCount(false) / 2);
    CHECK(relative(approx.volume(), interp.volume()) < 2e-3);
}

TEST_CASE("tessellation is a tube with outward triangles", "[surface]")
{
    const double r = 0.5, length = 4.0;
    const TowSurface s = TowSurface::fit(testing::ellipticalTube(r, r, length, {21, 24}));
    const TriangleMesh mesh = s.tessellate(41, 48);
    CHECK(mesh.vertices.size() == 41 * 48);
    CHECK(mesh.triangles.size() == 2 * 40 * 48);
    REQUIRE(mesh.normals.size() == mesh.vertices.size());
    for (const auto& t : mesh.triangles) {
        const Point3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
        const Vector3 n = cross(b - a, c - a);
        const Point3 centroid = (1.0 / 3.0) * (a + b + c);
        REQUIRE(dot(n, Vector3{0.0, centroid.y, centroid.z}) > 0.0);
    }
    // Every vertex lies on the fitted surface: at the knots on the cylinder, at the middle of a
    // span (every other vertex around) 1.24e-5 r inside it, where the reference B-spline is.
    const double mid = uniformBSplineCircle(24, interpolatingControlRadius(24, r)).midRadius;
    double lowest = r, highest = 0.0;
    for (const Point3& p : mesh.vertices) {
        lowest = std::min(lowest, std::hypot(p.y, p.z));
        highest = std::max(highest, std::hypot(p.y, p.z));
    }
    CHECK(lowest == Approx(mid).epsilon(1e-12));
    CHECK(highest == Approx(r).epsilon(1e-12));
    CHECK(1.0 - mid / r == Approx(1.24441e-5).epsilon(1e-4));
}

TEST_CASE("invalid queries and options are refused with a typed error", "[surface]")
{
    const TowSurface s = TowSurface::fit(testing::ellipticalTube(0.5, 0.5, 4.0, {21, 24}));
    CHECK_THROWS_AS(s.point(1.5, 0.0), Error);
    CHECK_THROWS_AS(s.point(std::nan(""), 0.0), Error);
    CHECK_THROWS_AS(s.tessellate(1, 10), Error);
    CHECK_THROWS_AS(s.isoU(0.5).polyline(0.0), Error);
    try {
        TowSurface::fit(testing::ellipticalTube(0.5, 0.5, 4.0, {21, 24}), {FitMode::Approximate, -1.0});
        FAIL("negative tolerance accepted");
    } catch (const Error& e) {
        CHECK(e.code() == ErrorCode::InvalidArgument);
    }
    const BoundingBox box = s.boundingBox();
    for (const double u : {0.0, 0.5, 1.0})
        for (const double v : {0.0, 0.3, 0.6, 0.9}) {
            const Point3 p = s.point(u, v);
            CHECK(p.x >= box.min.x - 1e-12);
            CHECK(p.x <= box.max.x + 1e-12);
            CHECK(p.y >= box.min.y);
            CHECK(p.y <= box.max.y);
            CHECK(p.z >= box.min.z);
            CHECK(p.z <= box.max.z);
        }
    // Conservative but not loose: the control points' box, whose radius around is the
    // interpolating control radius r 6 / (4 + 2 cos 15deg) = 1.0115 r.
    CHECK(box.max.y == Approx(interpolatingControlRadius(24, 0.5)).epsilon(1e-12));
    CHECK(box.min.z == Approx(-interpolatingControlRadius(24, 0.5)).epsilon(1e-12));
    CHECK(box.min.x == Approx(0.0).margin(1e-9));
    CHECK(box.max.x == Approx(4.0).margin(1e-9));
}

// ---------------------------------------------------------------------------------------------
// Start points: sections whose first point drifts around the tow are renumbered by fit().

namespace {

bool same(const Point3& a, const Point3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

bool sameSections(const std::vector<std::vector<Point3>>& a, const std::vector<std::vector<Point3>>& b)
{
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i].size() != b[i].size()) return false;
        for (std::size_t j = 0; j < a[i].size(); ++j)
            if (!same(a[i][j], b[i][j])) return false;
    }
    return true;
}

/// Normals point away from the centroid of their own section curve, at a grid of (u,v).
void checkOutwardFromSectionCentres(const TowSurface& s)
{
    for (int a = 0; a <= 10; ++a) {
        const double u = a / 10.0;
        Point3 c;
        for (int b = 0; b < 64; ++b) c = c + (1.0 / 64) * s.point(u, b / 64.0);
        for (int b = 0; b < 64; ++b) {
            const Point3 p = s.point(u, b / 64.0);
            REQUIRE(dot(s.normal(u, b / 64.0), p - c) > 0.0);
        }
    }
}

/// @p stack with the first point of section i moved drift[i] places back: its point j becomes
/// the undrifted point (j - drift[i]) mod N. Renumbering it by a shift of drift[i] (in the
/// input's own direction) gives the undrifted section back.
TowStack drifted(const TowStack& stack, const std::vector<long>& drift)
{
    TowStack out = stack;
    for (std::size_t i = 0; i < stack.sections.size(); ++i) {
        const long n = static_cast<long>(stack.sections[i].size());
        for (long j = 0; j < n; ++j)
            out.sections[i][static_cast<std::size_t>(j)] = stack.sections[i][static_cast<std::size_t>(((j - drift[i]) % n + n) % n)];
    }
    return out;
}

/// The shifts fit() must report for a drift: in the surface's order, i.e. negated when the input
/// is reversed.
std::vector<std::size_t> expectedShifts(const std::vector<long>& drift, long n, bool reversed)
{
    std::vector<std::size_t> out;
    for (const long d : drift) out.push_back(static_cast<std::size_t>((((reversed ? -d : d) % n) + n) % n));
    return out;
}

/// Drift +1 point per section, and a seeded random walk of +-1..3 points per section.
std::vector<long> steadyDrift(std::size_t m)
{
    std::vector<long> d(m);
    for (std::size_t i = 0; i < m; ++i) d[i] = static_cast<long>(i);
    return d;
}
std::vector<long> randomDrift(std::size_t m, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> size(1, 3), sign(0, 1);
    std::vector<long> d(m, 0);
    for (std::size_t i = 1; i < m; ++i) d[i] = d[i - 1] + (sign(rng) ? 1 : -1) * size(rng);
    return d;
}

/// Fits @p stack and its drifted copy; checks the shifts, and that the two surfaces are the
/// same to 1e-12 of the tow size (they are fitted to the same points in the same order).
void checkDriftUndone(const TowStack& stack, const std::vector<long>& drift, FitMode mode = FitMode::Interpolate)
{
    const TowSurface reference = TowSurface::fit(stack, {mode});
    const TowStack input = drifted(stack, drift);
    const TowSurface s = TowSurface::fit(input, {mode});
    const std::size_t m = stack.sectionCount(), n = stack.pointsPerSection();
    REQUIRE(reference.startShifts() == std::vector<std::size_t>(m, 0));
    CHECK(s.inputReversed() == reference.inputReversed());
    CHECK(s.startShifts() == expectedShifts(drift, static_cast<long>(n), s.inputReversed()));
    // sections() holds the renumbered points: exactly the undrifted ones.
    CHECK(sameSections(s.sections(), reference.sections()));
    // inputPointIndex maps every surface point back to the drifted input.
    for (std::size_t i = 0; i < m; ++i)
        for (std::size_t j = 0; j < n; ++j) REQUIRE(same(input.sections[i][s.inputPointIndex(i, j)], s.sections()[i][j]));
    // The seam runs through the first input point of section 0 (which keeps its start).
    CHECK(same(s.point(0.0, 0.0), reference.point(0.0, 0.0)));
    if (mode == FitMode::Interpolate) CHECK(distance(s.point(0.0, 0.0), input.sections[0][0]) <= 1e-12 * s.towSize());
    double worst = 0.0;
    for (int a = 0; a <= 20; ++a)
        for (int b = 0; b < 40; ++b) {
            const double u = a / 20.0, v = b / 40.0;
            worst = std::max(worst, distance(s.point(u, v), reference.point(u, v)));
        }
    CHECK(worst <= 1e-12 * s.towSize());
    CHECK(s.volume() == Approx(reference.volume()).epsilon(1e-12));
    CHECK(s.facetedVolume() == Approx(reference.facetedVolume()).epsilon(1e-12));
    const Deviation dr = reference.deviation(), ds = s.deviation();
    CHECK(ds.max == Approx(dr.max).margin(1e-15 * s.towSize()));
    // The worst point is reported in the drifted input's numbering.
    CHECK(ds.worstSection == dr.worstSection);
    const long nn = static_cast<long>(n);
    CHECK(ds.worstPoint == static_cast<std::size_t>(((static_cast<long>(dr.worstPoint) + drift[dr.worstSection]) % nn + nn) % nn));
    CHECK(same(input.sections[ds.worstSection][ds.worstPoint], stack.sections[dr.worstSection][dr.worstPoint]));
}

using testing::racetrackPoint;
using testing::tracedRacetrack;
using testing::TracedTow;

/// The largest distance between matched points of consecutive sections of @p s (centroids
/// made to coincide): how far the surface's point columns shear around the tow.
double largestColumnShear(const TowSurface& s)
{
    const auto centroid = [](const std::vector<Point3>& p) {
        Point3 c;
        for (const Point3& q : p) c = c + q;
        return (1.0 / static_cast<double>(p.size())) * c;
    };
    double worst = 0.0;
    for (std::size_t i = 1; i < s.sectionCount(); ++i) {
        const auto &a = s.sections()[i - 1], &b = s.sections()[i];
        const Point3 ca = centroid(a), cb = centroid(b);
        for (std::size_t j = 0; j < a.size(); ++j) worst = std::max(worst, norm((b[j] - cb) - (a[j] - ca)));
    }
    return worst;
}

}  // namespace

TEST_CASE("drifting start points: round and elliptical tubes, crimped tow, both orientations", "[surface][start]")
{
    for (const bool ccw : {true, false}) {
        const Sampling sampling{21, 24, 0.3, ccw};
        const std::vector<std::pair<std::string, TowStack>> tows{
            {"round", testing::tubeAlongX(0.5, 4.0, 0.0, 0.2, -0.1, sampling)},
            {"elliptical", testing::ellipticalTube(0.6, 0.2, 3.0, sampling)},
            {"crimped", testing::crimpedTow(0.5, 0.12, 4.0, 0.1, 2.0, sampling)}};
        for (const auto& [name, stack] : tows) {
            DYNAMIC_SECTION(name << (ccw ? ", counter-clockwise" : ", clockwise") << ", +1 per section")
            {
                checkDriftUndone(stack, steadyDrift(stack.sectionCount()));
            }
            DYNAMIC_SECTION(name << (ccw ? ", counter-clockwise" : ", clockwise") << ", random +-1..3 per section")
            {
                checkDriftUndone(stack, randomDrift(stack.sectionCount(), 11));
            }
        }
    }
    SECTION("tows that bend sharply: sections tilt by up to 90 degrees from one to the next")
    {
        // Matching removes the tilt between the sections' planes, so the drift is found as
        // well as between parallel slices. The orthogonal binders of the generator turn by
        // 90 degrees between their first sections at 6 sections (racetrack: without the tilt
        // removed, those sections would match with a similarity of 0.48 and be refused).
        for (const bool ccw : {true, false}) {
            INFO((ccw ? "counter-clockwise" : "clockwise"));
            checkDriftUndone(testing::bentTube(0.3, 1.0, 1.5 * kPi, {7, 16, 0.2, ccw}), randomDrift(7, 8));
            checkDriftUndone(testing::crimpedTow(0.5, 0.1, 2.0, 0.4, 2.0, {9, 16, 0.0, ccw}), steadyDrift(9));
        }
        WeaveOptions weave;
        weave.kind = WeaveKind::Orthogonal;
        weave.shape = SectionShape::Racetrack;
        weave.warps = 2;  // as towgeom generate --weave orthogonal --section racetrack --sections 6 --points 8
        weave.wefts = 2;
        weave.sectionsPerYarn = 6;
        weave.pointsPerSection = 8;
        const Textile textile = generateWeave(weave);
        const std::vector<TowStack> stacks = textile.stacks();
        std::size_t binders = 0;
        for (std::size_t k = 0; k < stacks.size(); ++k)
            if (textile.yarns[k].role == YarnRole::Binder) {
                ++binders;
                checkDriftUndone(stacks[k], randomDrift(6, 9));
            }
        CHECK(binders > 0);
    }
    SECTION("every fit mode sees the renumbered sections")
    {
        const TowStack stack = testing::ellipticalTube(0.6, 0.2, 3.0, {21, 24, 0.0, false});
        checkDriftUndone(stack, randomDrift(21, 5), FitMode::ControlNet);
        checkDriftUndone(stack, randomDrift(21, 6), FitMode::Approximate);
    }
}

TEST_CASE("hand-traced flat racetrack on pixel rows: drifting starts are renumbered", "[surface][start]")
{
    const std::size_t m = 40, n = 32;
    for (const bool clockwise : {false, true}) {
        DYNAMIC_SECTION((clockwise ? "clockwise" : "counter-clockwise") << ", whole-point drift")
        {
            const TracedTow tow = tracedRacetrack(m, n, std::vector<double>(m, 0.0), clockwise);
            checkDriftUndone(tow.stack, steadyDrift(m));
            checkDriftUndone(tow.stack, randomDrift(m, 3));
        }
        DYNAMIC_SECTION((clockwise ? "clockwise" : "counter-clockwise") << ", fractional drift")
        {
            // The tracer starts 1.37 point spacings further round on every slice, or a random
            // +-(1..3 +- 0.3) spacings: no renumbering matches exactly; each section is matched to
            // the nearest whole shift, so the point columns shear by at most ~0.4 spacing.
            std::mt19937 rng(17);
            std::uniform_int_distribution<int> whole(1, 3), sign(0, 1);
            std::uniform_real_distribution<double> fraction(-0.3, 0.3);
            std::vector<double> steady(m), walk(m, 0.0);
            for (std::size_t i = 0; i < m; ++i) steady[i] = 1.37 * static_cast<double>(i);
            for (std::size_t i = 1; i < m; ++i) walk[i] = walk[i - 1] + (sign(rng) ? 1 : -1) * whole(rng) + fraction(rng);
            const TracedTow still = tracedRacetrack(m, n, std::vector<double>(m, 0.0), clockwise);
            const TowSurface reference = TowSurface::fit(still.stack);
            for (const std::vector<double>* offset : {&steady, &walk}) {
                const TracedTow tow = tracedRacetrack(m, n, *offset, clockwise);
                const TowSurface s = TowSurface::fit(tow.stack);
                // Section i matches section i - 1 by the whole shift nearest to the offset
                // difference: cumulative shifts, in the surface's order.
                long k = 0;
                std::vector<long> cumulative{0};
                for (std::size_t i = 1; i < m; ++i) {
                    k += std::lround((*offset)[i] - (*offset)[i - 1]);
                    cumulative.push_back(k);
                }
                // Point j of section i (offset o) is the undrifted point at o + j: a drift of -o.
                for (long& c : cumulative) c = -c;
                CHECK(s.startShifts() == expectedShifts(cumulative, static_cast<long>(n), s.inputReversed()));
                CHECK(s.inputReversed() == !clockwise);
                const double shear = largestColumnShear(s), stillShear = largestColumnShear(reference);
                WARN((offset == &steady ? "steady 1.37" : "random walk")
                     << ": column shear " << shear / tow.spacing << " spacings (undrifted "
                     << stillShear / tow.spacing << "), volume " << s.volume() << " vs exact " << tow.volume
                     << " (" << 100 * (s.volume() / tow.volume - 1) << " %), undrifted fit "
                     << 100 * (reference.volume() / tow.volume - 1) << " %");
                CHECK(shear <= stillShear + 0.45 * tow.spacing);
                CHECK(s.deviation().max <= 1e-9);
                CHECK(std::fabs(s.volume() / tow.volume - 1) < 0.01);
                CHECK(std::fabs(s.volume() / reference.volume() - 1) < 0.005);
                checkOutwardFromSectionCentres(s);
            }
        }
    }
}
