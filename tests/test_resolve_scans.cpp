// What real scans bring to resolveTextile(): a loop nested in a loop of the same tow pair (an
// island where pressed surfaces separate again inside an overlap), at every mesh size the CLI
// accepts; and a tow pair that cannot be resolved, which must not cost the rest of the textile.
// Checked independently: CGAL's exact crossing test between the output meshes, CGAL volumes of
// the closed meshes and CGAL corefinement of the faceted input tubes.
#include <catch2/catch.hpp>

#include <towgeom/error.hpp>
#include <towgeom/stack_reader.hpp>
#include <towgeom/intersection_loop.hpp>
#include <towgeom/connect_regions.hpp>
#include <towgeom/mesh_tows.hpp>
#include <towgeom/report.hpp>
#include <towgeom/resolve.hpp>
#include <towgeom/textile_mesh.hpp>
#include <towgeom/tow_intersection.hpp>
#include <towgeom/tow_stack.hpp>
#include <towgeom/tow_surface.hpp>
#include <towgeom/triangle_mesh.hpp>
#include <towgeom/weave.hpp>

#include <unistd.h>

#include <cmath>
#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "cgal_reference.hpp"
#include "cli_runner.hpp"
#include "synthetic_tows.hpp"

using namespace towgeom;

namespace {

constexpr double kPi = 3.14159265358979323846;

testing::Sampling sampling(std::size_t sections, std::size_t points)
{
    testing::Sampling s;
    s.sections = sections;
    s.points = points;
    return s;
}

/// A round tube over a dented one: the overlap is a ring (outer loop, island loop inside it).
std::vector<TowStack> nestedPair()
{
    return {testing::tubeAlongX(0.5, 4.0, 0.0, 0.0, 0.0, sampling(41, 64), "x"),
            testing::dentedTubeAlongY(0.4, 0.82, 0.15, 0.12, sampling(161, 64), "y")};
}

std::vector<TowSurface> fit(const std::vector<TowStack>& stacks)
{
    std::vector<TowSurface> tows;
    for (const TowStack& s : stacks) tows.push_back(TowSurface::fit(s));
    return tows;
}

/// Crossing triangle pairs between tows @p i and @p j of @p res (CGAL, exact predicates).
std::size_t crossings(const ResolveResult& res, std::size_t i, std::size_t j)
{
    return testing::crossingTrianglePairs(res.mesh.nodes, res.mesh.tows[i].triangles, res.mesh.tows[j].triangles).crossing;
}

/// Every tow is closed by its caps and bounds the volume the result reports (CGAL's volume of the
/// closed mesh, which needs a closed 2-manifold).
void checkClosed(const ResolveResult& res)
{
    for (std::size_t t = 0; t < res.mesh.tows.size(); ++t) {
        INFO("tow " << res.mesh.tows[t].name);
        CHECK(res.tows[t].boundaryLoops == 0);
        CHECK(res.mesh.boundaryLoopCount(t) == 0);
        CHECK(testing::closedMeshVolume(res.mesh.towSurface(t)) == Approx(res.tows[t].volumeAfter).epsilon(1e-9));
    }
}

}  // namespace

TEST_CASE("an island loop inside a loop of the same pair is a hole of the region", "[resolve][scan][nested]")
{
    const std::vector<TowStack> stacks = nestedPair();
    const std::vector<TowSurface> tows = fit(stacks);
    const IntersectionReport loops = intersectTows(tows);
    REQUIRE(loops.loops.size() == 2);
    const IntersectionLoop& outer = loops.loops[0].length() > loops.loops[1].length() ? loops.loops[0] : loops.loops[1];
    const IntersectionLoop& island = loops.loops[0].length() > loops.loops[1].length() ? loops.loops[1] : loops.loops[0];
    CHECK(outer.closed());
    CHECK(island.closed());

    // A shallow overlap (0.08 deep at most): at the default h the inscribed facets of both tubes
    // make the lens about 6 % thinner; at h = 0.02 the loss is below 1 %.
    ResolveOptions o;
    o.mesh.edgeLength = 0.02;
    const ResolveResult res = resolveTextile(tows, o);
    CHECK(res.skippedLoops.empty());
    CHECK(res.unresolved.empty());
    REQUIRE(res.mesh.regions.size() == 1);
    const ConnectedRegion& r = res.mesh.regions[0];
    CHECK(r.primary == 0);
    CHECK(r.secondary == 1);
    REQUIRE(r.holes.size() == 1);
    CHECK(&res.intersections.loops[r.holes[0]] != &res.intersections.loops[r.loop]);
    CHECK(crossings(res, 0, 1) == 0);
    checkClosed(res);
    // The shared surface is the ring between the loops on the primary (the faceted patch of an
    // exact area: within 1 %).
    const double ring = outer.enclosedArea(LoopSide::A) - island.enclosedArea(LoopSide::A);
    CHECK(std::abs(r.area - ring) <= 0.01 * ring);
    // The secondary loses the overlap of the two tows: CGAL corefinement of fine tessellations of
    // the two surfaces (grids of about 0.01; the 64-point input polygons themselves are 5 % thin
    // in this shallow lens, so they are no reference here).
    const auto closedGrid = [](const TowSurface& t, std::size_t nu, std::size_t nv) {
        const TriangleMesh m = t.tessellate(nu, nv);
        return closedSurface(m.vertices, m.triangles);
    };
    const double overlap = testing::intersectionVolume(closedGrid(tows[0], 401, 256), closedGrid(tows[1], 401, 256));
    WARN("removed " << r.volumeRemoved << ", CGAL overlap of the tessellated surfaces " << overlap);
    CHECK(std::abs(r.volumeRemoved - overlap) <= 0.005 * overlap);  // measured: 0.17 %
    CHECK(res.tows[1].volumeBefore - res.tows[1].volumeAfter == Approx(r.volumeRemoved).epsilon(1e-9));
    CHECK(res.tows[0].volumeAfter == Approx(res.tows[0].volumeBefore).epsilon(1e-12));
}

