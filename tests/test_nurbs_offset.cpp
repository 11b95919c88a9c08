// Offsets with the same parametrisation and ply solids (issue 17, first part), checked against
// closed forms (a circle's offset is a circle, a cylinder ply's volume pi((R+t)^2 - R^2) L) and,
// on free-form input, against the exact offset computed here from finite differences of the
// input (not from the library's normals).
#include <catch2/catch.hpp>

#include <towgeom/error.hpp>
#include <towgeom/nurbs_offset.hpp>
#include <towgeom/placement_surface.hpp>
#include <towgeom/surface_offset_curves.hpp>
#include <towgeom/tow_intersection.hpp>
#include <towgeom/tow_ribbon.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "cli_runner.hpp"
#include "nurbs_shapes.hpp"
#include "occt_reference.hpp"

using namespace towgeom;
using towgeom::testing::circle;
using towgeom::testing::cylinder;
using towgeom::testing::saddle;
namespace fs = std::filesystem;

namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

TEST_CASE("a circle's offset keeping its parametrisation is the concentric circle of radius R + d", "[placement][offset]")
{
    const NurbsCurve c = circle(2.0, 1.0, -0.5, 0.25);
    const CurveOffset o = offsetCurve(c, 0.5, {0.0, 0.0, 1.0});
    CHECK(o.knotsInserted == 0);
    CHECK(o.offset.knots == c.knots);
    CHECK(o.offset.weights == c.weights);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> t(0.0, 1.0);
    double worst = 0.0;
    for (int k = 0; k < 1000; ++k) {
        const double s = t(random);
        const Point3 p = c.point(s), q = o.offset.point(s);
        // On the circle of radius 2.5, on the ray from the centre through p (the same parameter).
        worst = std::max(worst, std::abs(std::hypot(q.x - 1.0, q.y + 0.5) - 2.5));
        worst = std::max(worst, std::abs(q.z - 0.25));
        worst = std::max(worst, std::abs((q.x - 1.0) * (p.y + 0.5) - (q.y + 0.5) * (p.x - 1.0)));
    }
    INFO("largest deviation " << worst << ", maxError " << o.maxError);
    CHECK(worst <= 1.8e-14);  // README: to 1.8e-15
    CHECK(o.maxError <= 1.8e-14);
    // Inward: radius 1.5.
    const CurveOffset in = offsetCurve(c, -0.5, {0.0, 0.0, 1.0});
    const Point3 q = in.offset.point(0.3);
    CHECK(std::abs(std::hypot(q.x - 1.0, q.y + 0.5) - 1.5) <= 1.8e-14);
}

TEST_CASE("a free-form curve's offset: knots inserted until it is within the tolerance of the exact offset", "[placement][offset]")
{
    NurbsCurve c;
    c.degree = 3;
    c.knots = {0, 0, 0, 0, 0.5, 1, 1, 1, 1};
    c.poles = {{0, 0, 0}, {1, 1.2, 0}, {2, -1, 0}, {3, 1, 0}, {4, 0, 0}};
    c.weights = {1, 1, 1, 1, 1};
    OffsetOptions opt;
    opt.tolerance = 1e-7;
    const CurveOffset o = offsetCurve(c, 0.1, {0.0, 0.0, 1.0}, opt);
    INFO("knots inserted " << o.knotsInserted << ", maxError " << o.maxError);
    CHECK(o.knotsInserted > 0);
    CHECK(o.maxError <= 1e-7);
    CHECK(o.converged);
    // Independently: q - p has length d and is normal to the curve (derivative by central
    // differences of the input), at 1,000 random parameters.
    std::mt19937 random(11);
    std::uniform_real_distribution<double> t(0.001, 0.999);
    double worstLength = 0.0, worstAngle = 0.0;
    for (int k = 0; k < 1000; ++k) {
        const double s = t(random), h = 1e-6;
        const Point3 p = c.point(s), q = o.offset.point(s);
        const Vector3 tangent = (1.0 / (2.0 * h)) * (c.point(s + h) - c.point(s - h));
        worstLength = std::max(worstLength, std::abs(norm(q - p) - 0.1));
        worstAngle = std::max(worstAngle, std::abs(dot(q - p, tangent)) / norm(tangent));
    }
    INFO("length " << worstLength << ", along the tangent " << worstAngle);
    CHECK(worstLength <= 1.1e-7);
    CHECK(worstAngle <= 1.1e-7);
    // The base with the knots inserted is the same curve.
    CHECK(distance(o.base.point(0.37), c.point(0.37)) <= 1e-12);
}

TEST_CASE("a saddle's offset is within the tolerance of the exact offset at 10,000 random points", "[placement][offset]")
{
    const NurbsSurface s = saddle();
    OffsetOptions opt;
    opt.tolerance = 1e-6;
    const SurfaceOffset o = offsetSurface(s, 0.05, opt);
    INFO("knots inserted " << o.knotsInserted << ", maxError " << o.maxError);
    CHECK(o.knotsInserted > 0);
    CHECK(o.maxError <= 1e-6);
    std::mt19937 random(5);
    std::uniform_real_distribution<double> t(0.001, 0.999);
    double worst = 0.0;
    for (int k = 0; k < 10000; ++k) {
        const double u = t(random), v = t(random), h = 1e-6;
        const Vector3 su = (1.0 / (2.0 * h)) * (s.point(u + h, v) - s.point(u - h, v));
        const Vector3 sv = (1.0 / (2.0 * h)) * (s.point(u, v + h) - s.point(u, v - h));
        const Vector3 n = cross(su, sv);
        const Point3 exact = s.point(u, v) + (0.05 / norm(n)) * n;
        worst = std::max(worst, distance(o.offset.point(u, v), exact));
    }
    INFO("largest distance from the exact offset " << worst);
    CHECK(worst <= 1.05e-6);
}

