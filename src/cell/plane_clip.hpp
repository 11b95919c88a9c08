// A resolved textile's meshes clipped to the half-spaces of a cell's faces, triangle by triangle:
// where an edge crosses a face's plane, one new node on the edge (shared by every triangle on the
// edge, of every tow) exactly on the plane, so the clipped surfaces are parts of the resolved
// ones (but for the moved nodes below); the part of each triangle inside is kept (a quad split
// along its shorter diagonal), the rest dropped, and so is a triangle lying in the plane. Nodes
// close to a plane are first moved onto it, so the cut makes few slivers. The tows' surfaces are
// left open on the box's faces (meshBoxCaps() closes them).
#pragma once

#include <cstddef>
#include <unordered_map>
#include <vector>

#include "towgeom/cell.hpp"
#include "towgeom/textile_mesh.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// Per tow, the (u,v) of each node on its own surface (TowMesh::parameters as a map).
using NodeParameters = std::vector<std::unordered_map<std::size_t, UV>>;

/// TowMesh::parameters of every tow of @p mesh as maps.
NodeParameters nodeParameters(const TextileMesh& mesh);

/// Of the nodes of @p mesh in a tow's triangles: puts each within both 1e-9 of the box's diagonal
/// and @p fraction of its shortest edge of a face's plane on it; moves every node closer than
/// @p fraction of its shortest incident edge to the plane
/// of a face of @p cell (and within that distance of the face's rectangle), with a neighbour on
/// the plane's other side (the plane cuts an edge of it), onto the plane: along
/// its tow's surface (Newton's method in (u,v), its (u,v) in @p uv updated) where it lies on one
/// tow's own surface and the move stays under twice that distance, else straight along the
/// plane's normal when it lies within a tenth of that distance (a surface grazing the plane is
/// not flattened onto it). A node already on one plane moves only straight onto a second. Only nodes
/// from @p firstNode on, and only onto the faces in the bit set @p faces (bit f: CellFace f).
/// Returns the number of nodes moved.
std::size_t snapToCellPlanes(TextileMesh& mesh, NodeParameters& uv, const std::vector<TowSurface>& tows, const Cell& cell,
                             double fraction, std::size_t firstNode = 0, unsigned faces = 0x3f);

/// Clips every tow of @p mesh to the box of @p cell, face by face (see the file's comment); the
/// regions' triangle lists, nodes and areas follow. New nodes are appended to TextileMesh::nodes
/// (nodes outside stay, unused); @p uv follows the moved nodes. A node is on a
/// plane only when its coordinate equals the plane's exactly (snapToCellPlanes() first); before
/// each plane, the nodes the earlier planes made are moved onto it as snapToCellPlanes() does
/// (@p fraction), so a cut close to an edge of the box meets it there.
void clipToCellPlanes(TextileMesh& mesh, NodeParameters& uv, const std::vector<TowSurface>& tows, const Cell& cell, double fraction);

}  // namespace detail
TOWGEOM_END_NAMESPACE
