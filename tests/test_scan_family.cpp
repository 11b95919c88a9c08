// Scan-like textiles (issue 38, tests/support/scan_like.hpp) against the dense oracle
// (tests/support/dense_oracle.hpp): loop detection finds every curve CGAL finds on the same
// fitted surfaces tessellated finely, and every curve closes.
#include <catch2/catch.hpp>

#include <towgeom/towgeom.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cgal_reference.hpp"
#include "dense_oracle.hpp"
#include "mesh_checks.hpp"
#include "scan_like.hpp"
#include "synthetic_tows.hpp"

using namespace towgeom;

TEST_CASE("scan-like family: explore", "[.explore]")
{
    const unsigned first = static_cast<unsigned>(std::atoi(std::getenv("FIRST") ? std::getenv("FIRST") : "1"));
    const unsigned count = static_cast<unsigned>(std::atoi(std::getenv("COUNT") ? std::getenv("COUNT") : "5"));
    for (unsigned seed = first; seed < first + count; ++seed) {
        const testing::ScanLikeTextile t = testing::scanLikeTextile(seed);
        if (std::getenv("DUMP")) testing::writeStacks(std::string(std::getenv("DUMP")) + "/" + std::to_string(seed), t.stacks);
        const std::vector<TowSurface> tows = testing::fitAll(t.stacks);
        const IntersectionReport report = intersectTows(tows);
        const testing::TextileOracleComparison r = testing::compareTextileWithOracle(tows, report);
        std::printf("seed %u: %s\n  tows %zu loops %zu open %zu oracle %zu matched %zu longest missed %.3g farthest %.3g\n%s", seed,
                    t.choices.describe().c_str(), tows.size(), report.loops.size(), report.openCount(), r.considered, r.matched,
                    r.longestMissed, r.farthest, r.missed.c_str());
    }
}

TEST_CASE("scan-like family: explore resolve", "[.explore]")
{
    // Resolves seeds FIRST.. (COUNT of them) and prints, per tow pair, the crossing triangle pairs
    // of the output meshes with the pair's loops: for finding where resolve leaves tows crossing.
    const unsigned first = static_cast<unsigned>(std::atoi(std::getenv("FIRST") ? std::getenv("FIRST") : "1"));
    const unsigned count = static_cast<unsigned>(std::atoi(std::getenv("COUNT") ? std::getenv("COUNT") : "1"));
    for (unsigned seed = first; seed < first + count; ++seed) {
        const testing::ScanLikeTextile t = testing::scanLikeTextile(seed);
        const std::vector<TowSurface> tows = testing::fitAll(t.stacks);
        const ResolveResult r = resolveTextile(tows);
        std::printf("seed %u: %s: %zu unresolved, smallest angle %.3g\n", seed, t.choices.describe().c_str(), r.unresolved.size(),
                    r.quality.minAngle);
        for (std::size_t a = 0; a < r.mesh.tows.size(); ++a)
            for (std::size_t b = a + 1; b < r.mesh.tows.size(); ++b) {
                const testing::TriangleCrossings c =
                    testing::crossingTrianglePairs(r.mesh.nodes, r.mesh.tows[a].triangles, r.mesh.tows[b].triangles);
                if (c.crossing == 0) continue;
                std::printf("  %s / %s: %zu crossing pairs (%zu sharing a node)\n", tows[a].name().c_str(), tows[b].name().c_str(),
                            c.crossing, c.crossingSharing);
                const auto centroid = [&](const std::array<std::size_t, 3>& t) {
                    return (1.0 / 3.0) * (r.mesh.nodes[t[0]] + r.mesh.nodes[t[1]] + r.mesh.nodes[t[2]]);
                };
                for (const auto& [ta, tb] : c.first) {
                    const Point3 pa = centroid(r.mesh.tows[a].triangles[ta]), pb = centroid(r.mesh.tows[b].triangles[tb]);
                    std::printf("    (%.4f %.4f %.4f) region %ld / (%.4f %.4f %.4f) region %ld\n", pa.x, pa.y, pa.z,
                                r.mesh.tows[a].region[ta], pb.x, pb.y, pb.z, r.mesh.tows[b].region[tb]);
                }
                for (const IntersectionLoop& l : r.intersections.loops)
                    if ((l.towA() == a && l.towB() == b) || (l.towA() == b && l.towB() == a))
                        std::printf("    loop: closed %d, length %.4g, %zu points, area A %.3g, B %.3g\n", int(l.closed()), l.length(),
                                    l.points().size(), l.enclosedArea(LoopSide::A), l.enclosedArea(LoopSide::B));
            }
    }
}

