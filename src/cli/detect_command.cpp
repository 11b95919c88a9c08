// towgeom detect: fit the tows, find every interpenetration as an intersection loop, print JSON.
#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/tow_input.hpp"
#include "cli/progress_printer.hpp"
#include "cli/stopwatch.hpp"
#include "cli/unresolved_pairs.hpp"
#include "towgeom/towgeom.hpp"

namespace towgeom::cli {

namespace {

const char* kDetectHelp = R"(Usage: towgeom detect FILE.stw... [options]

Fits a surface to every tow (as 'towgeom fit' does), finds where the tows interpenetrate and
prints one JSON object on stdout with one entry per intersection curve:

  {"loops":[{"tow_a", "tow_b", "closed", "open_reason", "length", "area_a", "area_b",
             "max_distance", "point_count", "points"}],
   "findings":[{"tow_a", "tow_b", "kind", "message"}],
   "tow_pairs", "pairs_tested", "window_pairs", "seeds", "walks",
   "timings_ms":{"read", "fit", "broad_phase", "exact", "total"}}

  closed        true for a loop around an interpenetration region; false for a curve that
                cannot be closed (a tow ends inside the other, the surfaces are tangent)
  length        length of the curve
  area_a/b      area of tow a's / b's surface inside the loop (null when open, or when the
                loop goes around the tow)
  max_distance  largest distance of a curve point from either surface (<= the tolerance)
  points        [x,y,z] along the curve, exact intersection points (the first is not
                repeated for a closed loop); spaced by --spacing when given
  pairs_tested  tow pairs whose bounding boxes (per span of the surfaces) overlap; only
                these go to the exact surface-surface intersection
  findings      pairs that meet without an intersection curve: "touching" (surfaces tangent
                or coincident, e.g. identical tows) or "nested" (one tow inside the other):
                complete overlaps, unresolved pairs (exit 3, named on stderr); "contact"
                (closed curves enclosing no area: the surfaces touch along a line; not
                unresolved); "incomplete" (the search for loops stopped at its budget where
                the surfaces nearly touch over a wide area: a loop may be missing; unresolved)

Options:
  --tolerance T       largest distance of a curve point from either surface, in the input's
                      units (default: 1e-7 x the tow size, the mean perimeter / pi)
  --chordal C         largest distance of the curve from a chord between its points
                      (default: 1e-4 x the tow size)
  --spacing S         print points spaced at most S apart along each curve instead
  --save-report FILE  also write the exact intersection report to FILE (every curve point
                      with its (u,v) on both tows; written whole or not at all), for
                      'towgeom resolve --report FILE' with the same tows in the same order:
                      one intersection, many meshes
  --allow-open        exit 0 even when a curve is open (still named on stderr and reported in
                      the JSON); nested, identical or touching tows still exit 3
  --threads N         worker threads for reading, fitting and intersecting (default: all
                      hardware threads)
  --quiet             no progress lines on stderr (warnings are always printed)
  -h, --help          this help

Tows are closed solids: a curve that runs into a tow's end continues across that tow's end cap
(its points there have u beyond the tube's range), across both caps where both tows end inside
each other, so it closes; it stays open only where both tows end in one plane (caps face to
face) or the walk cannot go on.

Exit status: 0 every curve is closed and no tows overlap without one; 3 a tow pair is
unresolved: a curve is open (unless --allow-open), or two tows overlap with no curve (one inside
the other, identical or touching). One stderr line per such pair, also with --quiet:
  towgeom detect: unresolved tow pair 'a' and 'b': MESSAGE [open_curve|nested|identical_or_touching|search_incomplete]
and the JSON is printed all the same. 2 invalid input or usage (one line on stderr naming file
and line); 1 internal failure; 130 stopped by Ctrl-C or SIGTERM (nothing printed or written).

Examples:
  towgeom detect examples/data/twill/*.stw > loops.json
  towgeom detect examples/data/twill/*.stw --save-report twill.loops.json > /dev/null
  towgeom resolve examples/data/twill/*.stw --report twill.loops.json --mesh-size 0.05 --out h05
)";

}  // namespace

int runDetect(int argc, char** argv, int first)
{
    try {
        const Args args(argc, argv, first,
                        {{"help"}, {"quiet"}, {"allow-open"}, {"tolerance", true}, {"chordal", true}, {"spacing", true},
                         {"threads", true}, {"save-report", true}});
        if (args.has("help")) {
            std::cout << kDetectHelp;
            return kExitOk;
        }
        if (args.positional().empty()) throw UsageError("no input files");
        IntersectionOptions options;
        options.tolerance = args.positive("tolerance");
        options.chordalTolerance = args.positive("chordal");
        options.threads = args.threads();
        const double spacing = args.positive("spacing");
        const bool quiet = args.has("quiet");

        const auto start = std::chrono::steady_clock::now();
        const std::vector<TowStack> stacks = readStacks(args.positional(), options.threads);
        const double readMs = msSince(start);
        const auto fitStart = std::chrono::steady_clock::now();
        const std::vector<TowSurface> surfaces = fitSurfaces(stacks, {}, "detect", quiet, options.threads);
        const double fitMs = msSince(fitStart);

        ProgressPrinter printer("detect", quiet);
        options.monitor = &printer;
        const IntersectionReport report = intersectTows(surfaces, options);
        printer.throwIfCancelled();
        if (const auto path = args.value("save-report")) writeIntersectionReport(report, surfaces, *path);

        std::ostringstream out;
        DetectReportOptions written;
        written.spacing = spacing;
        written.threads = options.threads;
        written.times.read = readMs;
        written.times.fit = fitMs;
        written.times.total = msSince(start);
        writeDetectReport(report, surfaces, out, written);
        std::cout << out.str();

        if (!quiet)
            std::cerr << "towgeom detect: " << report.loops.size() << " intersection curves (" << report.openCount()
                      << " open) among " << report.pairsTested << " candidate tow pairs\n";
        // Warnings, not progress: printed whatever --quiet says.
        const std::vector<UnresolvedPairEntry> unresolved = unresolvedPairs(report);
        reportContacts("detect", report, surfaces);
        reportUnresolved("detect", unresolved, surfaces);
        return exitsUnresolved(unresolved, args.has("allow-open")) ? kExitUnresolved : kExitOk;
    } catch (const std::exception& e) {
        return reportError("detect", e);
    }
}

}  // namespace towgeom::cli
