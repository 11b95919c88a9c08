// Fibre-placement courses where the tool surface ends or closes on itself (issue 42): across the
// periodic seams of a sphere, a torus and a cylinder (checked against the closed-form geodesic
// parallels: polar or tube angle s / R), and trimmed at the boundary of a B-spline patch (the
// tows' ends checked on the boundary from the grid's own coordinates, not the library's (u,v)).
#include <catch2/catch.hpp>

#include <towgeom/error.hpp>
#include <towgeom/fibre_courses.hpp>
#include <towgeom/placement_surface.hpp>
#include <towgeom/reference_curve.hpp>

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "cli_runner.hpp"
#include "nurbs_shapes.hpp"
#include "occt_reference.hpp"

using namespace towgeom;
namespace fs = std::filesystem;

namespace {

constexpr double kHalfPi = 1.57079632679489661923;

/// A scratch directory removed at the end of the test.
struct CourseScratch {
    fs::path dir = fs::temp_directory_path() / ("towgeom_course_bounds_" + std::to_string(::getpid()));
    CourseScratch() { fs::create_directories(dir); }
    ~CourseScratch() { fs::remove_all(dir); }
};

/// Each tow's signed distance along the surface from the reference: its course's offset plus
/// its own from the course centre.
double towOffset(const CoursePlan& plan, const TowPath& t, std::size_t towsPerCourse, std::size_t index)
{
    const double course = static_cast<double>(t.course * towsPerCourse) * plan.spacing;
    return course + (static_cast<double>(index % towsPerCourse) - 0.5 * static_cast<double>(towsPerCourse - 1)) * plan.spacing;
}

/// Checks that every centreline point of @p plan lies at the angle @p angleOf(p) = sign * s /
/// radius from the reference's (s: the tow's offset), the sign found from the first tow, within
/// 1e-9; that each centreline is closed when @p closed; and that the gaps are 0 within 1e-8.
void checkParallels(const CoursePlan& plan, std::size_t towsPerCourse, double radius, bool closed, const std::function<double(const Point3&)>& angleOf,
                    const std::string& what)
{
    double sign = 0.0;
    for (std::size_t k = 0; k < plan.tows.size(); ++k) {
        const TowPath& t = plan.tows[k];
        const double s = towOffset(plan, t, towsPerCourse, k);
        if (sign == 0.0) sign = angleOf(t.centreline.points.front()) * s > 0.0 ? 1.0 : -1.0;
        double worst = 0.0;
        for (const Point3& p : t.centreline.points) worst = std::max(worst, std::abs(std::remainder(angleOf(p) - sign * s / radius, 2.0 * M_PI)));
        INFO(what << " " << t.name << " at s = " << s << ": largest angle difference " << worst);
        CHECK(worst <= 1e-9);
        if (closed) {
            CHECK(distance(t.centreline.points.front(), t.centreline.points.back()) <= 1e-9 * radius);
            CHECK(t.startBoundary.empty());
            CHECK(t.endBoundary.empty());
        }
    }
    for (const TowGap& g : plan.gaps) {
        INFO(what << " gap " << plan.tows[g.right].name << " | " << plan.tows[g.left].name << ": " << g.minWidth << " .. " << g.maxWidth);
        CHECK(g.measured == plan.tows[g.right].centreline.points.size());
        CHECK(std::abs(g.minWidth) <= 1e-8);
        CHECK(std::abs(g.maxWidth) <= 1e-8);
    }
}

}  // namespace