namespace {

/// Seeds [first, first + count) of the family: every oracle curve found, every curve closed (tows
/// are closed solids: a curve into a tow's end goes on across its cap, across both caps where
/// both tows end inside each other).
void checkFamily(unsigned first, unsigned count)
{
    for (unsigned seed = first; seed < first + count; ++seed) {
        const testing::ScanLikeTextile t = testing::scanLikeTextile(seed);
        INFO("seed " << seed << ": " << t.choices.describe());
        const std::vector<TowSurface> tows = testing::fitAll(t.stacks);
        const IntersectionReport report = intersectTows(tows);
        const testing::TextileOracleComparison r = testing::compareTextileWithOracle(tows, report);
        INFO(r.missed);
        CHECK(r.considered > 0);
        CHECK(r.matched == r.considered);
        for (const IntersectionLoop& l : report.loops) {
            INFO("tows " << tows[l.towA()].name() << " and " << tows[l.towB()].name() << ": " << l.openReason());
            CHECK(l.closed());
        }
    }
}

/// A tow's fitted surface tessellated finely (8 rows per section span, 4 columns per input
/// point) and closed at its ends: the reference solid for volumes.
TriangleMesh referenceSolid(const TowSurface& tow)
{
    const TriangleMesh m = tow.tessellate(8 * tow.sectionCount() + 1, 4 * tow.pointParameters().size());
    return closedSurface(m.vertices, m.triangles);
}

/// Triangles of @p r under MeshQuality::angleBound, counted independently of MeshQuality: in a
/// sharp corner's triangles (and at least a third of its angle) or not, and of those not, how
/// many have no node in the first or last section span of their tow (u from the tow's (u,v)
/// per node: TowMesh::parameters).
struct UnderBound {
    std::size_t atCorners = 0, elsewhere = 0, awayFromEnds = 0;
};
UnderBound underBound(const std::vector<TowSurface>& tows, const ResolveResult& r)
{
    UnderBound out;
    const double bound = r.quality.angleBound;
    std::map<std::pair<std::size_t, std::array<std::size_t, 3>>, double> corner;
    const auto sorted = [](std::array<std::size_t, 3> t) {
        std::sort(t.begin(), t.end());
        return t;
    };
    for (const SharpCorner& c : r.mesh.sharpCorners)
        for (const auto& t : c.triangles) {
            auto [it, added] = corner.emplace(std::make_pair(c.tow, sorted(t)), c.angle);
            if (!added) it->second = std::min(it->second, c.angle);
        }
    for (std::size_t t = 0; t < tows.size(); ++t) {
        const TowMesh& m = r.mesh.tows[t];
        const std::vector<double>& sections = tows[t].sectionParameters();
        const double endSpan0 = sections[1], endSpan1 = sections[sections.size() - 2];
        for (std::size_t k = 0; k < m.triangles.size(); ++k) {
            if (m.region[k] >= 0 && r.mesh.regions[static_cast<std::size_t>(m.region[k])].secondary == t) continue;
            const auto& tri = m.triangles[k];
            double smallest = 180.0;
            for (int c = 0; c < 3; ++c) {
                const Vector3 a = r.mesh.nodes[tri[(c + 1) % 3]] - r.mesh.nodes[tri[c]], b = r.mesh.nodes[tri[(c + 2) % 3]] - r.mesh.nodes[tri[c]];
                smallest = std::min(smallest, std::acos(std::clamp(dot(a, b) / (norm(a) * norm(b)), -1.0, 1.0)) * 180.0 / 3.14159265358979323846);
            }
            if (smallest >= bound) continue;
            const auto it = corner.find({t, sorted(tri)});
            if (it != corner.end() && smallest >= it->second / 3.0) {
                ++out.atCorners;
                continue;
            }
            ++out.elsewhere;
            bool nearEnd = m.face[k] != TowFace::Side;
            for (std::size_t n : tri) {
                const auto p = std::lower_bound(m.parameters.begin(), m.parameters.end(), n,
                                                [](const std::pair<std::size_t, UV>& e, std::size_t node) { return e.first < node; });
                if (p != m.parameters.end() && p->first == n && (p->second.u <= endSpan0 || p->second.u >= endSpan1)) nearEnd = true;
            }
            out.awayFromEnds += !nearEnd;
        }
    }
    return out;
}

/// Seeds [first, first + count) resolved with the default options: no pair left unresolved,
/// every tow's mesh closed and 2-manifold (counted from its triangles' edges alone), no two tows'
/// triangles crossing (CGAL box intersection and exact triangle tests), and every tow keeping its
/// volume minus the tows ranked above it that it meets (CGAL corefinement of the reference
/// solids) within 1 % (the issue asks 2 %; seeds 1-50 differ by at most 0.49 %). Prints the
/// worst volume difference and the smallest angle, and the triangles under the surface's angle
/// bound: in sharp corners, elsewhere, and away from the tows' end spans (asserted rare).
void checkFamilyResolved(unsigned first, unsigned count)
{
    double worstVolume = 0.0, smallestAngle = 180.0;
    UnderBound under;
    std::size_t triangles = 0, corners = 0;
    for (unsigned seed = first; seed < first + count; ++seed) {
        const testing::ScanLikeTextile t = testing::scanLikeTextile(seed);
        INFO("seed " << seed << ": " << t.choices.describe());
        const std::vector<TowSurface> tows = testing::fitAll(t.stacks);
        const ResolveResult r = resolveTextile(tows);
        for (const UnresolvedPairEntry& u : unresolvedPairs(r)) FAIL_CHECK(u.code << ": " << u.message);
        for (std::size_t k = 0; k < tows.size(); ++k) {
            INFO("tow " << tows[k].name());
            const testing::Boundary b = testing::boundaryOf(r.mesh.tows[k].triangles);
            CHECK(b.edges == 0);
            CHECK(b.nonManifoldEdges == 0);
            CHECK(b.misorientedEdges == 0);
        }
        CHECK(testing::crossingPairsBetweenTows(r.mesh) == 0);
        REQUIRE(r.ranks.size() == tows.size());
        std::vector<TriangleMesh> solids;
        for (const TowSurface& tow : tows) solids.push_back(referenceSolid(tow));
        for (std::size_t k = 0; k < tows.size(); ++k) {
            std::vector<TriangleMesh> above;
            for (std::size_t a = 0; a < tows.size(); ++a)
                if (r.ranks[a] < r.ranks[k] && tows[a].boundingBox().overlaps(tows[k].boundingBox())) above.push_back(solids[a]);
            const double kept = above.empty() ? testing::closedMeshVolume(solids[k]) : testing::differenceVolume(solids[k], above);
            INFO("tow " << tows[k].name() << " keeps " << r.tows[k].volumeAfter << ", CGAL " << kept);
            CHECK(std::abs(r.tows[k].volumeAfter - kept) <= 0.01 * kept);
            worstVolume = std::max(worstVolume, std::abs(r.tows[k].volumeAfter - kept) / kept);
        }
        smallestAngle = std::min(smallestAngle, r.quality.minAngle);
        // MeshQuality's figures against the bound, counted here again.
        const UnderBound u = underBound(tows, r);
        CHECK(r.quality.atSharpCorners == u.atCorners);
        CHECK(r.quality.underBound == u.elsewhere);
        triangles += r.quality.triangles;
        under.atCorners += u.atCorners;
        under.elsewhere += u.elsewhere;
        under.awayFromEnds += u.awayFromEnds;
        corners += r.mesh.sharpCorners.size();
    }
    WARN("seeds " << first << "-" << first + count - 1 << ": largest kept-volume difference from CGAL's " << 100.0 * worstVolume
                  << " %, smallest angle " << smallestAngle << " deg; " << triangles << " triangles, " << corners
                  << " sharp corners, under the bound " << under.atCorners << " at them, " << under.elsewhere << " elsewhere ("
                  << 100.0 * static_cast<double>(under.elsewhere) / static_cast<double>(triangles) << " %), " << under.awayFromEnds
                  << " of those away from the tows' end spans");
    // Observed in the five groups of ten: 31-68 away from the tows' end spans (at most 0.0052 %
    // of the triangles), all but a handful next to a loop that runs along the seam within a
    // small fraction of the mesh size. The rest lie where binders end at a grazing cut (their
    // end sections meet the tow at 16-28 degrees): seeds 15 and 20, 3,060 and 1,226; issue 38's
    // item 5 is open there.
    CHECK(static_cast<double>(under.awayFromEnds) <= 1e-4 * static_cast<double>(triangles));
}

}  // namespace

