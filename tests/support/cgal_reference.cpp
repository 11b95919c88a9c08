#include "cgal_reference.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/intersection.h>
#include <CGAL/Surface_mesh.h>

namespace towgeom::testing {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

Mesh toCgal(const TriangleMesh& m)
{
    Mesh out;
    std::vector<Mesh::Vertex_index> ids;
    for (const Point3& p : m.vertices) ids.push_back(out.add_vertex(Kernel::Point_3(p.x, p.y, p.z)));
    for (const auto& t : m.triangles) out.add_face(ids[t[0]], ids[t[1]], ids[t[2]]);
    return out;
}
}  // namespace

IntersectionPolylines surfaceIntersection(const TriangleMesh& a, const TriangleMesh& b)
{
    Mesh ma = toCgal(a), mb = toCgal(b);
    std::vector<std::vector<Kernel::Point_3>> polylines;
    CGAL::Polygon_mesh_processing::surface_intersection(ma, mb, std::back_inserter(polylines));
    IntersectionPolylines r;
    for (const auto& p : polylines) (p.size() > 2 && p.front() == p.back() ? r.closed : r.open) += 1;
    return r;
}

}  // namespace towgeom::testing
