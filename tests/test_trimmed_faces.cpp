// Fibre-placement courses on trimmed faces (issue 42): tows end at the face's own trimming curves,
// not at its (u,v) box. Checked against closed forms on faces OpenCASCADE builds here: a flat
// "D" (a disk cut by a line: tows along y = s ending on the arc and the line) and a cylinder
// drilled through (hoops ending on the drill's cylinder, arcs of known length), the coverage
// against the D's strip areas (Simpson's rule).
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
#include <random>
#include <string>

#include "cli_runner.hpp"
#include "occt_reference.hpp"
#include "trimmed_face_family.hpp"

using namespace towgeom;
namespace fs = std::filesystem;

namespace {

/// A scratch directory removed at the end of the test.
struct TrimScratch {
    fs::path dir = fs::temp_directory_path() / ("towgeom_trimmed_faces_" + std::to_string(::getpid()));
    TrimScratch() { fs::create_directories(dir); }
    ~TrimScratch() { fs::remove_all(dir); }
};

/// A disk of radius r with the part x > c cut off (a "D"): how far it reaches left of the y
/// axis at height y, and right of it.
struct DShape {
    double r = 10.0, c = 6.0;
    double left(double y) const { return std::sqrt(std::max(0.0, r * r - y * y)); }
    double right(double y) const { return std::min(c, left(y)); }
    /// Its area between y = a and y = b (Simpson's rule on 20,000 intervals: the kinks where the
    /// line meets the arc cost ~1e-8).
    double strip(double a, double b) const
    {
        a = std::max(a, -r), b = std::min(b, r);
        const int n = 20000;
        const double h = (b - a) / n;
        double sum = 0.0;
        for (int k = 0; k <= n; ++k) sum += (k == 0 || k == n ? 1.0 : k % 2 ? 4.0 : 2.0) * (left(a + k * h) + right(a + k * h));
        return sum * h / 3.0;
    }
    double area() const { return strip(-r, r); }
};

/// Checks that @p c lies on the line y = @p y of the plane z = 0 and runs across @p d from its
/// left boundary (the arc) to its right one (the line x = c, or the arc above and below it):
/// its ends on the boundary within 2e-9 of the shape's radius, and where they should be on it
/// (within 1e-4: along the line y = @p y an end's place is ill-conditioned where the line
/// touches the arc, as the outermost edges do).
void checkChord(const CurveOnSurface& c, double y, const DShape& d, const std::string& what)
{
    double off = 0.0;
    for (const Point3& p : c.points) off = std::max({off, std::abs(p.y - y), std::abs(p.z)});
    const bool forward = c.points.front().x < c.points.back().x;
    const Point3& a = forward ? c.points.front() : c.points.back();
    const Point3& b = forward ? c.points.back() : c.points.front();
    const auto boundaryGap = [&](const Point3& p) {
        const double arc = p.x <= d.c ? std::abs(std::hypot(p.x, p.y) - d.r) : 1e300;
        const double line = std::abs(p.y) <= d.left(d.c) ? std::abs(p.x - d.c) : 1e300;
        return std::min(arc, line);
    };
    INFO(what << " on y = " << y << ": off the line " << off << ", ends at x = " << a.x << ", " << b.x << " against " << -d.left(y) << ", "
              << d.right(y) << ", off the boundary " << boundaryGap(a) << ", " << boundaryGap(b));
    CHECK(off <= 1e-9 * d.r);
    CHECK(boundaryGap(a) <= 2e-9 * d.r);
    CHECK(boundaryGap(b) <= 2e-9 * d.r);
    CHECK(std::abs(a.x + d.left(y)) <= 1e-4 * d.r);
    CHECK(std::abs(b.x - d.right(y)) <= 1e-4 * d.r);
}

}  // namespace