TEST_CASE("nested loops resolve at 6 mesh sizes from the largest accepted to a tenth of it", "[resolve][scan][nested][sweep]")
{
    const std::vector<TowSurface> tows = fit(nestedPair());
    const double largest = kPi * std::min(tows[0].towSize(), tows[1].towSize()) / 4.0;
    for (int k = 0; k < 6; ++k) {
        const double h = largest * std::pow(10.0, -k / 5.0);
        INFO("mesh size " << h);
        ResolveOptions o;
        o.mesh.edgeLength = h;
        const ResolveResult res = resolveTextile(tows, o);
        CHECK(res.unresolved.empty());
        REQUIRE(res.mesh.regions.size() == 1);
        CHECK(res.mesh.regions[0].holes.size() == 1);
        CHECK(crossings(res, 0, 1) == 0);
        checkClosed(res);
    }
    // Above the largest: each tow meshed at a quarter of its own circumference.
    ResolveOptions o;
    o.mesh.edgeLength = 2.0 * largest;
    const ResolveResult capped = resolveTextile(tows, o);
    CHECK(capped.tows[1].meshSize == Approx(largest).epsilon(1e-15));
    CHECK(capped.tows[0].meshSize == Approx(kPi * tows[0].towSize() / 4.0).epsilon(1e-15));
    CHECK(capped.mesh.regions.size() == 1);
    CHECK(crossings(capped, 0, 1) == 0);
}

namespace {

/// x: a round tube along x; y crosses it at x = 2; w, thinner, runs diagonally through y where
/// y meets x, so the loops of (x, y) and (x, w) cross each other on x, and w's loops with y go
/// around w (w passes through y).
std::vector<TowStack> threeTows()
{
    TowStack w = testing::tubeAlongX(0.3, 3.0, -1.5, 0.0, 0.0, sampling(41, 48), "w");
    const double c = std::sqrt(0.5);
    for (auto& section : w.sections)
        for (Point3& p : section) p = {2.0 + c * p.x - c * p.y, c * p.x + c * p.y, p.z + 0.77};
    return {testing::tubeAlongX(0.5, 4.0, 0.0, 0.0, 0.0, sampling(41, 48), "x"), testing::tubeAlongY(0.4, 0.82, sampling(41, 48), "y"),
            w};
}

/// The tows' surfaces tessellated finely and closed (CGAL corefinement input).
TriangleMesh closedGrid(const TowSurface& t)
{
    const TriangleMesh m = t.tessellate(301, 192);
    return closedSurface(m.vertices, m.triangles);
}

/// Three tows resolved by rank (@p order: tow indices, highest first): every triple point is a
/// node of all three meshes on all three surfaces, no triangles cross, every tow is a tube, and
/// each keeps its volume minus the tows ranked above it (CGAL corefinement, within 2 %).
void checkThreeTows(const std::vector<TowSurface>& tows, const ResolveResult& res, const std::vector<std::size_t>& order,
                    std::size_t triplePoints, std::size_t regions = 3)
{
    CHECK(res.skippedLoops.empty());
    CHECK(res.unresolved.empty());
    CHECK(res.mesh.regions.size() == regions);
    for (const ConnectedRegion& r : res.mesh.regions) {
        const auto rankOf = [&](std::size_t t) { return std::find(order.begin(), order.end(), t) - order.begin(); };
        CHECK(rankOf(r.primary) < rankOf(r.secondary));
    }
    // Each region: its triangles (by index into the primary's mesh) are the primary's triangles
    // of that region, and the secondary holds each reversed, in the same region; its loop nodes
    // are nodes of its triangles.
    for (std::size_t g = 0; g < res.mesh.regions.size(); ++g) {
        const ConnectedRegion& r = res.mesh.regions[g];
        const TowMesh& p = res.mesh.tows[r.primary];
        const TowMesh& q = res.mesh.tows[r.secondary];
        std::set<std::array<std::size_t, 3>> inSecondary;
        for (std::size_t k = 0; k < q.triangles.size(); ++k)
            if (q.region[k] == static_cast<long>(g)) inSecondary.insert(q.triangles[k]);
        CHECK(inSecondary.size() == r.triangles.size());
        for (const std::size_t k : r.triangles) {
            REQUIRE(k < p.triangles.size());
            CHECK(p.region[k] == static_cast<long>(g));
            CHECK(inSecondary.count({p.triangles[k][0], p.triangles[k][2], p.triangles[k][1]}) == 1);
        }
        for (const std::size_t n : r.loopNodes) CHECK(std::binary_search(r.nodes.begin(), r.nodes.end(), n));
    }
    // No node without a triangle.
    std::vector<char> used(res.mesh.nodes.size(), 0);
    for (const TowMesh& m : res.mesh.tows)
        for (const auto& tri : m.triangles)
            for (const std::size_t n : tri) used[n] = 1;
    CHECK(std::count(used.begin(), used.end(), 0) == 0);
    REQUIRE(res.mesh.triplePoints.size() == triplePoints);
    for (const TriplePoint& p : res.mesh.triplePoints) {
        CHECK(p.tows == std::array<std::size_t, 3>{0, 1, 2});
        const Point3 x = res.mesh.nodes[p.node];
        for (std::size_t t = 0; t < 3; ++t) {
            const UV uv = tows[t].closestParameters(x);
            CHECK(distance(tows[t].point(uv.u, uv.v), x) < 1e-9);
            const std::vector<std::size_t> used = res.mesh.towNodes(t);
            CHECK(std::find(used.begin(), used.end(), p.node) != used.end());
        }
    }
    CHECK(testing::crossingPairsBetweenTows(res.mesh) == 0);
    checkClosed(res);
    std::vector<TriangleMesh> above;
    for (const std::size_t t : order) {
        const TriangleMesh grid = closedGrid(tows[t]);
        const double kept = above.empty() ? testing::closedMeshVolume(grid) : testing::differenceVolume(grid, above);
        INFO("tow " << tows[t].name());
        WARN("tow " << tows[t].name() << " keeps " << res.tows[t].volumeAfter << ", CGAL: " << kept);
        CHECK(std::abs(res.tows[t].volumeAfter - kept) <= 0.02 * kept);
        above.push_back(grid);
    }
}

}  // namespace

