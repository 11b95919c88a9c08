// Stress benchmark of loop detection on the scan-like family (issue 38): N random scan-like
// textiles (tests/support/scan_like.hpp: pressed weaves voxelised and contoured back, starts
// drifting, cut by the scan box), each detected by towgeom and checked against the dense oracle
// (tests/support/dense_oracle.hpp: CGAL's surface_intersection of the same fitted surfaces
// tessellated at 8 x sections by 4 x points). Checks: every oracle curve longer than 1e-3 of
// the tow size is found, and every curve closes (across the tows' caps). Printed: the worst case
// of each statistic, the open curves by reason, and towgeom's time against the oracle's.
// With --resolve each textile is also resolved (its detected loops, default options) and checked:
// no pair left unresolved, no two tows' triangles crossing (CGAL box intersection + exact
// triangle tests), every tow's mesh closed; the smallest angle is printed, and the triangles
// under 5 and 15 degrees with where those under 15 lie (caps, regions, at a loop node, next to
// one, on a rim or seam, near an end, under h/8). --no-oracle skips the oracle (and its check).
// With --large a single scan-like textile of a real scan's size instead (largeScanLikeTextile:
// a 3D orthogonal weave of 9 x 9 yarns in 2 warp layers, ~57 tows of 30 sections x 32 points,
// seed --first) is detected and resolved in process on --threads threads (default 2), and CGAL's
// surface_intersection runs on the same fitted surfaces tessellated at 120 stations x 64 points
// per tow, every pair whose boxes overlap, in the same run. Goals (issue 38): resolve <= 30 s
// and peak memory <= 1.5 GiB; detect >= 4x faster than CGAL; no pair unresolved, no crossing
// triangle pairs, every tow closed.
//   bench_scan_family [--count N] [--first SEED] [--resolve [--verbose]] [--no-oracle] [--dump DIR] [--smoke]
// --verbose prints each tow pair whose output triangles cross (with the loops detected between
// them and where). --dump DIR writes the tows there as .stw files (one per tow, in the order
// resolved; a subfolder per seed when --count is above 1);
// --detect-only stops after detect and prints its counts (for profiling).
//   bench_scan_family --large [--first SEED] [--threads T] [--dump DIR] [--detect-only] [--smoke]
// With --large --cell the same textile is cut by a box inset a tenth of its extent from each side
// and meshed into tetrahedra: issue 39's goal, fit to tetrahedra <= 5 min on 2 cores.
//   bench_scan_family --large --cell [--first SEED] [--threads T] [--smoke]
#include <towgeom/towgeom.hpp>

#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <map>
#include <set>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <vector>
#include <string>

#include "bench_goal.hpp"
#include "cgal_reference.hpp"
#include "dense_oracle.hpp"
#include "scan_like.hpp"
#include "synthetic_tows.hpp"

