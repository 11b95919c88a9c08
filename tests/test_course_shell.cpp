// Fibre-placement courses over a tool shell of several faces (issue 42): a cylinder and a cone
// sewn along a circle, joined into one surface, the courses crossing the shared edge, checked
// against the closed form of the unrolled surfaces (geodesic offsets of a hoop are hoops on the
// cylinder and parallels on the cone at the slant distance beyond the edge).
#include <catch2/catch.hpp>

#include <towgeom/course_coverage.hpp>
#include <towgeom/fibre_courses.hpp>
#include <towgeom/placement_surface.hpp>
#include <towgeom/reference_curve.hpp>

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "occt_reference.hpp"

using namespace towgeom;
namespace fs = std::filesystem;

namespace {

struct ShellScratch {
    fs::path dir = fs::temp_directory_path() / ("towgeom_course_shell_" + std::to_string(::getpid()));
    ShellScratch() { fs::create_directories(dir); }
    ~ShellScratch() { fs::remove_all(dir); }
};

}  // namespace

TEST_CASE("courses over a cylinder and a cone sewn along a circle: hoops at the closed form's heights on both faces, gaps 0 across "
          "the shared edge",
          "[placement][courses][shell]")
{
    ShellScratch scratch;
    const double r = 4.0, h = 3.0, top = 2.0, coneH = 2.0;
    const double slant = std::hypot(r - top, coneH), sinA = (r - top) / slant, cosA = coneH / slant;
    const fs::path file = scratch.dir / "shell.step";
    testing::writeCylinderConeShell(file.string(), r, h, top, coneH);
    const PlacementSurface tool = readPlacementSurface(file.string(), std::vector<std::size_t>{0, 1});
    CHECK(tool.faces.size() == 2);
    // The hoop z = 1.6, run so that the courses go up (to its left), across the edge at z = 3.
    const double z0 = 1.6;
    CurveOnSurface reference = referenceFromPlane(tool, {r, 0.0, z0}, {0.0, 0.0, 1.0}, 41);
    if (reference.points[1].y < reference.points[0].y) reference = referenceFromPlane(tool, {r, 0.0, z0}, {0.0, 0.0, 1.0}, 41, true);
    CourseOptions o;
    o.towWidth = 0.5;
    o.towsPerCourse = 4;
    o.courses = 3;
    o.method = SurfaceOffsetMethod::Geodesic;
    const CoursePlan plan = layCourses(tool, reference, o);
    // A point at distance s along the surface from the hoop z = z0 (up: positive), on the
    // cylinder below the edge, on the cone beyond it.
    const auto expected = [&](double s) {
        const double z = z0 + s;
        if (z <= h) return std::pair<double, double>{r, z};
        const double beyond = z - h;
        return std::pair<double, double>{r - beyond * sinA, h + beyond * cosA};
    };
    double sign = 0.0;
    std::size_t onCone = 0;
    for (std::size_t k = 0; k < plan.tows.size(); ++k) {
        const TowPath& t = plan.tows[k];
        const double s = (static_cast<double>(t.course * 4) + (static_cast<double>(k % 4) - 1.5)) * 0.5;
        if (sign == 0.0) sign = t.centreline.points.front().z > z0 ? (s > 0 ? 1.0 : -1.0) : (s > 0 ? -1.0 : 1.0);
        const auto [er, ez] = expected(sign * s);
        double worst = 0.0;
        for (const Point3& p : t.centreline.points) worst = std::max({worst, std::abs(std::hypot(p.x, p.y) - er), std::abs(p.z - ez)});
        INFO(t.name << " at s = " << sign * s << ": radius and height off the closed form by " << worst);
        CHECK(worst <= 1e-8);
        CHECK(distance(t.centreline.points.front(), t.centreline.points.back()) <= 1e-9 * r);
        onCone += t.centreline.points.front().z > h ? 1 : 0;
    }
    // Three tows of course 2 and two of course 3 on the cone; the last two past its top.
    CHECK(onCone == 5);
    CHECK(plan.offSurface == std::vector<std::string>{"c3_t3", "c3_t4"});
    for (const TowGap& g : plan.gaps) {
        INFO("gap " << plan.tows[g.right].name << " | " << plan.tows[g.left].name << ": " << g.minWidth << " .. " << g.maxWidth);
        CHECK(std::abs(g.minWidth) <= 1e-6);
        CHECK(std::abs(g.maxWidth) <= 1e-6);
    }
    const CourseCoverage cover = courseCoverage(tool, plan, 60);
    CHECK(std::abs(cover.uncovered + cover.once + cover.several - 1.0) <= 1e-12);
}