TEST_CASE("three tows overlapping at one point: each keeps its volume minus the tows ranked above it", "[resolve][scan][triple]")
{
    const std::vector<TowSurface> tows = fit(testing::threeTowsAtAPoint(0.3, 0.41));
    const IntersectionReport loops = intersectTows(tows);
    REQUIRE(loops.loops.size() == 3);
    // In input order: x above y above w; the three loops meet in two triple points.
    checkThreeTows(tows, resolveTextile(tows), {0, 1, 2}, 2);
    // w first (--primary w): w above x above y.
    ResolveOptions o;
    o.primaryPatterns = {"w"};
    checkThreeTows(tows, resolveTextile(tows, o), {2, 0, 1}, 2);
}

TEST_CASE("symmetric method where three tows overlap: the rank rule decides there, and says so", "[resolve][scan][triple][symmetric]")
{
    const std::vector<TowSurface> tows = fit(testing::threeTowsAtAPoint(0.3, 0.41));
    ResolveOptions o;
    o.method = ResolutionMethod::Symmetric;
    const ResolveResult res = resolveTextile(tows, o);
    // Every region has a part inside the third tow: each keeps the primary's surface, with a note.
    for (const ConnectedRegion& r : res.mesh.regions) {
        CHECK(r.surface == SharedSurface::Primary);
        INFO(r.note);
        CHECK((r.note.find("third tow") != std::string::npos || r.note.find("another loop") != std::string::npos));
    }
    checkThreeTows(tows, res, {0, 1, 2}, 2);
}

TEST_CASE("a triple point next to a tow's seam: no slivers", "[resolve][scan][triple][seam]")
{
    // w's seam (its sections' first point) turned to a triple point's angle plus a little: the
    // point a fraction of a period from the seam.
    const std::vector<TowSurface> base = fit(testing::threeTowsAtAPoint(0.3, 0.41));
    const ResolveResult ref = resolveTextile(base);
    REQUIRE(!ref.mesh.triplePoints.empty());
    const Point3 x = ref.mesh.nodes[ref.mesh.triplePoints[0].node];
    const double c = std::sqrt(0.5);
    const double yl = -c * (x.x - 2.0) + c * x.y - 0.3, zl = x.z - 0.41;  // w's local section coordinates
    const double angle = std::atan2(zl, yl);
    for (const double fraction : {1e-2, 1e-3, 1e-4, 1e-5}) {
        INFO("triple point " << fraction << " of a period from w's seam");
        const std::vector<TowSurface> tows = fit(testing::threeTowsAtAPoint(0.3, 0.41, angle - 2.0 * kPi * fraction));
        const ResolveResult res = resolveTextile(tows);
        // Measured: at 1e-2 and 1e-3 resolved (14.0 and 4.8 degrees); closer, the triple point is
        // refused (it would make a sliver: 0.09 degrees at 1e-5) and its pairs left out cleanly.
        WARN(fraction << ": " << res.unresolved.size() << " unresolved, " << res.mesh.triplePoints.size() << " triple points, min angle "
                      << res.quality.minAngle << ", over bounds " << res.quality.facesOverBounds);
        CHECK(res.quality.minAngle >= 4.0);
        if (res.unresolved.empty()) {
            CHECK(res.mesh.triplePoints.size() == 2);
            CHECK(testing::crossingPairsBetweenTows(res.mesh) == 0);
        }
        for (const UnresolvedPair& u : res.unresolved) CHECK(u.reason == UnresolvedPair::Reason::LoopsMeet);
        CHECK(crossings(res, 0, 1) == 0);  // (x, y) is resolved in every case
        checkClosed(res);
    }
    // Down to 1e-3 of a period the triple points are kept.
    CHECK(resolveTextile(fit(testing::threeTowsAtAPoint(0.3, 0.41, angle - 2.0 * kPi * 1e-3))).unresolved.empty());
}

TEST_CASE("three tows at one point resolve at mesh sizes from the largest accepted to a tenth of it", "[resolve][scan][triple][sweep]")
{
    // Symmetric: w right over the crossing of x and y; four triple points, two of them close
    // together on each loop.
    const std::vector<TowSurface> tows = fit(testing::threeTowsAtAPoint(0.0, 0.6));
    for (const double h : {0.785, 0.4, 0.2, 0.15, 0.1, 0.0785}) {
        INFO("relative mesh size " << h);
        ResolveOptions o;
        o.mesh.relativeEdgeLength = h;
        const ResolveResult res = resolveTextile(tows, o);
        CHECK(res.unresolved.empty());
        CHECK(res.mesh.triplePoints.size() == 4);
        CHECK(testing::crossingPairsBetweenTows(res.mesh) == 0);
        checkClosed(res);
    }
}

TEST_CASE("a tow through another where a third meets them: bands, triple points, each tow minus those above it", "[resolve][scan][triple][through]")
{
    // w passes through y (two loops around w) where y meets x: four triple points. In input
    // order w loses its band inside y and its part inside x, and is cut in two.
    const std::vector<TowSurface> tows = fit(threeTows());
    checkThreeTows(tows, resolveTextile(tows), {0, 1, 2}, 4, 4);
    // w first: y gets a tunnel where w passes through it.
    ResolveOptions o;
    o.primaryPatterns = {"w"};
    checkThreeTows(tows, resolveTextile(tows, o), {2, 0, 1}, 4, 3);  // w's band is one region with y
}

