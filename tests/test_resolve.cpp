// resolveTextile(): compatible tow meshes on a 4x4 2/2 twill and on two tubes whose loop crosses
// both periodic seams. Checked independently with CGAL: no crossing triangles between any two
// tows, each connected region shared triangle for triangle, two boundary loops per tube, the
// primaries unchanged, the secondary's volume loss equal to the overlap of the input tubes
// (corefinement; analytic too for the tubes), and the triangles' smallest angles.
#include <catch2/catch.hpp>

#include <towgeom/error.hpp>
#include <towgeom/intersection_loop.hpp>
#include <towgeom/report.hpp>
#include <towgeom/resolve.hpp>
#include <towgeom/tow_stack.hpp>
#include <towgeom/tow_surface.hpp>
#include <towgeom/weave.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "analytic_reference.hpp"
#include "cgal_reference.hpp"
#include "mesh_checks.hpp"
#include "synthetic_tows.hpp"

using namespace towgeom;

namespace {

constexpr double kPi = 3.14159265358979323846;
using Triangle = std::array<std::size_t, 3>;

double seconds(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

testing::Sampling sampling(double startAngle, std::size_t sections, std::size_t points)
{
    testing::Sampling s;
    s.sections = sections;
    s.points = points;
    s.startAngle = startAngle;
    return s;
}

WeaveOptions twill22(std::size_t sectionsPerYarn = 0, std::size_t pointsPerSection = 32)
{
    WeaveOptions o;
    o.kind = WeaveKind::Twill;
    o.floatOver = o.floatUnder = 2;
    o.overlap = 0.08;
    o.sectionsPerYarn = sectionsPerYarn;
    o.pointsPerSection = pointsPerSection;
    return o;
}

/// The tubes of the seam test: x-tube R = 0.5 along x, y-tube r = 0.4 at height d = 0.6; sections
/// starting at pi/2 (x) and -pi/2 (y) put both seams through the loop.
constexpr double kR = 0.5, kr = 0.4, kd = 0.6;
std::vector<TowStack> seamTubes(std::size_t sections, std::size_t points, double startX, double startY)
{
    return {testing::tubeAlongX(kR, 4.0, 0.0, 0.0, 0.0, sampling(startX, sections, points), "x"),
            testing::tubeAlongY(kr, kd, sampling(startY, sections, points), "y")};
}

/// The exact overlap of the two tubes' cylinders (both tubes long enough).
double analyticOverlapVolume() { return testing::CrossingCylinders{kR, kr, kd}.overlapVolume(); }

std::vector<TowSurface> fit(const std::vector<TowStack>& stacks)
{
    std::vector<TowSurface> tows;
    for (const TowStack& s : stacks) tows.push_back(TowSurface::fit(s));
    return tows;
}

Triangle canonical(Triangle t)
{
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    return t;
}

Triangle reversed(const Triangle& t) { return {t[0], t[2], t[1]}; }

/// Checks 1a-1d and 3 on a result; returns the number of crossing triangle pairs found.
std::size_t checkResolved(const ResolveResult& res, std::size_t expectedRegions)
{
    const TextileMesh& mesh = res.mesh;
    const std::size_t n = mesh.tows.size();
    CHECK(res.skippedLoops.empty());
    // At most 6 rounds (resolve.cpp's kMaxRounds; resolve.hpp documents it), and nothing left
    // over the bounds after them (README: 0 on every textile in the tests).
    CHECK(res.meshRounds >= 1);
    CHECK(res.meshRounds <= 6);
    CHECK(res.quality.facesOverBounds == 0);
    CHECK(mesh.regions.size() == expectedRegions);

    // a. No crossing triangle pair between any two tows (CGAL, exact predicates).
    std::size_t crossing = 0, sharingCrossing = 0, boxPairs = 0, identical = 0;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j) {
            const testing::TriangleCrossings c =
                testing::crossingTrianglePairs(mesh.nodes, mesh.tows[i].triangles, mesh.tows[j].triangles);
            INFO(mesh.tows[i].name << " x " << mesh.tows[j].name << ": " << c.crossing << " crossing pairs ("
                                   << c.crossingSharing << " of them sharing a node), " << c.boxPairs << " box pairs, "
                                   << c.identical << " identical");
            CHECK(c.crossing == 0);
            crossing += c.crossing;
            sharingCrossing += c.crossingSharing;
            boxPairs += c.boxPairs;
            identical += c.identical;
        }
    WARN("crossing triangle pairs between tows: " << crossing << " (" << sharingCrossing << " sharing a node) of "
                                                  << boxPairs << " box pairs; identical (shared) pairs: " << identical);

    // b. Each region: the secondary holds every one of the region's primary triangles, reversed.
    std::size_t sharedTotal = 0;
    for (std::size_t id = 0; id < mesh.regions.size(); ++id) {
        const ConnectedRegion& r = mesh.regions[id];
        INFO("region " << id << ": primary " << mesh.tows[r.primary].name << ", secondary " << mesh.tows[r.secondary].name);
        const TowMesh& p = mesh.tows[r.primary];
        const TowMesh& q = mesh.tows[r.secondary];
        std::set<Triangle> inSecondary;
        for (const Triangle& t : q.triangles) inSecondary.insert(canonical(t));
        std::size_t shared = 0, sharedUnreversed = 0;
        for (std::size_t k = 0; k < p.triangles.size(); ++k) {
            if (inSecondary.count(canonical(reversed(p.triangles[k])))) ++shared;
            if (inSecondary.count(canonical(p.triangles[k]))) ++sharedUnreversed;
        }
        CHECK(shared >= 1);
        CHECK(sharedUnreversed == 0);
        CHECK(shared == r.triangles.size());
        for (std::size_t k : r.triangles) {
            REQUIRE(k < p.triangles.size());
            CHECK(inSecondary.count(canonical(reversed(p.triangles[k]))) == 1);
        }
        CHECK(static_cast<std::size_t>(std::count(q.region.begin(), q.region.end(), static_cast<long>(id))) == shared);
        sharedTotal += shared;
    }
    WARN("shared triangles: " << sharedTotal << " in " << mesh.regions.size() << " regions");

    // c. Every tow closed by its two caps: no boundary, also counted without TextileMesh.
    for (std::size_t t = 0; t < n; ++t) {
        INFO("tow " << mesh.tows[t].name);
        const testing::Boundary b = testing::boundaryOf(mesh.tows[t].triangles);
        CHECK(mesh.boundaryLoopCount(t) == 0);
        CHECK(res.tows[t].boundaryLoops == 0);
        CHECK(b.loops == 0);
        CHECK(b.edges == 0);
        REQUIRE(mesh.tows[t].face.size() == mesh.tows[t].triangles.size());
        CHECK(std::count(mesh.tows[t].face.begin(), mesh.tows[t].face.end(), TowFace::Start) > 0);
        CHECK(std::count(mesh.tows[t].face.begin(), mesh.tows[t].face.end(), TowFace::End) > 0);
        CHECK(b.nodesNotTwo == 0);
        CHECK(b.nonManifoldEdges == 0);
        CHECK(b.misorientedEdges == 0);
    }

    // d. Primaries that are never secondary keep their mesh: their volume is unchanged, their
    // triangles belong to no region of another tow, and CGAL measures the same volume.
    for (std::size_t t = 0; t < n; ++t) {
        INFO("tow " << mesh.tows[t].name);
        const TowResolution& r = res.tows[t];
        const double cgal = testing::closedMeshVolume(mesh.closedTowSurface(t));
        CHECK(r.volumeAfter == Approx(cgal).epsilon(1e-9));
        if (r.secondaryAnywhere) continue;
        CHECK(r.volumeAfter == Approx(r.volumeBefore).epsilon(1e-12));
        for (long id : mesh.tows[t].region)
            if (id >= 0) CHECK(mesh.regions[static_cast<std::size_t>(id)].primary == t);
    }
    return crossing;
}

/// 1e: each region's volumeRemoved, and each secondary's volume loss, against CGAL's overlap
/// volume of the closed faceted input tubes. Returns the worst relative difference per region.
double checkRemovedVolume(const ResolveResult& res, const std::vector<TowStack>& stacks, double tolerance)
{
    const TextileMesh& mesh = res.mesh;
    std::vector<double> lost(stacks.size(), 0.0), reference(stacks.size(), 0.0);
    double worst = 0.0;
    for (const ConnectedRegion& r : mesh.regions) {
        const double cgal = testing::intersectionVolume(facetedTube(stacks[r.primary], true), facetedTube(stacks[r.secondary], true));
        const double rel = std::abs(r.volumeRemoved - cgal) / cgal;
        worst = std::max(worst, rel);
        INFO(mesh.tows[r.primary].name << " over " << mesh.tows[r.secondary].name << ": removed " << r.volumeRemoved
                                       << ", CGAL overlap of the faceted tubes " << cgal << " (" << 100.0 * rel << " %)");
        CHECK(rel <= tolerance);
        lost[r.secondary] += r.volumeRemoved;
        reference[r.secondary] += cgal;
    }
    for (std::size_t t = 0; t < stacks.size(); ++t) {
        if (!res.tows[t].secondaryAnywhere) continue;
        const double drop = res.tows[t].volumeBefore - res.tows[t].volumeAfter;
        INFO("tow " << mesh.tows[t].name << ": volume " << res.tows[t].volumeBefore << " -> " << res.tows[t].volumeAfter
                    << ", regions " << lost[t] << ", CGAL " << reference[t]);
        CHECK(drop == Approx(lost[t]).epsilon(1e-6));
        CHECK(std::abs(drop - reference[t]) <= tolerance * reference[t]);
    }
    return worst;
}

}  // namespace

