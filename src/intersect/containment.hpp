// Whether one tow lies inside another: a point of one against the other's closed faceted tube
// (CGAL Side_of_triangle_mesh), for pairs whose boxes overlap but whose surfaces never cross.
#pragma once

#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// True when a point of @p inner's surface (the middle of its first input section's first
/// point column) lies strictly inside @p outer's input tube, closed at its ends.
bool pointOfInsideOther(const TowSurface& inner, const TowSurface& outer);

}  // namespace detail
TOWGEOM_END_NAMESPACE
