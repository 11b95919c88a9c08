// ParametricMesher: one tow's surface meshed in its (u,v) rectangle with CGAL's constrained
// Delaunay mesher, in a parameter space scaled by the surface's lengths along and around the
// tow, the intersection loops as constraints. Nodes on v = vMin and v = vMax are the same
// nodes, so the 3D mesh is a tube closed across the seam, open at its two ends.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "mesh/loop_nodes.hpp"
#include "towgeom/tow_surface.hpp"

namespace towgeom::detail {

/// Size and shape asked of the mesh.
struct MeshSizes {
    double edgeLength = 0.1;  ///< target 3D edge length h
    double minAngle = 20.0;   ///< degrees
};

/// One tow's mesh over the global nodes.
struct ParametricMesh {
    std::vector<std::array<std::size_t, 3>> triangles;  ///< global nodes, outward orientation
    std::vector<UV> centroids;                          ///< (u,v) centroid of each triangle
};

/// The surface's mean lengths along u and around v (the scale of the parameter space).
struct ParameterScale {
    double alongU = 1.0;
    double aroundV = 1.0;
};
ParameterScale parameterScale(const TowSurface& surface);

/// Points the mesher had to add on constraints, which the other side must have too.
struct MeshRequests {
    struct OnLoop {
        std::size_t a = 0, b = 0;  ///< the loop chord's end nodes (global)
        double t = 0.0;            ///< where along it (in this tow's scaled (u,v))
    };
    std::vector<double> seamU;     ///< u of seam nodes that one side of the seam lacks
    std::vector<OnLoop> onLoop;    ///< nodes on loop chords
    bool empty() const { return seamU.empty() && onLoop.empty(); }
};

/// Meshes @p surface with @p constraints (pieces of loops, nodes already global) and nodes on the
/// seam at least at @p seamU. The mesh's other nodes are appended to @p newNodes and numbered from
/// @p firstNewNode on. If the mesher had to split a constraint, the mesh is not usable: the
/// points are returned in @p requests (add them as nodes and mesh again).
ParametricMesh meshTow(const TowSurface& surface, const std::vector<LoopConstraint>& constraints,
                       const std::vector<double>& seamU, const MeshSizes& sizes, std::vector<Point3>& newNodes,
                       std::size_t firstNewNode, MeshRequests& requests);

}  // namespace towgeom::detail