TEST_CASE("the CGAL crossing check finds the crossing of the unresolved tubes, none within one mesh", "[resolve][reference]")
{
    // The faceted input tubes on one node numbering cross along the loop; a mesh against itself
    // (every pair identical or sharing nodes) and against a copy moved clear of it do not.
    const std::vector<TowStack> stacks = seamTubes(21, 96, kPi / 2, -kPi / 2);
    const TriangleMesh x = facetedTube(stacks[0], false), y = facetedTube(stacks[1], false);
    std::vector<Point3> nodes = x.vertices;
    nodes.insert(nodes.end(), y.vertices.begin(), y.vertices.end());
    std::vector<Triangle> tx = x.triangles, ty = y.triangles, far = y.triangles;
    for (Triangle& t : ty)
        for (std::size_t& n : t) n += x.vertices.size();
    for (const Point3& p : y.vertices) nodes.push_back(p + Point3{0.0, 0.0, 5.0});
    for (Triangle& t : far)
        for (std::size_t& n : t) n += x.vertices.size() + y.vertices.size();
    const testing::TriangleCrossings crossing = testing::crossingTrianglePairs(nodes, tx, ty);
    WARN("faceted input tubes: " << crossing.crossing << " crossing triangle pairs");
    CHECK(crossing.crossing > 0);
    const testing::TriangleCrossings self = testing::crossingTrianglePairs(nodes, tx, tx);
    CHECK(self.crossing == 0);
    CHECK(self.identical == tx.size());
    CHECK(self.sharing > 0);
    CHECK(testing::crossingTrianglePairs(nodes, ty, far).crossing == 0);
}