// 50 textiles in five cases (CTest runs them side by side), about 1 s each.
TEST_CASE("scan-like family, seeds 1-10: detect finds every curve of the dense oracle", "[intersection][scan][family]") { checkFamily(1, 10); }
TEST_CASE("scan-like family, seeds 11-20: detect finds every curve of the dense oracle", "[intersection][scan][family]") { checkFamily(11, 10); }
TEST_CASE("scan-like family, seeds 21-30: detect finds every curve of the dense oracle", "[intersection][scan][family]") { checkFamily(21, 10); }
TEST_CASE("scan-like family, seeds 31-40: detect finds every curve of the dense oracle", "[intersection][scan][family]") { checkFamily(31, 10); }
TEST_CASE("scan-like family, seeds 41-50: detect finds every curve of the dense oracle", "[intersection][scan][family]") { checkFamily(41, 10); }

// The same 50 resolved (issue 38: no pair unresolved, no crossing triangles, closed tows, kept
// volumes), in five cases of about 25 s each.
TEST_CASE("scan-like family, seeds 1-10: resolved, closed, no triangles crossing, volumes as CGAL's", "[resolve][scan][family]") { checkFamilyResolved(1, 10); }
TEST_CASE("scan-like family, seeds 11-20: resolved, closed, no triangles crossing, volumes as CGAL's", "[resolve][scan][family]") { checkFamilyResolved(11, 10); }
TEST_CASE("scan-like family, seeds 21-30: resolved, closed, no triangles crossing, volumes as CGAL's", "[resolve][scan][family]") { checkFamilyResolved(21, 10); }
TEST_CASE("scan-like family, seeds 31-40: resolved, closed, no triangles crossing, volumes as CGAL's", "[resolve][scan][family]") { checkFamilyResolved(31, 10); }
TEST_CASE("scan-like family, seeds 41-50: resolved, closed, no triangles crossing, volumes as CGAL's", "[resolve][scan][family]") { checkFamilyResolved(41, 10); }

