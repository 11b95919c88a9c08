// Reading and fitting the tows named on a command line, shared by the subcommands.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "towgeom/fit_options.hpp"
#include "towgeom/tow_stack.hpp"
#include "towgeom/tow_surface.hpp"

namespace towgeom::cli {

/// Reads every file (on @p threads threads, 0: all hardware threads); throws towgeom::Error
/// for the first bad file in the order given, or when two files hold tows of the same name
/// (names become output file names).
std::vector<TowStack> readStacks(const std::vector<std::string>& paths, std::size_t threads = 0);

/// Fits every stack (on @p threads threads), with one progress line per tow on stderr as it
/// finishes unless @p quiet; throws the first failure in input order.
std::vector<TowSurface> fitSurfaces(const std::vector<TowStack>& stacks, const FitOptions& options,
                                    const char* command, bool quiet, std::size_t threads = 0);

}  // namespace towgeom::cli