TEST_CASE("resolved 4x4 2/2 twill: no crossing triangles, shared regions, tubes, primaries unchanged", "[resolve][weave]")
{
    const auto t0 = std::chrono::steady_clock::now();
    const std::vector<TowStack> stacks = generateWeave(twill22()).stacks();
    ResolveOptions o;
    o.mesh.edgeLength = 0.05;
    const ResolveResult res = resolveTextile(fit(stacks), o);
    CHECK(res.intersections.loops.size() == 16);
    CHECK(checkResolved(res, 16) == 0);
    // Warps come first: every warp is primary only, every weft secondary only, 4 regions each.
    for (std::size_t t = 0; t < 8; ++t) {
        CHECK(res.tows[t].primaryAnywhere == (t < 4));
        CHECK(res.tows[t].secondaryAnywhere == (t >= 4));
    }
    WARN("twill: " << res.quality.triangles << " triangles, " << res.meshRounds << " mesh rounds, min angle "
                   << res.quality.minAngle << ", >= 20 deg: " << res.quality.fractionAtLeast(20) << "; " << seconds(t0)
                   << " s (intersect " << res.timings.intersect << " ms, mesh " << res.timings.mesh << " ms, regions "
                   << res.timings.regions << " ms)");
}

namespace {

/// Crossing tubes sampled two ways with start angles that put each tube's seam through the loop
/// (pi/2, -pi/2), and a control without a seam through it (0, 0).
struct SeamTubeCase {
    std::size_t sections, points;
    double startX, startY;
    /// Relative difference of the removed volume from CGAL's overlap of the faceted input tubes
    /// (whose own error grows as the points around get fewer), 2-3x the observed: 1.1e-4 and
    /// 5.3e-5 at 96 points, 7.0e-3 at 48.
    double cgalTolerance;
};
const SeamTubeCase kSeamTubeCases[] = {
    {21, 96, kPi / 2, -kPi / 2, 3e-4}, {41, 48, kPi / 2, -kPi / 2, 1.5e-2}, {21, 96, 0.0, 0.0, 3e-4}};

/// How far a fitted tube of radius r sampled by n points around lies inside its cylinder: the
/// interpolating B-spline's sag at mid-span (testing::uniformBSplineCircle).
double fitSag(std::size_t n, double r)
{
    return r - testing::uniformBSplineCircle(n, testing::interpolatingControlRadius(n, r)).midRadius;
}

}  // namespace