TEST_CASE("a ply on a cylinder: the offset cylinder exactly, volume pi((R+t)^2 - R^2) L, positive Jacobian", "[placement][ply]")
{
    const double r = 1.0, t = 0.2, length = 3.0;
    const NurbsSurface base = cylinder(r, length);
    const SurfaceOffset o = offsetSurface(base, t);
    CHECK(o.knotsInserted == 0);
    std::mt19937 random(3);
    std::uniform_real_distribution<double> p(0.0, 1.0);
    double worst = 0.0;
    for (int k = 0; k < 10000; ++k) {
        const Point3 q = o.offset.point(p(random), p(random));
        worst = std::max(worst, std::abs(std::hypot(q.x, q.y) - (r + t)));
    }
    INFO("largest deviation from radius R + t: " << worst);
    CHECK(worst <= 1e-14);
    const NurbsVolume ply = plySolid(o.base, o.offset);
    const VolumeMeasure m = measureVolume(ply);
    const double exact = kPi * ((r + t) * (r + t) - r * r) * length;
    INFO("volume " << m.volume << ", exact " << exact << " (relative " << std::abs(m.volume - exact) / exact << "), Jacobian "
                   << m.minJacobian << " .. " << m.maxJacobian);
    CHECK(std::abs(m.volume - exact) <= 9e-11 * exact);  // README: to 9e-12
    CHECK(m.minJacobian > 0.0);
    CHECK_FALSE(m.folds());
    // The weakest quadrature point lies in the ply (between radii R and R + t), its parameters
    // giving that point.
    CHECK(std::hypot(m.weakestPoint.x, m.weakestPoint.y) >= r);
    CHECK(std::hypot(m.weakestPoint.x, m.weakestPoint.y) <= r + t);
    CHECK(distance(ply.point(m.weakestParameters[0], m.weakestParameters[1], m.weakestParameters[2]), m.weakestPoint) < 1e-12);
    // Positive: the weakest is the smallest Jacobian; the ply offset inwards is negative, its
    // weakest the largest (nearest zero).
    CHECK(ply.jacobian(m.weakestParameters[0], m.weakestParameters[1], m.weakestParameters[2]) == Approx(m.minJacobian).epsilon(1e-12));
    {
        const SurfaceOffset inwards = offsetSurface(base, -t);
        const NurbsVolume inner = plySolid(inwards.base, inwards.offset);
        const VolumeMeasure n = measureVolume(inner);
        REQUIRE(n.maxJacobian < 0.0);
        CHECK_FALSE(n.folds());
        CHECK(inner.jacobian(n.weakestParameters[0], n.weakestParameters[1], n.weakestParameters[2]) == Approx(n.maxJacobian).epsilon(1e-12));
        CHECK(n.minJacobian < n.maxJacobian);
    }
    // Sampled independently of the quadrature points: positive everywhere.
    double smallest = 1e300;
    for (int k = 0; k < 2000; ++k) smallest = std::min(smallest, ply.jacobian(p(random), p(random), p(random)));
    CHECK(smallest > 0.0);

    // The files: JSON that Python reads, VTK hexahedra that meshio reads.
    const fs::path dir = fs::temp_directory_path() / ("towgeom_ply_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    {
        std::ofstream json(dir / "ply.json"), vtk(dir / "ply.vtk");
        writeNurbsVolumeJson(ply, json);
        writeNurbsVolumeVtk(ply, vtk, 4);
    }
    const testing::Run py = testing::runShell(
        "/usr/bin/python3 -c \"import json, meshio\n"
        "j = json.load(open('" + (dir / "ply.json").string() + "'))\n"
        "m = meshio.read('" + (dir / "ply.vtk").string() + "')\n"
        "print(j['degrees'], j['counts'], len(j['poles']), len(m.cells_dict['hexahedron']), bool(m.point_data['jacobian'].min() > 0))\"");
    REQUIRE(py.status == 0);
    // 4 spans around x 4 samples, 1 span along x 4, 1 through x 2: 16 x 4 x 2 hexahedra.
    CHECK(py.out == "[2, 1, 1] [9, 2, 2] 36 128 True\n");
    fs::remove_all(dir);
}

TEST_CASE("a curve with a corner: the offset cannot converge there, says so and stops", "[placement][offset]")
{
    // An L of two straight quadratic pieces meeting at a double knot: the exact offset jumps.
    NurbsCurve c;
    c.degree = 2;
    c.knots = {0, 0, 0, 0.5, 0.5, 1, 1, 1};
    c.poles = {{0, 0, 0}, {0.5, 0, 0}, {1, 0, 0}, {1, 0.5, 0}, {1, 1, 0}};
    c.weights = {2, 2, 2, 2, 2};  // equal weights: not rational, kept as given
    const CurveOffset o = offsetCurve(c, 0.1, {0.0, 0.0, 1.0});
    INFO("knots inserted " << o.knotsInserted << ", maxError " << o.maxError);
    CHECK_FALSE(o.converged);
    CHECK(o.maxError > 0.01);
    CHECK(o.knotsInserted < 200);
    CHECK(o.offset.weights == std::vector<double>(o.offset.poles.size(), 2.0));
}

TEST_CASE("a ply offset to the inside: a negative Jacobian of one sign, the same volume", "[placement][ply]")
{
    const double r = 1.0, t = 0.2, length = 3.0;
    const NurbsSurface base = cylinder(r, length);
    const SurfaceOffset o = offsetSurface(base, -t);
    CHECK(o.converged);
    const VolumeMeasure m = measureVolume(plySolid(o.base, o.offset));
    const double exact = kPi * (r * r - (r - t) * (r - t)) * length;
    CHECK(std::abs(m.volume - exact) <= 1e-9 * exact);
    CHECK(m.maxJacobian < 0.0);
}

