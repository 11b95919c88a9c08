// Intersection benchmark (issue 3): a 2/2 twill of 8 warps x 8 wefts with 0.08 overlap, 400
// sections x 64 points per tow (64 overlapping crossings). Times `towgeom detect` end to end on
// the .stw files (read, fit, broad phase, exact SSI, consolidation, JSON) and, in the same
// run, CGAL's Polygon_mesh_processing::surface_intersection on the faceted tubes of every
// overlapping pair; prints both, their ratio and the loop counts. Goal: towgeom >= 4x faster;
// exits 3 when it is missed (bench_goal.hpp; --smoke: the ratio is only required to be measured).
//   bench_detect [--tows N] [--sections M] [--points P] [--threads T] [--no-cgal] [--smoke]
#include <towgeom/towgeom.hpp>

#include "bench_goal.hpp"
#include "bench_twill.hpp"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <cstdlib>
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
    const towgeom::bench::TwillArgs args = towgeom::bench::parseTwillArgs(argc, argv);
    const towgeom::WeaveOptions& o = args.weave;
    const std::size_t threads = static_cast<std::size_t>(args.number("--threads", 2));
    const bool cgal = !args.flag("--no-cgal");
    towgeom::bench::Goals goals(args.flag("--smoke"));
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

    // towgeom, end to end: the command-line tool on the files, as a user runs it.
    const fs::path json = dir / "loops.json";
    std::string command = std::string("'") + TOWGEOM_CLI + "' detect";
    for (const std::string& f : files) command += " '" + f + "'";
    command += " --quiet --threads " + std::to_string(threads) + " > '" + json.string() + "'";
    const auto t0 = std::chrono::steady_clock::now();
    const int status = std::system(command.c_str());
    const double tTowgeom = since(t0);
    std::ifstream in(json);
    const std::string out((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    fs::remove_all(dir);
    const auto count = [&](const std::string& what) {
        std::size_t n = 0;
        for (auto at = out.find(what); at != std::string::npos; at = out.find(what, at + 1)) ++n;
        return n;
    };
    const auto number = [&](const std::string& key) {
        const auto at = out.find("\"" + key + "\":");
        return at == std::string::npos ? -1.0 : std::atof(out.c_str() + at + key.size() + 3);
    };
    const std::size_t closed = count("\"closed\":true"), open = count("\"closed\":false");
    std::printf("towgeom detect (exit %d): %.3f s  (inside: read %.3f, fit %.3f, broad phase %.3f, exact %.3f)\n",
                WEXITSTATUS(status), tTowgeom, number("read") / 1e3, number("fit") / 1e3, number("broad_phase") / 1e3,
                number("exact") / 1e3);
    std::printf("         %zu closed and %zu open loops, %.0f of %.0f tow pairs tested, %.0f seeds, %.0f walks\n", closed,
                open, number("pairs_tested"), number("tow_pairs"), number("seeds"), number("walks"));

    if (cgal) {
        const auto t1 = std::chrono::steady_clock::now();
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
        // The peer checked before its time is compared: every crossing of the generated twill
        // overlaps, so CGAL too must find one closed curve per crossing and no open one.
        goals.require("CGAL finds one closed curve per crossing", cgalClosed == textile.crossings.size() && cgalOpen == 0);
        goals.ratioAtLeast("detect vs CGAL", tCgal / tTowgeom, 4.0);
    } else {
        std::printf("no CGAL run (--no-cgal): the ratio goal is not checked\n");
    }
    rusage usage{};
    getrusage(RUSAGE_CHILDREN, &usage);
    std::printf("peak memory of towgeom detect: %.1f MiB\n", usage.ru_maxrss / 1024.0);
    goals.require("towgeom detect exits 0", status == 0);
    goals.require("one closed loop per crossing", closed == textile.crossings.size() && open == 0);
    return goals.exitStatus();
}