TEST_CASE("resolved tubes whose loop crosses both seams: no crossing triangles, shared region, tubes", "[resolve][seam]")
{
    // Start angles pi/2 and -pi/2 put the seam of each tube through the loop; 0 and 0 (no seam
    // through it) is the control.
    for (const SeamTubeCase k : kSeamTubeCases) {
        INFO(k.sections << " sections x " << k.points << " points, start angles " << k.startX << ", " << k.startY);
        const auto t0 = std::chrono::steady_clock::now();
        const std::vector<TowStack> stacks = seamTubes(k.sections, k.points, k.startX, k.startY);
        ResolveOptions o;
        o.mesh.edgeLength = 0.05;
        try {
            const ResolveResult res = resolveTextile(fit(stacks), o);
            REQUIRE(res.intersections.loops.size() == 1);
            const IntersectionLoop& loop = res.intersections.loops.front();
            const std::size_t pieces = k.startX == 0.0 ? 1 : 2;  // cut by the seam, or not
            CHECK(loop.clippedUvCurves(LoopSide::A).size() == pieces);
            CHECK(loop.clippedUvCurves(LoopSide::B).size() == pieces);
            CHECK(checkResolved(res, 1) == 0);
            // Against the analytic cylinders: the secondary (y-tube) keeps only its surface outside
            // the x-tube (its loop nodes are on the fitted x-tube, inside the cylinder by at most
            // the fit's sag), and the shared surface is the x-tube's inside the y-tube (its loop
            // nodes on the fitted y-tube, which is inside its cylinder).
            const TextileMesh& m = res.mesh;
            const double sag = fitSag(k.points, kR);
            double worstOutside = 0.0, worstInside = 0.0;
            for (std::size_t t = 0; t < m.tows[1].triangles.size(); ++t)
                for (std::size_t n : m.tows[1].triangles[t]) {
                    const Point3& p = m.nodes[n];
                    if (m.tows[1].region[t] < 0)
                        worstOutside = std::max(worstOutside, kR - std::hypot(p.y, p.z));
                    else
                        worstInside = std::max(worstInside, std::hypot(p.x - 2.0, p.z - kd) - kr);
                }
            WARN("secondary nodes inside the x-tube by at most " << worstOutside << ", shared nodes outside the y-tube by at most "
                                                                 << worstInside);
            CHECK(worstOutside <= sag * (1.0 + 1e-6) + 1e-14);
            CHECK(worstInside <= 1e-14);
            CHECK(res.tows[0].primaryAnywhere);
            CHECK_FALSE(res.tows[0].secondaryAnywhere);
            CHECK(res.tows[1].secondaryAnywhere);
            WARN(k.sections << "x" << k.points << ": " << res.quality.triangles << " triangles, " << res.meshRounds
                            << " mesh rounds, min angle " << res.quality.minAngle << ", " << seconds(t0) << " s");
        } catch (const Error& e) {
            FAIL_CHECK("resolveTextile threw: " << e.what());
        }
    }
}

TEST_CASE("the secondary loses the overlap volume of the tubes (CGAL corefinement, analytic)", "[resolve][volume]")
{
    SECTION("crossing tubes")
    {
        const double exact = analyticOverlapVolume();
        for (const SeamTubeCase k : kSeamTubeCases) {
            INFO(k.sections << " sections x " << k.points << " points, start angles " << k.startX << ", " << k.startY);
            const std::vector<TowStack> stacks = seamTubes(k.sections, k.points, k.startX, k.startY);
            ResolveOptions o;
            o.mesh.edgeLength = 0.05;
            try {
                const ResolveResult res = resolveTextile(fit(stacks), o);
                REQUIRE(res.mesh.regions.size() == 1);
                const ConnectedRegion& r = res.mesh.regions.front();
                const double cgal = testing::intersectionVolume(facetedTube(stacks[0], true), facetedTube(stacks[1], true));
                const double drop = res.tows[1].volumeBefore - res.tows[1].volumeAfter;
                WARN(k.sections << "x" << k.points << ", start " << k.startX << ": removed " << r.volumeRemoved << ", drop "
                                << drop << ", CGAL (faceted) " << cgal << ", analytic " << exact << ": "
                                << 100.0 * (r.volumeRemoved / exact - 1.0) << " % vs analytic, "
                                << 100.0 * (r.volumeRemoved / cgal - 1.0) << " % vs CGAL");
                // Both patches bounding the removed volume are inscribed in convex cylinders, so it
                // is below the exact overlap: observed 0.240 % to 0.246 % below.
                CHECK(r.volumeRemoved < exact);
                CHECK(r.volumeRemoved > (1.0 - 0.005) * exact);
                CHECK(drop == Approx(r.volumeRemoved).epsilon(1e-9));
                CHECK(checkRemovedVolume(res, stacks, k.cgalTolerance) <= k.cgalTolerance);
            } catch (const Error& e) {
                FAIL_CHECK("resolveTextile threw: " << e.what());
            }
        }
    }
    SECTION("dense 2/2 twill")
    {
        const auto t0 = std::chrono::steady_clock::now();
        const std::vector<TowStack> stacks = generateWeave(twill22(121, 48)).stacks();
        ResolveOptions o;
        o.mesh.edgeLength = 0.05;
        const ResolveResult res = resolveTextile(fit(stacks), o);
        REQUIRE(res.mesh.regions.size() == 16);
        const double worst = checkRemovedVolume(res, stacks, 0.01);  // observed 0.49 %
        WARN("dense twill: worst relative difference of a region's removed volume from CGAL's overlap: " << 100.0 * worst
                                                                                                        << " %; " << seconds(t0) << " s");
    }
}