namespace {

/// The stacks of @p t named @p names, in that order (those found).
std::vector<TowStack> stacksNamed(const testing::ScanLikeTextile& t, const std::vector<std::string>& names)
{
    std::vector<TowStack> picked;
    for (const std::string& name : names)
        for (const TowStack& s : t.stacks)
            if (s.name == name) picked.push_back(s);
    return picked;
}

/// Tows @p a and @p b of the large scan-like textile of @p seed, fitted, and resolved with the
/// default options.
struct ResolvedPair {
    std::vector<TowSurface> tows;
    ResolveResult result;
};
ResolvedPair resolvedLargePair(unsigned seed, const std::string& a, const std::string& b)
{
    const testing::ScanLikeTextile t = testing::largeScanLikeTextile(seed);
    const std::vector<TowStack> pair = stacksNamed(t, {a, b});
    REQUIRE(pair.size() == 2);
    ResolvedPair out{testing::fitAll(pair), {}};
    out.result = resolveTextile(out.tows);
    return out;
}

}  // namespace

TEST_CASE("a loop nearly tangent to a tow's seam, crossing it four times close together, is meshed", "[mesh][scan][seam]")
{
    // From the large scan-like textile of seed 2 (bench_scan_family --large): the loop of this
    // pair runs along the weft's seam for a while, crossing it four times within 0.02 in u.
    // Newton on v = seam from one loop chord's guess found the crossing of another chord: two
    // loop nodes on one point, mesh_failed.
    const auto [tows, r] = resolvedLargePair(2, "warp_L1_8", "weft_L2_7");
    REQUIRE(r.intersections.loops.size() == 1);
    CHECK(r.intersections.loops[0].closed());
    for (const UnresolvedPairEntry& u : unresolvedPairs(r)) FAIL_CHECK(u.code << ": " << u.message);
    CHECK(r.mesh.regions.size() == 1);
    for (const TowResolution& tr : r.tows) CHECK(tr.boundaryLoops == 0);
    CHECK(testing::crossingPairsBetweenTows(r.mesh) == 0);
    // The weft's v crosses its seam four times along the loop (the loop's uv curve, unwrapped).
    const std::vector<UV> onWeft = r.intersections.loops[0].uvCurve(LoopSide::B);
    const ParameterRange range = tows[1].parameterRange();
    std::size_t crossings = 0;
    for (std::size_t k = 0; k < onWeft.size(); ++k) {
        const double a = (onWeft[k].v - range.vMin) / range.vPeriod(), b = (onWeft[(k + 1) % onWeft.size()].v - range.vMin) / range.vPeriod();
        crossings += std::floor(a) != std::floor(b);
    }
    CHECK(crossings == 4);
}

