// The faces of a cell meshed around the tows' cuts: each face a rectangle (its edges' nodes
// shared with the neighbouring faces) with the cut polygons on it as constraints, triangulated
// and refined by CGAL's constrained Delaunay mesher without splitting a constraint; the triangles
// inside a cut are that tow's cap, the others the matrix's. With a periodic cell the max faces
// are the min faces' meshes moved by the box.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "cell/tow_cuts.hpp"
#include "towgeom/cell.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// The box's faces as meshed.
struct CellFaces {
    /// Per tow and end (0 start, 1 end), the cap on the face that cut it: triangles over global
    /// nodes, outward from the tow (= from the box). Where two tows' cuts overlap (a loop of
    /// theirs crosses the face), the triangles inside both are in both caps.
    std::vector<std::array<std::vector<std::array<std::size_t, 3>>, 2>> caps;
    /// The box (@p cell as given), the matrix's triangles, every face's nodes, periodic pairs.
    CellMesh mesh;
};

/// The edge length the box's faces are meshed at: the finest of @p towH, or with no tow a
/// twentieth of the box's longest side.
double cellFaceSize(const Cell& cell, const std::vector<double>& towH);

/// Meshes the six faces of @p cell around the cuts @p cuts of @p tows at edge length @p h at the
/// cuts and near the tows, graded away from the tows as Cell::faceSizeGrowth and
/// Cell::faceSizeMax say (uniformly at @p h when there is no tow), and smallest angle
/// @p minAngle (degrees); new nodes are appended to @p nodes, which on entry holds the tows'
/// nodes only (their distance grades the faces). Two cuts may overlap on a face only where a
/// loop of their tows crosses it: they then share the crossings' nodes, cross only there, and
/// the part inside both is the cap of the tow ranked higher in @p rank (0 first), the rest of the
/// other's cut that tow's cap.
/// @throws Error (InvalidArgument) naming the two tows whose cuts overlap on a face otherwise.
CellFaces meshCellFaces(const std::vector<TowSurface>& tows, const Cell& cell, const CellCuts& cuts, double h, double minAngle,
                        std::vector<Point3>& nodes, const std::vector<std::size_t>& rank);

}  // namespace detail
TOWGEOM_END_NAMESPACE