namespace {

/// Quality of @p tows resolved with edge length h and loop spacing h/2, h (default) and 2h.
void checkQuality(const std::vector<TowSurface>& tows, const char* what)
{
    const double h = 0.05;
    for (const double spacing : {0.5 * h, 0.0, 2.0 * h}) {
        INFO(what << ", loop spacing " << spacing << " (0: h = " << h << ")");
        ResolveOptions o;
        o.mesh.edgeLength = h;
        o.mesh.loopSpacing = spacing;
        try {
            const auto t0 = std::chrono::steady_clock::now();
            const ResolveResult res = resolveTextile(tows, o);
            WARN(what << ", loop spacing " << spacing << ": min angle " << res.quality.minAngle << ", >= 20 deg "
                      << res.quality.fractionAtLeast(20) << ", >= 10 deg " << res.quality.fractionAtLeast(10) << ", "
                      << res.quality.triangles << " triangles, " << res.meshRounds << " rounds, " << seconds(t0) << " s");
            // Observed: at least 0.99989 of the triangles >= 20 deg, the smallest 18.05 deg (twill)
            // and 20.3 deg (tubes).
            CHECK(res.quality.fractionAtLeast(20) >= 0.9997);
            CHECK(res.quality.minAngle >= 16.0);
            CHECK(res.skippedLoops.empty());
            // Size in 3D: edges other than loop chords (which are at the loop spacing) at most h,
            // up to the metric's interpolation; faces the mesher could not make good are counted.
            std::set<std::size_t> loopNodes;
            for (const ConnectedRegion& g : res.mesh.regions) loopNodes.insert(g.loopNodes.begin(), g.loopNodes.end());
            std::size_t edges = 0, over = 0;
            double longest = 0.0;
            for (const TowMesh& m : res.mesh.tows)
                for (const Triangle& t : m.triangles)
                    for (int k = 0; k < 3; ++k) {
                        const std::size_t a = t[k], b = t[(k + 1) % 3];
                        if (loopNodes.count(a) && loopNodes.count(b)) continue;
                        const double l = distance(res.mesh.nodes[a], res.mesh.nodes[b]);
                        ++edges;
                        over += l > 1.05 * h;
                        longest = std::max(longest, l);
                    }
            WARN(what << ": " << over << " of " << edges << " edges longer than 1.05 h, longest " << longest / h
                      << " h, faces over bounds " << res.quality.facesOverBounds);
            // Observed: at most 2 of 484004 edges over 1.05 h, the longest 1.064 h, no face over
            // the bounds (README: 0 on every textile in the tests).
            CHECK(over <= edges / 100000);
            CHECK(longest <= 1.1 * h);
            CHECK(res.quality.facesOverBounds == 0);
        } catch (const Error& e) {
            FAIL_CHECK("resolveTextile threw: " << e.what());
        }
    }
}

}  // namespace

TEST_CASE("mesh quality for small, default and large loop spacing: twill", "[resolve][quality]")
{
    checkQuality(fit(generateWeave(twill22()).stacks()), "twill");
}

TEST_CASE("mesh quality for small, default and large loop spacing: tubes, loop across both seams", "[resolve][quality][seam]")
{
    checkQuality(fit(seamTubes(21, 96, kPi / 2, -kPi / 2)), "tubes");
}

