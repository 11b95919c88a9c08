// The exact solids as resolve and export build and report them: progress, the note when they
// come from OpenCASCADE's general fuse, and the warnings for solids a CAD tool may refuse.
#pragma once

#include <string>
#include <vector>

#include "cli/progress_printer.hpp"
#include "towgeom/resolve.hpp"
#include "towgeom/trimmed_brep.hpp"

namespace towgeom::cli {

/// trimmedBrep() of @p resolved with progress on @p printer; unless @p quiet, a note on stderr
/// when the solids come from the general fuse, saying why.
TrimmedBrep buildTrimmedBrep(const char* command, const std::vector<TowSurface>& tows, const ResolveResult& resolved,
                             ProgressPrinter& printer, bool quiet);

/// Warnings on stderr (whatever --quiet says) for each solid of @p brep that OpenCASCADE's
/// checker refuses and for a cell's MATRIX solid not built; @p files names the files written.
/// Returns true when the MATRIX solid was not built (an output asked for is missing: exit 3).
bool warnAboutBrep(const char* command, const TrimmedBrep& brep, const std::string& files);

}  // namespace towgeom::cli
