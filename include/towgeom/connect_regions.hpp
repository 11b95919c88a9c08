/// @file connect_regions.hpp
/// @brief connectRegions(): the last stage of resolveTextile() on its own: the tows' meshes
/// classified by their loops and made compatible by the rank rule (ConnectedRegion).
#pragma once

#include <vector>

#include "towgeom/resolve.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// @defgroup regions Connecting regions (stage 3)
/// @brief connectRegions(): the tows' meshes classified by their loops and made compatible by
/// the rank rule (ConnectedRegion), on meshTows()'s result or the host's own.
/// @{

/// The third stage of resolveTextile(): makes every tow itself minus the tows ranked above it
/// (ResolveOptions::primaryPatterns), on the meshes of @p meshed (meshTows()'s result for
/// @p tows, or the same data built by the host: each tow's closed mesh, TowMesh::parameters for
/// every node of its own surface, TextileMesh::loops with their nodes on both tows' meshes).
///
/// A triangle of tow t lies inside tow o when its (u,v) centroid (from its nodes' parameters) lies
/// inside an odd number of the loops of its pair with o (exact point-in-polygon, CGAL); loops
/// around a tow cut it into bands alternately inside and outside the other, its caps in the end
/// bands. A triangle inside a higher-ranked tow is removed; one inside lower-ranked tows only is
/// also a triangle of the highest-ranked of them (a ConnectedRegion, both tows' same nodes and
/// triangles). Each region gets its area and the volume of the overlap it replaced; every tow its
/// volume before and after, area and pieces; the triple points kept are those whose node all three
/// tows still use.
///
/// A tow that is not a closed surface after the swap costs only the tow pairs with loops on it:
/// they are listed in ResolveResult::unresolved (UnresolvedPair::Reason::RegionFailed), their
/// loops get no region (their nodes stay in both meshes), and the rest is connected again.
///
/// @code
/// towgeom::ResolveResult meshed = towgeom::meshTows(tows, towgeom::intersectTows(tows));
/// towgeom::ResolveOptions options;
/// options.primaryPatterns = {"binder*"};  // binders keep their surface
/// const towgeom::ResolveResult r = towgeom::connectRegions(tows, std::move(meshed), options);
/// for (const towgeom::ConnectedRegion& g : r.mesh.regions)
///     std::cout << "tows " << g.primary << " and " << g.secondary << " share " << g.area << "\n";
/// @endcode
///
/// @throws towgeom::Error (InvalidArgument) for ResolutionMethod::Shrink (not a region method), when @p meshed does not fit @p tows (tow count or
/// names, per-triangle lists of another length, node indices out of range, a side triangle's or
/// loop's node without (u,v) on its tow, a loop not closed in the report, regions already made),
/// naming the tow or loop; (Internal) for a tow that is not closed with no loop on it; (Cancelled).
TOWGEOM_EXPORT ResolveResult connectRegions(const std::vector<TowSurface>& tows, ResolveResult meshed,
                                            const ResolveOptions& options = {});

/// @}

TOWGEOM_END_NAMESPACE
