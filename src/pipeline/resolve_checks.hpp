// The checks resolveTextile() makes before it intersects the tows, for other entry points that
// intersect themselves (compareMethods()).
#pragma once

#include <vector>

#include "towgeom/resolve.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// Checks @p options and refuses (ErrorCode::TooLarge) a mesh whose estimated triangle count is
/// over MeshOptions::maxTriangles, before any intersection is computed.
/// @throws towgeom::Error as resolveTextile() does for these.
void checkBeforeIntersecting(const std::vector<TowSurface>& tows, const ResolveOptions& options);

}  // namespace detail
TOWGEOM_END_NAMESPACE