TEST_CASE("courses across periodic seams: the sphere's equator, a torus's outer equator, a cylinder's generator, against closed forms",
          "[placement][courses][seam]")
{
    CourseScratch scratch;
    CourseOptions o;
    o.towWidth = 0.5;
    o.towsPerCourse = 4;
    o.courses = 3;
    o.method = SurfaceOffsetMethod::Geodesic;
    SECTION("sphere R = 10, the equator: closed circles at polar angle pi/2 -+ (k + 1/2) W / R, their lengths 2 pi R cos(s / R)")
    {
        const double r = 10.0;
        testing::writeSphereFace((scratch.dir / "sphere.step").string(), r, -kHalfPi, kHalfPi);
        const PlacementSurface sphere = readPlacementSurface((scratch.dir / "sphere.step").string());
        // Through the seam's meridian: the cut starts and ends on it.
        const CurveOnSurface equator = referenceFromPlane(sphere.surface, {r, 0, 0}, {0, 0, 1}, 17);
        REQUIRE(distance(equator.points.front(), equator.points.back()) <= 1e-9 * r);
        const CoursePlan plan = layCourses(sphere.surface, equator, o);
        REQUIRE(plan.tows.size() == 12);
        CHECK(plan.offSurface.empty());
        // Latitude: pi/2 less the polar angle.
        checkParallels(plan, 4, r, true, [&](const Point3& p) { return kHalfPi - std::acos(std::clamp(p.z / norm(p - Point3{0, 0, 0}), -1.0, 1.0)); }, "sphere");
        for (std::size_t k = 0; k < plan.tows.size(); ++k) {
            const double s = towOffset(plan, plan.tows[k], 4, k);
            CHECK(std::abs(plan.tows[k].length - 2.0 * M_PI * r * std::cos(s / r)) <= 1e-6 * r);
        }
    }
    SECTION("torus R = 10, r = 3, its outer equator (both seams crossed): tube angle -+ s / r")
    {
        const double big = 10.0, small = 3.0;
        testing::writeTorusFace((scratch.dir / "torus.step").string(), big, small);
        const PlacementSurface torus = readPlacementSurface((scratch.dir / "torus.step").string());
        const CurveOnSurface outer = referenceFromPlane(torus.surface, {big + small, 0, 0}, {0, 0, 1}, 17);
        for (const Point3& p : outer.points) REQUIRE(std::abs(std::hypot(p.x, p.y) - (big + small)) <= 1e-9);
        const CoursePlan plan = layCourses(torus.surface, outer, o);
        REQUIRE(plan.tows.size() == 12);
        const auto tubeAngle = [&](const Point3& p) { return std::atan2(p.z, std::hypot(p.x, p.y) - big); };
        checkParallels(plan, 4, small, true, tubeAngle, "torus");
        for (const TowPath& t : plan.tows)  // on the torus
            for (const Point3& p : t.left.points) CHECK(std::abs(std::hypot(std::hypot(p.x, p.y) - big, p.z) - small) <= 1e-9);
    }
    SECTION("cylinder R = 2 (a rational circle), a generator beside its seam: courses around it at angle -+ s / R")
    {
        const double r = 2.0;
        const NurbsSurface cylinder = testing::cylinder(r, 3.0);
        std::vector<UV> uv;
        for (int k = 0; k < 9; ++k) uv.push_back({0.97, 0.9 - 0.1 * k});
        const CurveOnSurface line = curveOnSurface(cylinder, uv);
        const double start = std::atan2(line.points[0].y, line.points[0].x);
        o.towWidth = 0.6;
        const CoursePlan plan = layCourses(cylinder, line, o);
        REQUIRE(plan.tows.size() == 12);
        checkParallels(plan, 4, r, false, [&](const Point3& p) { return std::remainder(std::atan2(p.y, p.x) - start, 2.0 * M_PI); }, "cylinder");
        // The courses run on past the seam: their u beyond the knots' range, the points as the
        // surface's there (periodic).
        bool past = false;
        for (const TowPath& t : plan.tows)
            for (std::size_t i = 0; i < t.left.uv.size(); ++i) {
                past = past || t.left.uv[i].u > 1.0 || t.left.uv[i].u < 0.0;
                CHECK(distance(cylinder.point(t.left.uv[i].u, t.left.uv[i].v), t.left.points[i]) <= 1e-12);
            }
        CHECK(past);
    }
}

