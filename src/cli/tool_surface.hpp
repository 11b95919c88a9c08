// The tool surface of the fibre-placement commands (ply, courses): a face of a STEP or IGES
// file by --face N (0-based) or --face NAME, several joined by --face N,M,... or --face all, or
// a .grid file of points.
#pragma once

#include <string>

#include "cli/args.hpp"
#include "towgeom/placement_surface.hpp"

namespace towgeom::cli {

/// Reads @p file's face as --face says (absent: the first; a list or "all": joined, see
/// readPlacementSurface()).
PlacementSurface readToolSurface(const Args& args, const std::string& file);

}  // namespace towgeom::cli
