// towgeom ply: a fibre-placement ply as a trivariate NURBS between a tool surface (STEP or IGES)
// and its offset, thin layer on layer.
#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/json_text.hpp"
#include "cli/tool_surface.hpp"
#include "io/output_files.hpp"
#include "towgeom/towgeom.hpp"

namespace towgeom::cli {

namespace {

const char* kPlyHelp = R"(Usage: towgeom ply SURFACE.step --thickness T --out DIR [options]

Reads a tool surface (a face of a STEP or IGES file, converted exactly to a NURBS over its
(u,v) box, or a .grid file of points interpolated by a bicubic B-spline: '#' comments,
'grid NU NV', then NU x NV lines 'x y z', v fastest), offsets it by T along its outward
normal keeping its parametrisation (the same degrees, knots and weights; knots inserted until
the offset is within --tolerance of the exact one: Nguyen et al. 2014) and writes each ply as
a trivariate NURBS, linear through its thickness (or quadratic: --through), for isogeometric
analysis. With --layers K the plies stack, each on the last one's top. Writes, all or nothing:

  DIR/ply_K.json  the K-th ply: {"degrees":[p,q,r], "knots":[[u..],[v..],[w..]],
                  "counts":[nu,nv,r+1], "poles":[[x,y,z,weight],...]} (pole (i,j,k) at
                  (i nv + j) (r+1) + k; r = 1 linear, 2 quadratic)
  DIR/ply_K.vtk   the ply sampled as hexahedra for ParaView, point data "jacobian"

and prints one JSON object on stdout:

  {"file", "face", "faces", "face_name", "fit_deviation", "thickness", "through", "plies":[{"volume",
   "min_jacobian", "max_jacobian", "offset_error", "knots_inserted", "converged"}]}

  face_name       the face's name in the file ("" if none)
  fit_deviation   0: a face is converted exactly, a .grid interpolated through its points