TEST_CASE("courses on a D-shaped face (a plane trimmed by an arc and a line): every tow across it ending on its boundary, its "
          "length the closed form's, coverage the D's strip",
          "[placement][courses][trim]")
{
    TrimScratch scratch;
    const DShape shape;
    const double r = shape.r, w = 2.0;
    const std::pair<bool, SurfaceOffsetMethod> cases[] = {
        {false, SurfaceOffsetMethod::Geodesic}, {false, SurfaceOffsetMethod::ProjectTangent}, {true, SurfaceOffsetMethod::Geodesic}};
    for (const auto& [reversed, method] : cases) {
        const std::string what = std::string(reversed ? "reversed D" : "D") + (method == SurfaceOffsetMethod::Geodesic ? ", geodesic" : ", tangent step");
        const fs::path file = scratch.dir / (reversed ? "d_reversed.step" : "d.step");
        testing::writeDiskFace(file.string(), r, shape.c, reversed);  // not symmetric: a reversal mistaken would show
        const PlacementSurface tool = readPlacementSurface(file.string());
        REQUIRE(tool.trim != nullptr);
        CHECK(tool.trimEdges == 2);
        // The plane y = 0 cuts the face's box from side to side; on the face, from the arc to the line.
        const CurveOnSurface reference = referenceFromPlane(tool, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 41);
        checkChord(reference, 0.0, shape, what + " reference");
        CourseOptions o;
        o.towWidth = w;
        o.towsPerCourse = 4;
        o.courses = 3;
        o.method = method;
        const CoursePlan plan = layCourses(tool, reference, o);
        // Tows at s = -+1, -+3 (course 1), then on one side 5, 7, 9; 11 and the third course lie off the face.
        REQUIRE(plan.tows.size() == 7);
        CHECK(std::find(plan.offSurface.begin(), plan.offSurface.end(), "c2_t4") != plan.offSurface.end());
        CHECK(std::find(plan.offSurface.begin(), plan.offSurface.end(), "c3") != plan.offSurface.end());
        double lowest = r, highest = -r;  // the strip the tows' bands cover
        for (const TowPath& t : plan.tows) {
            const double s = t.centreline.points.front().y;
            INFO(what << " " << t.name << " at y = " << s);
            CHECK(std::abs(std::remainder(s - 1.0, 2.0)) <= 1e-9);  // an odd whole number: W/2 + k W from the reference
            checkChord(t.centreline, s, shape, what + " " + t.name + " centreline");
            CHECK(std::abs(t.length - (shape.left(s) + shape.right(s))) <= 1e-8 * r);
            // Edge 0 is the arc, edge 1 the line (where the tow meets it).
            const std::string rightEnd = std::abs(s) < std::sqrt(r * r - shape.c * shape.c) ? "edge 1" : "edge 0";
            CHECK(((t.startBoundary == "edge 0" && t.endBoundary == rightEnd) || (t.startBoundary == rightEnd && t.endBoundary == "edge 0")));
            lowest = std::min(lowest, s - 0.5 * w), highest = std::max(highest, s + 0.5 * w);
            for (const CurveOnSurface* e : {&t.right, &t.left}) {
                if (e->points.empty()) continue;  // the edge along y = +-R touches the circle only
                checkChord(*e, e->points.front().y, shape, what + " " + t.name + " edge");
                CHECK(std::abs(std::abs(e->points.front().y - s) - 0.5 * w) <= 1e-9 * r);
            }
        }
        for (const TowGap& g : plan.gaps) {
            INFO(what << " gap " << plan.tows[g.right].name << " | " << plan.tows[g.left].name);
            CHECK(g.measured > 0);
            CHECK(std::abs(g.minWidth) <= 1e-8);
            CHECK(std::abs(g.maxWidth) <= 1e-8);
        }
        // Coverage: the strip between the outermost tows' outer edges (the last one's reaching
        // the arc), once; the rest of the face none; only cells on the face counted.
        const CourseCoverage cover = courseCoverage(tool, plan, 100);
        const double area = shape.area(), strip = shape.strip(lowest, highest) / area;
        INFO(what << ": once " << cover.once << " against " << strip << ", area " << cover.totalArea << " against " << area);
        CHECK(std::abs(cover.once - strip) <= 1e-3);
        CHECK(cover.several == 0.0);
        CHECK(std::abs(cover.uncovered + cover.once + cover.several - 1.0) <= 1e-12);
        CHECK(std::abs(cover.totalArea - area) <= 2e-3 * area);
    }
}

