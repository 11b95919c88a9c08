// Fibre-placement courses where the tool surface ends or closes on itself (issue 42): across the
// periodic seams of a sphere, a torus and a cylinder (checked against the closed-form geodesic
// parallels: polar or tube angle s / R), and trimmed at the boundary of a B-spline patch (the
// tows' ends checked on the boundary from the grid's own coordinates, not the library's (u,v)).
#include <catch2/catch.hpp>

#include <towgeom/course_coverage.hpp>
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
#include <sstream>
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
        // The tow curves as STEP, read back by OpenCASCADE: 36 named edges, each on the sphere at
        // its latitude within the 3D curves' tolerance (1e-6 W).
        writeCoursePlanStep(sphere.surface, plan, (scratch.dir / "courses.step").string());
        const std::vector<testing::ReadEdge> edges = testing::readStepEdges((scratch.dir / "courses.step").string(), 41);
        REQUIRE(edges.size() == 36);
        for (std::size_t k = 0; k < plan.tows.size(); ++k)
            for (const auto& [kind, shift] : {std::pair{"centreline", 0.0}, std::pair{"right", -0.25}, std::pair{"left", 0.25}}) {
                const std::string name = plan.tows[k].name + "/" + kind;
                const auto e = std::find_if(edges.begin(), edges.end(), [&](const testing::ReadEdge& x) { return x.name == name; });
                REQUIRE(e != edges.end());
                double worst = 0.0;
                // Its latitude: the tow's offset and the edge's shift from it, on the courses' side
                // (the sign of the first tow's latitude over its offset).
                const double first = std::asin(std::clamp(plan.tows[0].centreline.points[0].z / r, -1.0, 1.0));
                const double side = first * towOffset(plan, plan.tows[0], 4, 0) > 0.0 ? 1.0 : -1.0;
                const double latitude = side * (towOffset(plan, plan.tows[k], 4, k) + shift) / r;
                for (const Point3& p : e->points) {
                    worst = std::max(worst, std::abs(norm(p - Point3{0, 0, 0}) - r));
                    worst = std::max(worst, r * std::abs(std::asin(std::clamp(p.z / norm(p - Point3{0, 0, 0}), -1.0, 1.0)) - latitude));
                }
                INFO(name << " (" << shift << "): " << worst);
                CHECK(worst <= 1e-6 * o.towWidth);
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
    const CurveOnSurface reference = referenceFromPlane(patch.surface, {1.3, 1, 0}, {1, 0.2, 0}, 21, true);
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
        if (method == SurfaceOffsetMethod::Geodesic) {
            CHECK(plan.offSurface == std::vector<std::string>{"c3", "c3_t1", "c3_t2", "c3_t3", "c3_t4"});
            REQUIRE(plan.tows.size() == 8);
        } else {  // Schueler's steps fall short: c3_t1's reaches the patch near y = 3
            REQUIRE(plan.offSurface.size() >= 4);
            CHECK(plan.offSurface.front() == "c3");
            REQUIRE(plan.tows.size() >= 8);
        }
        std::size_t throughSide = 0;
        for (const TowPath& t : plan.tows) {
            INFO(t.name);
            REQUIRE_FALSE(t.centreline.points.empty());
            for (const CurveOnSurface* c : {&t.centreline, &t.left, &t.right}) {
                if (c->points.empty()) continue;  // an edge wholly off the patch
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
                                          "--courses 3 --exact --min-steering-radius 1e6 --quiet --out '" + out.string() + "'");
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
    // A steering radius of a million: every tow on the curved patch needs less.
    CHECK(summary["steering"]["below"].size() == 6);
    CHECK(summary["steering"]["smallest_radius"].get<double>() < 1e6);
    CHECK(run.err.find("warning: 6 tow(s) must be steered") != std::string::npos);
    for (const auto& t : plan["tows"]) CHECK(t["geodesic_curvature"].size() == t["centreline"]["points"].size());
}

TEST_CASE("steering radius on a cone: geodesic offsets of a parallel are parallels, their radius of geodesic curvature the slant distance to the apex",
          "[placement][courses][steering]")
{
    // Frustum r 4 at z = 0 to r 2 at z = 3: generators 5 long (3-4-5 with the radius's change 2:
    // sqrt(9 + 4)), the apex at slant distance r L / (r0 - r1) from a parallel of radius r. Unrolled,
    // a parallel is a circle about the apex and its geodesic offsets (along the generators) the
    // concentric circles: radius of geodesic curvature = slant distance.
    const double r0 = 4.0, r1 = 2.0, h = 3.0, slant = std::hypot(h, r0 - r1);
    const NurbsSurface cone = testing::cone(r0, r1, h);
    const CurveOnSurface parallel = referenceFromPlane(cone, {3.0, 0, 1.5}, {0, 0, 1}, 33);
    REQUIRE(distance(parallel.points.front(), parallel.points.back()) <= 1e-9);
    CourseOptions o;
    o.towWidth = 0.3;
    o.towsPerCourse = 3;
    o.courses = 2;
    o.method = SurfaceOffsetMethod::Geodesic;
    o.minSteeringRadius = 5.5;  // the hoop's slant distance is 3 sqrt(13) / 2 = 5.41: tows either side
    const CoursePlan plan = layCourses(cone, parallel, o);
    REQUIRE(plan.tows.size() == 6);
    std::vector<std::string> below;
    for (const TowPath& t : plan.tows) {
        // Its slant distance to the apex from its own points (radius about the axis).
        const double r = std::hypot(t.centreline.points.front().x, t.centreline.points.front().y);
        const double apex = r * slant / (r0 - r1);
        INFO(t.name << " at radius " << r << ", slant " << apex << ": steering radius " << t.steeringRadius);
        CHECK(std::abs(t.steeringRadius - apex) <= 1e-6 * apex);
        REQUIRE(t.geodesicCurvature.size() == t.centreline.points.size());
        for (const double k : t.geodesicCurvature) CHECK(std::abs(std::abs(k) - 1.0 / apex) <= 1e-6 / apex);
        if (apex < 5.5) below.push_back(t.name);
    }
    CHECK_FALSE(below.empty());
    CHECK(plan.belowSteeringRadius == below);
    // A straight generator as reference on the cone: geodesics, no steering (radius infinite or
    // beyond a thousand times the cone).
    std::vector<UV> uv;
    for (int k = 0; k < 9; ++k) uv.push_back({0.3, 0.1 + 0.1 * k});
    o.courses = 1;
    o.towsPerCourse = 1;
    const CoursePlan straight = layCourses(cone, curveOnSurface(cone, uv), o);
    CHECK(straight.tows[0].steeringRadius >= 1e3 * slant);
}

TEST_CASE("coverage of a cylinder by hoop courses: the bands' share of the area once, the rest none, overlaps where the spacing is short",
          "[placement][courses][coverage]")
{
    // Cylinder R 2, 3 long; hoops (closed across the seam) from z = 1.5: 2 courses of 2 tows,
    // W 0.4, so the tows cover z in [1.1, 2.7] (courses go to one side: 1.6 of the 3, the
    // fraction 1.6 / 3 whichever side), edge to edge. At spacing 0.36 the three overlaps inside
    // a course pair and between courses are 0.04 each.
    const NurbsSurface cylinder = testing::cylinder(2.0, 3.0);
    const CurveOnSurface hoop = referenceFromPlane(cylinder, {2.0, 0, 1.5}, {0, 0, 1}, 33);
    CourseOptions o;
    o.towWidth = 0.4;
    o.towsPerCourse = 2;
    o.courses = 2;
    o.method = SurfaceOffsetMethod::Geodesic;
    // 150 cells along the axis: rows 0.02 high, and every band's border (z = 1.5 + multiples of
    // 0.02) on a row's edge, so each row is wholly in or out of a band and the fractions are
    // exact: whole rows of equal area (the cylinder's symmetry) over 150.
    const std::size_t cells = 150;
    {
        const CourseCoverage c = courseCoverage(cylinder, layCourses(cylinder, hoop, o), cells);
        CHECK(std::abs(c.uncovered + c.once + c.several - 1.0) <= 1e-12);
        CHECK(std::abs(c.once - 80.0 / cells) <= 1e-9);  // 1.6 / 0.02 rows
        CHECK(c.several <= 1e-12);
        CHECK(c.triangles.size() == 2 * cells * cells);
        // The tessellation's area: the cylinder's to the chords' error.
        CHECK(std::abs(c.totalArea - 2.0 * M_PI * 2.0 * 3.0) <= 1e-3 * c.totalArea);
        std::size_t twice = 0;
        for (const std::size_t n : c.count) twice += n > 1;
        CHECK(twice == 0);
    }
    o.spacing = 0.36;
    const CourseCoverage c = courseCoverage(cylinder, layCourses(cylinder, hoop, o), cells);
    CHECK(std::abs(c.uncovered + c.once + c.several - 1.0) <= 1e-12);
    // Covered: from -0.2 to 3 x 0.36 + 0.2 about the hoop (1.48, 74 rows); three overlaps of
    // 0.04 (6 rows) covered twice, 68 rows once.
    CHECK(std::abs(c.several - 6.0 / cells) <= 1e-9);
    CHECK(std::abs(c.once - 68.0 / cells) <= 1e-9);
    CHECK(std::abs(c.uncovered - 76.0 / cells) <= 1e-9);
    std::ostringstream vtk;
    writeCourseCoverageVtk(c, vtk);
    CHECK(vtk.str().find("coverage 1 " + std::to_string(c.triangles.size()) + " int") != std::string::npos);
}

TEST_CASE("a closed reference whose offset leaves the face over an arc: one tow from boundary to boundary, whatever the joint",
          "[placement][courses][trim]")
{
    // A tilted hoop z = 2.5 - 0.2 x on a cylinder R 2, 3 high (z in [2.1, 2.9]); tows 0.3 either
    // side: one stays on the face (closed), the other passes z = 3 around x = -2 and is cut there
    // twice: one open tow whose two ends lie on the top (v_max), every point at z <= 3.
    const NurbsSurface cylinder = testing::cylinder(2.0, 3.0);
    for (const double start : {0.0, 3.0}) {  // the cut's sampling from x = 2 or from near x = -2 (the joint in the off arc or not)
        const CurveOnSurface hoop = referenceFromPlane(cylinder, {2.0 * std::cos(start), 2.0 * std::sin(start), 2.5 - 0.4 * std::cos(start)}, {0.2, 0, 1}, 41);
        REQUIRE(distance(hoop.points.front(), hoop.points.back()) <= 1e-9);
        CourseOptions o;
        o.towWidth = 0.2;
        o.towsPerCourse = 2;
        o.spacing = 0.6;
        o.method = SurfaceOffsetMethod::Geodesic;
        const CoursePlan plan = layCourses(cylinder, hoop, o);
        REQUIRE(plan.tows.size() == 2);
        std::size_t cut = 0;
        for (const TowPath& t : plan.tows) {
            INFO(t.name << " from " << start);
            double highest = 0.0;
            for (const Point3& p : t.centreline.points) highest = std::max(highest, p.z);
            CHECK(highest <= 3.0 + 1e-12);
            if (t.startBoundary.empty()) {
                CHECK(distance(t.centreline.points.front(), t.centreline.points.back()) <= 1e-9);  // closed, on the face
                continue;
            }
            ++cut;
            CHECK(t.startBoundary == "v_max");
            CHECK(t.endBoundary == "v_max");
            CHECK(std::abs(t.centreline.points.front().z - 3.0) <= 1e-9);
            CHECK(std::abs(t.centreline.points.back().z - 3.0) <= 1e-9);
            CHECK(t.length > 2.0 * M_PI * 2.0 * 0.6);  // most of the way round
        }
        CHECK(cut == 1);
    }
}
