// A tool surface from a .grid file of points (see readPlacementSurface()).
#pragma once

#include <string>

#include "towgeom/placement_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// Reads the .grid file @p path ('#' comments, 'grid NU NV', then NU x NV lines 'x y z') and
/// interpolates it. @throws towgeom::Error naming the file and line.
PlacementSurface readGridSurface(const std::string& path);

}  // namespace detail
TOWGEOM_END_NAMESPACE
