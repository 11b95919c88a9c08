// towgeom export: the resolved tows' exact solids (trimmed B-rep) as STEP and/or BREP files.
#include <chrono>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "cli/args.hpp"
#include "cli/brep_output.hpp"
#include "cli/resolve_input.hpp"
#include "cli/stopwatch.hpp"
#include "cli/commands.hpp"
#include "cli/progress_printer.hpp"
#include "cli/tow_input.hpp"
#include "cli/unresolved_pairs.hpp"
#include "io/output_files.hpp"
#include "towgeom/towgeom.hpp"

namespace towgeom::cli {

namespace {

const char* kExportHelp = R"(Usage: towgeom export FILE.stw... (--step FILE | --brep FILE | both) [options]

Writes the resolved textile as exact solids for CAD-based finite-element tools (Abaqus/CAE,
ANSYS, Gmsh's OpenCASCADE kernel) and CAD: fits every tow, finds where tows interpenetrate and
resolves them by the rank rule as 'towgeom resolve --method connect' does (tows ranked by
--primary patterns, then command-line order; a tow gives way to every tow ranked above it), then
builds each tow as an OpenCASCADE solid: its B-spline face trimmed by its intersection loops (the
loops' (u,v) curves as the face's edges), the higher-ranked tow's face inside each loop shared
by both solids as one face, and planar end caps. Where three tows meet at a point, a loop goes
around a tow or across an end cap, or loops nest three deep, the solids come from OpenCASCADE's
general fuse of the whole tows by the same rank rule instead (slower; a note says so). With
--cell every tow is clipped to the box and the box minus the tows is one more solid, MATRIX.
Every solid is checked by OpenCASCADE's BRepCheck_Analyzer (a warning names any it refuses).
Writes, all or nothing:

  FILE (--step)  STEP AP214, one solid per tow named after it (a tow cut apart by a tow ranked
                 above it or by the box: a solid per piece, each of its name); your units
                 written as millimetres
  FILE (--brep)  the same compound in OpenCASCADE's BREP format, where the faces two solids
                 share stay one face of both (STEP keeps them as two equal faces)

The surface meshes that decide which tow gives way where are computed and not written ('towgeom
resolve --formats stl,vtk,step' writes both).

Options:
  --step FILE        write the STEP file (at least one of --step and --brep)
  --brep FILE        write the BREP file
  --primary GLOB     tows whose names match rank above tows that do not (repeatable; shell
                     patterns, e.g. --primary 'warp_*')
  --cell X0,Y0,Z0,X1,Y1,Z1 | --cell DIR/textile.json
                     clip every tow by this box and add the MATRIX solid (as 'towgeom resolve
                     --cell'; the faces must cut tows across, away from crossings)
  --periodic         with --cell: check that the textile repeats with the box, as 'towgeom
                     resolve --periodic' does (exit 2 where a tow's cuts on opposite faces
                     differ); the solids are the same either way. A --cell textile.json
                     marked periodic is checked so always
  --mesh-size H      edge length of the surface meshes that decide the regions (default: 0.1 x
                     each tow's own size); the solids' faces are exact whatever H is
  --mesh-deviation D grade those meshes by curvature, as resolve's --mesh-deviation
  --loop-spacing S   node spacing along intersection loops in those meshes (default: the
                     smaller mesh size of the loop's two tows)
  --tolerance T      intersection point tolerance (default: 1e-7 x the tow size)
  --report FILE      take the intersection loops from FILE ('towgeom detect --save-report FILE'
                     for the same tows in the same order) instead of intersecting again
  --max-triangles N  refuse (exit 2) meshes estimated at more than N triangles (default 20000000)
  --allow-open       exit 0 even when an intersection curve is open (still named on stderr);
                     with --cell the MATRIX solid is then not built (exit 3), and where the
                     general fuse is needed the open pair is refused (exit 2)
  --threads N        worker threads (default: all hardware threads)
  --quiet            no progress lines on stderr (warnings are always printed)
  -h, --help         this help

Exit status: 0 success; 3 a tow pair is unresolved (named on stderr; its two solids are written
and overlap there) or, with --cell, the MATRIX solid not built (a warning says why); 2 invalid
input or usage, or solids this version does not build (a non-planar end section; the general
fuse while a pair still overlaps): one line on stderr, nothing written; 1 a file could not be
written or an internal failure; 130 stopped by Ctrl-C or SIGTERM. A failed run leaves the files
as they were.

Examples:
  towgeom export examples/data/twill/*.stw --step twill.step
  towgeom generate --weave twill --tows 6x6 --overlap 0.08 --out weave
  towgeom export weave/*.stw --cell weave/textile.json --step cell.step --brep cell.brep
  (then mesh it: gmsh -3 cell.step, or import cell.step into Abaqus/CAE)
)";

}  // namespace

int runExport(int argc, char** argv, int first)
{
    try {
        const Args args(argc, argv, first,
                        {{"help"}, {"quiet"}, {"allow-open"}, {"step", true}, {"brep", true}, {"primary", true}, {"cell", true},
                         {"periodic"}, {"mesh-size", true}, {"mesh-deviation", true}, {"loop-spacing", true}, {"tolerance", true}, {"report", true},
                         {"max-triangles", true}, {"threads", true}});
        if (args.has("help")) {
            std::cout << kExportHelp;
            return kExitOk;
        }
        if (args.positional().empty()) throw UsageError("no input files");
        const std::optional<std::string> stepPath = args.value("step"), brepPath = args.value("brep");
        if (!stepPath && !brepPath) throw UsageError("nothing to write: give --step FILE and/or --brep FILE");
        // The same file however written (./, .., symbolic links); a path that cannot be resolved
        // is compared as written, made absolute (its write fails later, naming it).
        const auto where = [](const std::string& path) {
            const std::filesystem::path absolute = std::filesystem::absolute(path);
            std::error_code failed;
            const std::filesystem::path resolved = std::filesystem::weakly_canonical(absolute, failed);
            return failed ? absolute.lexically_normal() : resolved;
        };
        if (stepPath && brepPath && where(*stepPath) == where(*brepPath))
            throw UsageError("--step and --brep must name two different files, not '" + *stepPath + "' and '" + *brepPath + "'");
        ResolveOptions options;  // --method connect: the only one whose faces are the tows' B-splines
        readResolveOptions(args, options);
        const auto reportPath = args.value("report");
        const bool quiet = args.has("quiet");
        ProgressPrinter printer("export", quiet);
        options.monitor = &printer;

        const auto start = std::chrono::steady_clock::now();
        const std::vector<TowStack> stacks = readStacks(args.positional(), options.threads);
        const std::vector<TowSurface> tows = fitSurfaces(stacks, {}, "export", quiet, options.threads);
        const ResolveResult result = resolveExplained(tows, options, reportPath);
        const TrimmedBrep brep = buildTrimmedBrep("export", tows, result, printer, quiet);

        // Everything is computed before anything is written.
        detail::OutputFiles files;
        for (const std::optional<std::string>& p : {stepPath, brepPath}) {
            if (!p) continue;
            const std::filesystem::path parent = std::filesystem::path(*p).parent_path();
            if (!parent.empty()) files.makeDirectory(parent.string());
        }
        if (stepPath) brep.writeStep(files.open(*stepPath));
        if (brepPath) brep.writeBrep(files.open(*brepPath));
        printer.throwIfCancelled();  // a signal while writing: nothing is committed
        files.commit();

        std::string written = stepPath ? *stepPath : *brepPath;
        if (stepPath && brepPath) written += " and " + *brepPath;
        if (!quiet) {
            std::size_t kept = 0;  // tows with a solid (a tow cut apart has several)
            for (const BrepSolid& s : brep.solids()) kept += s.faces > 0 ? 1 : 0;
            std::cerr << "towgeom export: " << kept << (kept == 1 ? " tow" : " tows") << (brep.matrix().faces > 0 ? " and the MATRIX" : "")
                      << " as solids, " << brep.sharedFaceCount() << (brep.sharedFaceCount() == 1 ? " face" : " faces") << " shared by two tows, in " << msSince(start) / 1000.0
                      << " s; written to " << written << "\n";
        }
        const bool noMatrix = warnAboutBrep("export", brep, written);
        reportContacts("export", result, tows);
        const std::vector<UnresolvedPairEntry> unresolved = unresolvedPairs(result);
        reportUnresolved("export", unresolved, tows);
        return exitsUnresolved(unresolved, args.has("allow-open")) || noMatrix ? kExitUnresolved : kExitOk;
    } catch (const std::exception& e) {
        return reportError("export", e);
    }
}

}  // namespace towgeom::cli
