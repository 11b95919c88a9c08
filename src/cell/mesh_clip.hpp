// A resolved textile's meshes clipped to a cell's box (CellCut::Mesh): nodes near a face's plane
// moved onto it, every triangle clipped by the six planes (plane_clip.hpp), the box's faces meshed
// with each tow's caps (box_caps.hpp), the nodes left unused dropped and renumbered. Any box:
// a face may cut a tow several times, along its length, through its regions, or at the box's
// edges and corners.
#pragma once

#include <vector>

#include "towgeom/cell.hpp"
#include "towgeom/resolve.hpp"
#include "towgeom/textile_mesh.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// How close to a face's plane (a fraction of its shortest edge) a node is moved onto it along its
/// surface before clipping (a tenth of that straight, off its surface): the cut then makes few
/// edges shorter than this fraction of the mesh's.
constexpr double kCellSnapFraction = 0.2;

/// @p mesh (closed tows over one node numbering, in the units of @p cell and @p tows) clipped to
/// @p cell, its faces meshed at @p h (the finest tow's mesh size) with smallest angle
/// @p minAngle: TextileMesh::cell set, each tow's caps TowFace::Cell triangles, only the nodes
/// in use kept (renumbered in their order), the loops, triple points, sharp corners and regions
/// kept where they still have nodes (regions renumbered, TowMesh::region following).
/// @throws Error as meshBoxCaps() does.
TextileMesh clipMeshToCell(TextileMesh mesh, const std::vector<TowSurface>& tows, const Cell& cell, double h, double minAngle);

/// @p result (connectRegions()'s, in the units of @p options) clipped to ResolveOptions::cell
/// by clipMeshToCell() at the finest TowResolution::meshSize: each tow's volume, area and pieces
/// then are those inside the cell, the quality that of the clipped mesh, the time added to
/// ResolveTimings::regions.
/// @throws Error (Internal) naming a tow left open by the clip; as clipMeshToCell().
ResolveResult clipResultToCell(const std::vector<TowSurface>& tows, ResolveResult result, const ResolveOptions& options);

}  // namespace detail
TOWGEOM_END_NAMESPACE
