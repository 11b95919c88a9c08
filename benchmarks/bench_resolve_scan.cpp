// Resolve benchmark on a textile of the kind real scans give (issue 12): a pressed 3D orthogonal
// weave, 7 x 7 tows in 3 warp layers, 4 weft layers and binders (55 tows), flat racetrack
// sections of 0.9 x 0.2 whose flat faces touch with no gap (--overlap 0), 30 sections x 32
// points per tow as a scan's hand-traced slices: the fitted surfaces cross each other a little
// over every contact, about 6 shallow, wide, partly nested loops per crossing, ~1600 loops.
// (--tows 8 --overlap 0.15: 63 tows pressed 15 % into each other, ~540 loops, one per crossing.)
//
// Times `towgeom resolve` end to end (stage times from its report, peak memory of the process)
// and `towgeom detect`, and in the same run CGAL's Polygon_mesh_processing::surface_intersection
// on the faceted tubes of every tow pair whose boxes overlap (the discrete peer). Goals: resolve
// <= 60 s and <= 2 GiB on 2 cores; detect >= 2x faster than CGAL. Exits 3 when one is missed
// (bench_goal.hpp; --smoke: measured, not held).
//   bench_resolve_scan [--tows N] [--layers L] [--overlap F] [--sections M] [--points P] [--threads T] [--smoke]
#include <towgeom/towgeom.hpp>

#include "bench_goal.hpp"
#include "bench_twill.hpp"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <utility>

#include "cgal_reference.hpp"

namespace fs = std::filesystem;