namespace {

/// Tows @p names of the scan-like textile of @p seed, in that order, resolved with their loops:
/// every pair resolved, every tow closed, no crossing triangle pairs (unless @p crossingKnown).
void checkResolved(unsigned seed, const std::vector<std::string>& names, bool crossingKnown = false)
{
    const testing::ScanLikeTextile t = testing::scanLikeTextile(seed);
    INFO("seed " << seed << ": " << t.choices.describe());
    const std::vector<TowStack> picked = stacksNamed(t, names);
    REQUIRE(picked.size() == names.size());
    const std::vector<TowSurface> tows = testing::fitAll(picked);
    const ResolveResult r = resolveTextile(tows);
    CHECK(!r.intersections.loops.empty());
    for (const UnresolvedPairEntry& u : unresolvedPairs(r)) FAIL_CHECK(u.code << ": " << u.message);
    CHECK(!r.mesh.regions.empty());
    for (const TowResolution& tr : r.tows) CHECK(tr.boundaryLoops == 0);
    if (!crossingKnown) CHECK(testing::crossingPairsBetweenTows(r.mesh) == 0);
}

}  // namespace

TEST_CASE("a loop with a narrow neck: no edge across it is shared by the two tows' meshes", "[mesh][scan]")
{
    // A thin binder through a weft's edge, its loop on the binder nearly all the way round with
    // a neck where the surfaces nearly touch. Both tows' meshers joined the neck's loop nodes
    // by the same edges, one tow's triangles outside the loop and the other's inside: after the
    // swap the binder held those edges four times (region_failed). Such edges now get a node of
    // the tow's own. The second textile: a twill's weft, region_failed with four warps; its
    // meshes still cross in 42 triangle pairs where the tows nearly touch (issue 38, item 3:
    // contact), not checked here.
    checkResolved(47, {"weft_L0_2", "binder_0"});
    checkResolved(96, {"warp_0", "warp_1", "warp_2", "warp_3", "weft_3"}, true);
}

