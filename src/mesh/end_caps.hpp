// End caps: a tow's mesh closed by the planar polygons of its two ends, each meshed by CGAL's 2D
// constrained Delaunay mesher in its plane with the tube's end nodes as they are.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "mesh/loop_nodes.hpp"
#include "mesh/parametric_mesher.hpp"
#include "towgeom/point.hpp"
#include "towgeom/textile_mesh.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// A node's position by its number: the global nodes, or during meshing the shared nodes and a
/// tow's own ones.
using NodeAt = std::function<const Point3&(std::size_t)>;

/// One cap's triangles and its own new nodes.
struct CapMesh {
    /// Over global nodes; the cap's own nodes are numbered from the firstNewNode given on.
    std::vector<std::array<std::size_t, 3>> triangles;
    std::vector<Point3> newNodes;  ///< positions of the cap's own nodes, in the cap's plane
    /// Wedges between its rim and loop pieces sharper than surfaceAngleBound() (nodes numbered as
    /// in triangles; SharpCorner::tow left 0, SharpCorner::face Side: the caller knows which end).
    std::vector<SharpCorner> sharpCorners;
};

/// Meshes the polygon of global nodes @p loop (a boundary loop of an outward-oriented tube, in
/// the direction its triangles run along it) in its plane (Newell's normal through its centroid):
/// CGAL's constrained Delaunay triangulation of the polygon, refined to edges of about @p h and
/// the smallest angle @p minAngle without splitting the boundary (a split would be a node the
/// tube lacks). The triangles run along the loop the other way round, so tube and cap make a
/// closed, consistently oriented surface.
/// @throws Error (SelfIntersectingSection) naming @p where when the loop is no simple polygon in
/// its plane (resolveTextile() turns it into InvalidArgument: the mesh size is too coarse for
/// the section).
/// @p paths are loop pieces on the cap (global nodes, projected into its plane): constraints of
/// the mesh, their ends nodes of @p loop or closed.
CapMesh meshCap(const NodeAt& nodes, const std::vector<std::size_t>& loop, double h, double minAngle,
                std::size_t firstNewNode, const std::string& where, const std::vector<CapConstraint>& paths = {});

/// One open end of a tow's tube mesh that a cap closes: its boundary loop and which end it is.
struct TubeEnd {
    std::vector<std::size_t> loop;
    TowFace face = TowFace::Start;
};

/// The ends of @p tow's tube mesh @p tube (nodes at @p nodes) that caps close: its two boundary
/// loops, each named by the nearer of the tow's first and last sections (none when the tube has
/// not exactly two). An end whose nodes are all marked in @p cutNode (by node, if given: a cell's
/// cut) is left out; @p cutEnds (its start cut, its end cut) then says which end the other is.
std::vector<TubeEnd> tubeEnds(const TowSurface& tow, const std::vector<std::array<std::size_t, 3>>& tube, const NodeAt& nodes,
                              const std::vector<char>* cutNode = nullptr, const std::array<bool, 2>* cutEnds = nullptr);

/// The pieces of @p paths (CapConstraint::end -1 the first end's, +1 the last's) on the cap of @p face.
std::vector<CapConstraint> pathsOnCap(const std::vector<CapConstraint>& paths, TowFace face);

/// The caps of @p tow's tube mesh @p tube while it is still being meshed, to check it against
/// other tows (its nodes at @p nodes, @p paths the loop pieces on its caps): both caps in one
/// mesh, their own nodes numbered from @p firstNewNode on. A cap that cannot be meshed is left
/// out (closeEnds() reports it).
CapMesh provisionalCaps(const TowSurface& tow, double h, double minAngle, const std::vector<std::array<std::size_t, 3>>& tube,
                        const NodeAt& nodes, const std::vector<CapConstraint>& paths, std::size_t firstNewNode,
                        const std::vector<char>* cutNode = nullptr, const std::array<bool, 2>* cutEnds = nullptr);

/// Closes every tow's tube mesh (@p meshes, open at their two ends) by its two end caps
/// (meshCap(), at the tow's mesh size @p towH); @p face gets each triangle's part
/// (TowFace::Start or End by the nearer of the tow's first and last sections). The caps' nodes
/// are appended to @p nodes. @p capPaths, if given, holds per tow the loop pieces on its caps
/// (CapConstraint::end -1 the first end's, +1 the last's), constraints of those caps' meshes.
/// A cap with loop pieces that cannot be meshed is noted in @p failed (one entry per tow, if
/// given) and that tow's caps are left out; the tow's mesh is then not closed. An end whose
/// nodes are all marked in @p cutNode (by global node, if given: a cell's cut) is left open;
/// @p cutEnds (per tow: its start cut, its end cut) then says which end the other one is.
/// @throws Error (InvalidArgument) naming the tow and end whose cap cannot be meshed.
void closeEnds(const std::vector<TowSurface>& tows, const std::vector<double>& towH, double minAngle, std::size_t threads,
               std::vector<ParametricMesh>& meshes, std::vector<std::vector<TowFace>>& face, std::vector<Point3>& nodes,
               const std::vector<std::vector<CapConstraint>>& capPaths = {}, std::vector<std::string>* failed = nullptr,
               const std::vector<char>* cutNode = nullptr, const std::vector<std::array<bool, 2>>* cutEnds = nullptr);

}  // namespace detail
TOWGEOM_END_NAMESPACE
