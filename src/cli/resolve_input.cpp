// The options resolve and export share, and the resolve they run.
#include "cli/resolve_input.hpp"

#include "cli/cell_option.hpp"
#include "towgeom/error.hpp"
#include "towgeom/intersection_report_json.hpp"

namespace towgeom::cli {

void readResolveOptions(const Args& args, ResolveOptions& o)
{
    o.primaryPatterns = args.values("primary");
    // A volume mesh costs about five tetrahedra per surface triangle: by default its surfaces
    // are graded by curvature (MeshOptions::forVolume()) unless a size is given; a deviation
    // given replaces the preset's.
    if (args.has("volume") && !args.has("mesh-size")) o.mesh = MeshOptions::forVolume();
    o.mesh.edgeLength = args.positive("mesh-size");
    if (args.has("mesh-deviation")) o.mesh.chordDeviation = args.positive("mesh-deviation");
    o.mesh.loopSpacing = args.positive("loop-spacing");
    o.mesh.maxTriangles = args.maxTriangles(o.mesh.maxTriangles);
    o.intersection.tolerance = args.positive("tolerance");
    o.threads = args.threads();
    if (const auto cell = args.value("cell")) o.cell = parseCell(*cell, args.has("periodic"));
    else if (args.has("periodic")) throw UsageError("--periodic needs --cell");
    if (const auto cut = args.value("cell-cut")) {
        if (!o.cell) throw UsageError("--cell-cut needs --cell");
        if (*cut == "auto") o.cell->cut = CellCut::Auto;
        else if (*cut == "parametric") o.cell->cut = CellCut::Parametric;
        else if (*cut == "mesh") o.cell->cut = CellCut::Mesh;
        else throw UsageError("--cell-cut takes auto, parametric or mesh, not '" + *cut + "'");
        if (o.cell->periodic && o.cell->cut == CellCut::Mesh)
            throw UsageError("--cell-cut mesh is not periodic: a --periodic cell is cut parametrically");
    }
    if (args.has("report") && o.intersection.tolerance > 0.0)
        throw UsageError("--tolerance has no effect with --report: the loops were computed with the report's tolerance");
}

Error budgetExplained(const Error& e)
{
    return Error(e.code(), e.message() + "; --max-triangles N raises the limit, a larger --mesh-size, --mesh-deviation or --loop-spacing makes fewer",
                 e.file(), e.line());
}

ResolveResult resolveExplained(const std::vector<TowSurface>& tows, const ResolveOptions& o, const std::optional<std::string>& reportPath)
{
    return explainingBudget([&] {
        if (reportPath) return resolveTextile(tows, readIntersectionReport(*reportPath, tows), o);
        return resolveTextile(tows, o);
    });
}

}  // namespace towgeom::cli