TEST_CASE("the minimum angle asked for is the one the mesher refines to", "[resolve][quality]")
{
    // A larger bound refines further (a bound that never reached the mesher would give the same
    // mesh both times: CGAL's criteria derive virtually from the shape criterion, whose bound
    // the most derived class must pass on). The bound is met in the plane each tow is meshed
    // in, 3/4 of it on the surface; in 3D the 30 degree mesh keeps 99 % of its triangles above
    // 25 degrees. Observed: 154,854 and 163,736 triangles, 98.60 % and 98.97 % of them at
    // least 30 degrees (before the surface's bound was 3/4 of the plane's, the 30 degree mesh
    // had 1.5 times the triangles: the surface's bound at the plane's refined on and on).
    const std::vector<TowSurface> tows = fit(generateWeave(twill22()).stacks());
    const auto quality = [&](double degrees) {
        ResolveOptions o;
        o.mesh.edgeLength = 0.05;
        o.mesh.minAngle = degrees;
        return resolveTextile(tows, o).quality;
    };
    const MeshQuality q20 = quality(20.0), q30 = quality(30.0);
    WARN("min angle 20: " << q20.triangles << " triangles, >= 25 deg " << q20.fractionAtLeast(25) << ", >= 30 deg "
                          << q20.fractionAtLeast(30) << "; min angle 30: " << q30.triangles << " triangles, >= 25 deg "
                          << q30.fractionAtLeast(25) << ", >= 30 deg " << q30.fractionAtLeast(30));
    CHECK(q30.triangles > 103 * q20.triangles / 100);
    CHECK(q30.fractionAtLeast(30) > q20.fractionAtLeast(30) + 0.002);
    CHECK(q20.fractionAtLeast(20) >= 0.99);
    CHECK(q30.fractionAtLeast(25) >= 0.99);
}

namespace {

/// Two tows resolved with @p primaryPattern first: one region, nothing skipped or unresolved,
/// closed, no crossing triangle pair; the primary keeps its volume and the secondary loses the
/// overlap of the closed faceted tows (CGAL corefinement) within 2 %.
ResolveResult checkTwoResolved(const std::vector<TowSurface>& tows, const std::vector<TowStack>& stacks, const IntersectionReport& report,
                               double h, const std::string& primaryPattern)
{
    ResolveOptions o;
    o.mesh.edgeLength = h;
    o.primaryPatterns = {primaryPattern};
    const ResolveResult r = resolveTextile(tows, report, o);
    CHECK(r.skippedLoops.empty());
    for (const UnresolvedPair& u : r.unresolved) FAIL_CHECK(u.message);
    CHECK(r.mesh.regions.size() == 1);
    for (const TowResolution& t : r.tows) CHECK(t.boundaryLoops == 0);
    CHECK(testing::crossingPairsBetweenTows(r.mesh) == 0);
    const std::size_t primary = tows[0].name() == primaryPattern ? 0 : 1, secondary = 1 - primary;
    REQUIRE(r.ranks.size() == 2);
    CHECK(r.ranks[primary] == 0);
    CHECK(r.ranks[secondary] == 1);
    const double overlap = testing::intersectionVolume(facetedTube(stacks[0], true), facetedTube(stacks[1], true));
    CHECK(r.tows[primary].volumeAfter == Approx(r.tows[primary].volumeBefore).epsilon(1e-12));
    CHECK(r.tows[secondary].volumeBefore - r.tows[secondary].volumeAfter == Approx(overlap).epsilon(0.02));
    if (!r.mesh.regions.empty()) CHECK(r.mesh.regions.front().volumeRemoved == Approx(overlap).epsilon(0.02));
    return r;
}

}  // namespace

