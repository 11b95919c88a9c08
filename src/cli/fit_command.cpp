// towgeom fit: read stacks, fit surfaces, report their accuracy as JSON, optionally write VTK.
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/tow_input.hpp"
#include "cli/json_text.hpp"
#include "io/output_files.hpp"
#include "towgeom/towgeom.hpp"

namespace towgeom::cli {

namespace {

const char* kFitHelp = R"(Usage: towgeom fit FILE.stw... [options]

Fits a bicubic B-spline surface to every tow stack (open along the tow, periodic and C2 around
it, normals pointing out of the tow) and prints one JSON object on stdout:

  {"tows":[{"name", "mode", "sections", "points", "control_points", "max_deviation",
            "rms_deviation", "volume", "faceted_volume", "area", "reversed",
            "shifted_sections", "start_shifts"}]}

  max_deviation, rms_deviation  closest-point distances of the input points from the surface
  volume          the surface's volume, closed at its ends by the end sections (exact quadrature)
  faceted_volume  the volume of the input polygons joined by flat facets, for comparison
  control_points  the surface's control points along and around the tow
  reversed        true when the input went counter-clockwise and was reversed for the fit
  start_shifts    per section, how many places its points were renumbered cyclically so that
                  it matches the previous section point by point (hand-traced sections whose
                  first point drifts around the tow): point j of section i on the surface is
                  its input point (j + shift) mod N, counted backwards from the first point
                  when reversed. The seam runs through the first input point of section 1 and
                  of every section with shift 0. Input that no shift makes consistent is
                  refused [inconsistent_start].
  shifted_sections  how many sections have a shift other than 0

Options:
  --mode M        interpolate (default): the surface passes through every input point;
                  approximate: least squares within --tolerance (fewer control points);
                  controlnet: input points as control points (the original SISL method,
                  ~0.5 % volume loss; for comparison)
  --tolerance T   approximate only: largest distance of an input point from the surface, in
                  the input's units (default: 1e-3 x the tow size, the mean perimeter / pi)
  --out DIR       also write DIR/NAME.vtk for every tow: the surface tessellated for ParaView
                  (legacy VTK polydata with normals). Files appear only if every tow succeeds.
  --samples U,V   tessellation density for --out: U stations along, V around
                  (default: 3 per section interval along, 3 per input point around)
  --max-triangles N  refuse (exit 2, before fitting) tessellations of more than N triangles,
                  2 (U - 1) V per tow, all tows together (default 20000000)
  --bezier        with --out, also DIR/NAME_bezier.json per tow for isogeometric analysis:
                  the tube's B-spline (degrees, knots, control points of its basis, periodic
                  around the tow) and every knot-span element as a Bezier patch with its
                  extraction operator C_e (Borden et al. 2011) and Bezier control points
                  (library: extractBezier(), writeBezierJson())
  --quiet         no progress lines on stderr
  -h, --help      this help

Exit status: 0 success; 2 invalid input or usage (one line on stderr naming file and line),
or a tessellation over --max-triangles; 1 an output file could not be written, or an internal
failure (a failed run leaves DIR exactly as it was).

Examples:
  towgeom fit examples/data/*.stw --out fitted/ > fit.json
  towgeom fit examples/data/twill/warp_0.stw --out iga/ --bezier > /dev/null
)";

struct Samples {
    std::size_t u = 0, v = 0;  // 0: automatic
};

Samples parseSamples(const std::optional<std::string>& text)
{
    Samples s;
    if (!text) return s;
    const auto comma = text->find(',');
    try {
        if (comma == std::string::npos) throw std::invalid_argument("no comma");
        std::size_t used = 0;
        const long u = std::stol(text->substr(0, comma), &used);
        if (used != comma) throw std::invalid_argument("u");
        const std::string vs = text->substr(comma + 1);
        const long v = std::stol(vs, &used);
        if (used != vs.size()) throw std::invalid_argument("v");
        if (u < 2 || v < 3 || u > 100000 || v > 100000) throw std::out_of_range("range");
        s.u = static_cast<std::size_t>(u);
        s.v = static_cast<std::size_t>(v);
    } catch (const std::logic_error&) {
        throw UsageError("--samples needs U,V with U >= 2 and V >= 3, e.g. --samples 200,48");
    }
    return s;
}

FitMode parseMode(const std::optional<std::string>& text)
{
    if (!text || *text == "interpolate") return FitMode::Interpolate;
    if (*text == "approximate") return FitMode::Approximate;
    if (*text == "controlnet") return FitMode::ControlNet;
    throw UsageError("--mode must be interpolate, approximate or controlnet, not '" + *text + "'");
}

}  // namespace

int runFit(int argc, char** argv, int first)
{
    try {
        const Args args(argc, argv, first,
                        {{"help"}, {"quiet"}, {"mode", true}, {"tolerance", true}, {"out", true}, {"samples", true},
                         {"max-triangles", true}, {"bezier"}});
        if (args.has("help")) {
            std::cout << kFitHelp;
            return kExitOk;
        }
        if (args.positional().empty()) throw UsageError("no input files");
        FitOptions options;
        options.mode = parseMode(args.value("mode"));
        if (const auto tol = args.number("tolerance")) {
            if (options.mode != FitMode::Approximate) throw UsageError("--tolerance applies to --mode approximate only");
            if (!(*tol > 0.0)) throw UsageError("--tolerance must be positive");
            options.tolerance = *tol;
        }
        const Samples samples = parseSamples(args.value("samples"));
        const auto outDir = args.value("out");
        if (!outDir && args.has("samples")) throw UsageError("--samples applies to --out only");
        if (!outDir && args.has("max-triangles")) throw UsageError("--max-triangles applies to --out only");
        const bool bezier = args.has("bezier");
        if (!outDir && bezier) throw UsageError("--bezier writes files: it needs --out DIR");
        const std::size_t maxTriangles = args.maxTriangles(MeshOptions{}.maxTriangles);
        const bool quiet = args.has("quiet");

        // Read everything first: one bad file stops the run before anything is written.
        const std::vector<TowStack> stacks = readStacks(args.positional());
        // The tessellation's size, before any of it is made: nu x nv vertices, 2 (nu - 1) nv triangles per tow.
        const auto stations = [&](const TowStack& s) {
            return std::make_pair(samples.u ? samples.u : 3 * (s.sectionCount() - 1) + 1, samples.v ? samples.v : 3 * s.pointsPerSection());
        };
        if (outDir) {
            double triangles = 0.0;
            for (const TowStack& s : stacks) {
                const auto [nu, nv] = stations(s);
                triangles += 2.0 * static_cast<double>(nu - 1) * static_cast<double>(nv);
            }
            if (triangles > static_cast<double>(maxTriangles)) {
                std::ostringstream message;
                message << "the tessellations for --out would have " << static_cast<unsigned long long>(triangles)
                        << " triangles (2 (U - 1) V per tow, " << stacks.size() << " tows), over the limit of " << maxTriangles
                        << "; --max-triangles N raises it, a smaller --samples U,V makes fewer";
                throw Error(ErrorCode::TooLarge, message.str());
            }
        }
        const std::vector<TowSurface> surfaces = fitSurfaces(stacks, options, "fit", quiet);

        // Every figure first: an error here must leave neither files nor half a report.
        struct Figures {
            Deviation deviation;
            double volume, faceted, area;
        };
        std::vector<Figures> figures;
        for (const TowSurface& s : surfaces) figures.push_back({s.deviation(), s.volume(), s.facetedVolume(), s.area()});
        Json towList = Json::array();
        for (std::size_t k = 0; k < surfaces.size(); ++k) {
            const TowSurface& s = surfaces[k];
            std::size_t shifted = 0;
            for (const std::size_t n : s.startShifts()) shifted += n != 0;
            Json t;
            t["name"] = s.name();
            t["mode"] = fitModeName(s.mode());
            t["sections"] = s.sectionCount();
            t["points"] = s.pointsPerSection();
            t["control_points"] = {s.controlPointCount(true), s.controlPointCount(false)};
            t["max_deviation"] = figures[k].deviation.max;
            t["rms_deviation"] = figures[k].deviation.rms;
            t["volume"] = figures[k].volume;
            t["faceted_volume"] = figures[k].faceted;
            t["area"] = figures[k].area;
            t["reversed"] = s.inputReversed();
            t["shifted_sections"] = shifted;
            t["start_shifts"] = s.startShifts();
            towList.push_back(std::move(t));
        }
        const std::string report = jsonText({{"tows", std::move(towList)}});
        // The Bézier extractions (isogeometric analysis), all computed before anything is written.
        std::vector<BezierSurface> extractions;
        if (bezier)
            for (const TowSurface& s : surfaces) extractions.push_back(extractBezier(s));

        if (outDir) {
            detail::OutputFiles files;
            files.makeDirectory(*outDir);
            for (std::size_t k = 0; k < surfaces.size(); ++k) {
                const TowSurface& s = surfaces[k];
                const auto [nu, nv] = stations(stacks[k]);
                const std::string path = (std::filesystem::path(*outDir) / (s.name() + ".vtk")).string();
                writeVtk(s.tessellate(nu, nv), files.open(path), "towgeom surface of tow " + s.name());
                if (bezier) writeBezierJson(extractions[k], s.name(), files.open((std::filesystem::path(*outDir) / (s.name() + "_bezier.json")).string()));
            }
            files.commit();
        }
        std::cout << report << "\n";
        return kExitOk;
    } catch (const std::exception& e) {
        return reportError("fit", e);
    }
}

}  // namespace towgeom::cli
