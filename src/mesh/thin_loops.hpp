// Loops too thin to bound a region: the surfaces nearly touch along them, and the loop's own
// nodes cannot follow its sides. Such a loop is a contact: its overlap, shallower than the
// meshes' chord deviation, stays, and the mesh stage refines both tows there until their meshes
// do not cross.
#pragma once

#include <string>

#include "mesh/loop_nodes.hpp"
#include "towgeom/intersection_loop.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// A loop may be taken for a contact when its overlap is at most this fraction of the mesh size
/// deep (a triangle of size h on a tow of radius R sags h^2 / 8R, about h/40 on a pressed tow).
constexpr double kContactDepth = 1.0 / 64.0;

/// Why @p loop, with its shared nodes @p shared, is a contact rather than a region, or empty.
/// It is when its node polygon crosses itself in (u,v) on either tow (the mesher could not keep
/// it as a constraint: its chords would cut each other) and the overlap it bounds is shallow:
/// half its extent (the diagonal of its points' box) times the tangent of the largest angle at
/// which the two surfaces meet along it is below kContactDepth of @p meshSize. A loop that goes
/// around a tow or runs across a cap is never one (its polygons are not closed in (u,v)).
std::string thinLoopContact(const IntersectionLoop& loop, const SharedLoop& shared, double meshSize);

}  // namespace detail
TOWGEOM_END_NAMESPACE
