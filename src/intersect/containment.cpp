#include "intersect/containment.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

bool pointOfInsideOther(const TowSurface& inner, const TowSurface& outer)
{
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Mesh = CGAL::Surface_mesh<K::Point_3>;
    TowStack stack;
    stack.name = outer.name();
    stack.sections = outer.sections();
    const TriangleMesh tube = facetedTube(stack, true);
    Mesh mesh;
    std::vector<Mesh::Vertex_index> v;
    for (const Point3& p : tube.vertices) v.push_back(mesh.add_vertex(K::Point_3(p.x, p.y, p.z)));
    for (const auto& t : tube.triangles) mesh.add_face(v[t[0]], v[t[1]], v[t[2]]);
    const CGAL::Side_of_triangle_mesh<Mesh, K> side(mesh);
    const std::vector<std::vector<Point3>>& s = inner.sections();
    const Point3 p = s[s.size() / 2][0];
    return side(K::Point_3(p.x, p.y, p.z)) == CGAL::ON_BOUNDED_SIDE;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
