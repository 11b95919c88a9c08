// What every stage that makes a TextileMesh does last: drops the nodes no triangle uses (loop
// nodes inside a removed triangle, a secondary's nodes inside a region it gave up) and measures
// the triangles' quality.
#pragma once

#include <vector>

#include "mesh/angle_bound.hpp"
#include "towgeom/intersection_loop.hpp"
#include "towgeom/resolve.hpp"
#include "towgeom/textile_mesh.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// Keeps only the nodes of @p mesh that a tow's triangle uses, numbered in the order the tows'
/// triangles first use them. TowMesh::parameters, TextileMesh::loops and ConnectedRegion::
/// loopNodes lose their unused nodes (parameters and region nodes sorted by the new numbers);
/// a triple point whose node is unused is dropped, and a sharp corner keeps only its triangles
/// still in its tow's own mesh (it is dropped with none).
void keepUsedNodes(TextileMesh& mesh);

/// Keeps the triple points of @p mesh whose three tow pairs each have a loop in
/// TextileMesh::loops through the point's node (@p loops: the intersection report's, for the
/// pairs) and whose node all three tows' meshes use: where a pair was left out, its loops'
/// nodes may stay in the meshes, but no three resolved loops cross there.
void keepResolvedTriplePoints(TextileMesh& mesh, const std::vector<IntersectionLoop>& loops);

/// The smallest angles of @p mesh's distinct triangles (a region's copy in its secondary is not
/// counted again), judged against @p angleBound (degrees) away from the mesh's sharp corners
/// and against a third of a corner's angle in its triangles (SharpCorner::triangles);
/// facesOverBounds is left 0.
MeshQuality meshQuality(const TextileMesh& mesh, double angleBound);

}  // namespace detail
TOWGEOM_END_NAMESPACE
