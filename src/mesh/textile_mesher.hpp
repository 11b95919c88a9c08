// The mesh stage of the pipeline (meshTows()): every tow meshed in its (u,v) rectangle with the
// closed intersection loops as constraints, loop nodes shared by both tows of a loop, refined in
// rounds until neither tow asks for another node on a loop or seam, and closed by its end caps.
#pragma once

#include <functional>
#include <vector>

#include "towgeom/resolve.hpp"
#include "towgeom/tow_intersection.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// A tow's target edge length at a (u,v), in the frame's units (MeshSizes::sizeAt).
using TowSizeField = std::function<double(const UV&)>;

/// meshTows() on tows already in a normalised frame (@p report on those tows), options in the
/// frame's units, @p towH the mesh size of each tow there, @p sizeAt (if given for a tow) a size
/// that varies over it within [h / 100, h]. The result holds every tow's own
/// closed mesh (TextileMesh::loops the loops it was made with, no regions yet). A tow whose mesh
/// fails (or is not a tube) costs only the tow pairs with loops on it: they are left unresolved
/// (UnresolvedPair::Reason::MeshFailed) and the rest is meshed again without them.
/// @throws Error (Internal) for a tow that fails with no loop on it; (Cancelled).
ResolveResult meshTowsInFrame(const std::vector<TowSurface>& tows, const std::vector<double>& towH, const ResolveOptions& options,
                              const IntersectionReport& report, const std::vector<TowSizeField>& sizeAt = {});

}  // namespace detail
TOWGEOM_END_NAMESPACE