TEST_CASE("a loop chord along a tow's seam, split off the seam: the seam's edge under it gets a station", "[mesh][scan][seam]")
{
    // Plain weave of seed 145: a loop chord of the weft lies along its seam, 0.158 long (2.5 x
    // the mesh size). Split, its new node lies just off the seam; the seam's edge between the
    // chord's ends stayed one edge, exempt from the size bound (both ends loop nodes), and the
    // faces across the seam from it sagged through the warp's faces around the new node: 4
    // crossing triangle pairs, 13 after the contact refinement (and 119 after one more). The
    // whole textile (the pair alone meshes differently and does not cross); fails with the
    // seam's edge kept as a loop chord (13).
    const testing::ScanLikeTextile t = testing::scanLikeTextile(145);
    const ResolveResult r = resolveTextile(testing::fitAll(t.stacks));
    CHECK(unresolvedPairs(r).empty());
    CHECK(testing::crossingPairsBetweenTows(r.mesh) == 0);
}

TEST_CASE("a loop that dips across a tow's seam and back between two loop nodes gets nodes on the seam", "[mesh][scan][seam]")
{
    // Plain weave of seed 32: the loop runs along the warp's seam within 1e-4 of its period and
    // dips across it and back between two loop nodes 0.04 apart (the curve's middle lies at
    // v = -0.0004, its ends at +0.0001). Without nodes at those two seam crossings the chord
    // could not be split (its middle falls outside the tow's rectangle), the warp's seam
    // stations lay a hair off the loop, and the meshes crossed in 11 triangle pairs.
    checkResolved(32, {"warp_1", "weft_1"});
    // Directly: every crossing of the warp's seam by the curve is a loop node on the seam.
    const testing::ScanLikeTextile t = testing::scanLikeTextile(32);
    const std::vector<TowStack> pair = stacksNamed(t, {"warp_1", "weft_1"});
    REQUIRE(pair.size() == 2);
    const std::vector<TowSurface> tows = testing::fitAll(pair);
    const ResolveResult r = meshTows(tows, intersectTows(tows));
    const ParameterRange range = tows[0].parameterRange();
    std::size_t curveCrossings = 0, seamNodes = 0;
    for (const MeshedLoop& m : r.mesh.loops) {
        const IntersectionLoop& l = r.intersections.loops[m.loop];
        const std::vector<UV> onWarp = l.uvCurve(l.towA() == 0 ? LoopSide::A : LoopSide::B);
        for (std::size_t k = 0; k < onWarp.size(); ++k) {
            const double a = (onWarp[k].v - range.vMin) / range.vPeriod(), b = (onWarp[(k + 1) % onWarp.size()].v - range.vMin) / range.vPeriod();
            curveCrossings += std::floor(a) != std::floor(b);
        }
        for (const std::size_t n : m.nodes)
            for (const auto& [node, uv] : r.mesh.tows[0].parameters)
                if (node == n && uv.v == range.vMin) ++seamNodes;
    }
    CHECK(curveCrossings >= 4);
    CHECK(seamNodes >= curveCrossings);
}

TEST_CASE("where two tows meet at a shallow angle, both meshes are refined until they do not cross", "[mesh][scan][contact]")
{
    // Plain weaves of seeds 45 and 77: a loop runs close along the warp's seam, so the warp's
    // seam stations lie within the weft's chord sag of the weft's surface (the surfaces meet at
    // a shallow angle there): 4 and 5 crossing triangle pairs at the default size. The mesh
    // stage finds the crossings (exact triangle tests) and refines both tows around them.
    checkResolved(45, {"warp_1", "weft_0"});
    checkResolved(77, {"warp_0", "weft_1"});
}