TEST_CASE("courses over a folded sheet (two flat faces meeting at a crease, their parameters' rates differing across it): geodesic "
          "offsets of a line are the lines parallel to it in the sheet unfolded, across the crease",
          "[placement][courses][shell]")
{
    ShellScratch scratch;
    const double fold = 0.5;  // radians
    const fs::path file = scratch.dir / "folded.step";
    testing::writeFoldedSheet(file.string(), fold);
    const PlacementSurface tool = readPlacementSurface(file.string(), std::vector<std::size_t>{0, 1});
    // A point of the sheet unfolded into the plane z = 0: the turned face laid flat beyond y = 2.
    const auto unfolded = [](const Point3& p) {
        return p.y <= 2.0 && std::abs(p.z) < 1e-12 ? std::pair<double, double>{p.x, p.y} : std::pair<double, double>{p.x, 2.0 + std::hypot(p.y - 2.0, p.z)};
    };
    // The reference: a line on the flat face, slanting to the crease; the tows to its left cross it.
    const double x0 = 0.3, y0 = 0.4, x1 = 3.7, y1 = 1.1;
    std::vector<Point3> line;
    for (int k = 0; k <= 40; ++k) line.push_back({x0 + (x1 - x0) * k / 40.0, y0 + (y1 - y0) * k / 40.0, 0.0});
    const CurveOnSurface reference = referenceFromPoints(tool.surface, line);
    CourseOptions o;
    o.towWidth = 0.3;
    o.towsPerCourse = 3;
    o.courses = 3;
    o.method = SurfaceOffsetMethod::Geodesic;
    const CoursePlan plan = layCourses(tool, reference, o);
    const double length = std::hypot(x1 - x0, y1 - y0), nx = -(y1 - y0) / length, ny = (x1 - x0) / length;  // left of the line
    std::size_t acrossCrease = 0;
    for (std::size_t k = 0; k < plan.tows.size(); ++k) {
        const TowPath& t = plan.tows[k];
        const double s = (static_cast<double>(t.course * 3) + (static_cast<double>(k % 3) - 1.0)) * o.towWidth;
        double worst = 0.0;
        bool crosses = false;
        for (const Point3& p : t.centreline.points) {
            const auto [X, Y] = unfolded(p);
            worst = std::max(worst, std::abs((X - x0) * nx + (Y - y0) * ny - s));
            crosses = crosses || Y > 2.0;
        }
        acrossCrease += crosses ? 1 : 0;
        INFO(t.name << " at s = " << s << ": off its line in the unfolded sheet by " << worst);
        CHECK(worst <= 1e-8);
    }
    CHECK(acrossCrease >= 3);
    for (const TowGap& g : plan.gaps) {
        INFO("gap " << plan.tows[g.right].name << " | " << plan.tows[g.left].name << ": " << g.minWidth << " .. " << g.maxWidth);
        CHECK(std::abs(g.minWidth) <= 1e-6);
        CHECK(std::abs(g.maxWidth) <= 1e-6);
    }
}

TEST_CASE("towgeom courses --face 0,1 and --face all on a cylinder and cone's shell: exit 0, tows on the cone, ply refuses two faces",
          "[placement][courses][shell][cli]")
{
    ShellScratch scratch;
    const fs::path file = scratch.dir / "shell.step";
    testing::writeCylinderConeShell(file.string(), 4.0, 3.0, 2.0, 2.0);
    for (const char* faces : {"0,1", "all"}) {
        const fs::path out = scratch.dir / (std::string("plan_") + (faces[0] == 'a' ? "all" : "list"));
        const testing::Run run = testing::cli("courses '" + file.string() + "' --face " + faces + " --reference plane:4,0,2.6,0,0,1 --tow-width 0.5 " +
                                              "--tows 4 --exact --coverage-cells 40 --quiet --out '" + out.string() + "'");
        INFO(faces << ": " << run.err << run.out);
        REQUIRE(run.status == 0);
        CHECK(nlohmann::json::parse(run.out)["faces"].size() == 2);
        // Tows about the hoop z = 2.6, 0.5 apart: one of them beyond the edge z = 3, on the cone
        // (radius below 4), whichever way the courses go.
        std::ifstream planFile(out / "courses.json");
        const nlohmann::json plan = nlohmann::json::parse(planFile);
        REQUIRE(plan["tows"].size() == 4);
        std::size_t onCone = 0;
        for (const auto& t : plan["tows"]) {
            const auto& p = t["centreline"]["points"].front();
            onCone += p[2].get<double>() > 3.0 && std::hypot(p[0].get<double>(), p[1].get<double>()) < 4.0 - 1e-6 ? 1 : 0;
        }
        CHECK(onCone == 1);
    }
    const testing::Run ply = testing::cli("ply '" + file.string() + "' --face 0,1 --thickness 0.1 --quiet --out '" + (scratch.dir / "ply").string() + "'");
    CHECK(ply.status == 2);
    CHECK(ply.err.find("one face") != std::string::npos);
    CHECK_FALSE(fs::exists(scratch.dir / "ply" / "ply_1.json"));
}