TEST_CASE("offsets and plies refuse ill-formed NURBS, naming what", "[placement]")
{
    {
        NurbsCurve c;  // an inner knot three times on a quadratic: not continuous
        c.degree = 2;
        c.knots = {0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1};
        c.poles = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {2, 1, 0}, {2, 2, 0}, {3, 2, 0}};
        c.weights.assign(6, 1.0);
        CHECK_THROWS_WITH(c.point(0.3), Catch::Contains("more than degree times"));
    }
    {
        // A sphere's pole: no normal there (dS/du vanishes up to rounding only).
        NurbsSurface s;
        s.uDegree = 2;
        s.vDegree = 2;
        s.uKnots = {0, 0, 0, 1, 1, 1};
        s.vKnots = {0, 0, 0, 1, 1, 1};
        s.uCount = s.vCount = 3;
        const double h = std::sqrt(0.5);
        const Point3 c{0.3, 0.7, 0.2};
        // An octant of the unit sphere about c: the row u = 0 collapsed onto its pole.
        const Point3 p[3][3] = {{{0, 0, 1}, {0, 0, 1}, {0, 0, 1}}, {{1, 0, 1}, {1, 1, 1}, {0, 1, 1}}, {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}}};
        const double w[3] = {1, h, 1};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                s.poles.push_back(c + p[i][j]);
                s.weights.push_back(w[i] * w[j]);
            }
        CHECK_THROWS_WITH(s.normal(0.0, 0.5), Catch::Contains("no normal"));
    }
    {
        // A cone: the cylinder's row at z = 0 collapsed onto its axis, the apex. Its normal's
        // limit there turns with u, so no offset point is the apex's: refused, naming it.
        NurbsSurface cone = cylinder(1.0, 2.0);
        for (std::size_t i = 0; i < cone.uCount; ++i) cone.poles[i * cone.vCount] = {0.0, 0.0, 0.0};
        try {
            offsetSurface(cone, 0.1);
            FAIL("offset");
        } catch (const Error& e) {
            CHECK(e.code() == ErrorCode::Unsupported);
            CHECK_THAT(e.message(), Catch::Contains("no single normal at its point (") && Catch::Contains("a cone's apex"));
            // The apex is the origin: the point named is the row's, to the digits printed.
            CHECK_THAT(e.message(), Catch::Matches(".*point \\(-?0\\.000000, -?0\\.000000, -?0\\.000000\\).*"));
        }
    }

    NurbsCurve c = circle(1.0, 0.0, 0.0, 0.0);
    c.knots[2] = 0.1;  // not clamped
    CHECK_THROWS_WITH(offsetCurve(c, 0.1, {0, 0, 1}), Catch::Contains("clamped"));
    c = circle(1.0, 0.0, 0.0, 0.0);
    c.weights[2] = 0.0;
    CHECK_THROWS_WITH(offsetCurve(c, 0.1, {0, 0, 1}), Catch::Contains("weight"));
    CHECK_THROWS_AS(offsetCurve(circle(1.0, 0.0, 0.0, 0.0), 0.1, {0, 0, 0}), Error);
    const NurbsSurface a = cylinder(1.0, 2.0), b = saddle();
    try {
        plySolid(a, b);
        FAIL("no error");
    } catch (const Error& e) {
        CHECK(e.code() == ErrorCode::InvalidArgument);
    }
}

TEST_CASE("courses around a cylinder: 50 tangent-and-project offsets lose what Schueler's Eq. 2 says, geodesic ones none",
          "[placement][courses]")
{
    // R = 2, L = 3; the reference a generator line run downwards, so that O = N x T points
    // around the cylinder (counter-clockwise seen from +z).
    const double r = 2.0, d = 0.1;
    const NurbsSurface s = cylinder(r, 3.0);
    std::vector<UV> line;
    for (int k = 0; k < 5; ++k) line.push_back({0.02, 0.9 - 0.2 * k});
    const auto angleOf = [](const Point3& p) { return std::atan2(p.y, p.x); };
    for (const SurfaceOffsetMethod method : {SurfaceOffsetMethod::ProjectTangent, SurfaceOffsetMethod::Geodesic}) {
        SurfaceOffsetOptions o;
        o.method = method;
        CurveOnSurface c = curveOnSurface(s, line);
        const double start = angleOf(c.points[2]);
        double estimated = 0.0, measuredSum = 0.0;
        for (int step = 0; step < 50; ++step) {
            const SurfaceOffsetStep next = offsetOnSurface(s, c, d, o);
            estimated += next.estimatedError[2];
            measuredSum += next.geodesicDistance[2];
            c = next.curve;
        }
        // The true distance along the surface from the reference: the arc R (theta_50 - theta_0)
        // at the same height, every point alike.
        double turned = angleOf(c.points[2]) - start;
        if (turned < 0.0) turned += 2.0 * kPi;
        const double accumulated = 50 * d - r * turned;
        for (const Point3& p : c.points) CHECK(std::abs(std::hypot(p.x, p.y) - r) <= 1e-9);
        INFO((method == SurfaceOffsetMethod::Geodesic ? "geodesic" : "tangent and project") << ": accumulated error " << accumulated
             << ", Eq. 2 summed " << estimated << ", measured geodesics " << 50 * d - measuredSum);
        if (method == SurfaceOffsetMethod::ProjectTangent) {
            CHECK(accumulated > 0.004);  // 50 (d - R atan(d / R)) = 0.00416
            CHECK(std::abs(accumulated - estimated) <= 1e-7);  // README: to 1e-8 measured
            CHECK(std::abs((50 * d - measuredSum) - accumulated) <= 1e-6);
        } else {
            CHECK(std::abs(accumulated) <= 1e-6);
        }
    }
}

