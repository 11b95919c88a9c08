// Stress benchmark of loop detection on the scan-like family (issue 38): N random scan-like
// textiles (tests/support/scan_like.hpp: pressed weaves voxelised and contoured back, starts
// drifting, cut by the scan box), each detected by towgeom and checked against the dense oracle
// (tests/support/dense_oracle.hpp: CGAL's surface_intersection of the same fitted surfaces
// tessellated at 8 x sections by 4 x points). Checks: every oracle curve longer than 1e-3 of
// the tow size is found, and every curve closes (across the tows' caps). Printed: the worst case
// of each statistic, the open curves by reason, and towgeom's time against the oracle's.
//   bench_scan_family [--count N] [--first SEED] [--smoke]
#include <towgeom/towgeom.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "bench_goal.hpp"
#include "dense_oracle.hpp"
#include "scan_like.hpp"
#include "synthetic_tows.hpp"

int main(int argc, char** argv)
{
    unsigned count = 500, first = 1;
    bool smoke = false;
    for (int k = 1; k < argc; ++k) {
        const std::string a = argv[k];
        if (a == "--smoke") smoke = true;
        else if (a == "--count" && k + 1 < argc) count = static_cast<unsigned>(std::stoul(argv[++k]));
        else if (a == "--first" && k + 1 < argc) first = static_cast<unsigned>(std::stoul(argv[++k]));
        else {
            std::fprintf(stderr, "usage: bench_scan_family [--count N] [--first SEED] [--smoke]\n");
            return 2;
        }
    }
    towgeom::bench::Goals goals(smoke);
    std::printf("towgeom bench_scan_family: %u scan-like textiles from seed %u\n", count, first);
    std::size_t atEnds = 0, walkStops = 0;  // open curves by reason
    std::size_t tows = 0, loops = 0, open = 0, pairs = 0, considered = 0, matched = 0, withOpen = 0, failedToFit = 0;
    double longestMissed = 0.0, farthest = 0.0, detectSeconds = 0.0, oracleSeconds = 0.0, slowest = 0.0;
    unsigned slowestSeed = 0;
    for (unsigned seed = first; seed < first + count; ++seed) {
        const towgeom::testing::ScanLikeTextile t = towgeom::testing::scanLikeTextile(seed);
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
        const towgeom::testing::TextileOracleComparison c = towgeom::testing::compareTextileWithOracle(fitted, report);
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
    std::printf("textiles %u (fit refused %zu), tows %zu, overlapping pairs %zu, loops %zu\n", count, failedToFit, tows, pairs, loops);
    std::printf("oracle curves longer than 1e-3 of the tow size: %zu, found by towgeom %zu, longest missed %.3g x tow size\n", considered,
                matched, longestMissed);
    std::printf("largest distance of a found oracle curve from its loop: %.3g x tow size\n", farthest);
    std::printf("open curves: %zu in %zu textiles, %zu at a tow's end, %zu where the walk stops\n", open, withOpen, atEnds, walkStops);
    std::printf("              towgeom_s    oracle_s      ratio\n");
    std::printf("detect      %10.3f  %10.3f  %9.1fx   (slowest textile: seed %u, %.3f s)\n", detectSeconds, oracleSeconds,
                oracleSeconds / detectSeconds, slowestSeed, slowest);
    goals.require("every textile fits", failedToFit == 0);
    goals.require("every oracle curve longer than 1e-3 of the tow size is found", matched == considered);
    goals.require("every curve closes (across the tows' caps where it reaches an end)", open == 0);
    return goals.exitStatus();
}
