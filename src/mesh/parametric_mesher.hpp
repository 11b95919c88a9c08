// ParametricMesher: one tow's surface meshed in its (u,v) rectangle with CGAL's constrained
// Delaunay mesher, in a parameter space scaled by the surface's lengths along and around the
// tow, the intersection loops as constraints. Nodes on v = vMin and v = vMax are the same
// nodes, so the 3D mesh is a tube closed across the seam, open at its two ends.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "mesh/loop_nodes.hpp"
#include "towgeom/textile_mesh.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// Size and shape asked of the mesh.
struct MeshSizes {
    double edgeLength = 0.1;  ///< target 3D edge length h
    double minAngle = 20.0;   ///< degrees
    /// The target edge length at a (u,v), if given: the mesh is refined to it, taken within
    /// [h / 100, h] (the seam and end stations and the starting lattice stay at h).
    std::function<double(const UV&)> sizeAt;
    /// If given, only u in [uSpan[0], uSpan[1]] is wanted (a cell keeps nothing beyond its
    /// cuts): the mesh stops about h beyond it (within the tow's u range), where it has ends like
    /// the tow's own; every constraint must lie in the span.
    std::optional<std::array<double, 2>> uSpan;
};

/// One tow's mesh: its triangles over global nodes (loop nodes) and its own new nodes.
struct ParametricMesh {
    std::vector<std::array<std::size_t, 3>> triangles;  ///< outward orientation
    std::vector<UV> centroids;                          ///< (u,v) centroid of each triangle
    std::vector<UV> newNodes;   ///< (u,v) of the tow's own nodes, numbered from firstNewNode on
    std::size_t badFaces = 0;   ///< faces left beyond the size or shape bound (next to constraints)
    /// Wedges between constraints sharper than surfaceAngleBound() on the surface (nodes numbered
    /// as in triangles; SharpCorner::tow left 0).
    std::vector<SharpCorner> sharpCorners;
};

/// Splits of constraints that would let the mesh meet its bounds everywhere: nodes that both
/// tows of a loop, or both sides of the seam, must have before the next meshing.
struct MeshRequests {
    struct OnLoop {
        std::size_t a = 0, b = 0;  ///< the loop chord's end nodes (global): split in the middle
    };
    std::vector<double> seamU;     ///< u of new seam stations (both sides)
    std::vector<OnLoop> onLoop;    ///< nodes on loop chords
    bool empty() const { return seamU.empty() && onLoop.empty(); }
};

/// A node added on a loop chord: the chord's end nodes, the new node and its (u,v) on this tow.
struct ChordSplit {
    std::size_t a = 0, b = 0, node = 0;
    UV at;
};

/// A smaller mesh size wanted around a point of the surface (where the tow's mesh crosses
/// another's): within @p radius of @p at (3D lengths, measured in the scaled parameter space),
/// edges at most @p size.
struct SizeSpot {
    UV at;
    double radius = 0.0;
    double size = 0.0;
};

/// Meshes one tow's surface and keeps the triangulation, so that nodes added on its loops or
/// seam later are put in and refined around, not meshed again from scratch. The parameter
/// space's scale and the surface metric are computed once, at construction.
///
/// Refinement never splits a constraint (a loop chord split on one tow would be a node the other
/// tow lacks, a seam edge split on one side a node the other side lacks), so the mesh after any
/// round is consistent with the other tows'. Where a triangle could not be made good without a
/// split, the split is returned in MeshRequests; the caller adds it to both sides (split()) for
/// a better mesh. result() checks that the seam's two sides have the same nodes.
class ParametricMesher {
public:
    ParametricMesher(const TowSurface& surface, const MeshSizes& sizes);
    ~ParametricMesher();
    ParametricMesher(ParametricMesher&&) noexcept;
    ParametricMesher& operator=(ParametricMesher&&) = delete;

    /// Meshes the surface with @p constraints (pieces of loops, nodes already global) and nodes
    /// on the seam at least at @p seamU.
    void mesh(const std::vector<LoopConstraint>& constraints, const std::vector<double>& seamU, MeshRequests& requests);

    /// Adds nodes on loop chords and seam stations (at u), then refines again. False if a chord
    /// is not in the mesh (then mesh() again with the new constraints).
    bool split(const std::vector<ChordSplit>& splits, const std::vector<double>& seamU, MeshRequests& requests);

    /// Refines again with edges at most SizeSpot::size around each of @p spots (kept for every
    /// later mesh() and split()), then asks for the splits the faces still bad need.
    void refineAround(const std::vector<SizeSpot>& spots, MeshRequests& requests);

    /// Faces over the size or shape bound after the last mesh() or split().
    std::size_t badFaces() const;

    /// The mesh, the tow's own nodes numbered from @p firstNewNode on.
    ParametricMesh result(std::size_t firstNewNode);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace detail
TOWGEOM_END_NAMESPACE
