/// @file mesh_tows.hpp
/// @brief meshTows(): the mesh stage of resolveTextile() on its own: every tow's closed surface
/// mesh with the intersection loops as shared constraints, no region swapped yet.
#pragma once

#include <vector>

#include "towgeom/resolve.hpp"
#include "towgeom/tow_intersection.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// @defgroup tow_meshes Meshing every tow (stage 2)
/// @brief meshTows(): each tow's own closed mesh with the intersection loops as shared
/// constraints, before any region is swapped (after intersectTows(), before connectRegions()).
/// @{

/// The second stage of resolveTextile(): every tow meshed in its (u,v) rectangle with the closed
/// loops of @p report as constraints (ParametricMesher: loop nodes shared by both tows of a loop,
/// seam nodes by both sides of the seam), in rounds until no tow asks for another node on a loop
/// or seam, then closed by its end caps (MeshOptions::caps). Nothing is swapped: each TowMesh is
/// the tow's own closed surface, the tows still overlap, ResolveResult::mesh has no regions and
/// TextileMesh::loops lists the loops meshed, each with its nodes. connectRegions() takes the
/// result on to the compatible meshes; `connectRegions(tows, meshTows(tows, report, options),
/// options)` is resolveTextile(tows, report, options), node for node.
///
/// Of the result, ResolveResult::tows gives each tow's own volume (volumeBefore = volumeAfter),
/// area and mesh size; quality counts every triangle; skippedLoops and unresolved say which loops
/// and pairs are not meshed as constraints (a tow whose mesh fails costs only the pairs with loops
/// on it). ResolveOptions::primaryPatterns is used only with a cell whose face cuts through an
/// overlap (Cell): the part of the face inside both tows' cuts is a cap of both here, and
/// connectRegions() takes it off the lower-ranked tow (with ResolutionMethod::Symmetric too: the
/// region there keeps the higher-ranked tow's surface).
///
/// @code
/// const towgeom::IntersectionReport loops = towgeom::intersectTows(tows);
/// towgeom::ResolveResult meshed = towgeom::meshTows(tows, loops);       // the tows' own meshes
/// for (const towgeom::MeshedLoop& l : meshed.mesh.loops)
///     std::cout << "loop " << l.loop << ": " << l.nodes.size() << " shared nodes\n";
/// towgeom::ResolveOptions options;
/// options.primaryPatterns = {"warp*"};
/// const towgeom::ResolveResult r = towgeom::connectRegions(tows, std::move(meshed), options);
/// @endcode
///
/// @throws towgeom::Error as resolveTextile(tows, report, options).
TOWGEOM_EXPORT ResolveResult meshTows(const std::vector<TowSurface>& tows, const IntersectionReport& report,
                                      const ResolveOptions& options = {});

/// @}

TOWGEOM_END_NAMESPACE
