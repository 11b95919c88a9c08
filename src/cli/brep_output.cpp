// The exact solids' progress, note and warnings, shared by resolve and export.
#include "cli/brep_output.hpp"

#include <iostream>

namespace towgeom::cli {

TrimmedBrep buildTrimmedBrep(const char* command, const std::vector<TowSurface>& tows, const ResolveResult& resolved,
                             ProgressPrinter& printer, bool quiet)
{
    printer.update("building the trimmed B-rep (OpenCASCADE)", 0, 1);
    TrimmedBrep brep = trimmedBrep(tows, resolved);
    printer.update("building the trimmed B-rep (OpenCASCADE)", 1, 1);
    if (!quiet && !brep.fusedBecause().empty())
        std::cerr << "towgeom " << command
                  << ": note: the exact solids are built from the whole tows by OpenCASCADE's general fuse "
                     "(slower: it intersects them again), as their loops alone do not bound every face: "
                  << brep.fusedBecause() << "\n";
    return brep;
}

bool warnAboutBrep(const char* command, const TrimmedBrep& brep, const std::string& files)
{
    for (const BrepSolid& solid : brep.solids())
        if (solid.faces > 0 && !solid.valid)  // faces 0: wholly outside the cell, no solid
            std::cerr << "towgeom " << command << ": warning: the solid of tow '" << solid.name << "' in " << files
                      << " is not valid for OpenCASCADE's checker (BRepCheck_Analyzer; largest edge tolerance "
                      << solid.maxTolerance << "): CAD tools may refuse it\n";
    if (brep.matrix().faces > 0 && !brep.matrix().valid)
        std::cerr << "towgeom " << command << ": warning: the MATRIX solid in " << files
                  << " is not valid for OpenCASCADE's checker (BRepCheck_Analyzer; largest edge tolerance "
                  << brep.matrix().maxTolerance << "): CAD tools may refuse it\n";
    if (brep.matrixNote().empty()) return false;
    std::cerr << "towgeom " << command << ": warning: no MATRIX solid in " << files << " (the tows only): " << brep.matrixNote() << "\n";
    return true;
}

}  // namespace towgeom::cli