namespace {

/// The connected pieces of a mesh (triangles joined through their nodes).
std::size_t pieces(const std::vector<std::array<std::size_t, 3>>& triangles)
{
    std::map<std::size_t, std::size_t> parent;
    const auto find = [&](std::size_t n) {
        while (parent[n] != n) n = parent[n] = parent[parent[n]];
        return n;
    };
    for (const auto& t : triangles)
        for (const std::size_t n : t) parent.try_emplace(n, n);
    for (const auto& t : triangles) {
        parent[find(t[1])] = find(t[0]);
        parent[find(t[2])] = find(t[0]);
    }
    std::set<std::size_t> roots;
    for (const auto& [n, p] : parent) roots.insert(find(n));
    return roots.size();
}

}  // namespace

TEST_CASE("a tow through another, or ending inside it: each keeps its volume minus the tow ranked above it", "[resolve][scan][through]")
{
    for (const int kind : {0, 1, 2}) {  // through, ending inside, starting inside
        const bool endsInside = kind > 0;
        const std::vector<TowSurface> tows = fit(testing::thinThrough(kind == 1, kind == 2));
        const IntersectionReport loops = intersectTows(tows);
        // Through: two loops around the thin tube; ending inside: one.
        REQUIRE(loops.loops.size() == (endsInside ? 1u : 2u));
        for (const IntersectionLoop& l : loops.loops) CHECK(l.windsAround(LoopSide::B));
        for (const bool thinFirst : {false, true}) {
            INFO((kind == 0 ? "through" : kind == 1 ? "ending inside" : "starting inside") << ", " << (thinFirst ? "thin" : "outer")
                                                                                               << " ranked first");
            ResolveOptions o;
            if (thinFirst) o.primaryPatterns = {"thin"};
            const ResolveResult res = resolveTextile(tows, o);
            CHECK(res.unresolved.empty());
            CHECK(res.skippedLoops.empty());
            CHECK(testing::crossingPairsBetweenTows(res.mesh) == 0);
            checkClosed(res);
            // The thin tow given way is cut in two where it passes through; a tunnel through the
            // outer one, or a pocket where the thin one ends inside it, keeps it one piece.
            CHECK(pieces(res.mesh.tows[1].triangles) == (!thinFirst && !endsInside ? 2u : 1u));
            CHECK(pieces(res.mesh.tows[0].triangles) == 1u);
            CHECK(res.tows[1].pieces == pieces(res.mesh.tows[1].triangles));
            CHECK(res.tows[0].pieces == 1u);
            const TriangleMesh outer = closedGrid(tows[0]), thin = closedGrid(tows[1]);
            const double keeps[2] = {thinFirst ? testing::differenceVolume(outer, {thin}) : testing::closedMeshVolume(outer),
                                     thinFirst ? testing::closedMeshVolume(thin) : testing::differenceVolume(thin, {outer})};
            for (std::size_t t = 0; t < 2; ++t) {
                WARN("tow " << tows[t].name() << " keeps " << res.tows[t].volumeAfter << ", CGAL: " << keeps[t]);
                CHECK(std::abs(res.tows[t].volumeAfter - keeps[t]) <= 0.005 * keeps[t]);  // measured 0.16 %
            }
        }
    }
}

TEST_CASE("a loop through the point where both tows' seams meet, mid-chord: one node", "[resolve][scan][through][seam]")
{
    // The thin tube's seam turned to face the outer one's: both seams cross the loop at one
    // point, in the middle of a loop chord at this spacing (two nodes at one point before).
    testing::Sampling s = sampling(41, 32);
    s.startAngle = kPi;
    const std::vector<TowSurface> tows = fit({testing::tubeAlongX(0.5, 4.0, 0.0, 0.0, 0.0, sampling(41, 32), "outer"),
                                             testing::tubeAlongY(0.1, 0.0, s, "thin")});
    for (const double spacing : {0.0, 0.013, 0.007}) {
        INFO("loop spacing " << spacing);
        ResolveOptions o;
        o.mesh.loopSpacing = spacing;
        const ResolveResult res = resolveTextile(tows, o);
        CHECK(res.unresolved.empty());
        CHECK(testing::crossingPairsBetweenTows(res.mesh) == 0);
        checkClosed(res);
    }
}

TEST_CASE("loops of two pairs that cross without a triple point leave the later pair unresolved and named, the rest is resolved", "[resolve][scan][unresolved]")
{
    const std::vector<TowSurface> tows = fit(threeTows());
    // Without end caps the loops around w are not resolved: the loops of (x, y) and (x, w) cross
    // on x, but (y, w) has no loop there. (x, w), the later pair, is left out.
    ResolveOptions open;
    open.mesh.caps = false;
    const ResolveResult res = resolveTextile(tows, open);
    REQUIRE(res.unresolved.size() == 1);
    CHECK(res.unresolved[0].towA == 0);
    CHECK(res.unresolved[0].towB == 2);
    CHECK(res.unresolved[0].reason == UnresolvedPair::Reason::LoopsMeet);
    CHECK(res.unresolved[0].message ==
          "a loop of tows 'x' and 'w' crosses a loop of tows 'x' and 'y' on tow 'x': three tows overlap there, and the loops "
          "do not meet in a point of the three tows' surfaces there (the third pair has no resolved loop through it, or the "
          "point was not found)");
    // (x, y) is resolved; every tow is still a tube.
    REQUIRE(res.mesh.regions.size() == 1);
    CHECK(res.mesh.regions[0].primary == 0);
    CHECK(res.mesh.regions[0].secondary == 1);
    CHECK(res.mesh.triplePoints.empty());
    CHECK(crossings(res, 0, 1) == 0);
    for (std::size_t t = 0; t < 3; ++t) CHECK(res.tows[t].boundaryLoops == 2);
}

