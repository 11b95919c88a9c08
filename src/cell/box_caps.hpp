// A textile's meshes clipped to a cell (clipToCellPlanes()) closed on the box's faces: on each
// face, the edges where the tows were cut (and the box's edges, through the tows' nodes on them)
// are constraints of CGAL's constrained Delaunay mesher, refined without splitting a constraint;
// each part between constraints is the cap of the tow whose closed surface before clipping holds
// it (its winding number there over 1/2), or the matrix's. A tow cut several times by one face,
// along its length, or at an edge or corner of the box gets a cap for each piece.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "towgeom/cell.hpp"
#include "towgeom/textile_mesh.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// Closes every tow of @p mesh, clipped to @p cell, by caps on the box's faces (TowFace::Cell
/// triangles, outward from the box, fibre direction that of the tow's triangles along the cut)
/// and returns the matrix's part of the faces. @p solids: each tow's closed surface over
/// TextileMesh::nodes before clipping, which decides what a face's part lies in. Faces are meshed
/// at @p h near the tows, graded away from them as Cell::faceSizeGrowth and faceSizeMax say,
/// smallest angle @p minAngle (degrees); new nodes are appended to TextileMesh::nodes.
/// @throws Error (InvalidArgument) naming the tow whose clipped mesh has an open edge off the
/// box's faces (it was not closed), the two tows whose cuts cross or whose caps overlap on a
/// face (an overlap left unresolved there), or the face where two nodes coincide.
CellMesh meshBoxCaps(TextileMesh& mesh, const std::vector<std::vector<std::array<std::size_t, 3>>>& solids, const Cell& cell, double h,
                     double minAngle);

}  // namespace detail
TOWGEOM_END_NAMESPACE