TEST_CASE("geodesics on a skewed, unevenly parametrised plane are its straight chords", "[placement][courses]")
{
    // A tilted plane whose u runs unevenly (quadratic, poles at 0, 0.2, 1) and whose v is skewed:
    // S_u . S_v != 0 and S_uu != 0, yet every geodesic is a straight line.
    NurbsSurface s;
    s.uDegree = 2;
    s.vDegree = 1;
    s.uKnots = {0, 0, 0, 1, 1, 1};
    s.vKnots = {0, 0, 1, 1};
    s.uCount = 3;
    s.vCount = 2;
    for (const double x : {0.0, 0.2, 1.0})
        for (const double y : {0.0, 1.0}) {
            const double px = x + 0.5 * y;
            s.poles.push_back({px, y, 0.1 * px + 0.2 * y});
            s.weights.push_back(1.0);
        }
    std::mt19937 random(9);
    std::uniform_real_distribution<double> p(0.2, 0.8), q(-0.15, 0.15);
    double worst = 0.0;
    for (int k = 0; k < 100; ++k) {
        const UV a{p(random), p(random)}, b{std::clamp(a.u + q(random), 0.0, 1.0), std::clamp(a.v + q(random), 0.0, 1.0)};
        worst = std::max(worst, std::abs(geodesicDistance(s, a, b) - distance(s.point(a.u, a.v), s.point(b.u, b.v))));
    }
    INFO("largest difference from the chord " << worst);
    CHECK(worst <= 1e-9);
}

TEST_CASE("courses along a cylinder's axis: no error, and on a saddle Eq. 2 against the measured geodesic", "[placement][courses]")
{
    // Along the axis: the offsets of a circle are circles d apart.
    const NurbsSurface cyl = cylinder(2.0, 3.0);
    std::vector<UV> ring;
    for (int k = 0; k < 5; ++k) ring.push_back({0.1 + 0.2 * k, 0.1});
    CurveOnSurface c = curveOnSurface(cyl, ring);
    for (int step = 0; step < 20; ++step) {
        const SurfaceOffsetStep next = offsetOnSurface(cyl, c, 0.1, {});
        for (std::size_t k = 0; k < next.curve.points.size(); ++k) {
            CHECK(next.estimatedError[k] <= 1e-12);
            CHECK(std::abs(next.geodesicDistance[k] - 0.1) <= 1e-9);
        }
        c = next.curve;
    }
    for (const Point3& p : c.points) CHECK(std::abs(p.z - (0.3 + 20 * 0.1)) <= 1e-9);

    // On the saddle: the tangent step's loss against the geodesic, point by point. Eq. 2 takes a
    // circular section of the normal curvature where the step starts; the saddle's curvature
    // changes along the step, so it agrees to leading order only: closer for shorter steps.
    const NurbsSurface s = saddle();
    std::vector<UV> mid;
    for (int k = 0; k < 7; ++k) mid.push_back({0.2 + 0.1 * k, 0.45});
    double previous = 1e300;
    for (const double step : {0.15, 0.05}) {
        const SurfaceOffsetStep o = offsetOnSurface(s, curveOnSurface(s, mid), step, {});
        double worst = 0.0;
        for (std::size_t k = 0; k < mid.size(); ++k) {
            const double measured = step - o.geodesicDistance[k];
            INFO("d " << step << ", point " << k << ": Eq. 2 " << o.estimatedError[k] << ", measured " << measured);
            REQUIRE(measured > 0.0);
            worst = std::max(worst, std::abs(o.estimatedError[k] / measured - 1.0));
        }
        WARN("saddle, d = " << step << ": Eq. 2 within " << 100.0 * worst << " % of the measured loss");
        CHECK(worst < previous);
        previous = worst;
    }
    CHECK(previous <= 0.2);  // measured: 15 % at d = 0.05 (28 % at 0.15)
    const double d = 0.15;
    SurfaceOffsetOptions exact;
    exact.method = SurfaceOffsetMethod::Geodesic;
    const SurfaceOffsetStep geodesic = offsetOnSurface(s, curveOnSurface(s, mid), d, exact);
    for (double g : geodesic.geodesicDistance) CHECK(std::abs(g - d) <= 1e-7);
}