TEST_CASE("resolveTextile refuses bad intersection options", "[resolve][scan]")
{
    const std::vector<TowSurface> tows = fit(nestedPair());
    for (const double bad : {0.0, -1e-7, std::numeric_limits<double>::quiet_NaN()}) {
        INFO("relative tolerance " << bad);
        ResolveOptions o;
        o.intersection.relativeTolerance = bad;
        try {
            resolveTextile(tows, o);
            FAIL("accepted");
        } catch (const Error& e) {
            CHECK(e.code() == ErrorCode::InvalidArgument);
        }
    }
}


TEST_CASE("towgeom resolve names a pair it could not resolve, writes the rest and exits 3", "[resolve][scan][unresolved][cli]")
{
    const auto dir = std::filesystem::temp_directory_path() / ("towgeom_three_tows_" + std::to_string(::getpid()));
    const std::string files = testing::writeStacks(dir, threeTows());
    const testing::Run r = testing::cli("resolve" + files + " --quiet --no-caps --out '" + (dir / "out").string() + "'");
    INFO(r.err);
    CHECK(r.status == 3);
    CHECK(r.err.find("towgeom resolve: unresolved tow pair 'x' and 'w': a loop of tows 'x' and 'w' crosses a loop of tows "
                     "'x' and 'y' on tow 'x': three tows overlap there") != std::string::npos);
    CHECK(r.err.find("[loops_meet]\n") != std::string::npos);
    CHECK(r.err.find("towgeom resolve: unresolved tow pair 'y' and 'w': the loop goes around tow 'w'") != std::string::npos);
    const std::string report = testing::slurp(dir / "out" / "report.json");
    CHECK(testing::count(report, "\"reason\":\"loops_meet\"") == 1);
    CHECK(testing::count(report, "\"volume_removed\"") == 1);
    CHECK(testing::count(report, "\"boundary_loops\":2") == 3);
    for (const char* tow : {"x", "y", "w"}) CHECK(std::filesystem::exists(dir / "out" / (std::string(tow) + ".vtk")));
    std::filesystem::remove_all(dir);
}

TEST_CASE("towgeom resolve lists the triple points in report.json", "[resolve][scan][triple][cli]")
{
    const auto dir = std::filesystem::temp_directory_path() / ("towgeom_triple_" + std::to_string(::getpid()));
    const std::string files = testing::writeStacks(dir, testing::threeTowsAtAPoint(0.3, 0.41));
    const testing::Run r = testing::cli("resolve" + files + " --quiet --out '" + (dir / "out").string() + "'");
    INFO(r.err);
    CHECK(r.status == 0);
    const std::string report = testing::slurp(dir / "out" / "report.json");
    // The tows of a triple point in input order (x, y, w are tows 0, 1, 2).
    CHECK(testing::count(report, "{\"tows\":[\"x\",\"y\",\"w\"],\"node\":") == 2);
    CHECK(testing::count(report, "\"volume_removed\"") == 3);
    CHECK(testing::count(report, "\"boundary_loops\":0") == 3);
    std::filesystem::remove_all(dir);
}

namespace {

/// The pressed 3D orthogonal weave of these tests, 0.15 pressed; 8 x 8 x 3: 63 tows.
std::vector<TowStack> pressedOrthogonal(std::size_t tows = 8, std::size_t layers = 3)
{
    return testing::pressedOrthogonal(tows, layers, 0.15);
}

const TowStack& named(const std::vector<TowStack>& stacks, const std::string& name)
{
    for (const TowStack& s : stacks)
        if (s.name == name) return s;
    throw std::runtime_error("no tow " + name);
}

}  // namespace

TEST_CASE("a shallow loop that leaves through the top of a seam is traced once around, not out and back", "[intersection][scan][seam]")
{
    // binder_3 lies on weft_L0_7: their fitted surfaces cross shallowly over a wide patch (the
    // faceted tubes do not cross at all), a loop 0.45 long that crosses the binder's seam
    // twice. The walk from the seed reaches the seam going up in v; it used to be continued
    // from the same side of the seam, retraced its own way back and came back as a "closed"
    // curve enclosing 2e-12, reported as a line contact: the overlap was lost.
    const std::vector<TowStack> all = pressedOrthogonal();
    const std::vector<TowSurface> tows = fit({named(all, "binder_3"), named(all, "weft_L0_7")});
    const IntersectionReport r = intersectTows(tows);
    CHECK(r.findings.empty());
    REQUIRE(r.loops.size() == 1);
    const IntersectionLoop& l = r.loops[0];
    CHECK(l.closed());
    CHECK(l.length() == Approx(0.4549).epsilon(1e-3));
    // Independent of the (u,v) quadrature: the loop polygon's vector area, a lower bound of the
    // area of any surface it bounds (a curve run out and back has none), close to both areas
    // for a patch this flat.
    Point3 c;
    const std::vector<LoopPoint>& pts = l.points();
    for (const LoopPoint& p : pts) c = c + p.point;
    c = (1.0 / static_cast<double>(pts.size())) * c;
    Vector3 twice;
    for (std::size_t k = 0; k < pts.size(); ++k) twice = twice + cross(pts[k].point - c, pts[(k + 1) % pts.size()].point - c);
    const double vectorArea = 0.5 * norm(twice);
    INFO("vector area " << vectorArea << ", areas " << l.enclosedArea(LoopSide::A) << ", " << l.enclosedArea(LoopSide::B));
    CHECK(vectorArea > 5e-3);
    CHECK(vectorArea <= l.enclosedArea(LoopSide::A) * (1.0 + 1e-6));
    CHECK(vectorArea <= l.enclosedArea(LoopSide::B) * (1.0 + 1e-6));
    // And resolved: no crossing triangles, both tows closed.
    const ResolveResult res = resolveTextile(tows, ResolveOptions{});
    CHECK(res.unresolved.empty());
    CHECK(testing::crossingPairsBetweenTows(res.mesh) == 0);
    checkClosed(res);
}