TEST_CASE("a tow ending inside another: its loop runs across the cap, both ranks resolved exactly", "[resolve][caps]")
{
    // The stub (radius 0.5 along x) ends at x = 2 inside the y-tube (axis x = 2, z = d): with its
    // last end (x from 0 to 2, listed first: the cap on side A) or its first end (x from 2 to 4,
    // listed second: side B). For d = 0.7 the cap's part inside the y-tube is a segment off its
    // centre; for d = 0.5 the chord runs through the centre, where the cap chart's v is
    // undefined; for d = 0.3 the part holds the centre, and the loop goes once around the stub
    // in its closed chart (tube and cap).
    for (const bool firstEnd : {false, true})
        for (const double d : {0.7, 0.5, 0.3})
            for (const bool stubFirst : {true, false}) {
                DYNAMIC_SECTION((firstEnd ? "the stub's first end" : "the stub's last end")
                                << ", d = " << d << (stubFirst ? ", the stub ranked first" : ", the y-tube ranked first"))
                {
                    const TowStack stub = testing::tubeAlongX(0.5, 2.0, firstEnd ? 2.0 : 0.0, 0.0, 0.0, sampling(0.0, 41, 48), "stub");
                    const TowStack y = testing::tubeAlongY(0.5, d, sampling(0.0, 41, 48), "y");
                    const std::vector<TowStack> stacks = firstEnd ? std::vector<TowStack>{y, stub} : std::vector<TowStack>{stub, y};
                    const std::size_t s = firstEnd ? 1 : 0;  // the stub's index
                    const LoopSide side = firstEnd ? LoopSide::B : LoopSide::A;
                    const LoopSide other = firstEnd ? LoopSide::A : LoopSide::B;
                    const std::vector<TowSurface> tows = fit(stacks);
                    const IntersectionReport report = intersectTows(tows);
                    REQUIRE(report.loops.size() == 1);
                    const IntersectionLoop& l = report.loops.front();
                    CHECK(l.closed());
                    CHECK(l.crossesCap(side));
                    CHECK_FALSE(l.crossesCap(other));
                    CHECK(l.windsAround(side) == (d < 0.45));
                    CHECK_FALSE(l.windsAround(other));
                    for (const LoopPoint& p : l.points()) {
                        const UV a = side == LoopSide::A ? p.onA : p.onB, b = side == LoopSide::A ? p.onB : p.onA;
                        CHECK(distance(tows[s].pointOnClosed(a.u, a.v), p.point) <= l.tolerance());
                        CHECK(distance(tows[1 - s].point(b.u, b.v), p.point) <= l.tolerance());
                    }
                    checkTwoResolved(tows, stacks, report, 0.05, stubFirst ? "stub" : "y");
                }
            }
}

TEST_CASE("a thin tow entering another through its end cap only: found and resolved, both ranks", "[resolve][caps]")
{
    // The fat x-tube (radius 0.5, x from 0 to 2); the thin one (radius 0.1, axis y = 0.2, z = 0,
    // x from 1.5 to 3) crosses no part of the fat tube's side: it enters through the fat tube's
    // end cap and ends inside it. The loop is a circle on the cap, around the thin tube.
    const std::vector<TowStack> stacks{testing::tubeAlongX(0.5, 2.0, 0.0, 0.0, 0.0, sampling(0.0, 41, 48), "fat"),
                                       testing::tubeAlongX(0.1, 1.5, 1.5, 0.2, 0.0, sampling(0.0, 31, 32), "thin")};
    const std::vector<TowSurface> tows = fit(stacks);
    const IntersectionReport report = intersectTows(tows);
    REQUIRE(report.loops.size() == 1);
    const IntersectionLoop& l = report.loops.front();
    CHECK(l.closed());
    CHECK(l.crossesCap(LoopSide::A));
    CHECK_FALSE(l.crossesCap(LoopSide::B));
    CHECK_FALSE(l.windsAround(LoopSide::A));
    CHECK(l.windsAround(LoopSide::B));
    for (const LoopPoint& p : l.points()) {
        CHECK(p.point.x == Approx(2.0).margin(1e-9));
        CHECK(std::hypot(p.point.y - 0.2, p.point.z) == Approx(0.1).margin(2e-3));  // the thin tube's section
    }
    for (const bool fatFirst : {true, false}) {
        DYNAMIC_SECTION((fatFirst ? "the fat tube" : "the thin tube") << " ranked first")
        {
            checkTwoResolved(tows, stacks, report, 0.03, fatFirst ? "fat" : "thin");
        }
    }
}

TEST_CASE("a tow grazing another's end: resolved, or named, never overlapping silently", "[resolve][caps]")
{
    // The y-tube (axis z = 0.999) just touches the top of the stub's end (radius 0.5): its cap
    // piece is a sliver along the rim.
    const std::vector<TowSurface> tows = fit({testing::tubeAlongX(0.5, 2.0, 0.0, 0.0, 0.0, sampling(0.0, 41, 48), "stub"),
                                             testing::tubeAlongY(0.5, 0.999, sampling(0.0, 41, 48), "y")});
    for (const double h : {0.2, 0.1}) {
        INFO("mesh size " << h);
        ResolveOptions o;
        o.mesh.edgeLength = h;
        try {
            const ResolveResult r = resolveTextile(tows, o);
            for (const TowResolution& t : r.tows) CHECK(t.boundaryLoops == 0);
            // Crossings are excused by a pair left unresolved or a loop skipped, not by a contact
            // (its meshes are refined until they do not cross).
            const bool excused = !r.unresolved.empty() || std::any_of(r.skippedLoops.begin(), r.skippedLoops.end(), [](const SkippedLoop& k) {
                                     return k.reason != SkippedLoop::Reason::Contact;
                                 });
            if (testing::crossingPairsBetweenTows(r.mesh) > 0) CHECK(excused);
        } catch (const Error& e) {
            FAIL_CHECK("resolveTextile threw: " << e.what());
        }
    }
}