namespace {

/// What --resolve found over the family: each statistic's total and worst case.
struct ResolveTally {
    std::size_t textiles = 0, failed = 0, unresolvedPairs = 0, textilesUnresolved = 0, crossing = 0, textilesCrossing = 0;
    std::size_t notClosed = 0;  ///< tows whose final mesh has a boundary
    std::map<std::string, std::size_t> byCode;  ///< unresolved pairs by the reports' code
    std::size_t triangles = 0, under5 = 0, under15 = 0;  ///< counted by MeshQuality, and those under 5 and 15 degrees
    std::size_t mostTriangles = 0;
    /// Triangles under 15 degrees by place: on a cap, in a region, their small angle at a node
    /// two tows share (a loop node: a constraint's corner or chord), another corner on a loop
    /// node, none.
    std::size_t capUnder15 = 0, regionUnder15 = 0, atLoopNode = 0, besideLoopNode = 0, ownOnly = 0;
    std::size_t ownOnRim = 0, ownOnSeam = 0, ownSmall = 0, ownNearEnd = 0;  ///< of ownOnly: a node on an end, on the seam; shorter than h/8
    unsigned mostTrianglesSeed = 0;
    double seconds = 0.0, slowest = 0.0, smallestAngle = 180.0;
    unsigned slowestSeed = 0, smallestAngleSeed = 0;
    /// Against MeshQuality::angleBound: sharp constraint corners, triangles excused at them, the
    /// rest under the bound, the smallest angle away from corners.
    std::size_t sharpCorners = 0, atSharpCorners = 0, underBound = 0;
    double smallestAway = 180.0;
    unsigned smallestAwaySeed = 0;
};

/// One line per tow pair whose output triangles cross: how many, how many of those share a node,
/// the loops detect found between the two tows, and where the first crossing lies.
void printCrossingPairs(const std::vector<towgeom::TowSurface>& tows, const towgeom::IntersectionReport& report,
                        const towgeom::TextileMesh& mesh)
{
    for (const towgeom::testing::TowPairCrossings& c : towgeom::testing::crossingsByTowPair(mesh)) {
        std::size_t loops = 0;
        for (const towgeom::IntersectionLoop& l : report.loops)
            loops += (l.towA() == c.towA && l.towB() == c.towB) || (l.towA() == c.towB && l.towB() == c.towA);
        std::printf("    %s/%s: %zu crossing (%zu sharing a node), %zu loop(s) detected, first at (%.4g, %.4g, %.4g)\n",
                    tows[c.towA].name().c_str(), tows[c.towB].name().c_str(), c.crossings.crossing, c.crossings.crossingSharing,
                    loops, c.firstAt.x, c.firstAt.y, c.firstAt.z);
    }
}

/// Adds the places of @p mesh's triangles under 15 degrees to @p tally (as MeshQuality counts
/// them: a region's triangles once).
void placeSmallAngles(const std::vector<towgeom::TowSurface>& tows, const towgeom::ResolveResult& r, ResolveTally& tally)
{
    const towgeom::TextileMesh& mesh = r.mesh;
    std::vector<std::set<std::size_t>> towsAt(mesh.nodes.size());
    for (std::size_t t = 0; t < mesh.tows.size(); ++t)
        for (const auto& tri : mesh.tows[t].triangles)
            for (std::size_t n : tri) towsAt[n].insert(t);
    for (std::size_t t = 0; t < mesh.tows.size(); ++t) {
        const towgeom::TowMesh& m = mesh.tows[t];
        for (std::size_t k = 0; k < m.triangles.size(); ++k) {
            const long region = k < m.region.size() ? m.region[k] : -1;
            if (region >= 0 && mesh.regions[static_cast<std::size_t>(region)].secondary == t) continue;
            const auto& tri = m.triangles[k];
            double smallest = 180.0;
            std::size_t at = 0;
            for (std::size_t c = 0; c < 3; ++c) {
                const towgeom::Point3 &p = mesh.nodes[tri[c]], &a = mesh.nodes[tri[(c + 1) % 3]], &b = mesh.nodes[tri[(c + 2) % 3]];
                const towgeom::Vector3 u = a - p, w = b - p;
                const double angle = std::atan2(towgeom::norm(towgeom::cross(u, w)), towgeom::dot(u, w)) * 180.0 / 3.14159265358979323846;
                if (angle < smallest) {
                    smallest = angle;
                    at = c;
                }
            }
            if (smallest >= 15.0) continue;
            if (m.face[k] != towgeom::TowFace::Side) ++tally.capUnder15;
            else if (region >= 0) ++tally.regionUnder15;
            else if (towsAt[tri[at]].size() > 1) ++tally.atLoopNode;
            else if (towsAt[tri[0]].size() > 1 || towsAt[tri[1]].size() > 1 || towsAt[tri[2]].size() > 1) ++tally.besideLoopNode;
            else {
                ++tally.ownOnly;
                std::size_t rim = 0, seam = 0;
                for (std::size_t n : tri) {
                    const auto it = std::lower_bound(m.parameters.begin(), m.parameters.end(), std::make_pair(n, towgeom::UV{-1e300, -1e300}),
                                                     [](const auto& a, const auto& b) { return a.first < b.first; });
                    if (it == m.parameters.end() || it->first != n) continue;
                    const towgeom::ParameterRange pr = tows[t].parameterRange();
                    rim += it->second.u == pr.uMin || it->second.u == pr.uMax;
                    seam += it->second.v == pr.vMin;
                }
                double longest = 0.0;
                for (std::size_t c = 0; c < 3; ++c) longest = std::max(longest, towgeom::distance(mesh.nodes[tri[c]], mesh.nodes[tri[(c + 1) % 3]]));
                const towgeom::Point3 c = (1.0 / 3.0) * (mesh.nodes[tri[0]] + mesh.nodes[tri[1]] + mesh.nodes[tri[2]]);
                const towgeom::ParameterRange pr = tows[t].parameterRange();
                const double size = tows[t].towSize();
                for (const double u : {pr.uMin, pr.uMax}) {
                    towgeom::Point3 end{0, 0, 0};
                    for (int k = 0; k < 8; ++k) end = end + 0.125 * tows[t].point(u, pr.vMin + pr.vPeriod() * k / 8.0);
                    if (towgeom::distance(end, c) < 2.0 * size) {
                        ++tally.ownNearEnd;
                        break;
                    }
                }
                if (rim > 0) ++tally.ownOnRim;
                else if (seam > 0) ++tally.ownOnSeam;
                else if (8.0 * longest < r.tows[t].meshSize) ++tally.ownSmall;
            }
        }
    }
}

/// Resolves one textile with its detected loops and adds what it gives to @p tally; prints the
/// textile's line when something is wrong (and with @p verbose its crossing tow pairs).
void resolveOne(unsigned seed, const std::string& what, const std::vector<towgeom::TowSurface>& tows,
                const towgeom::IntersectionReport& report, ResolveTally& tally, bool verbose)
{
    ++tally.textiles;
    const auto t0 = std::chrono::steady_clock::now();
    towgeom::ResolveResult r;
    try {
        r = towgeom::resolveTextile(tows, report);
    } catch (const towgeom::Error& e) {
        ++tally.failed;
        std::printf("seed %u: %s: resolve failed: %s\n", seed, what.c_str(), e.what());
        return;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    tally.seconds += seconds;
    if (seconds > tally.slowest) {
        tally.slowest = seconds;
        tally.slowestSeed = seed;
    }
    tally.sharpCorners += r.mesh.sharpCorners.size();
    tally.atSharpCorners += r.quality.atSharpCorners;
    tally.underBound += r.quality.underBound;
    if (r.quality.minAngleAwayFromCorners < tally.smallestAway) {
        tally.smallestAway = r.quality.minAngleAwayFromCorners;
        tally.smallestAwaySeed = seed;
    }
    if (r.quality.minAngle < tally.smallestAngle) {
        tally.smallestAngle = r.quality.minAngle;
        tally.smallestAngleSeed = seed;
    }
    tally.triangles += r.quality.triangles;
    placeSmallAngles(tows, r, tally);
    for (std::size_t b = 0; b < r.quality.histogram.size() && b < 3; ++b) (b == 0 ? tally.under5 : tally.under15) += r.quality.histogram[b];
    if (!r.quality.histogram.empty()) tally.under15 += r.quality.histogram[0];
    if (r.quality.triangles > tally.mostTriangles) {
        tally.mostTriangles = r.quality.triangles;
        tally.mostTrianglesSeed = seed;
    }
    const std::vector<towgeom::UnresolvedPairEntry> unresolved = towgeom::unresolvedPairs(r);
    std::set<std::pair<std::size_t, std::size_t>> pairs;
    std::string codes;
    for (const towgeom::UnresolvedPairEntry& u : unresolved) {
        if (!pairs.insert({u.towA, u.towB}).second) continue;
        ++tally.byCode[u.code];
        codes += " " + tows[u.towA].name() + "/" + tows[u.towB].name() + ":" + u.code;
    }
    tally.unresolvedPairs += pairs.size();
    tally.textilesUnresolved += !pairs.empty();
    std::size_t open = 0;
    for (const towgeom::TowResolution& t : r.tows) open += t.boundaryLoops > 0;
    tally.notClosed += open;
    const std::size_t crossing = towgeom::testing::crossingPairsBetweenTows(r.mesh);
    tally.crossing += crossing;
    tally.textilesCrossing += crossing > 0;
    if (!pairs.empty() || crossing > 0 || open > 0)
        std::printf("seed %u: %s: resolve: %zu unresolved pair(s)%s; %zu crossing triangle pairs; %zu tow(s) not closed\n", seed,
                    what.c_str(), pairs.size(), codes.c_str(), crossing, open);
    if (verbose && crossing > 0) printCrossingPairs(tows, report, r.mesh);
}

void printResolveTally(const ResolveTally& t)
{
    std::printf("resolve: %zu textiles (%zu failed), unresolved pairs %zu in %zu textiles", t.textiles, t.failed, t.unresolvedPairs,
                t.textilesUnresolved);
    for (const auto& [code, n] : t.byCode) std::printf(", %s %zu", code.c_str(), n);
    std::printf("\n  crossing triangle pairs between tows %zu in %zu textiles; tows not closed %zu\n", t.crossing, t.textilesCrossing,
                t.notClosed);
    std::printf("  smallest angle %.3g deg (seed %u); resolve %.1f s in all, slowest %.2f s (seed %u)\n", t.smallestAngle,
                t.smallestAngleSeed, t.seconds, t.slowest, t.slowestSeed);
    const double all = static_cast<double>(std::max<std::size_t>(1, t.triangles));
    std::printf("  triangles %zu (most %zu, seed %u); smallest angle under 5 deg: %zu (%.3g %%), under 15 deg: %zu (%.3g %%)\n",
                t.triangles, t.mostTriangles, t.mostTrianglesSeed, t.under5, 100.0 * static_cast<double>(t.under5) / all, t.under15,
                100.0 * static_cast<double>(t.under15) / all);
    std::printf("  against the surface's angle bound: %zu sharp constraint corners, %zu triangles at them (at least a third of the "
                "corner's angle), %zu under the bound elsewhere (%.3g %%); smallest angle away from corners %.3g deg (seed %u)\n",
                t.sharpCorners, t.atSharpCorners, t.underBound, 100.0 * static_cast<double>(t.underBound) / all, t.smallestAway,
                t.smallestAwaySeed);
    std::printf("  under 15 deg: on caps %zu, in regions %zu, small angle at a loop node %zu, another corner on one %zu, "
                "no loop node %zu (a node on an end %zu, on the seam %zu, else shorter than h/8 %zu; within 2 tow sizes of an end %zu)\n",
                t.capUnder15, t.regionUnder15, t.atLoopNode, t.besideLoopNode, t.ownOnly, t.ownOnRim, t.ownOnSeam, t.ownSmall, t.ownNearEnd);
}

double since(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// The peak resident memory of this process so far, in MiB.
double peakMiB()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

/// The first few crossing triangle pairs of crossingsInSurfaces(): whose, which face, where.
void printSurfaceCrossings(const std::vector<towgeom::TowSurface>& tows, const towgeom::TextileMesh& mesh,
                           const towgeom::testing::SurfaceCrossings& crossings)
{
    const auto describe = [&](const towgeom::testing::MeshTriangle& t) {
        const bool cell = t.tow == towgeom::testing::MeshTriangle::kCellTriangles;
        const std::array<std::size_t, 3>& n = cell ? mesh.cell->triangles[t.index] : mesh.tows[t.tow].triangles[t.index];
        const towgeom::Point3 &a = mesh.nodes[n[0]], &b = mesh.nodes[n[1]], &c = mesh.nodes[n[2]];
        char text[256];
        std::snprintf(text, sizeof text, "%s triangle %zu (face %d, region %ld) at (%.4f, %.4f, %.4f)",
                      cell ? "the box's" : tows[t.tow].name().c_str(), t.index,
                      cell ? static_cast<int>(mesh.cell->face[t.index]) : static_cast<int>(mesh.tows[t.tow].face[t.index]),
                      cell ? -1L : mesh.tows[t.tow].region[t.index], (a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3, (a.z + b.z + c.z) / 3);
        return std::string(text);
    };
    for (std::size_t k = 0; k < crossings.first.size() && k < 10; ++k)
        std::printf("  crossing: %s and %s\n", describe(crossings.first[k].first).c_str(), describe(crossings.first[k].second).c_str());
}

/// The tows whose surfaces resolveTextile() found folding (TowResolution::fold).
void printFolds(const std::vector<towgeom::TowSurface>& tows, const towgeom::ResolveResult& r)
{
    for (std::size_t t = 0; t < tows.size(); ++t)
        if (const auto& f = r.tows[t].fold)
            std::printf("  fold reported: %s near (%.4f, %.4f, %.4f), %zu crossing pairs of its sampled surface\n", tows[t].name().c_str(),
                        f->at.x, f->at.y, f->at.z, f->crossingPairs);
}

/// The 57-tow goals of issue 38 on largeScanLikeTextile(seed): detect and resolve timed in
/// process, peak memory after resolving (before CGAL runs), then CGAL's surface_intersection on
/// every overlapping pair tessellated at 120 x 64.
int runLarge(unsigned seed, std::size_t threads, bool smoke, bool detectOnly, const std::string& dump)
{
    towgeom::bench::Goals goals(smoke);
    const towgeom::testing::ScanLikeTextile t = towgeom::testing::largeScanLikeTextile(seed);
    if (!dump.empty()) std::printf("tows written, in the order resolved:%s\n", towgeom::testing::writeStacks(dump, t.stacks).c_str());
    auto t0 = std::chrono::steady_clock::now();
    const std::vector<towgeom::TowSurface> tows = towgeom::testing::fitAll(t.stacks);
    const double fitSeconds = since(t0);
    std::printf("towgeom bench_scan_family --large: seed %u, %s, %zu tows, %zu threads; fit %.2f s\n", seed,
                t.choices.describe().c_str(), tows.size(), threads, fitSeconds);
    towgeom::IntersectionOptions detectOptions;
    detectOptions.threads = threads;
    t0 = std::chrono::steady_clock::now();
    const towgeom::IntersectionReport report = towgeom::intersectTows(tows, detectOptions);
    const double detectSeconds = since(t0);
    if (detectOnly) {
        std::printf("detect %.3f s: broad %.0f ms exact %.0f ms, %zu pairs tested, %zu windows, %zu seeds, %zu walks\n", detectSeconds,
                    report.timings.broadPhase, report.timings.exact, report.pairsTested, report.windowPairs, report.seeds, report.walks);
        return 0;
    }
    towgeom::ResolveOptions resolveOptions;
    resolveOptions.threads = threads;
    t0 = std::chrono::steady_clock::now();
    const towgeom::ResolveResult r = towgeom::resolveTextile(tows, report, resolveOptions);
    const double resolveSeconds = since(t0);
    const double peak = peakMiB();
    std::set<std::pair<std::size_t, std::size_t>> unresolved;
    std::string codes;
    for (const towgeom::UnresolvedPairEntry& u : towgeom::unresolvedPairs(r))
        if (unresolved.insert({u.towA, u.towB}).second) codes += " " + tows[u.towA].name() + "/" + tows[u.towB].name() + ":" + u.code;
    std::size_t notClosed = 0, triangles = 0;
    for (const towgeom::TowResolution& tr : r.tows) notClosed += tr.boundaryLoops > 0;
    for (const towgeom::TowMesh& m : r.mesh.tows) triangles += m.triangles.size();
    t0 = std::chrono::steady_clock::now();
    const towgeom::testing::SurfaceCrossings crossings = towgeom::testing::crossingsInSurfaces(r.mesh);
    const std::size_t crossing = crossings.crossing;
    std::printf("CGAL's crossing check of all surfaces: %.2f s\n", since(t0));
    std::printf("detect: %zu loops (%zu open); resolve: %zu unresolved pair(s)%s, %zu crossing triangle pairs (within or between tows), %zu tow(s) not "
                "closed, smallest angle %.3g deg, %zu triangles; peak memory %.0f MiB\n",
                report.loops.size(), report.openCount(), unresolved.size(), codes.c_str(), crossing, notClosed, r.quality.minAngle,
                triangles, peak);
    printSurfaceCrossings(tows, r.mesh, crossings);
    printFolds(tows, r);
    t0 = std::chrono::steady_clock::now();
    for (const towgeom::TowSurface& tow : tows) (void)towgeom::findFold(tow);
    std::printf("  findFold on every tow (part of resolve): %.2f s on one thread\n", since(t0));
    std::printf("  %zu sharp constraint corners, %zu triangles at them, %zu under the %.3g deg bound elsewhere; smallest angle away "
                "from corners %.3g deg\n",
                r.mesh.sharpCorners.size(), r.quality.atSharpCorners, r.quality.underBound, r.quality.angleBound,
                r.quality.minAngleAwayFromCorners);

    t0 = std::chrono::steady_clock::now();
    std::vector<towgeom::TriangleMesh> faceted;
    for (const towgeom::TowSurface& tow : tows) faceted.push_back(tow.tessellate(120, 64));
    std::size_t pairs = 0, curves = 0;
    for (std::size_t i = 0; i < tows.size(); ++i)
        for (std::size_t j = i + 1; j < tows.size(); ++j) {
            if (!tows[i].boundingBox().overlaps(tows[j].boundingBox())) continue;
            ++pairs;
            const towgeom::testing::IntersectionPolylines p = towgeom::testing::surfaceIntersection(faceted[i], faceted[j]);
            curves += p.closed + p.open;
        }
    const double cgalSeconds = since(t0);
    std::printf("CGAL surface_intersection at 120 x 64 per tow, %zu pairs whose boxes overlap: %zu polylines\n", pairs, curves);
    std::printf("%-10s %12s %12s %10s\n", "", "towgeom_s", "cgal_s", "ratio");
    std::printf("%-10s %12.2f %12.2f %9.2fx  (goal >= 4x)\n", "detect", detectSeconds, cgalSeconds, cgalSeconds / detectSeconds);
    std::printf("%-10s %12.2f %12s %10s  (goal <= 30 s, <= 1536 MiB: %.0f MiB)\n", "resolve", resolveSeconds, "", "", peak);
    goals.require("the textile has a real scan's size (>= 50 tows)", tows.size() >= 50);
    goals.require("every curve closes", report.openCount() == 0);
    goals.require("no tow pair left unresolved", unresolved.empty());
    goals.require("no two output triangles cross (within or between tows)", crossing == 0);
    goals.require("every tow's output mesh is closed", notClosed == 0);
    goals.secondsAtMost("resolve", resolveSeconds, 30.0);
    goals.require("peak memory <= 1536 MiB", peak <= 1536.0);
    goals.ratioAtLeast("detect vs CGAL at 120 x 64", cgalSeconds / detectSeconds, 4.0);
    return goals.exitStatus();
}

/// Issue 39's scan cell: largeScanLikeTextile(seed) cut by a box inset a tenth of the textile's
/// extent from each side (its faces cut binders several times, tows along their length and at
/// the box's edges), resolved and meshed into tetrahedra (--volume's defaults) on @p threads
/// threads. Goal: fit to tetrahedra <= 5 min on 2 cores; every tow closed, the tetrahedra filling
/// the box (meshVolumes checks that they conform).
int runLargeCell(unsigned seed, std::size_t threads, bool smoke)
{
    towgeom::bench::Goals goals(smoke);
    const auto start = std::chrono::steady_clock::now();
    const towgeom::testing::ScanLikeTextile t = towgeom::testing::largeScanLikeTextile(seed);
    const std::vector<towgeom::TowSurface> tows = towgeom::testing::fitAll(t.stacks);
    towgeom::BoundingBox all;
    for (const towgeom::TowSurface& tow : tows) {
        all.add(tow.boundingBox().min);
        all.add(tow.boundingBox().max);
    }
    towgeom::Cell cell;
    const towgeom::Vector3 inset = 0.1 * (all.max - all.min);
    cell.min = all.min + inset;
    cell.max = all.max - inset;
    towgeom::ResolveOptions options;
    options.threads = threads;
    options.cell = cell;
    auto t0 = std::chrono::steady_clock::now();
    const towgeom::ResolveResult r = towgeom::resolveTextile(tows, options);
    const double resolveSeconds = since(t0);
    std::size_t triangles = 0;
    for (const towgeom::TowMesh& m : r.mesh.tows) triangles += m.triangles.size();
    t0 = std::chrono::steady_clock::now();
    const towgeom::testing::SurfaceCrossings crossings = towgeom::testing::crossingsInSurfaces(r.mesh);
    const double checkSeconds = since(t0);  // the bench's own check: not counted in the goal's time
    std::printf("CGAL's crossing check of all surfaces (not timed below): %.2f s\n", checkSeconds);
    std::printf("resolved in %.2f s: %zu unresolved pair(s), %zu triangles (%zu on the box's faces), %zu crossing triangle pairs "
                "(within or between tows, or against the box's faces)\n",
                resolveSeconds, towgeom::unresolvedPairs(r).size(), triangles, r.mesh.cell->triangles.size(), crossings.crossing);
    printSurfaceCrossings(tows, r.mesh, crossings);
    printFolds(tows, r);
    std::fflush(stdout);
    towgeom::VolumeMeshOptions volumeOptions;
    volumeOptions.threads = threads;
    t0 = std::chrono::steady_clock::now();
    towgeom::VolumeMesh v;
    try {
        v = towgeom::meshVolumes(r.mesh, volumeOptions);
    } catch (const towgeom::Error& e) {
        std::printf("meshVolumes failed after %.2f s: %s\n", since(t0), e.what());
        goals.require("the cell's tetrahedra are made", false);
        return goals.exitStatus();
    }
    const double volumeSeconds = since(t0);
    const double total = since(start) - checkSeconds;
    double filled = 0.0;
    for (std::size_t k = 0; k < v.tetrahedra.size(); ++k) filled += std::abs(v.tetrahedronVolume(k));
    std::size_t inside = 0, pieces = 0, notClosed = 0;
    for (std::size_t k = 0; k < tows.size(); ++k) {
        if (r.mesh.tows[k].triangles.empty()) continue;
        ++inside;
        pieces += r.tows[k].pieces;
        notClosed += r.tows[k].boundaryLoops > 0;
    }
    std::printf("towgeom bench_scan_family --large --cell: seed %u, %s, %zu tows, %zu threads; box (%.3g, %.3g, %.3g) to (%.3g, %.3g, %.3g)\n",
                seed, t.choices.describe().c_str(), tows.size(), threads, cell.min.x, cell.min.y, cell.min.z, cell.max.x, cell.max.y,
                cell.max.z);
    std::printf("  %zu tows in the box in %zu pieces, %zu unresolved pair(s); %zu tetrahedra, filling the box within %.2g; peak memory %.0f MiB\n",
                inside, pieces, towgeom::unresolvedPairs(r).size(), v.tetrahedra.size(), std::abs(filled - cell.volume()) / cell.volume(),
                peakMiB());
    std::printf("%-28s %10s\n", "stage", "seconds");
    std::printf("%-28s %10.2f\n", "intersect", r.timings.intersect / 1000.0);
    std::printf("%-28s %10.2f\n", "mesh", r.timings.mesh / 1000.0);
    std::printf("%-28s %10.2f\n", "regions and the cell's clip", r.timings.regions / 1000.0);
    std::printf("%-28s %10.2f\n", "resolve in all", resolveSeconds);
    std::printf("%-28s %10.2f  (Gmsh %.2f)\n", "volume", volumeSeconds, v.gmshSeconds);
    std::printf("%-28s %10.2f  (goal <= 300 s)\n", "fit to tetrahedra", total);
    goals.require("the textile has a real scan's size (>= 50 tows)", tows.size() >= 50);
    goals.require("every tow in the box closed", notClosed == 0);
    goals.require("no two surface triangles cross (within or between tows, or against the box's faces)", crossings.crossing == 0);
    goals.require("the tetrahedra fill the box within 1e-9", std::abs(filled - cell.volume()) <= 1e-9 * cell.volume());
    goals.secondsAtMost("fit to tetrahedra", total, 300.0);
    return goals.exitStatus();
}

}  // namespace

int main(int argc, char** argv)
{
    unsigned count = 500, first = 1;
    bool smoke = false, resolve = false, oracle = true, large = false, detectOnly = false, verbose = false, cell = false;
    std::size_t threads = 2;
    std::string dump;
    for (int k = 1; k < argc; ++k) {
        const std::string a = argv[k];
        if (a == "--smoke") smoke = true;
        else if (a == "--resolve") resolve = true;
        else if (a == "--no-oracle") oracle = false;
        else if (a == "--large") large = true;
        else if (a == "--cell") cell = true;
        else if (a == "--detect-only") detectOnly = true;
        else if (a == "--verbose") verbose = true;
        else if (a == "--threads" && k + 1 < argc) threads = std::stoul(argv[++k]);
        else if (a == "--dump" && k + 1 < argc) dump = argv[++k];
        else if (a == "--count" && k + 1 < argc) count = static_cast<unsigned>(std::stoul(argv[++k]));
        else if (a == "--first" && k + 1 < argc) first = static_cast<unsigned>(std::stoul(argv[++k]));
        else {
            std::fprintf(stderr, "usage: bench_scan_family [--count N] [--first SEED] [--resolve [--verbose]] [--no-oracle] [--dump DIR] [--smoke]\n"
                                 "       bench_scan_family --large [--first SEED] [--threads T] [--dump DIR] [--detect-only] [--smoke]\n"
                                 "       bench_scan_family --large --cell [--first SEED] [--threads T] [--smoke]\n");
            return 2;
        }
    }
    if (large && cell) return runLargeCell(first, threads, smoke);
    if (large) return runLarge(first, threads, smoke, detectOnly, dump);
    ResolveTally tally;
    towgeom::bench::Goals goals(smoke);
    std::printf("towgeom bench_scan_family: %u scan-like textiles from seed %u\n", count, first);
    std::size_t atEnds = 0, walkStops = 0;  // open curves by reason
    std::size_t tows = 0, loops = 0, open = 0, pairs = 0, considered = 0, matched = 0, withOpen = 0, failedToFit = 0;
    double longestMissed = 0.0, farthest = 0.0, detectSeconds = 0.0, oracleSeconds = 0.0, slowest = 0.0;
    unsigned slowestSeed = 0;
    for (unsigned seed = first; seed < first + count; ++seed) {
        const towgeom::testing::ScanLikeTextile t = towgeom::testing::scanLikeTextile(seed);
        if (!dump.empty()) {
            const std::filesystem::path dir = count == 1 ? std::filesystem::path(dump) : std::filesystem::path(dump) / std::to_string(seed);
            std::filesystem::create_directories(dir);
            std::printf("seed %u: tows written to %s, in the order resolved:%s\n", seed, dir.c_str(),
                        towgeom::testing::writeStacks(dir, t.stacks).c_str());
        }
        std::vector<towgeom::TowSurface> fitted;
        try {
            fitted = towgeom::testing::fitAll(t.stacks);
        } catch (const towgeom::Error& e) {
            ++failedToFit;
            std::printf("seed %u: %s: fit refused: %s\n", seed, t.choices.describe().c_str(), e.what());
            continue;
        }
        const auto t0 = std::chrono::steady_clock::now();
        const towgeom::IntersectionReport report = towgeom::intersectTows(fitted);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const towgeom::testing::TextileOracleComparison c =
            oracle ? towgeom::testing::compareTextileWithOracle(fitted, report) : towgeom::testing::TextileOracleComparison{};
        if (resolve) resolveOne(seed, t.choices.describe(), fitted, report, tally, verbose);
        tows += fitted.size();
        loops += report.loops.size();
        open += report.openCount();
        for (const towgeom::IntersectionLoop& l : report.loops) {
            if (l.closed()) continue;
            const auto k = l.openKind();
            (k == towgeom::IntersectionLoop::OpenKind::ReachesEndOfA || k == towgeom::IntersectionLoop::OpenKind::ReachesEndOfB ? atEnds
                                                                                                                                : walkStops) += 1;
        }
        withOpen += report.openCount() > 0;
        pairs += c.pairs;
        considered += c.considered;
        matched += c.matched;
        longestMissed = std::max(longestMissed, c.longestMissed);
        farthest = std::max(farthest, c.farthest);
        detectSeconds += seconds;
        oracleSeconds += c.oracleSeconds;
        if (seconds > slowest) {
            slowest = seconds;
            slowestSeed = seed;
        }
        if (c.matched < c.considered || report.openCount() > 0)
            std::printf("seed %u: %s: %zu of %zu oracle curves found, %zu open curve(s)\n%s", seed, t.choices.describe().c_str(),
                        c.matched, c.considered, report.openCount(), c.missed.c_str());
    }
    std::printf("textiles %u (fit refused %zu), tows %zu, loops %zu\n", count, failedToFit, tows, loops);
    if (oracle) {
        std::printf("overlapping pairs %zu; oracle curves longer than 1e-3 of the tow size: %zu, found by towgeom %zu, longest missed "
                    "%.3g x tow size\n",
                    pairs, considered, matched, longestMissed);
        std::printf("largest distance of a found oracle curve from its loop: %.3g x tow size\n", farthest);
    }
    std::printf("open curves: %zu in %zu textiles, %zu at a tow's end, %zu where the walk stops\n", open, withOpen, atEnds, walkStops);
    if (oracle) {
        std::printf("              towgeom_s    oracle_s      ratio\n");
        std::printf("detect      %10.3f  %10.3f  %9.1fx   (slowest textile: seed %u, %.3f s)\n", detectSeconds, oracleSeconds,
                    oracleSeconds / detectSeconds, slowestSeed, slowest);
    } else {
        std::printf("detect %.3f s (slowest textile: seed %u, %.3f s); the oracle not run (--no-oracle)\n", detectSeconds, slowestSeed,
                    slowest);
    }
    if (resolve) printResolveTally(tally);
    goals.require("every textile fits", failedToFit == 0);
    if (oracle) goals.require("every oracle curve longer than 1e-3 of the tow size is found", matched == considered);
    goals.require("every curve closes (across the tows' caps where it reaches an end)", open == 0);
    if (resolve) {
        goals.require("every textile resolves (no error)", tally.failed == 0);
        goals.require("no tow pair left unresolved", tally.unresolvedPairs == 0);
        goals.require("no two tows' output triangles cross", tally.crossing == 0);
        goals.require("every tow's output mesh is closed", tally.notClosed == 0);
    }
    return goals.exitStatus();
}