TEST_CASE("pressed layers resolve at 6 mesh sizes from the largest accepted to a tenth of it", "[resolve][scan][pressed][sweep]")
{
    // A pressed 3D orthogonal weave, 3 x 3 tows in 2 layers with binders (17 tows, 44 loops):
    // racetrack sections pressed 15 % into each other (shallow, wide contacts), binders a tenth
    // of the warps' size.
    const std::vector<TowSurface> tows = fit(pressedOrthogonal(3, 2));
    REQUIRE(tows.size() == 17);
    for (const double h : {0.785, 0.4, 0.2, 0.15, 0.1, 0.0785}) {
        INFO("relative mesh size " << h);
        ResolveOptions o;
        o.mesh.relativeEdgeLength = h;
        const ResolveResult res = resolveTextile(tows, o);
        CHECK(res.intersections.loops.size() == 44);
        CHECK(res.unresolved.empty());
        CHECK(res.skippedLoops.empty());
        CHECK(res.mesh.regions.size() == 44);
        CHECK(testing::crossingPairsBetweenTows(res.mesh) == 0);
        checkClosed(res);
    }
}

TEST_CASE("hand-traced pixel-row tows pressed across each other, starts drifting: resolved at 3 sizes", "[resolve][scan][traced]")
{
    // Two flat racetracks (1 x 0.25) traced on pixel rows (1/50 of the width), each slice's
    // first point wandering by 1 to 3 point spacings at random, the second turned to run along
    // y over the first's middle and pressed 0.05 into it (a fifth of their height).
    std::mt19937 rng(5);
    std::uniform_int_distribution<int> step(-3, 3);
    const auto drift = [&](std::size_t m) {
        std::vector<double> offset(m, 0.0);
        for (std::size_t i = 1; i < m; ++i) offset[i] = offset[i - 1] + step(rng);
        return offset;
    };
    TowStack lower = testing::tracedRacetrack(40, 32, drift(40), false).stack;
    lower.name = "lower";
    TowStack upper = testing::tracedRacetrack(40, 32, drift(40), true).stack;
    upper.name = "upper";
    for (auto& section : upper.sections)
        for (Point3& p : section) p = {0.78 - p.y, p.x - 0.78, p.z + 0.2};
    const std::vector<TowSurface> tows = fit({lower, upper});
    const IntersectionReport loops = intersectTows(tows);
    REQUIRE(!loops.loops.empty());
    for (const IntersectionLoop& l : loops.loops) CHECK(l.closed());
    const TriangleMesh a = closedGrid(tows[0]), b = closedGrid(tows[1]);
    const double keeps[2] = {testing::closedMeshVolume(a), testing::differenceVolume(b, {a})};
    for (const double h : {0.785, 0.2, 0.1}) {
        INFO("relative mesh size " << h);
        ResolveOptions o;
        o.mesh.relativeEdgeLength = h;
        const ResolveResult res = resolveTextile(tows, o);
        CHECK(res.unresolved.empty());
        CHECK(res.skippedLoops.empty());
        CHECK(!res.mesh.regions.empty());
        CHECK(testing::crossingPairsBetweenTows(res.mesh) == 0);
        checkClosed(res);
        if (h > 0.1) continue;  // coarser meshes inscribe a thinner lens
        for (std::size_t t = 0; t < 2; ++t) {
            WARN("tow " << tows[t].name() << " keeps " << res.tows[t].volumeAfter << ", CGAL: " << keeps[t]);
            CHECK(std::abs(res.tows[t].volumeAfter - keeps[t]) <= 0.02 * keeps[t]);
        }
    }
}

TEST_CASE("a figure-8 comes back as two closed lobes at every sampling", "[resolve][scan][singular][sweep]")
{
    // The figure-8 of the next test with the y-tube sampled by 101 to 397 sections: OCCT's march
    // passed its start at the singular point and went round again on 23 of 76 samplings (a lobe
    // 2 to 12 times its length, or a runaway open "curve" 350 times as long).
    const double R = 0.5, r = 0.4, d = 0.82;
    const TowSurface x = TowSurface::fit(testing::tubeAlongX(R, 4.0, 0.0, 0.0, 0.0, sampling(81, 64), "x"));
    std::size_t resolved = 0;
    for (std::size_t n = 101; n <= 397; n += 8) {
        INFO(n << " sections");
        const std::vector<TowSurface> tows{
            x, TowSurface::fit(testing::dentedTubeAlongY(r, d, R - (d - r), 0.15, sampling(n, 64), "y", std::numeric_limits<double>::infinity()))};
        const IntersectionReport loops = intersectTows(tows);
        REQUIRE(loops.loops.size() == 2);
        for (const IntersectionLoop& l : loops.loops) {
            CHECK(l.closed());
            CHECK(l.length() == Approx(0.9057).epsilon(1e-3));  // one lobe, once
        }
        if ((n - 101) % 32 != 0) continue;
        const ResolveResult res = resolveTextile(tows);
        CHECK(res.unresolved.empty());
        CHECK(res.mesh.regions.size() == 2);
        CHECK(crossings(res, 0, 1) == 0);
        ++resolved;
    }
    CHECK(resolved == 10);
}

