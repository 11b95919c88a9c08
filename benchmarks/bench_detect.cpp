// Intersection benchmark (issue 3): a 2/2 twill of 8 warps x 8 wefts with 0.08 overlap, 400
// sections x 64 points per tow (64 overlapping crossings). Times towgeom's whole detect
// pipeline (read the .stw files, fit, broad phase, exact SSI, consolidation) and, in the same
// run, CGAL's Polygon_mesh_processing::surface_intersection on the faceted tubes of every
// overlapping pair; prints both, their ratio and the loop counts. Goal: towgeom >= 4x faster.
//   bench_detect [--tows N] [--sections M] [--points P] [--threads T] [--no-cgal]
#include <towgeom/towgeom.hpp>

#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "cgal_reference.hpp"

namespace fs = std::filesystem;

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
    o.warps = o.wefts = 8;
    o.sectionsPerYarn = 400;
    o.pointsPerSection = 64;
    std::size_t threads = 2;
    bool cgal = true;
    for (int i = 1; i < argc; ++i) {
        const bool more = i + 1 < argc;
        if (!std::strcmp(argv[i], "--no-cgal")) cgal = false;
        else if (more && !std::strcmp(argv[i], "--tows")) o.warps = o.wefts = std::stoul(argv[++i]);
        else if (more && !std::strcmp(argv[i], "--sections")) o.sectionsPerYarn = std::stoul(argv[++i]);
        else if (more && !std::strcmp(argv[i], "--points")) o.pointsPerSection = std::stoul(argv[++i]);
        else if (more && !std::strcmp(argv[i], "--threads")) threads = std::stoul(argv[++i]);
        else {
            std::fprintf(stderr, "usage: bench_detect [--tows N] [--sections M] [--points P] [--threads T] [--no-cgal]\n");
            return 2;
        }
    }
    const towgeom::Textile textile = towgeom::generateWeave(o);
    const std::vector<towgeom::TowStack> stacks = textile.stacks();
    const fs::path dir = fs::temp_directory_path() / ("towgeom_bench_detect_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::vector<std::string> files;
    for (const towgeom::TowStack& s : stacks) {
        files.push_back((dir / (s.name + ".stw")).string());
        std::ofstream out(files.back());
        towgeom::writeStack(out, s);
    }
    std::printf("towgeom bench_detect: 2/2 twill, %zu tows of %zu sections x %zu points, %zu crossings, %zu threads\n",
                stacks.size(), o.sectionsPerYarn, o.pointsPerSection, textile.crossings.size(), threads);

    // towgeom, end to end.
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<towgeom::TowStack> read;
    for (const std::string& f : files) read.push_back(towgeom::readStackFile(f));
    const double tRead = since(t0);
    auto t1 = std::chrono::steady_clock::now();
    std::vector<towgeom::TowSurface> tows;
    for (const towgeom::TowStack& s : read) tows.push_back(towgeom::TowSurface::fit(s));
    const double tFit = since(t1);
    towgeom::IntersectionOptions options;
    options.threads = threads;
    const towgeom::IntersectionReport report = towgeom::intersectTows(tows, options);
    const double tTowgeom = since(t0);
    fs::remove_all(dir);
    std::size_t closed = report.loops.size() - report.openCount();
    std::printf("towgeom: %.3f s  (read %.3f, fit %.3f, broad phase %.3f, exact %.3f)\n", tTowgeom, tRead, tFit,
                report.timings.broadPhase / 1e3, report.timings.exact / 1e3);
    std::printf("         %zu loops (%zu closed), %zu of %zu tow pairs tested, %zu seeds, %zu walks\n", report.loops.size(),
                closed, report.pairsTested, report.towPairs, report.seeds, report.walks);

    if (cgal) {
        t1 = std::chrono::steady_clock::now();
        std::size_t cgalClosed = 0, cgalOpen = 0;
        for (const towgeom::Crossing& c : textile.crossings) {
            const auto p = towgeom::testing::surfaceIntersection(towgeom::facetedTube(stacks[c.warp], false),
                                                                 towgeom::facetedTube(stacks[c.weft], false));
            cgalClosed += p.closed;
            cgalOpen += p.open;
        }
        const double tCgal = since(t1);
        std::printf("CGAL surface_intersection, faceted tubes of the %zu overlapping pairs: %.3f s, %zu closed, %zu open\n",
                    textile.crossings.size(), tCgal, cgalClosed, cgalOpen);
        std::printf("%-10s %12s %12s %10s\n", "", "towgeom_s", "cgal_s", "ratio");
        std::printf("%-10s %12.3f %12.3f %9.1fx  (goal >= 4x)\n", "detect", tTowgeom, tCgal, tCgal / tTowgeom);
    }
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    std::printf("peak memory: %.1f MiB\n", usage.ru_maxrss / 1024.0);
    return closed == textile.crossings.size() ? 0 : 1;
}