TEST_CASE("a hole smaller than the spacing of a curve's points is found between them: the reference and the tow across it cut "
          "on its rim, the tows beside it whole",
          "[placement][courses][trim]")
{
    TrimScratch scratch;
    const DShape shape;
    // Between two of the plane cut's 200 samples (0.08 apart, at x = 0.24 and 0.32) and between
    // two of the reference's 41 points: found only by probing between points.
    const double holeX = 0.28, holeRadius = 0.03;
    const fs::path file = scratch.dir / "d_hole.step";
    testing::writeDiskFace(file.string(), shape.r, shape.c, false, holeX, holeRadius);
    const PlacementSurface tool = readPlacementSurface(file.string());
    REQUIRE(tool.trim != nullptr);
    CHECK(tool.trimEdges == 3);
    const auto onRim = [&](const Point3& p) { return std::abs(std::hypot(p.x - holeX, p.y) - holeRadius); };
    const auto rightEnd = [](const CurveOnSurface& c) { return c.points.front().x > c.points.back().x ? c.points.front() : c.points.back(); };
    const CurveOnSurface reference = referenceFromPlane(tool, {-5.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 41);
    INFO("the reference ends at x = " << rightEnd(reference).x << ", off the rim by " << onRim(rightEnd(reference)));
    CHECK(onRim(rightEnd(reference)) <= 2e-9 * shape.r);  // its longer run, from the arc to the hole
    CourseOptions o;
    o.towWidth = 2.0;
    o.towsPerCourse = 3;
    o.method = SurfaceOffsetMethod::Geodesic;
    const CoursePlan plan = layCourses(tool, reference, o);
    REQUIRE(plan.tows.size() == 3);
    for (const TowPath& t : plan.tows) {
        const double s = t.centreline.points.front().y;
        INFO(t.name << " at y = " << s << " ends at x = " << rightEnd(t.centreline).x << ", off the rim by " << onRim(rightEnd(t.centreline)));
        if (std::abs(s) < 1e-9) {
            CHECK(onRim(rightEnd(t.centreline)) <= 2e-9 * shape.r);  // the tow over the hole: cut on its rim
            CHECK((t.startBoundary.rfind("edge ", 0) == 0 && t.endBoundary.rfind("edge ", 0) == 0 && t.startBoundary != t.endBoundary));
        } else {
            CHECK(std::abs(std::abs(s) - 2.0) <= 1e-9);  // beside it: whole, from the arc to the line
            CHECK(std::abs(t.length - (shape.left(s) + shape.right(s))) <= 1e-8 * shape.r);
        }
    }
}

TEST_CASE("courses on a cylinder drilled through: hoops cut where they meet the holes, ends on the drill's cylinder, arcs of the "
          "closed-form length, whole hoops above the holes closed, coverage the strip between the holes",
          "[placement][courses][trim]")
{
    TrimScratch scratch;
    const double r = 5.0, height = 10.0, hole = 1.5, size = std::hypot(2.0 * r, height);
    const fs::path file = scratch.dir / "holed.step";
    testing::writeHoledCylinderFace(file.string(), r, height, hole);
    const PlacementSurface tool = readPlacementSurface(file.string());
    REQUIRE(tool.trim != nullptr);
    CHECK(tool.trimEdges == 4);  // the two circles at the ends and the two holes' rims
    const auto onDrill = [&](const Point3& p) { return std::hypot(p.x, p.z - 0.5 * height); };
    // The holes' rims are the boolean's approximations of the cylinders' intersection: an end
    // lies on the drill within their tolerance (as OpenCASCADE records it), not closer.
    const testing::FaceOracle oracle(file.string());
    const double rim = 1e-9 * size + oracle.edgeTolerance();
    INFO("the rims' tolerance " << oracle.edgeTolerance());
    CHECK(oracle.edgeTolerance() <= 1e-6);
    // The hoop through the holes' middle: its run on the face nearest (r, 0, 5), the arc x > 0
    // between the holes, across the cylinder's seam (the cut is one closed curve: the run passes
    // its start).
    const CurveOnSurface reference = referenceFromPlane(tool, {r, 0.0, 0.5 * height}, {0.0, 0.0, 1.0}, 61);
    for (const Point3& p : {reference.points.front(), reference.points.back()}) CHECK(std::abs(onDrill(p) - hole) <= rim);
    CourseOptions o;
    o.towWidth = 0.6;
    o.towsPerCourse = 4;
    o.method = SurfaceOffsetMethod::Geodesic;
    const CoursePlan plan = layCourses(tool, reference, o);
    REQUIRE(plan.tows.size() == 4);
    // The arc of the hoop at z = 5 + s between the holes: from the drill's cylinder round to it.
    const auto arcLength = [&](double s) { return r * (M_PI - 2.0 * std::asin(std::sqrt(hole * hole - s * s) / r)); };
    const auto checkArc = [&](const CurveOnSurface& c, const std::string& what) {
        const double z = c.points.front().z;
        double off = 0.0;
        for (const Point3& p : c.points) {
            off = std::max({off, std::abs(std::hypot(p.x, p.y) - r), std::abs(p.z - z)});
            CHECK(p.x > 0.0);
        }
        INFO(what << " at z = " << z << ": off its hoop " << off << ", ends on the drill at " << onDrill(c.points.front()) << ", "
                  << onDrill(c.points.back()));
        CHECK(off <= 1e-9 * r);
        CHECK(std::abs(onDrill(c.points.front()) - hole) <= rim);
        CHECK(std::abs(onDrill(c.points.back()) - hole) <= rim);
    };
    for (const TowPath& t : plan.tows) {
        checkArc(t.centreline, t.name + " centreline");
        const double s = t.centreline.points.front().z - 0.5 * height;
        INFO(t.name << ": length " << t.length << " against " << arcLength(s));
        CHECK(std::abs(t.length - arcLength(s)) <= 1e-7 * r);
        CHECK(t.startBoundary.rfind("edge ", 0) == 0);
        CHECK(t.endBoundary.rfind("edge ", 0) == 0);
        checkArc(t.right, t.name + " right edge");
        checkArc(t.left, t.name + " left edge");
    }
    // Coverage: the strip |z - 5| <= 1.2 of the arc x > 0, once (Simpson's rule on the arcs'
    // lengths), of the face's area as OpenCASCADE measures it.
    double strip = 0.0;
    const int n = 2000;
    for (int k = 0; k <= n; ++k) strip += (k == 0 || k == n ? 1.0 : k % 2 ? 4.0 : 2.0) * arcLength(-1.2 + 2.4 * k / n);
    strip *= 2.4 / n / 3.0;
    const CourseCoverage cover = courseCoverage(tool, plan, 100);
    INFO("once " << cover.once << " against " << strip / oracle.area() << "; area " << cover.totalArea << " against " << oracle.area());
    CHECK(std::abs(cover.totalArea - oracle.area()) <= 1e-3 * oracle.area());  // measured 2e-4 (the cells' chords)
    CHECK(std::abs(cover.once - strip / oracle.area()) <= 5e-4);  // measured 4e-5
    CHECK(cover.several == 0.0);
    // Above the holes the hoops close round the seam.
    const CoursePlan above = layCourses(tool, referenceFromPlane(tool, {r, 0.0, 8.5}, {0.0, 0.0, 1.0}, 61), o);
    REQUIRE(above.tows.size() == 4);
    for (const TowPath& t : above.tows) {
        INFO(t.name);
        CHECK(distance(t.centreline.points.front(), t.centreline.points.back()) <= 1e-9 * r);
        CHECK(t.startBoundary.empty());
        CHECK(std::abs(t.length - 2.0 * M_PI * r) <= 1e-7 * r);
    }
}

TEST_CASE("towgeom courses on a disk's STEP: exit 0, the trims on 'edge 0', trim_edges in the summary", "[placement][courses][trim][cli]")
{
    TrimScratch scratch;
    const fs::path file = scratch.dir / "disk.step";
    testing::writeDiskFace(file.string(), 10.0, 10.0);
    const fs::path out = scratch.dir / "plan";
    const testing::Run run = testing::cli("courses '" + file.string() + "' --reference plane:0,0,0,0,1,0 --tow-width 2 --tows 2 --courses 2 --exact " +
                                          "--coverage-cells 100 --quiet --out '" + out.string() + "'");
    INFO(run.err << run.out);
    REQUIRE(run.status == 0);
    const nlohmann::json summary = nlohmann::json::parse(run.out);
    CHECK(summary["trim_edges"] == 1);
    REQUIRE(summary["trimmed"].size() == 4);
    for (const auto& t : summary["trimmed"]) {
        CHECK(t["start_boundary"] == "edge 0");
        CHECK(t["end_boundary"] == "edge 0");
    }
    // Tows at y = -+1 (course 1) and 3, 5 (course 2): each a chord 2 sqrt(100 - y^2) long.
    std::vector<double> lengths;
    for (const auto& t : summary["trimmed"]) lengths.push_back(t["length"].get<double>());
    std::sort(lengths.begin(), lengths.end());
    const double expected[] = {2.0 * std::sqrt(75.0), 2.0 * std::sqrt(91.0), 2.0 * std::sqrt(99.0), 2.0 * std::sqrt(99.0)};
    for (std::size_t k = 0; k < 4; ++k) CHECK(std::abs(lengths[k] - expected[k]) <= 1e-7);
    CHECK(fs::exists(out / "courses.step"));
    CHECK(fs::exists(out / "coverage.vtk"));
}

TEST_CASE("a randomized family of trimmed B-spline patches (ellipses, some with a hole) cut by random planes: every tow on the face, "
          "its cut ends on the boundary, by OpenCASCADE's own distances",
          "[placement][courses][trim][random]")
{
    TrimScratch scratch;
    for (unsigned seed = 1; seed <= 6; ++seed) {
        const bool hole = seed % 2 == 0;
        const fs::path file = scratch.dir / ("patch" + std::to_string(seed) + ".step");
        const testing::RandomTrimmedPatch made = testing::writeRandomTrimmedPatch(file.string(), seed, hole);
        const testing::FaceOracle oracle(file.string());
        const PlacementSurface tool = readPlacementSurface(file.string());
        REQUIRE(tool.trim != nullptr);
        CHECK(tool.trimEdges == (hole ? 2u : 1u));
        std::mt19937 random(1000 + seed);
        const double turn = std::uniform_real_distribution<double>(0.0, M_PI)(random);
        const CurveOnSurface reference = referenceFromPlane(tool, made.inside, {std::cos(turn), std::sin(turn), 0.0}, 41);
        CourseOptions o;
        o.towWidth = 0.2;
        o.towsPerCourse = 3;
        o.method = seed % 4 < 2 ? SurfaceOffsetMethod::Geodesic : SurfaceOffsetMethod::ProjectTangent;
        const CoursePlan plan = layCourses(tool, reference, o);
        const double onTolerance = 2e-9 * oracle.size();
        const auto checkOnFace = [&](const CurveOnSurface& c, const std::string& what) {
            double worst = 0.0;
            for (const Point3& p : c.points) worst = std::max(worst, oracle.toFace(p));
            INFO("seed " << seed << " " << what << ": farthest point from the face " << worst);
            CHECK(worst <= onTolerance);
        };
        checkOnFace(reference, "reference");
        for (const Point3& p : {reference.points.front(), reference.points.back()}) {
            INFO("seed " << seed << " reference end off the boundary by " << oracle.toBoundary(p));
            CHECK(oracle.toBoundary(p) <= onTolerance);  // a plane cut's run: boundary to boundary
        }
        REQUIRE(!plan.tows.empty());
        for (const TowPath& t : plan.tows) {
            checkOnFace(t.centreline, t.name + " centreline");
            checkOnFace(t.right, t.name + " right edge");
            checkOnFace(t.left, t.name + " left edge");
            for (const bool start : {true, false}) {
                const std::string& side = start ? t.startBoundary : t.endBoundary;
                const Point3& end = start ? t.centreline.points.front() : t.centreline.points.back();
                INFO("seed " << seed << " " << t.name << (start ? " start" : " end") << " on '" << side << "', off the boundary by "
                             << oracle.toBoundary(end));
                if (!side.empty()) CHECK(oracle.toBoundary(end) <= onTolerance);
                if (!side.empty()) CHECK(side.rfind("edge ", 0) == 0);
            }
        }
        const CourseCoverage cover = courseCoverage(tool, plan, 60);
        INFO("seed " << seed << ": coverage area " << cover.totalArea << " against the face's " << oracle.area());
        CHECK(std::abs(cover.totalArea - oracle.area()) <= 1e-2 * oracle.area());  // 60 cells a side: measured 0.25 % at most
        CHECK(std::abs(cover.uncovered + cover.once + cover.several - 1.0) <= 1e-12);
        CHECK(cover.once > 0.0);
    }
}