TEST_CASE("surfaces tangent at a saddle inside the overlap: a figure-8 as two closed loops, resolved", "[resolve][scan][singular]")
{
    // The y-tube's underside has a groove across it at y = 0 whose bottom just touches the x-tube's
    // top at (2, 0, 0.5): there the surfaces are tangent and the intersection curve crosses itself.
    // Each lobe comes back as a closed loop through the singular point; both are resolved, the
    // point a node of both.
    const double R = 0.5, r = 0.4, d = 0.82;
    const std::vector<TowStack> stacks = {
        testing::tubeAlongX(R, 4.0, 0.0, 0.0, 0.0, sampling(81, 64), "x"),
        testing::dentedTubeAlongY(r, d, R - (d - r), 0.15, sampling(241, 64), "y", std::numeric_limits<double>::infinity())};
    const std::vector<TowSurface> tows = fit(stacks);
    const IntersectionReport loops = intersectTows(tows);
    REQUIRE(loops.loops.size() == 2);
    for (const IntersectionLoop& l : loops.loops) {
        CHECK(l.closed());
        // Each lobe passes within a loop-point spacing of the singular point.
        double nearest = 1e300;
        for (const LoopPoint& p : l.points()) nearest = std::min(nearest, distance(p.point, {2.0, 0.0, R}));
        CHECK(nearest < 0.01);
    }
    // The lobes are mirror images (y -> -y): equal lengths and areas (to the chordal tolerance,
    // 1e-4; measured 2.4e-5 for the lengths: each lobe stops near the singular point on its own).
    CHECK(loops.loops[0].length() == Approx(loops.loops[1].length()).epsilon(1e-4));
    CHECK(loops.loops[0].enclosedArea(LoopSide::A) == Approx(loops.loops[1].enclosedArea(LoopSide::A)).epsilon(1e-4));
    const ResolveResult res = resolveTextile(tows);
    CHECK(res.unresolved.empty());
    CHECK(res.mesh.regions.size() == 2);
    checkClosed(res);
    // The lobes meet in one node, the touching point (8e-5 from each other's curve before): no
    // triangle crosses there (2 pairs did while they passed a hair's breadth apart).
    CHECK(crossings(res, 0, 1) == 0);
    const std::vector<std::size_t>& n0 = res.mesh.regions[0].loopNodes;
    std::set<std::size_t> common(n0.begin(), n0.end());
    std::size_t shared = 0;
    for (std::size_t n : res.mesh.regions[1].loopNodes) shared += common.count(n);
    CHECK(shared == 1);
    // Finer meshes ask for splits of the chords at the shared node, which belongs to both lobes:
    // they must reach the lobe the chord is on (they were dropped: 0.33 deg and 22 faces over the
    // bounds at h = 0.03, 1.2 deg and 14 at h = 0.05, found by review). What remains is the
    // corner between the two lobes' constraints at the singular point, which no split improves:
    // measured 5.7 deg and 10 faces (h = 0.03), 10.6 deg and 2 faces (h = 0.05).
    for (const double h : {0.05, 0.03}) {
        INFO("mesh size " << h);
        ResolveOptions o;
        o.mesh.edgeLength = h;
        const ResolveResult fine = resolveTextile(tows, o);
        CHECK(fine.mesh.regions.size() == 2);
        CHECK(crossings(fine, 0, 1) == 0);
        CHECK(fine.quality.facesOverBounds <= 10);
        CHECK(fine.quality.minAngle > 5.0);
    }
}

namespace {

/// Moves the polygon of meshed loop @p k on its tow @p side half way round that tow (its nodes'
/// (u,v) there), so that the tow's triangles inside it are not the ones the loop bounds: that
/// tow cannot close after the swap.
void spoilLoop(ResolveResult& meshed, std::size_t k, const std::vector<TowSurface>& tows, LoopSide side)
{
    const MeshedLoop& ml = meshed.mesh.loops.at(k);
    const IntersectionLoop& loop = meshed.intersections.loops[ml.loop];
    const std::size_t t = side == LoopSide::A ? loop.towA() : loop.towB();
    const ParameterRange range = tows[t].parameterRange();
    for (auto& [node, uv] : meshed.mesh.tows[t].parameters)
        if (std::find(ml.nodes.begin(), ml.nodes.end(), node) != ml.nodes.end())
            uv.v = range.vMin + std::fmod(uv.v - range.vMin + 0.5 * range.vPeriod(), range.vPeriod());
}

}  // namespace

TEST_CASE("connectRegions: two tows failing in one pass, one pair between them, are both left out (RegionFailed)",
          "[resolve][connect]")
{
    // w and y do not meet; x crosses both: pairs (w,x) and (x,y), ranked w > x > y.
    const std::vector<TowSurface> tows = fit({testing::tubeAlongX(0.5, 4.0, 0.0, 0.0, 0.0, sampling(41, 48), "w"),
                                             testing::tubeAlongY(0.4, 0.82, sampling(41, 48), "x"),
                                             testing::tubeAlongX(0.4, 4.0, 0.0, 1.2, 1.52, sampling(41, 48), "y")});
    ResolveOptions o;
    o.mesh.relativeEdgeLength = 0.2;
    ResolveResult meshed = meshTows(tows, intersectTows(tows), o);
    REQUIRE(meshed.mesh.loops.size() == 2);
    // Each loop spoiled on its secondary: x fails for (w,x), y for (x,y) -- y's only pair is with x.
    for (std::size_t k = 0; k < 2; ++k) spoilLoop(meshed, k, tows, LoopSide::B);
    const ResolveResult r = connectRegions(tows, meshed, o);
    REQUIRE(r.unresolved.size() == 2);
    for (const UnresolvedPair& u : r.unresolved) CHECK(u.reason == UnresolvedPair::Reason::RegionFailed);
    CHECK(r.mesh.regions.empty());
    CHECK(r.mesh.loops.empty());
    for (std::size_t t = 0; t < 3; ++t) {
        CHECK(r.tows[t].boundaryLoops == 0);
        CHECK(r.tows[t].volumeAfter == r.tows[t].volumeBefore);  // nothing swapped
    }
}

