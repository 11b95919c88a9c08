// Collision detection benchmark (issue 5): a 2/2 twill of 4 x 4 yarns with 0.08 overlap,
// 200 sections x 48 points per yarn. Times the hierarchy (CGAL box intersection + exact tests)
// on the whole textile and, for a few yarn pairs, the hierarchy against brute force (every
// triangle pair) on the same pairs, and prints the ratio. Goal: hierarchy >= 10x faster; exits 3
// when it is missed (bench_goal.hpp; --smoke: the ratio is only required to be measured).
//   bench_collision [--sections M] [--points N] [--pairs K] [--smoke]
#include <towgeom/towgeom.hpp>

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

#include "bench_goal.hpp"

namespace {
double since(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

int main(int argc, char** argv)
{
    towgeom::WeaveOptions o;
    o.kind = towgeom::WeaveKind::Twill;
    o.overlap = 0.08;
    o.sectionsPerYarn = 200;
    o.pointsPerSection = 48;
    std::size_t pairs = 2;
    bool smoke = false;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--smoke")) smoke = true;
        else if (i + 1 == argc) break;
        else if (!std::strcmp(argv[i], "--sections")) o.sectionsPerYarn = std::stoul(argv[++i]);
        else if (!std::strcmp(argv[i], "--points")) o.pointsPerSection = std::stoul(argv[++i]);
        else if (!std::strcmp(argv[i], "--pairs")) pairs = std::stoul(argv[++i]);
    }
    towgeom::bench::Goals goals(smoke);
    const towgeom::Textile textile = towgeom::generateWeave(o);
    const std::vector<towgeom::TowStack> stacks = textile.stacks();
    std::printf("towgeom bench_collision: 2/2 twill, %zu yarns of %zu sections x %zu points (%zu triangles each)\n",
                stacks.size(), o.sectionsPerYarn, o.pointsPerSection, 2 * (o.sectionsPerYarn - 1) * o.pointsPerSection);

    auto t0 = std::chrono::steady_clock::now();
    const towgeom::CollisionReport all = towgeom::detectCollisions(stacks);
    std::printf("hierarchy, whole textile: %.3f s, %zu colliding yarn pairs, %zu triangle pairs, %zu exact tests\n",
                since(t0), all.collisions.size(), all.trianglePairCount(), all.trianglePairsTested);

    // The same yarn pairs both ways: colliding crossings first, then a parallel neighbour pair.
    std::vector<std::pair<std::size_t, std::size_t>> chosen;
    for (const auto& c : all.collisions)
        if (chosen.size() + 1 < pairs) chosen.emplace_back(c.yarnA, c.yarnB);
    chosen.emplace_back(0, 1);
    double fast = 0.0, brute = 0.0;
    bool same = true;
    std::printf("%-18s %12s %12s %10s %8s\n", "pair", "hierarchy_s", "brute_s", "ratio", "same");
    for (const auto& [a, b] : chosen) {
        const std::vector<towgeom::TowStack> two{stacks[a], stacks[b]};
        t0 = std::chrono::steady_clock::now();
        const auto h = towgeom::detectCollisions(two, towgeom::CollisionMethod::Hierarchy);
        const double th = since(t0);
        t0 = std::chrono::steady_clock::now();
        const auto f = towgeom::detectCollisions(two, towgeom::CollisionMethod::BruteForce);
        const double tb = since(t0);
        const bool equal = h.trianglePairCount() == f.trianglePairCount() &&
                           (h.collisions.empty() || h.collisions[0].triangles == f.collisions[0].triangles);
        same = same && equal;
        fast += th;
        brute += tb;
        std::printf("%-18s %12.4f %12.3f %10.0f %8s\n", (stacks[a].name + "/" + stacks[b].name).c_str(), th, tb, tb / th,
                    equal ? "yes" : "NO");
    }
    std::printf("total on these pairs: hierarchy %.4f s, brute force %.3f s, ratio %.0fx (goal >= 10x), identical: %s\n",
                fast, brute, brute / fast, same ? "yes" : "NO");
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    std::printf("peak memory: %.1f MiB\n", static_cast<double>(usage.ru_maxrss) / 1024.0);
    goals.ratioAtLeast("hierarchy vs brute force", brute / fast, 10.0);
    goals.require("hierarchy and brute force find the same triangle pairs", same);
    return goals.exitStatus();
}