TEST_CASE("a loop through the corner where both tows' seams meet keeps its seam crossings in order", "[mesh][scan][seam]")
{
    // Plain weave of seed 7: the loop of warp_1 and weft_1 passes 0.0007 from the point where
    // the two tows' seams cross, nearly tangent to the warp's seam. Both seam crossings fell on
    // one loop chord; the weft's replaced the chord's end and the warp's, behind it along the
    // curve, was put before it. The warp's v then crossed its seam between two nodes, the loop's
    // piece on the warp was clamped onto the seam (half the loop), the warp's mesh inside the
    // loop folded, and the weft was not closed after the swap: three pairs region_failed, 753
    // crossing triangle pairs.
    checkResolved(7, {"warp_0", "warp_1", "warp_2", "weft_0", "weft_1", "weft_2"});
    // Directly: on both tows, consecutive loop nodes never lie across the seam from each other
    // (one of them on it is a seam node).
    const testing::ScanLikeTextile t = testing::scanLikeTextile(7);
    const std::vector<TowStack> pair = stacksNamed(t, {"warp_1", "weft_1"});
    REQUIRE(pair.size() == 2);
    const std::vector<TowSurface> tows = testing::fitAll(pair);
    const ResolveResult r = meshTows(tows, intersectTows(tows));
    REQUIRE(r.mesh.loops.size() == 1);
    for (std::size_t tow = 0; tow < 2; ++tow) {
        const ParameterRange range = tows[tow].parameterRange();
        std::map<std::size_t, double> vOf;
        for (const auto& [node, uv] : r.mesh.tows[tow].parameters) vOf[node] = uv.v;
        const std::vector<std::size_t>& nodes = r.mesh.loops[0].nodes;
        std::size_t seamNodes = 0, longSteps = 0;
        for (std::size_t k = 0; k < nodes.size(); ++k) {
            const double a = vOf.at(nodes[k]), b = vOf.at(nodes[(k + 1) % nodes.size()]);
            seamNodes += a == range.vMin;
            // Wrapped into [vMin, vMax): a step across the seam without a node on it is a jump
            // of nearly a period between two neighbours.
            if (a != range.vMin && b != range.vMin) longSteps += std::abs(a - b) > 0.5 * range.vPeriod();
        }
        INFO("tow " << tows[tow].name());
        CHECK(seamNodes >= 2);
        CHECK(longSteps == 0);
    }
}

TEST_CASE("crossings the mesh stage cannot remove are counted, not refined without end", "[mesh][scan][contact]")
{
    // Plain weave of seed 7 with the loop of warp_1 and weft_1 taken out of the report: the two
    // tows pass through each other where no loop bounds the overlap. Their crossing triangle
    // pairs are many, so they are not taken for sag: the meshes are not refined there, and
    // ResolveResult::crossingTrianglePairs says how many cross, as the independent count does.
    const testing::ScanLikeTextile t = testing::scanLikeTextile(7);
    const std::vector<TowSurface> tows = testing::fitAll(t.stacks);
    IntersectionReport report = intersectTows(tows);
    const auto named = [&](std::size_t tow, const char* name) { return tows[tow].name() == name; };
    const std::size_t before = report.loops.size();
    report.loops.erase(std::remove_if(report.loops.begin(), report.loops.end(),
                                      [&](const IntersectionLoop& l) {
                                          return (named(l.towA(), "warp_1") && named(l.towB(), "weft_1")) ||
                                                 (named(l.towA(), "weft_1") && named(l.towB(), "warp_1"));
                                      }),
                       report.loops.end());
    REQUIRE(report.loops.size() + 1 == before);
    const ResolveResult meshed = meshTows(tows, report);
    const std::size_t crossing = testing::crossingPairsBetweenTows(meshed.mesh);
    CHECK(crossing > 100);
    CHECK(meshed.crossingTrianglePairs == crossing);
    std::size_t triangles = 0;
    for (const TowMesh& m : meshed.mesh.tows) triangles += m.triangles.size();
    CHECK(triangles < 75000);  // 72,546 (416 crossing pairs): not refined around the crossings (a pass adds ~30,000)
}