TEST_CASE("a loop meeting a cap's rim at a small angle is a sharp corner: listed with its angle, its triangles judged by it",
          "[resolve][caps][quality]")
{
    // The y-tube (radius 0.5, axis x = 2, z = d) meets the plane of the stub's end cap (x = 2,
    // radius 0.5) in the band |z - d| <= 0.5: the loop crosses the cap along the chord z = d - 0.5,
    // which meets the rim at arccos((d - 0.5) / 0.5) to its tangent (closed form); on the tubes
    // the loop meets the rim square. With the stub ranked first: two corners of its cap, none
    // elsewhere, each listed at its place (x = 2, |z| = d - 0.5, on the rim) with its angle less
    // half the turn of the rim chord next to it (at most h / 0.5); every triangle under the
    // bound is in one of them and keeps a third of its angle. With the y-tube first the stub
    // gives up the cap's piece inside it, the corners' wedges with it: none is listed.
    const double h = 0.02;
    const double halfTurn = 0.5 * h / 0.5 * 180.0 / kPi;  // degrees
    for (const double corner : {10.0, 5.0})
        for (const bool stubFirst : {true, false}) {
            DYNAMIC_SECTION("corner " << corner << " deg, " << (stubFirst ? "the stub" : "the y-tube") << " ranked first")
            {
                const double z0 = 0.5 * std::cos(corner * kPi / 180.0), d = 0.5 + z0;
                const std::vector<TowSurface> tows = fit({testing::tubeAlongX(0.5, 2.0, 0.0, 0.0, 0.0, sampling(0.0, 41, 48), "stub"),
                                                         testing::tubeAlongY(0.5, d, sampling(0.0, 41, 48), "y")});
                ResolveOptions o;
                o.mesh.edgeLength = h;
                o.primaryPatterns = {stubFirst ? "stub" : "y"};
                const ResolveResult r = resolveTextile(tows, o);
                REQUIRE(r.unresolved.empty());
                CHECK(testing::crossingPairsBetweenTows(r.mesh) == 0);
                const MeshQuality& q = r.quality;
                CHECK(q.angleBound == Approx(15.0));
                WARN("corner " << corner << " deg: " << r.mesh.sharpCorners.size() << " sharp corners, " << q.atSharpCorners
                               << " triangles at them, " << q.underBound << " under the bound elsewhere, smallest angle " << q.minAngle
                               << ", away from corners " << q.minAngleAwayFromCorners);
                CHECK(q.underBound == 0);
                std::ostringstream json;
                writeResolveReport(r, tows, json);
                const nlohmann::json report = nlohmann::json::parse(json.str());
                CHECK(report["mesh_quality"]["under_bound"] == 0);
                CHECK(report["mesh_quality"]["angle_bound_deg"].get<double>() == Approx(15.0));
                if (!stubFirst) {
                    CHECK(r.mesh.sharpCorners.empty());
                    CHECK(report["sharp_corners"].empty());
                    CHECK(q.atSharpCorners == 0);
                    CHECK(q.minAngle >= 15.0);
                    continue;
                }
                REQUIRE(r.mesh.sharpCorners.size() == 2);
                for (const SharpCorner& c : r.mesh.sharpCorners) {
                    const Point3& p = r.mesh.nodes[c.node];
                    CHECK(tows[c.tow].name() == "stub");
                    CHECK(c.face == TowFace::End);
                    CHECK(p.x == Approx(2.0).margin(1e-9));
                    CHECK(std::abs(p.z) == Approx(z0).margin(1e-6));
                    CHECK(std::hypot(p.y, p.z) == Approx(0.5).margin(1e-6));
                    CHECK(c.angle <= corner + 1e-6);
                    CHECK(c.angle >= corner - halfTurn - 1e-6);
                    CHECK_FALSE(c.triangles.empty());
                }
                CHECK(q.atSharpCorners >= 2);
                CHECK(q.minAngle >= corner / 3.0);  // observed 9.3 and 4.4 degrees
                // The report lists them with their place.
                REQUIRE(report["sharp_corners"].size() == 2);
                for (const auto& c : report["sharp_corners"]) {
                    CHECK(c["tow"] == "stub");
                    CHECK(c["face"] == "end");
                    CHECK(c["point"][0].get<double>() == Approx(2.0).margin(1e-9));
                    CHECK(std::abs(c["point"][2].get<double>()) == Approx(z0).margin(1e-6));
                    CHECK(c["angle_deg"].get<double>() <= corner + 1e-6);
                }
            }
        }
}