namespace {

double since(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::pair<std::string, std::string> orderedPair(const std::string& a, const std::string& b)
{
    return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
}

/// The tow pairs of `towgeom detect`'s loops ("tow_a":"...","tow_b":"...").
std::set<std::pair<std::string, std::string>> loopPairs(const std::string& json)
{
    std::set<std::pair<std::string, std::string>> pairs;
    const std::string keyA = "\"tow_a\":\"", keyB = "\"tow_b\":\"";
    for (auto at = json.find(keyA); at != std::string::npos; at = json.find(keyA, at + 1)) {
        const auto a0 = at + keyA.size(), a1 = json.find('"', a0);
        const auto b0 = json.find(keyB, a1) + keyB.size(), b1 = json.find('"', b0);
        pairs.insert(orderedPair(json.substr(a0, a1 - a0), json.substr(b0, b1 - b0)));
    }
    return pairs;
}

std::string slurp(const fs::path& p)
{
    std::ifstream in(p);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

/// The number after "key": in @p json (the last one: the report's totals come last), or -1.
double number(const std::string& json, const std::string& key)
{
    const auto at = json.rfind("\"" + key + "\":");
    return at == std::string::npos ? -1.0 : std::atof(json.c_str() + at + key.size() + 3);
}

std::size_t count(const std::string& text, const std::string& what)
{
    std::size_t n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

/// Peak resident memory of the children waited for so far, in MiB.
double childrenPeakMiB()
{
    rusage usage{};
    getrusage(RUSAGE_CHILDREN, &usage);
    return usage.ru_maxrss / 1024.0;
}

}  // namespace

int main(int argc, char** argv)
{
    towgeom::bench::TwillArgs args = towgeom::bench::parseTwillArgs(argc, argv);
    towgeom::WeaveOptions o = args.weave;
    o.kind = towgeom::WeaveKind::Orthogonal;
    o.layers = static_cast<std::size_t>(args.number("--layers", 3));
    o.shape = towgeom::SectionShape::Racetrack;
    o.overlap = args.number("--overlap", 0.0);
    o.width = 0.9;
    bool towsGiven = false;
    for (int k = 1; k < argc; ++k) towsGiven = towsGiven || std::string(argv[k]) == "--tows";
    if (!towsGiven) o.warps = o.wefts = 7;
    if (!args.other.count("--sections") && o.sectionsPerYarn == 400) o.sectionsPerYarn = 30;
    if (!args.other.count("--points") && o.pointsPerSection == 64) o.pointsPerSection = 32;
    const std::size_t threads = static_cast<std::size_t>(args.number("--threads", 2));
    towgeom::bench::Goals goals(args.flag("--smoke"));

    const towgeom::Textile textile = towgeom::generateWeave(o);
    const std::vector<towgeom::TowStack> stacks = textile.stacks();
    const fs::path dir = fs::temp_directory_path() / ("towgeom_bench_resolve_scan_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::string files;
    for (const towgeom::TowStack& s : stacks) {
        const fs::path f = dir / (s.name + ".stw");
        std::ofstream out(f);
        towgeom::writeStack(out, s);
        files += " '" + f.string() + "'";
    }
    std::printf("towgeom bench_resolve_scan: pressed 3D orthogonal weave, %zu tows (%zu x %zu, %zu layers) of %zu sections x %zu "
                "points, racetrack 0.9 x 0.2, overlap %g, %zu threads\n",
                stacks.size(), o.warps, o.wefts, o.layers, o.sectionsPerYarn, o.pointsPerSection, o.overlap, threads);

    // 1. towgeom resolve, end to end, as a user runs it.
    const std::string resolve = std::string("'") + TOWGEOM_CLI + "' resolve" + files + " --out '" + (dir / "out").string() +
                                "' --threads " + std::to_string(threads) + " --formats stl,vtk --quiet 2> '" +
                                (dir / "resolve.err").string() + "'";
    auto t0 = std::chrono::steady_clock::now();
    const int resolveStatus = std::system(resolve.c_str());
    const double resolveWall = since(t0);
    const double resolvePeak = childrenPeakMiB();
    const std::string report = slurp(dir / "out" / "report.json");
    std::printf("towgeom resolve (exit %d): %.1f s, peak memory %.0f MiB\n", WEXITSTATUS(resolveStatus), resolveWall, resolvePeak);
    std::printf("  stages (s): read %.2f, fit %.2f, intersect %.2f, mesh %.2f, regions %.2f, write %.2f\n",
                number(report, "read") / 1e3, number(report, "fit") / 1e3, number(report, "intersect") / 1e3,
                number(report, "mesh") / 1e3, number(report, "regions") / 1e3, number(report, "write") / 1e3);
    const std::size_t loops = count(report, "\"closed\":");
    const std::size_t regions = count(report, "\"volume_removed\":");
    const auto from = report.find("\"unresolved\":[");
    const bool none = from == std::string::npos || report.compare(from, 15, "\"unresolved\":[]") == 0;
    const std::string unresolved = none ? "" : report.substr(from, report.find("}]", from) + 2 - from);
    std::printf("  %zu loops, %zu regions, %zu unresolved pairs (%zu winds_around, %zu loops_meet, %zu mesh_failed), "
                "%zu contact findings; %.0f triangles, smallest angle %.1f deg\n",
                loops, regions, count(unresolved, "\"reason\":\""), count(unresolved, "\"reason\":\"winds_around\""),
                count(unresolved, "\"reason\":\"loops_meet\""), count(unresolved, "\"reason\":\"mesh_failed\""),
                count(report, "\"kind\":\"contact\""), number(report, "triangles"), number(report, "min_angle_deg"));
    goals.require("resolve wrote its report (exit 0 or 3)",
                  !report.empty() && (WEXITSTATUS(resolveStatus) == 0 || WEXITSTATUS(resolveStatus) == 3));
    goals.require("every tow closed by its caps", count(report, "\"boundary_loops\":0") == stacks.size());
    goals.secondsAtMost("resolve", resolveWall, 60.0);
    goals.require("resolve peak memory <= 2048 MiB", resolvePeak <= 2048.0);

    // 2. towgeom detect, end to end, against CGAL on the faceted tubes of every pair whose boxes
    //    overlap.
    const std::string detect = std::string("'") + TOWGEOM_CLI + "' detect" + files + " --quiet --threads " +
                               std::to_string(threads) + " > '" + (dir / "loops.json").string() + "' 2>/dev/null";
    t0 = std::chrono::steady_clock::now();
    const int detectStatus = std::system(detect.c_str());
    const double detectWall = since(t0);
    const std::string loopsJson = slurp(dir / "loops.json");
    fs::remove_all(dir);
    std::printf("towgeom detect (exit %d): %.2f s (exact stage %.2f s), %zu closed curves\n", WEXITSTATUS(detectStatus), detectWall,
                number(loopsJson, "exact") / 1e3, count(loopsJson, "\"closed\":true"));

    std::vector<towgeom::TriangleMesh> faceted;
    std::vector<towgeom::BoundingBox> boxes;
    for (const towgeom::TowStack& s : stacks) {
        faceted.push_back(towgeom::facetedTube(s, false));
        towgeom::BoundingBox b;
        for (const towgeom::Point3& p : faceted.back().vertices) b.add(p);
        boxes.push_back(b);
    }
    t0 = std::chrono::steady_clock::now();
    std::size_t pairs = 0, cgalClosed = 0, cgalOpen = 0;
    std::set<std::pair<std::string, std::string>> cgalPairs;
    for (std::size_t i = 0; i < stacks.size(); ++i)
        for (std::size_t j = i + 1; j < stacks.size(); ++j) {
            if (!boxes[i].overlaps(boxes[j])) continue;
            ++pairs;
            const auto p = towgeom::testing::surfaceIntersection(faceted[i], faceted[j]);
            cgalClosed += p.closed;
            cgalOpen += p.open;
            if (p.closed + p.open > 0) cgalPairs.insert(orderedPair(stacks[i].name, stacks[j].name));
        }
    const double cgalWall = since(t0);
    std::printf("CGAL surface_intersection, faceted tubes of the %zu pairs whose boxes overlap: %.2f s, %zu closed, %zu open "
                "curves on %zu pairs\n",
                pairs, cgalWall, cgalClosed, cgalOpen, cgalPairs.size());
    // The peer checked before its time is compared: both must find the same tow pairs
    // intersecting. (Curve counts are no common measure here: the faceted tubes are open at the
    // tows' ends, where towgeom closes its loops across the caps, and CGAL's polylines break
    // wherever pressed flat faces are coplanar.)
    // A pair only towgeom finds: the fitted surfaces are not the faceted tubes (they bulge between
    // the traced points and sections, up to a third of the thickness over the binders' bends).
    // Such a pair must either have faceted tubes that touch (CGAL's least triangle distance within
    // 1 % of the tows' thickness, 0.2), or the same fitted surfaces, tessellated densely (8 x the
    // sections by 4 x the points), must intersect in CGAL's surface_intersection.
    const std::set<std::pair<std::string, std::string>> towgeomPairs = loopPairs(loopsJson);
    std::map<std::string, std::size_t> index;
    for (std::size_t i = 0; i < stacks.size(); ++i) index[stacks[i].name] = i;
    const double touching = 0.01 * 0.2;
    std::size_t onlyCgal = 0, onlyTowgeom = 0, onlyTowgeomApart = 0, onlyTowgeomUnconfirmed = 0;
    double farthest = 0.0;
    for (const auto& p : cgalPairs) onlyCgal += !towgeomPairs.count(p);
    for (const auto& p : towgeomPairs) {
        if (cgalPairs.count(p)) continue;
        ++onlyTowgeom;
        const double d = towgeom::testing::minimumDistance(faceted[index.at(p.first)], faceted[index.at(p.second)], 0.2);
        farthest = std::max(farthest, d);
        if (d <= touching) continue;
        ++onlyTowgeomApart;
        const auto dense = [&](const std::string& name) {
            const towgeom::TowStack& s = stacks[index.at(name)];
            return towgeom::TowSurface::fit(s).tessellate(8 * s.sections.size(), 4 * s.sections.front().size());
        };
        const auto q = towgeom::testing::surfaceIntersection(dense(p.first), dense(p.second));
        if (q.closed + q.open == 0) ++onlyTowgeomUnconfirmed;
    }
    std::printf("intersecting tow pairs: towgeom %zu, CGAL %zu; %zu only CGAL's, %zu only towgeom's (%zu of them with faceted "
                "tubes further apart than %g, the farthest %g; of those, %zu whose densely tessellated fitted surfaces CGAL finds apart)\n",
                towgeomPairs.size(), cgalPairs.size(), onlyCgal, onlyTowgeom, onlyTowgeomApart, touching, farthest,
                onlyTowgeomUnconfirmed);
    goals.require("towgeom detect exits 0", WEXITSTATUS(detectStatus) == 0);
    goals.require("every pair CGAL finds intersecting, towgeom finds too", onlyCgal == 0 && !cgalPairs.empty());
    goals.require("every pair only towgeom finds touches, or intersects densely tessellated", onlyTowgeomUnconfirmed == 0);
    std::printf("%-10s %12s %12s %10s\n", "", "towgeom_s", "cgal_s", "ratio");
    std::printf("%-10s %12.2f %12.2f %9.2fx  (goal >= 2x)\n", "detect", detectWall, cgalWall, cgalWall / detectWall);
    goals.ratioAtLeast("detect vs CGAL", cgalWall / detectWall, 2.0);
    return goals.exitStatus();
}