TEST_CASE("a loop thinner than its nodes can follow, where pressed tows nearly touch, is a contact", "[mesh][scan][contact]")
{
    // From the large scan-like textile of seed 8: besides their large loop, the weft and the
    // binder meet in a loop 0.015 long around 6.6e-6 of area, where the surfaces meet at 0.4-1.4
    // degrees. Its two sides run within 1e-6 of each other for a stretch, closer than its nodes
    // can follow: its node polygon crossed itself, the mesher's constraints cut each other, the
    // binder was not closed after the swap and all nine of its pairs in the textile ended
    // region_failed, their meshes crossing in 73 triangle pairs.
    const auto [tows, r] = resolvedLargePair(8, "weft_L0_3", "binder_5");
    REQUIRE(r.intersections.loops.size() == 2);
    for (const UnresolvedPairEntry& u : unresolvedPairs(r)) FAIL_CHECK(u.code << ": " << u.message);
    // The large loop is a region; the small one a contact, named in the result.
    CHECK(r.mesh.regions.size() == 1);
    REQUIRE(r.skippedLoops.size() == 1);
    const SkippedLoop& contact = r.skippedLoops[0];
    CHECK(contact.reason == SkippedLoop::Reason::Contact);
    CHECK(r.intersections.loops[contact.loop].length() < 0.02);
    CHECK(contact.message.find("'weft_L0_3' and 'binder_5'") != std::string::npos);
    for (const TowResolution& tr : r.tows) CHECK(tr.boundaryLoops == 0);
    // The meshes do not cross there (the mesh stage refines both tows where they would).
    CHECK(testing::crossingPairsBetweenTows(r.mesh) == 0);
    CHECK(r.crossingTrianglePairs == 0);
}

TEST_CASE("a loop grazing a tow's rim gets no node on the cap between two nodes on the tube", "[mesh][scan][caps]")
{
    // Twills of seeds 182 and 234: a loop across the warp's (or weft's) end cap runs back along
    // the tube within 2e-4 of the rim, dipping onto the cap and back between two loop nodes. A
    // split of such a chord (asked for by a mesher) put a node on the cap into the loop's piece on
    // the tube; the tube's mesh lost a rim node, and meshing the cap failed (mesh_failed, 281 and
    // 401 crossing triangle pairs). Such a chord now stays whole.
    checkResolved(182, {"warp_3", "weft_1"});
    checkResolved(234, {"warp_1", "weft_3"});
}

TEST_CASE("a loop running along a tow's rim: the rim is refined until the meshes do not cross", "[mesh][scan][caps]")
{
    // Orthogonal weave of seed 53: the loop of warp_L1_0 and weft_L2_0 runs along the warp's
    // rim, within 1e-4 of it in u, crossing onto the cap and back. The warp's end stations are
    // h/2 apart (0.39 here) and the rim's chord there sags 0.001 off the curve, more than the
    // loop's distance from it: the weft's mesh, following the loop's exact nodes, crossed the
    // warp's cap and the sliver of its tube along the rim (3 crossing triangle pairs). The caps
    // are now checked with the tubes in the mesh stage, and an end's edges are split where faces
    // next to them need it.
    checkResolved(53, {"warp_L1_0", "weft_L2_0"});
}

TEST_CASE("a loop chord whose curve dips across a seam next to a node on it gets a node where it crosses", "[mesh][scan][seam]")
{
    // Orthogonal weaves of seeds 314 and 418: the loop hugs the weft's seam from below, touching
    // it at a node; the curve between that node and the previous one (0.97 apart) crosses the
    // seam and comes back. The chord's middle lies across the seam, so it was never split: one
    // long chord, both meshes coarse along it, 11 and 6 crossing triangle pairs. The chord's new
    // node is now the curve's first crossing of the seam, a node on it.
    checkResolved(314, {"warp_L0_2", "weft_L1_1"});
    checkResolved(418, {"warp_L1_0", "weft_L2_2"});
    // Seed 99: the weft's seam had stations between the two nodes of such a chord (made before
    // it was split onto the seam); its loop chord along the seam was not one edge, and the weft
    // was not closed after the swap (four pairs region_failed). Its stations there are dropped.
    checkResolved(99, {"warp_L0_0", "warp_L0_1", "warp_L0_2", "binder_1", "weft_L0_0"});
}
