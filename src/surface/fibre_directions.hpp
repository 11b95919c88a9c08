// The fibre direction of a tow at many (u,v): the unit tangent along it, dS/du / |dS/du|.
#pragma once

#include <vector>

#include "towgeom/export.hpp"
#include "towgeom/point.hpp"
#include "towgeom/textile_mesh.hpp"
#include "towgeom/tow_surface.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// dS/du / |dS/du| of @p tow at each of @p at (0 where dS/du vanishes), evaluated through
/// OpenCASCADE's per-span cache: several times faster than TowSurface::derivatives() each for
/// points that come span by span, as a mesh's triangles do.
std::vector<Vector3> fibreDirections(const TowSurface& tow, const std::vector<UV>& at);

/// The unit mean of fibreDirections(@p tow, @p at) (zero if they cancel): a cap's direction.
Vector3 meanFibreDirection(const TowSurface& tow, const std::vector<UV>& at);

/// Appends to @p fibre (one direction per triangle so far) the directions of the cap triangles
/// that follow in @p face: the tow's direction along its first or last section, the unit mean
/// of dS/du / |dS/du| over v there.
void appendCapDirections(const TowSurface& tow, const std::vector<TowFace>& face, std::vector<Vector3>& fibre);

}  // namespace detail
TOWGEOM_END_NAMESPACE
