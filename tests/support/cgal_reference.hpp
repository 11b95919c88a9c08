// Independent references for the tests, computed with CGAL on faceted meshes (not with the code
// under test): surface intersection polylines between two faceted tubes.
#pragma once

#include <towgeom/triangle_mesh.hpp>

#include <cstddef>
#include <vector>

namespace towgeom::testing {

struct IntersectionPolylines {
    std::size_t closed = 0;  ///< polylines whose ends coincide
    std::size_t open = 0;    ///< the others
};

/// CGAL::Polygon_mesh_processing::surface_intersection of two triangle meshes.
IntersectionPolylines surfaceIntersection(const TriangleMesh& a, const TriangleMesh& b);

}  // namespace towgeom::testing
