// Independent references for the tests, computed with CGAL on faceted meshes (not with the code
// under test): surface intersection polylines between two faceted tubes, crossing triangles
// between two meshes on one node numbering, and volumes of closed meshes and their overlap.
#pragma once

#include <towgeom/point.hpp>
#include <towgeom/textile_mesh.hpp>
#include <towgeom/triangle_mesh.hpp>

#include <array>
#include <cstddef>
#include <vector>

namespace towgeom::testing {

struct IntersectionPolylines {
    std::size_t closed = 0;  ///< polylines whose ends coincide
    std::size_t open = 0;    ///< the others
};

/// CGAL::Polygon_mesh_processing::surface_intersection of two triangle meshes.
IntersectionPolylines surfaceIntersection(const TriangleMesh& a, const TriangleMesh& b);

/// The polylines of surfaceIntersection(): a closed one ends on its first point.
std::vector<std::vector<Point3>> surfaceIntersectionCurves(const TriangleMesh& a, const TriangleMesh& b);

/// What crossingTrianglePairs() found.
struct TriangleCrossings {
    std::size_t crossing = 0;         ///< pairs that intersect beyond what they share (see below)
    std::size_t crossingSharing = 0;  ///< of those, pairs that share one or two nodes
    std::size_t boxPairs = 0;         ///< pairs whose bounding boxes overlap (tested)
    std::size_t identical = 0;        ///< pairs with the same three nodes (a shared region): skipped
    std::size_t sharing = 0;          ///< box pairs that share one or two nodes
    std::vector<std::pair<std::size_t, std::size_t>> first;  ///< the first 100 crossing pairs (a's, b's triangle)
};

/// Pairs of triangles, one from @p a and one from @p b (node indices into @p nodes), that cross:
/// CGAL::box_intersection_d on the triangles' boxes, then exact predicates (Epick) per pair.
///  - Three shared nodes: the same triangle (a connected region shared by both tows); skipped.
///  - No shared node: crossing if CGAL::do_intersect(triangle, triangle).
///  - Two shared nodes (an edge): crossing only if the triangles are coplanar and lie on the same
///    side of the edge (overlap); otherwise they meet in the edge only.
///  - One shared node: crossing if the edge opposite the shared node in either triangle meets the
///    other triangle (they meet beyond the shared node exactly then, as in CGAL's own
///    self-intersection test); touching at the node only is not crossing.
/// This is stricter than skipping every pair that shares a node.
TriangleCrossings crossingTrianglePairs(const std::vector<Point3>& nodes,
                                        const std::vector<std::array<std::size_t, 3>>& a,
                                        const std::vector<std::array<std::size_t, 3>>& b);

/// crossingTrianglePairs() summed over every two tows of @p mesh: the crossing pairs.
std::size_t crossingPairsBetweenTows(const TextileMesh& mesh);

/// The crossing triangle pairs of two tows of a mesh, with where the first of them lies.
struct TowPairCrossings {
    std::size_t towA = 0, towB = 0;  ///< indices into TextileMesh::tows, towA < towB
    TriangleCrossings crossings;
    Point3 firstAt;                  ///< the centroid of a's triangle in the first crossing pair
};

/// A triangle of a TextileMesh: its tow (or kCellTriangles for the box's matrix faces) and its
/// index in that tow's (or CellMesh's) triangles.
struct MeshTriangle {
    static constexpr std::size_t kCellTriangles = static_cast<std::size_t>(-1);
    std::size_t tow = 0;
    std::size_t index = 0;
};

/// Every crossing pair of triangles among all of @p mesh's surfaces at once: within one tow,
/// between tows, and against the box's matrix faces (CellMesh::triangles), by
/// crossingTrianglePairs()'s rules (a triangle in two tows' lists, a region's, taken once). This is what
/// a tetrahedral mesher needs of its boundary: no two facets meeting beyond what they share.
struct SurfaceCrossings {
    std::size_t crossing = 0;                                    ///< crossing pairs, each counted once
    std::vector<std::pair<MeshTriangle, MeshTriangle>> first;    ///< up to the first 50 of them
};
SurfaceCrossings crossingsInSurfaces(const TextileMesh& mesh);

/// crossingTrianglePairs() for every two tows of @p mesh, only the pairs that cross.
std::vector<TowPairCrossings> crossingsByTowPair(const TextileMesh& mesh);

/// The least distance between the triangles of @p a and those of @p b that come within
/// @p within of each other (boxes grown by it, CGAL::box_intersection_d), +infinity when none
/// do: for each such pair the least of the six vertex-triangle and nine edge-edge distances
/// (CGAL::squared_distance, Epick), which is the triangles' distance when they do not
/// intersect (0 where they do). Pairs are taken nearest boxes first and no further once their
/// boxes lie further apart than the least distance found (they cannot come nearer).
double minimumDistance(const TriangleMesh& a, const TriangleMesh& b, double within);

/// CGAL::Polygon_mesh_processing::volume of a closed triangle mesh (oriented outwards first).
double closedMeshVolume(const TriangleMesh& m);

/// The volume of the intersection of two closed triangle meshes:
/// CGAL::Polygon_mesh_processing::corefine_and_compute_intersection, then PMP::volume.
/// Inputs are oriented to bound a volume first.
/// @throws std::runtime_error if an input does not bound a volume or the corefinement fails.
double intersectionVolume(const TriangleMesh& a, const TriangleMesh& b);

/// The volume of @p a minus every mesh of @p minus (closed triangle meshes):
/// CGAL::Polygon_mesh_processing::corefine_and_compute_difference one after the other, then
/// PMP::volume. Inputs are oriented to bound a volume first.
/// @throws std::runtime_error if an input does not bound a volume or a corefinement fails.
double differenceVolume(const TriangleMesh& a, const std::vector<TriangleMesh>& minus);

}  // namespace towgeom::testing