TEST_CASE("a plane cut running to a B-spline patch's boundary: every tow cut at the boundary or carried to it, courses off it not laid",
          "[placement][courses][trim]")
{
    // z = 0.15 (x - 2)^2 - 0.1 (y - 1.5)^2 + 0.05 x y on [0, 4] x [0, 3], interpolated: the patch's
    // sides are the grid's rows and columns, so a side's points have x = 0, x = 4, y = 0 or y = 3
    // exactly (the interpolation of equal coordinates).
    const std::size_t nu = 11, nv = 9;
    std::vector<Point3> grid;
    for (std::size_t i = 0; i < nu; ++i)
        for (std::size_t j = 0; j < nv; ++j) {
            const double x = 4.0 * i / (nu - 1), y = 3.0 * j / (nv - 1);
            grid.push_back({x, y, 0.15 * (x - 2) * (x - 2) - 0.1 * (y - 1.5) * (y - 1.5) + 0.05 * x * y});
        }
    const PlacementSurface patch = fitPlacementSurface(grid, nu, nv);
    const double size = 5.0;  // the patch's diagonal
    const auto onBoundary = [&](const Point3& p) {
        return std::min({std::abs(p.x), std::abs(p.x - 4.0), std::abs(p.y), std::abs(p.y - 3.0)}) <= 1e-9 * size;
    };
    // x = 1.3 - 0.2 (y - 1), from y = 0 to y = 3, run so that the courses go to +x.
    const CurveOnSurface reference = referenceFromPlane(patch.surface, {1.3, 1, 0}, {1, 0.2, 0}, 33, true);
    REQUIRE(onBoundary(reference.points.front()));
    REQUIRE(onBoundary(reference.points.back()));
    for (const SurfaceOffsetMethod method : {SurfaceOffsetMethod::Geodesic, SurfaceOffsetMethod::ProjectTangent}) {
        CourseOptions o;
        o.towWidth = 0.5;
        o.towsPerCourse = 4;
        o.courses = 3;
        o.method = method;
        const CoursePlan plan = layCourses(patch.surface, reference, o);
        INFO((method == SurfaceOffsetMethod::Geodesic ? "geodesic" : "project_tangent"));
        // The third course's centreline lies at x ~ 5.3: off the patch, not laid; c2_t4's
        // centreline (x ~ 4.05 at y = 3) leaves it through x = 4.
        CHECK(plan.offSurface == std::vector<std::string>{"c3"});
        REQUIRE(plan.tows.size() == 8);
        std::size_t throughSide = 0;
        for (const TowPath& t : plan.tows) {
            INFO(t.name);
            for (const CurveOnSurface* c : {&t.centreline, &t.left, &t.right}) {
                CHECK(onBoundary(c->points.front()));
                CHECK(onBoundary(c->points.back()));
            }
            CHECK_FALSE(t.startBoundary.empty());
            CHECK_FALSE(t.endBoundary.empty());
            throughSide += t.endBoundary == "u_max" || t.startBoundary == "u_max";
            // The length along the surface: at least the chords' and within their sagitta.
            double chords = 0.0;
            for (std::size_t i = 1; i < t.centreline.points.size(); ++i) chords += distance(t.centreline.points[i], t.centreline.points[i - 1]);
            CHECK(t.length >= chords - 1e-12);
            CHECK(t.length <= chords * (1.0 + 1e-3));
            // A point cut at the boundary is an offset like the others: its step is d along the
            // surface (geodesic), or as Schueler's (within its estimate's order).
            const double d = std::abs(t.step.distance);
            for (std::size_t i = 0; i < t.step.geodesicDistance.size(); ++i)
                if (!std::isnan(t.step.geodesicDistance[i]) && method == SurfaceOffsetMethod::Geodesic)
                    CHECK(std::abs(t.step.geodesicDistance[i] - d) <= 1e-9);
        }
        if (method == SurfaceOffsetMethod::Geodesic) CHECK(throughSide == 1);  // c2_t4 (Schueler's steps fall short of x = 4)
        // Neighbours in a course edge to edge: both exact offsets of its centreline, no gap
        // where measured away from the ends (at the ends the perpendicular runs along the
        // boundary): 1e-7, or 1e-5 where the course's centreline was carried on by a geodesic
        // (the joint's jump in geodesic curvature costs the (u,v) cubics' tangents accuracy).
        for (const TowGap& g : plan.gaps) {
            if (g.betweenCourses || method != SurfaceOffsetMethod::Geodesic) continue;
            const TowPath& right = plan.tows[g.right];
            INFO(right.name << " | " << plan.tows[g.left].name);
            const bool carried = right.course > 0;  // the second course's centre ran short of the boundary
            for (std::size_t i = 2; i + 2 < g.width.size(); ++i)
                if (!std::isnan(g.width[i])) CHECK(std::abs(g.width[i]) <= (carried ? 1e-5 : 1e-7));
        }
    }
}

TEST_CASE("towgeom courses on a patch's grid: tows trimmed at the boundary, exit 0, the trims in the summary and the plan",
          "[placement][courses][trim][cli]")
{
    CourseScratch scratch;
    const fs::path grid = scratch.dir / "patch.grid";
    {
        std::ofstream out(grid);
        out << "grid 11 9\n";
        for (int i = 0; i < 11; ++i)
            for (int j = 0; j < 9; ++j) {
                const double x = 0.4 * i, y = 0.375 * j;
                out << x << " " << y << " " << 0.15 * (x - 2) * (x - 2) - 0.1 * (y - 1.5) * (y - 1.5) + 0.05 * x * y << "\n";
            }
    }
    const fs::path out = scratch.dir / "plan";
    const testing::Run run = testing::cli("courses '" + grid.string() + "' --reference plane:1.3,1,0,1,0.2,0 --reverse --points 25 --tow-width 0.5 --tows 2 " +
                                          "--courses 3 --exact --quiet --out '" + out.string() + "'");
    INFO(run.err << run.out);
    REQUIRE(run.status == 0);
    const nlohmann::json summary = nlohmann::json::parse(run.out);
    CHECK(summary["trimmed"].size() == 6);
    for (const auto& t : summary["trimmed"]) {
        CHECK(t["start_boundary"] == "v_max");
        CHECK(t["length"].get<double>() > 3.0);
    }
    std::ifstream planFile(out / "courses.json");
    const nlohmann::json plan = nlohmann::json::parse(planFile);
    REQUIRE(plan["tows"].size() == 6);
    for (const auto& t : plan["tows"]) {
        const auto& first = t["centreline"]["points"].front();
        CHECK(std::abs(first[1].get<double>() - 3.0) <= 1e-9);  // y = 3: the side v_max
        CHECK_FALSE(t["end_boundary"].is_null());
    }
    CHECK(fs::exists(out / "c3_t2.stw"));
}