  volume          the ply's volume (Gauss-Legendre per knot span of its Jacobian)
  min/max_jacobian  the Jacobian's range at the quadrature points: of one sign where the ply
                  does not fold (negative for a negative --thickness: a ply on the inside)
  offset_error    the largest distance of the top surface from the exact offset, sampled
  converged       false where no refinement meets --tolerance (a crease in the surface, or a
                  tolerance finer than rounding allows): each such ply is also named on stderr

Options:
  --thickness T   ply thickness in millimetres (OpenCASCADE reads STEP and IGES lengths as
                  mm, whatever unit the file uses); negative: on the other side
  --face N|NAME   which face of the file: its index (0-based, default 0) or its name in the
                  file (a STEP ADVANCED_FACE's or IGES entity's name; digits only are an
                  index)
  --layers K      plies stacked (default 1)
  --tolerance E   largest distance of an offset from the exact one (default: 1e-6 x the
                  size of the surface's control net)
  --through KIND  linear (default: w degree 1, poles on the surface and its offset) or
                  quadratic (w degree 2: the same solid, degree-elevated, for codes that
                  want quadratic functions through the thickness)
  --samples S     VTK hexahedra per knot span along u and v (default 4; S/2 through)
  --allow-unconverged  exit 0 even when a ply's offset misses --tolerance (still warned)
  --out DIR       where to write (created if needed)
  --quiet         no progress lines on stderr
  -h, --help      this help

The offset passes a pole of the surface's parametrisation (a boundary row of poles collapsed
to one point, as at a sphere face's poles) along the normal's limit there. A ply that folds
(its Jacobian changes sign at its volume's quadrature points: the offset turns inside out where
the surface curves tighter than the thickness), or whose surface has a point with no single
normal (a cone's apex), is refused, naming the ply or the place; nothing is written.

Exit status: 0 success; 3 written, but a ply's offset misses --tolerance ("converged": false;
a warning on stderr names it, even with --quiet; --allow-unconverged makes this 0); 2 invalid
input or usage, or a ply that folds (one line on stderr naming the file or the place); 1 an
output file could not be written, or an internal failure of OpenCASCADE.

Example:
  towgeom ply tool.step --thickness 0.25 --layers 4 --out plies
)";

/// Why ply @p ply (1-based) is refused: its Jacobian changes sign (measure @p m), on @p base.
std::string plyFolds(std::size_t ply, double thickness, const VolumeMeasure& m, const NurbsSurface& base)
{
    std::ostringstream text;
    text << std::setprecision(6) << "ply " << ply << " folds near (" << m.weakestPoint.x << ", " << m.weakestPoint.y << ", "
         << m.weakestPoint.z << ") (u " << m.weakestParameters[0] << ", v " << m.weakestParameters[1] << " of the surface under it; "
         << "u in [" << base.uKnots.front() << ", " << base.uKnots.back() << "], v in [" << base.vKnots.front() << ", " << base.vKnots.back()
         << "]): its Jacobian runs from " << m.minJacobian << " to " << m.maxJacobian << ", so the offset by " << thickness
         << " turns inside out there (the surface curves tighter than the thickness); nothing written";
    return text.str();
}

/// The warning for ply @p ply (1-based) whose offset @p o missed its tolerance.
std::string plyMissesTolerance(std::size_t ply, const SurfaceOffset& o)
{
    std::ostringstream text;
    text << std::setprecision(6) << "ply " << ply << ": its top is up to " << o.maxError
         << " from the exact offset, over --tolerance after " << o.knotsInserted
         << " knot(s) inserted (a crease in the surface, or a tolerance finer than rounding allows); "
            "written with \"converged\": false";
    return text.str();
}

}  // namespace

int runPly(int argc, char** argv, int first)
{
    try {
        const Args args(argc, argv, first,
                        {{"help"}, {"quiet"}, {"allow-unconverged"}, {"thickness", true}, {"face", true}, {"layers", true}, {"tolerance", true}, {"samples", true}, {"through", true},
                         {"out", true}});
        if (args.has("help")) {
            std::cout << kPlyHelp;
            return kExitOk;
        }
        if (args.positional().size() != 1) throw UsageError("one STEP or IGES file, the tool surface");
        const auto thickness = args.number("thickness");
        if (!thickness || *thickness == 0.0) throw UsageError("--thickness T is needed, not 0");
        const auto outDir = args.value("out");
        if (!outDir) throw UsageError("--out DIR is needed");
        const std::size_t layers = args.whole("layers", 1, 1, 1000, "1 to 1000"),
                          samples = args.whole("samples", 4, 1, 64, "1 to 64");
        OffsetOptions options;
        options.tolerance = args.positive("tolerance");
        const bool quiet = args.has("quiet");
        const std::string through = args.value("through").value_or("linear");
        if (through != "linear" && through != "quadratic") throw UsageError("--through is linear or quadratic");
        const bool quadratic = through == "quadratic";

        const std::string& file = args.positional().front();
        const PlacementSurface tool = readToolSurface(args, file);
        if (tool.faces.size() > 1)
            throw UsageError("ply offsets one face (--face N or NAME): joined faces meet at a crease, where an offset opens or folds");
        std::vector<NurbsVolume> plies;
        Json report;
        report["file"] = file;
        report["face"] = tool.face;
        report["faces"] = tool.faceCount;
        report["face_name"] = tool.name;
        report["fit_deviation"] = tool.fitDeviation;
        report["thickness"] = *thickness;
        report["through"] = through;
        report["plies"] = Json::array();
        NurbsSurface base = tool.surface;
        std::vector<std::string> unconverged;  // warnings, one per ply
        for (std::size_t k = 0; k < layers; ++k) {
            if (!quiet) std::cerr << "towgeom ply: [" << k + 1 << "/" << layers << "] offsetting the surface\n";
            const SurfaceOffset o = offsetSurface(base, *thickness, options);
            if (quadratic) {
                // The linear ply's degree elevation: the middle poles the average of base and top
                // (a normal offset's through-thickness field is linear).
                NurbsSurface middle = o.base;
                for (std::size_t i = 0; i < middle.poles.size(); ++i) middle.poles[i] = 0.5 * (o.base.poles[i] + o.offset.poles[i]);
                plies.push_back(plySolid(o.base, middle, o.offset));
            } else {
                plies.push_back(plySolid(o.base, o.offset));
            }
            const VolumeMeasure m = measureVolume(plies.back());
            if (m.folds()) throw Error(ErrorCode::Unsupported, plyFolds(k + 1, *thickness, m, base));
            if (!o.converged) unconverged.push_back(plyMissesTolerance(k + 1, o));
            report["plies"].push_back({{"volume", m.volume},
                                       {"min_jacobian", m.minJacobian},
                                       {"max_jacobian", m.maxJacobian},
                                       {"offset_error", o.maxError},
                                       {"knots_inserted", o.knotsInserted},
                                       {"converged", o.converged}});
            base = o.offset;
        }
        detail::OutputFiles files;
        files.makeDirectory(*outDir);
        for (std::size_t k = 0; k < plies.size(); ++k) {
            const std::string stem = (std::filesystem::path(*outDir) / ("ply_" + std::to_string(k + 1))).string();
            writeNurbsVolumeJson(plies[k], files.open(stem + ".json"));
            writeNurbsVolumeVtk(plies[k], files.open(stem + ".vtk"), static_cast<int>(samples));
        }
        files.commit();
        std::cout << jsonText(report) << "\n";
        for (const std::string& warning : unconverged) std::cerr << "towgeom ply: warning: " << warning << "\n";
        return unconverged.empty() || args.has("allow-unconverged") ? kExitOk : kExitUnresolved;
    } catch (const std::exception& e) {
        return reportError("ply", e);
    }
}

}  // namespace towgeom::cli