TEST_CASE("towgeom ply: a tool surface from STEP or IGES, stacked plies of exact volume, refusals", "[placement][ply][cli]")
{
    const fs::path dir = fs::temp_directory_path() / ("towgeom_ply_cli_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const double r = 1.5, h = 2.0, t = 0.1;
    for (const char* name : {"tool.step", "tool.igs"}) {
        const fs::path tool = dir / name, out = dir / (std::string(name) + ".out");
        testing::writeCylinderFace(tool.string(), r, h);
        const testing::Run run = testing::cli("ply '" + tool.string() + "' --thickness 0.1 --layers 2 --out '" + out.string() + "' --quiet");
        INFO(name << ": " << run.err << run.out);
        REQUIRE(run.status == 0);
        // Two plies: the annuli R..R+t and R+t..R+2t (the cylinder's face normal points outward).
        const double first = kPi * ((r + t) * (r + t) - r * r) * h, second = kPi * ((r + 2 * t) * (r + 2 * t) - (r + t) * (r + t)) * h;
        const auto volumeAt = [&](std::size_t k) {
            std::size_t at = 0;
            for (std::size_t n = 0; n <= k; ++n) at = run.out.find("\"volume\":", at + 1);
            return std::stod(run.out.substr(at + 9));
        };
        CHECK(std::abs(volumeAt(0) - first) <= 1e-6 * first);
        CHECK(std::abs(volumeAt(1) - second) <= 1e-6 * second);
        CHECK(testing::count(run.out, "\"converged\":true") == 2);
        CHECK(fs::exists(out / "ply_1.json"));
        CHECK(fs::exists(out / "ply_2.vtk"));
    }
    // A half cylinder whose angles start below 0 (OCCT moves them by a period when it converts).
    {
        const fs::path half = dir / "half.step", out = dir / "half.out";
        testing::writeCylinderFace(half.string(), r, h, -kPi / 2, kPi / 2);
        const testing::Run run = testing::cli("ply '" + half.string() + "' --thickness 0.1 --out '" + out.string() + "' --quiet");
        INFO(run.err << run.out);
        REQUIRE(run.status == 0);
        const double expected = 0.5 * kPi * ((r + t) * (r + t) - r * r) * h;
        const std::size_t at = run.out.find("\"volume\":");
        REQUIRE(at != std::string::npos);
        CHECK(std::abs(std::stod(run.out.substr(at + 9)) - expected) <= 1e-6 * expected);
    }
    const testing::Run past = testing::cli("ply '" + (dir / "tool.step").string() + "' --thickness 0.1 --face 3 --out '" + (dir / "x").string() + "'");
    CHECK(past.status == 2);
    CHECK(past.err.find("has 1 face(s)") != std::string::npos);
    CHECK_FALSE(fs::exists(dir / "x"));
    const testing::Run missing = testing::cli("ply '" + (dir / "none.step").string() + "' --thickness 0.1 --out '" + (dir / "x").string() + "'");
    CHECK(missing.status == 2);
    CHECK(missing.err.find("[file_not_found]") != std::string::npos);
    fs::remove_all(dir);
}

TEST_CASE("a course of tows on a cylinder as .stw ribbons: detect finds an overlap at every boundary when too narrow, none when apart",
          "[placement][ribbon]")
{
    const double width = 0.3;
    const NurbsSurface s = cylinder(2.0, 3.0);
    std::vector<UV> line;
    for (int k = 0; k < 19; ++k) line.push_back({0.02, 0.95 - 0.05 * k});
    CrossSection section;
    section.shape = SectionShape::Racetrack;
    section.width = width;
    section.height = 0.05;
    SurfaceOffsetOptions exact;
    exact.method = SurfaceOffsetMethod::Geodesic;
    for (const double spacing : {0.9 * width, 1.1 * width}) {
        std::vector<TowSurface> tows;
        CurveOnSurface centre = curveOnSurface(s, line);
        for (int k = 0; k < 3; ++k) {
            tows.push_back(TowSurface::fit(towRibbon(s, centre, section, 16, "tow" + std::to_string(k))));
            // The next tow a step shorter at both ends (staggered ends, as a course's tows are
            // cut: where two tows' ends met in one plane their caps would touch flat).
            centre = offsetOnSurface(s, centre, spacing, exact).curve;
            centre.uv = std::vector<UV>(centre.uv.begin() + 1, centre.uv.end() - 1);
            centre.points = std::vector<Point3>(centre.points.begin() + 1, centre.points.end() - 1);
        }
        const IntersectionReport r = intersectTows(tows);
        std::size_t boundary[2] = {0, 0}, other = 0;
        for (const IntersectionLoop& l : r.loops) {
            if (l.towB() == l.towA() + 1 && l.closed()) ++boundary[l.towA()];
            else ++other;
        }
        INFO("spacing " << spacing << ": loops " << r.loops.size() << " (" << boundary[0] << ", " << boundary[1] << "), findings "
                        << r.findings.size());
        if (spacing < width) {
            CHECK(boundary[0] >= 1);
            CHECK(boundary[1] >= 1);
            CHECK(other == 0);
        } else {
            CHECK(r.loops.empty());
            CHECK(r.findings.empty());
        }
    }
}

TEST_CASE("a tool surface by its face's name, or fitted to a point grid, and the ply on it", "[placement][ply][cli]")
{
    const fs::path dir = fs::temp_directory_path() / ("towgeom_tool_surface_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const double r = 1.5, h = 2.0, t = 0.1;
    // A STEP file whose face is named: OCCT writes ADVANCED_FACE(''...); name it as a CAD
    // system would.
    const fs::path plain = dir / "plain.step", named = dir / "named.step";
    testing::writeCylinderFace(plain.string(), r, h);
    {
        std::ifstream in(plain);
        std::stringstream text;
        text << in.rdbuf();
        std::string s = text.str();
        const std::size_t at = s.find("ADVANCED_FACE(''");
        REQUIRE(at != std::string::npos);
        s.replace(at, 16, "ADVANCED_FACE('mould top'");
        std::ofstream(named) << s;
    }
    const PlacementSurface byName = readPlacementSurface(named.string(), "mould top");
    CHECK(byName.name == "mould top");
    CHECK(byName.face == 0);
    CHECK(readPlacementSurface(named.string(), 0).name == "mould top");
    try {
        readPlacementSurface(named.string(), "mould bottom");
        FAIL("no error");
    } catch (const Error& e) {
        CHECK(e.code() == ErrorCode::InvalidArgument);
        CHECK(std::string(e.what()).find("'mould top'") != std::string::npos);  // the names there are
    }
    CHECK_THROWS_AS(readPlacementSurface(plain.string(), "mould top"), Error);
    const testing::Run run = testing::cli("ply '" + named.string() + "' --face 'mould top' --thickness 0.1 --out '" + (dir / "named.out").string() + "' --quiet");
    INFO(run.err << run.out);
    REQUIRE(run.status == 0);
    CHECK(run.out.find("\"face_name\":\"mould top\"") != std::string::npos);

    // IGES names: a box whose six faces share the label FACE, told apart by subscripts 1 to 6,
    // and a face labelled SURF right-justified in its 8 columns, subscript 3 (OCCT-written
    // files with their DE labels edited).
    const std::string data = std::string(TOWGEOM_TEST_DATA) + "/placement/";
    const PlacementSurface fourth = readPlacementSurface(data + "box_face_labels.igs", "FACE(4)");
    CHECK(fourth.face == 3);
    CHECK(fourth.faceCount == 6);
    CHECK(readPlacementSurface(data + "face_label_right_justified.igs", "SURF(3)").name == "SURF(3)");
    CHECK_THROWS_AS(readPlacementSurface(data + "box_face_labels.igs", "FACE"), Error);

    // A grid of 11 x 9 points on a quarter of that cylinder (u around, v up: the normal
    // outward), interpolated: every point on the surface, the ply's volume the annulus sector's.
    const double from = -0.5, to = 0.5;
    std::vector<Point3> grid;
    std::ostringstream file;
    file << "# a cylinder patch\ngrid 11 9\n";
    for (int i = 0; i < 11; ++i)
        for (int j = 0; j < 9; ++j) {
            const double a = from + (to - from) * i / 10.0, z = h * j / 8.0;
            grid.push_back({r * std::cos(a), r * std::sin(a), z});
            file << grid.back().x << " " << grid.back().y << " " << grid.back().z << "\n";
        }
    const PlacementSurface fitted = fitPlacementSurface(grid, 11, 9);
    CHECK(fitted.fitDeviation <= 1e-9);
    std::mt19937 random(3);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double worst = 0.0;
    for (int k = 0; k < 1000; ++k) {
        const Point3 p = fitted.surface.point(unit(random), unit(random));
        worst = std::max(worst, std::abs(std::hypot(p.x, p.y) - r));
    }
    INFO("interpolated cylinder patch: largest radial error " << worst);
    CHECK(worst <= 2e-4);  // measured 1.1e-4 (cubic interpolation of 11 points over 1 radian)
    const SurfaceOffset top = offsetSurface(fitted.surface, t);
    const double sector = 0.5 * (to - from) * ((r + t) * (r + t) - r * r) * h;
    CHECK(std::abs(measureVolume(plySolid(top.base, top.offset)).volume - sector) <= 5e-4 * sector);  // measured 2.8e-4
    const fs::path gridFile = dir / "patch.grid";
    std::ofstream(gridFile) << file.str();
    const testing::Run gridRun = testing::cli("ply '" + gridFile.string() + "' --thickness 0.1 --out '" + (dir / "grid.out").string() + "' --quiet");
    INFO(gridRun.err << gridRun.out);
    REQUIRE(gridRun.status == 0);
    const testing::Run quadratic = testing::cli("ply '" + gridFile.string() + "' --thickness 0.1 --through quadratic --out '" +
                                                (dir / "quadratic.out").string() + "' --quiet");
    INFO(quadratic.err << quadratic.out);
    REQUIRE(quadratic.status == 0);
    {
        std::ifstream json(dir / "quadratic.out" / "ply_1.json");
        std::stringstream text;
        text << json.rdbuf();
        CHECK(text.str().find("\"degrees\":[3,3,2]") != std::string::npos);
        const std::size_t at = quadratic.out.find("\"volume\":");
        REQUIRE(at != std::string::npos);
        CHECK(std::abs(std::stod(quadratic.out.substr(at + 9)) - sector) <= 5e-4 * sector);
    }
    // Refusals: a short grid, a line that is not a point, too few points; nothing written.
    std::ofstream(dir / "bad.grid") << "grid 4 4\n0 0 0\n1 0\n";
    const testing::Run bad = testing::cli("ply '" + (dir / "bad.grid").string() + "' --thickness 0.1 --out '" + (dir / "x").string() + "'");
    CHECK(bad.status == 2);
    CHECK(bad.err.find("bad.grid:3:") != std::string::npos);
    CHECK_THROWS_AS(fitPlacementSurface(grid, 11, 8), Error);
    CHECK_THROWS_AS(fitPlacementSurface(std::vector<Point3>(9), 3, 3), Error);
    // A collapsed row (all its points one) and identical points are refused, naming them.
    std::vector<Point3> collapsed = grid;
    for (int j = 0; j < 9; ++j) collapsed[4 * 9 + j] = collapsed[4 * 9];
    try {
        fitPlacementSurface(collapsed, 11, 9);
        FAIL("no error");
    } catch (const Error& e) {
        CHECK(std::string(e.what()).find("row 4: points 0 and 1 coincide") != std::string::npos);
    }
    CHECK_THROWS_AS(fitPlacementSurface(std::vector<Point3>(16), 4, 4), Error);
    // Approximation: within its tolerance, or refused.
    const PlacementSurface smooth = fitPlacementSurface(grid, 11, 9, 1e-3);
    CHECK(smooth.fitDeviation <= 1e-3);
    for (const char* header : {"grid -1 4", "grid 4294967296 4294967296", "grid 3 3", "grid 4 4 4"}) {
        std::ofstream(dir / "header.grid") << "# header\n" << header << "\n";
        const testing::Run run = testing::cli("ply '" + (dir / "header.grid").string() + "' --thickness 0.1 --out '" + (dir / "x").string() + "'");
        INFO(header << ": " << run.err);
        CHECK(run.status == 2);
        CHECK(run.err.find("header.grid:2:") != std::string::npos);
    }
    std::ofstream(dir / "long.grid") << "grid 4 4\n" << [] {
        std::string points;
        for (int k = 0; k < 17; ++k) points += std::to_string(k % 4) + " " + std::to_string(k / 4) + " 0\n";
        return points;
    }();
    const testing::Run extra = testing::cli("ply '" + (dir / "long.grid").string() + "' --thickness 0.1 --out '" + (dir / "x").string() + "'");
    CHECK(extra.status == 2);
    CHECK(extra.err.find("long.grid:18:") != std::string::npos);  // the 17th point
    try {
        readPlacementSurface((dir / "long.grid").string(), "top");
        FAIL("no error");
    } catch (const Error& e) {
        CHECK(std::string(e.what()).find("has no named faces") != std::string::npos);
    }
    // An empty name must not pick the unnamed face.
    const testing::Run empty = testing::cli("ply '" + plain.string() + "' --face '' --thickness 0.1 --out '" + (dir / "x").string() + "'");
    CHECK(empty.status == 2);
    CHECK(empty.err.find("empty string") != std::string::npos);
    // A grid's repeated point and a huge coordinate are named by their line.
    std::ofstream(dir / "same.grid") << [] {
        std::string text = "grid 4 4\n";
        for (int k = 0; k < 16; ++k) text += std::to_string(k == 5 ? 0 : k % 4) + " " + std::to_string(k / 4) + " 0\n";
        return text;
    }();
    const testing::Run same = testing::cli("ply '" + (dir / "same.grid").string() + "' --thickness 0.1 --out '" + (dir / "x").string() + "'");
    INFO(same.err);
    CHECK(same.status == 2);
    CHECK(same.err.find("same.grid:7:") != std::string::npos);  // point 5 (row 1, point 1) repeats point 4
    std::ofstream(dir / "huge.grid") << "grid 4 4\n1e300 0 0\n";
    const testing::Run huge = testing::cli("ply '" + (dir / "huge.grid").string() + "' --thickness 0.1 --out '" + (dir / "x").string() + "'");
    CHECK(huge.status == 2);
    CHECK(huge.err.find("huge.grid:2:") != std::string::npos);
    CHECK_FALSE(fs::exists(dir / "x"));
    fs::remove_all(dir);
}

TEST_CASE("a ply quadratic through its thickness: any middle surface at w = 1/2, common knots by exact insertion", "[placement][ply]")
{
    // On a cylinder ply (rational): a middle surface that is not the average of base and top
    // (its poles moved), which the ply must pass through at w = 1/2; w = 0 and 1 are the faces.
    const double r = 1.0, length = 3.0, t = 0.2;
    const SurfaceOffset o = offsetSurface(cylinder(r, length), t);
    NurbsSurface middle = o.base;
    for (std::size_t k = 0; k < middle.poles.size(); ++k)
        middle.poles[k] = 0.5 * (o.base.poles[k] + o.offset.poles[k]) + Point3{0.01 * static_cast<double>(k % 3), 0.02, -0.005 * static_cast<double>(k % 2)};
    const NurbsVolume ply = plySolid(o.base, middle, o.offset);
    CHECK(ply.degree[2] == 2);
    std::mt19937 random(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double worst = 0.0;
    for (int k = 0; k < 1000; ++k) {
        const double u = unit(random), v = unit(random);
        worst = std::max({worst, distance(ply.point(u, v, 0.5), middle.point(u, v)), distance(ply.point(u, v, 0.0), o.base.point(u, v)),
                          distance(ply.point(u, v, 1.0), o.offset.point(u, v))});
    }
    INFO("largest distance from the three surfaces " << worst);
    CHECK(worst <= 1e-12);
    // With the average as middle it is the linear ply: the same volume, the annulus's.
    NurbsSurface average = o.base;
    for (std::size_t k = 0; k < average.poles.size(); ++k) average.poles[k] = 0.5 * (o.base.poles[k] + o.offset.poles[k]);
    const VolumeMeasure quadratic = measureVolume(plySolid(o.base, average, o.offset)), linear = measureVolume(plySolid(o.base, o.offset));
    const double exact = kPi * ((r + t) * (r + t) - r * r) * length;
    INFO("quadratic ply volume " << quadratic.volume << ", exact " << exact);
    CHECK(std::abs(quadratic.volume - exact) <= 9e-11 * exact);
    CHECK(std::abs(quadratic.volume - linear.volume) <= 1e-12 * exact);
    CHECK(quadratic.minJacobian > 0.0);
    // Surfaces of different knots are refused; withKnotsOf() inserts a finer surface's knots
    // (here a new double knot in u, the degree, a single one in v, and the rational circle's
    // double knots kept): the same surface to rounding, the finer one's knot vectors.
    const NurbsSurface s = cylinder(r, length);
    NurbsSurface finer = s;
    finer.uKnots.insert(finer.uKnots.begin() + 3, {0.1, 0.1});
    finer.vKnots.insert(finer.vKnots.begin() + 2, 0.4);
    finer.uCount += 2;
    finer.vCount += 1;
    finer.poles.assign(finer.uCount * finer.vCount, Point3{0, 0, 0});
    finer.weights.assign(finer.poles.size(), 1.0);
    CHECK_THROWS_AS(plySolid(s, finer, finer), Error);
    const NurbsSurface matched = withKnotsOf(s, finer);
    CHECK(matched.uKnots == finer.uKnots);
    CHECK(matched.vKnots == finer.vKnots);
    double moved = 0.0;
    for (int k = 0; k < 1000; ++k) {
        const double u = unit(random), v = unit(random);
        moved = std::max(moved, distance(matched.point(u, v), s.point(u, v)));
    }
    CHECK(moved <= 1e-12);
    CHECK_THROWS_AS(withKnotsOf(finer, s), Error);  // the "finer" one lacks knots
}

TEST_CASE("towgeom ply on a sphere: through its poles without folding, a band exact, a missed tolerance warned (exit 3)", "[placement][ply][cli]")
{
    const fs::path dir = fs::temp_directory_path() / ("towgeom_ply_sphere_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const double r = 10.0, t = 0.3;
    // The whole sphere: its parametrisation collapses a row of poles onto each pole. The offset
    // there follows the normal's limit, the same for the whole row (it folded before: Jacobian
    // -22 to 38). Outwards and inwards: 4/3 pi ((R + t)^3 - R^3) and 4/3 pi (R^3 - (R - t)^3).
    testing::writeSphereFace((dir / "sphere.step").string(), r, -kPi / 2, kPi / 2);
    for (const double thickness : {t, -t}) {
        const fs::path out = dir / (thickness > 0.0 ? "outwards.out" : "inwards.out");
        const testing::Run run = testing::cli("ply '" + (dir / "sphere.step").string() + "' --thickness " + std::to_string(thickness) + " --out '" +
                                              out.string() + "' --quiet");
        INFO(run.err << run.out);
        REQUIRE(run.status == 0);
        const double outer = std::max(r, r + thickness), inner = std::min(r, r + thickness);
        const double exact = 4.0 / 3.0 * kPi * (std::pow(outer, 3) - std::pow(inner, 3));
        const std::size_t at = run.out.find("\"volume\":");
        REQUIRE(at != std::string::npos);
        // Measured 1.3e-9 (the quadrature of the rational Jacobian); exact offset, no knot added.
        CHECK(std::stod(run.out.substr(at + 9)) == Approx(exact).epsilon(1e-8));
        CHECK(testing::count(run.out, "\"knots_inserted\":0,") == 1);
        const std::size_t error = run.out.find("\"offset_error\":");
        REQUIRE(error != std::string::npos);
        CHECK(std::stod(run.out.substr(error + 15)) < 1e-12 * r);
        // The Jacobian keeps its sign, sampled independently of the quadrature points: in the
        // VTK file's point data (4 x 4 x 2 hexahedra per knot span), read by meshio. It vanishes
        // on the poles' collapsed rows (to rounding: 1e-9 of its largest size allowed there).
        const testing::Run py = testing::runShell("/usr/bin/python3 -c \"import meshio\n"
                                                  "j = meshio.read('" + (out / "ply_1.vtk").string() + "').point_data['jacobian']\n"
                                                  "e = 1e-9 * abs(j).max()\n"
                                                  "print(int(j.min() >= -e or j.max() <= e), j.min(), j.max())\"");
        REQUIRE(py.status == 0);
        INFO("one sign (1), then the Jacobian's range: " << py.out);
        CHECK(py.out.substr(0, 2) == "1 ");
    }
    // Folding is refused, naming the place: a cylinder (R 1.5) offset inwards by 2 passes its
    // axis at three quarters of the thickness (R + t w = 0), where the Jacobian changes sign.
    testing::writeCylinderFace((dir / "cylinder.step").string(), 1.5, 2.0);
    {
        const fs::path out = dir / "folded.out";
        const testing::Run run = testing::cli("ply '" + (dir / "cylinder.step").string() + "' --thickness -2 --out '" + out.string() + "' --quiet");
        INFO(run.err << run.out);
        CHECK(run.status == 2);
        CHECK(run.out.empty());
        CHECK_FALSE(fs::exists(out));
        CHECK(testing::count(run.err, "\n") == 1);
        CHECK_THAT(run.err, Catch::Contains("ply 1 folds near (") && Catch::Contains("[unsupported]"));
        const Point3 at = testing::placeNamedIn(run.err);
        // Past the axis, where the offset lies turned over: within 0.5 of it (the offset's radius).
        CHECK(std::hypot(at.x, at.y) <= 0.5 + 1e-9);
        CHECK(at.z >= 0.0);
        CHECK(at.z <= 2.0);
    }
    // A band between latitudes -1 and 1 has no pole: the exact volume
    // 2 pi / 3 ((R + t)^3 - R^3) (sin 1 - sin -1), converged, exit 0.
    testing::writeSphereFace((dir / "band.step").string(), r, -1.0, 1.0);
    const double exact = 2.0 * kPi / 3.0 * (std::pow(r + t, 3) - std::pow(r, 3)) * 2.0 * std::sin(1.0);
    const testing::Run band = testing::cli("ply '" + (dir / "band.step").string() + "' --thickness 0.3 --out '" + (dir / "band.out").string() + "' --quiet");
    INFO(band.err << band.out);
    REQUIRE(band.status == 0);
    CHECK(band.err.empty());
    const std::size_t at = band.out.find("\"volume\":");
    REQUIRE(at != std::string::npos);
    // Gauss-Legendre (8 points per span) integrates the rational Jacobian to 1.0e-8 here
    // (measured), within the 1e-6 that fibre placement asks of a ply's volume.
    CHECK(std::stod(band.out.substr(at + 9)) == Approx(exact).epsilon(5e-8));
    // A tolerance below what rounding allows is never met: written, "converged": false, a
    // warning naming the ply even under --quiet, exit 3; --allow-unconverged: exit 0, still warned.
    for (const bool allow : {false, true}) {
        const fs::path out = dir / (allow ? "tight_allowed.out" : "tight.out");
        const testing::Run tight = testing::cli("ply '" + (dir / "band.step").string() + "' --thickness 0.3 --tolerance 1e-15 --out '" + out.string() +
                                                "' --quiet" + (allow ? " --allow-unconverged" : ""));
        INFO(tight.err << tight.out);
        CHECK(tight.status == (allow ? 0 : 3));
        CHECK(testing::count(tight.out, "\"converged\":false") == 1);
        CHECK_THAT(tight.err, Catch::Contains("towgeom ply: warning: ply 1: its top is up to ") && Catch::Contains("over --tolerance"));
        CHECK(fs::exists(out / "ply_1.json"));
    }
    fs::remove_all(dir);
}
