// Reading and fitting the tows named on a command line, shared by the subcommands.
#pragma once

#include <string>
#include <vector>

#include "towgeom/fit_options.hpp"
#include "towgeom/tow_stack.hpp"
#include "towgeom/tow_surface.hpp"

namespace towgeom::cli {

/// Reads every file; throws towgeom::Error for the first bad file, or when two files hold tows
/// of the same name (names become output file names).
std::vector<TowStack> readStacks(const std::vector<std::string>& paths);

/// Fits every stack, with one progress line per tow on stderr unless @p quiet.
std::vector<TowSurface> fitSurfaces(const std::vector<TowStack>& stacks, const FitOptions& options,
                                    const char* command, bool quiet);

}  // namespace towgeom::cli
