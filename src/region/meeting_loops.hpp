// Loops of different tow pairs that meet on a tow: three tows overlap there. The rank rule
// resolves them where they meet only in triple points or lie one inside the other while the
// third pair has loops resolved there too; otherwise one of the two pairs is left out.
#pragma once

#include <vector>

#include "mesh/loop_nodes.hpp"
#include "region/triple_points.hpp"
#include "towgeom/intersection_loop.hpp"
#include "towgeom/resolve.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// Loops of different tow pairs that meet on a tow (@p crossing: those whose node polygons still
/// cross after joinAtTriplePoints(), and any that touch or nest) where the rank rule cannot
/// resolve them: the later pair (by tow indices) is left out (UnresolvedPair::Reason::LoopsMeet,
/// appended to @p unresolved) and its loops removed from @p shared; pairs that relied on it
/// follow.
void dropMeetingLoops(const std::vector<TowSurface>& tows, const std::vector<IntersectionLoop>& loops,
                      std::vector<SharedLoop>& shared, const std::vector<CrossingLoops>& crossing,
                      std::vector<UnresolvedPair>& unresolved);

}  // namespace detail
TOWGEOM_END_NAMESPACE