TEST_CASE("connectRegions: triple points of pairs left out are not reported", "[resolve][connect][triple]")
{
    const std::vector<TowSurface> tows = fit(testing::threeTowsAtAPoint(0.3, 0.41));
    ResolveOptions o;
    const ResolveResult meshed = meshTows(tows, intersectTows(tows), o);
    REQUIRE(meshed.mesh.loops.size() == 3);
    REQUIRE(meshed.mesh.triplePoints.size() == 2);
    const ResolveResult whole = connectRegions(tows, meshed, o);
    CHECK(whole.mesh.triplePoints.size() == 2);
    // The loop of (x, w) spoiled on w: w fails, its pairs (x,w) and (y,w) are left out; the
    // loops of the three pairs no longer cross anywhere resolved.
    ResolveResult spoiled = meshed;
    std::size_t xw = 3;
    for (std::size_t k = 0; k < 3; ++k) {
        const IntersectionLoop& l = meshed.intersections.loops[meshed.mesh.loops[k].loop];
        if (l.towA() == 0 && l.towB() == 2) xw = k;
    }
    REQUIRE(xw < 3);
    spoilLoop(spoiled, xw, tows, LoopSide::B);
    const ResolveResult r = connectRegions(tows, spoiled, o);
    CHECK(r.unresolved.size() == 2);
    CHECK(r.mesh.regions.size() == 1);
    CHECK(r.mesh.triplePoints.empty());
}

TEST_CASE("pressed layers with tows cut short inside others: every curve closes, all resolved at 3 sizes", "[resolve][scan][pressed][caps]")
{
    // The pressed weave of the sweep above, with its binders cut at 57 % of their length and one
    // warp of each layer starting at about 41 % of its length: their ends lie inside or across
    // other tows, as where a scan's binder pieces end inside the volume.
    std::vector<TowStack> stacks = pressedOrthogonal(3, 2);
    std::size_t cut = 0;
    for (TowStack& s : stacks) {
        const std::size_t m = s.sections.size();
        if (s.name.rfind("binder", 0) == 0) {
            s.sections.resize(m * 57 / 100);
            ++cut;
        } else if (s.name.rfind("warp", 0) == 0 && s.name.back() == '1') {
            s.sections.erase(s.sections.begin(), s.sections.begin() + static_cast<std::ptrdiff_t>(m * 40 / 100));
            // The cut between two sections (not at the generator's regular stations, where the
            // cap's plane would be tangent to a weft's edge).
            for (std::size_t j = 0; j < s.sections[0].size(); ++j)
                s.sections[0][j] = 0.63 * s.sections[0][j] + 0.37 * s.sections[1][j];
            ++cut;
        }
    }
    REQUIRE(cut >= 4);
    const std::vector<TowSurface> tows = fit(stacks);
    const IntersectionReport report = intersectTows(tows);
    const auto acrossCap = [](const IntersectionLoop& l) { return l.closed() && (l.crossesCap(LoopSide::A) || l.crossesCap(LoopSide::B)); };
    const std::size_t acrossCaps = static_cast<std::size_t>(std::count_if(report.loops.begin(), report.loops.end(), acrossCap));
    WARN(report.loops.size() << " loops, " << acrossCaps << " closed across a cap, " << report.openCount() << " open");
    // Observed 37 loops, 5 of them across a cap.
    CHECK(acrossCaps >= 5);
    CHECK(report.openCount() == 0);
    for (const double h : {0.4, 0.25, 0.15}) {
        INFO("relative mesh size " << h);
        ResolveOptions o;
        o.mesh.relativeEdgeLength = h;
        const ResolveResult res = resolveTextile(tows, report, o);
        checkClosed(res);
        // Every pair whose meshes still cross is named; the loops across caps of the pairs not
        // named are resolved.
        const std::vector<UnresolvedPairEntry> named = unresolvedPairs(res);
        const auto isNamed = [&](std::size_t a, std::size_t b) {
            return std::any_of(named.begin(), named.end(), [&](const UnresolvedPairEntry& e) {
                return std::minmax(e.towA, e.towB) == std::minmax(a, b);
            });
        };
        for (std::size_t i = 0; i < tows.size(); ++i)
            for (std::size_t j = i + 1; j < tows.size(); ++j)
                if (crossings(res, i, j) > 0) CHECK(isNamed(i, j));
        std::size_t resolvedAcross = 0;
        for (const IntersectionLoop& l : report.loops)
            if (acrossCap(l) && !isNamed(l.towA(), l.towB())) ++resolvedAcross;
        WARN("relative mesh size " << h << ": " << named.size() << " pairs named, " << resolvedAcross << " loops across caps resolved");
        CHECK(named.empty());
        CHECK(resolvedAcross == acrossCaps);
        CHECK(testing::crossingPairsBetweenTows(res.mesh) == 0);
        if (h == 0.15) {
            // Each tow keeps its volume minus the tows ranked above it (input order) that it
            // meets (CGAL corefinement of the closed faceted tows), within 2 %.
            double worst = 0.0;
            for (std::size_t t = 0; t < tows.size(); ++t) {
                std::vector<TriangleMesh> above;
                for (std::size_t a = 0; a < t; ++a)
                    if (tows[a].boundingBox().overlaps(tows[t].boundingBox())) above.push_back(facetedTube(stacks[a], true));
                const TriangleMesh own = facetedTube(stacks[t], true);
                const double kept = above.empty() ? testing::closedMeshVolume(own) : testing::differenceVolume(own, above);
                // The faceted input lies inside the fitted surface: its own volume's shortfall
                // (about 2 % on the thin binders) is allowed on top.
                const double faceting = std::abs(res.tows[t].volumeBefore - testing::closedMeshVolume(own));
                INFO("tow " << tows[t].name() << " keeps " << res.tows[t].volumeAfter << ", CGAL " << kept << ", faceting " << faceting);
                CHECK(std::abs(res.tows[t].volumeAfter - kept) <= 0.02 * kept + faceting);
                worst = std::max(worst, (std::abs(res.tows[t].volumeAfter - kept) - faceting) / kept);
            }
            WARN("largest relative difference of a kept volume from CGAL's, beyond the faceting: " << 100.0 * worst << " %");
        }
    }
}

