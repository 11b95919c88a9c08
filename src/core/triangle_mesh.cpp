// TriangleMesh measures, computed with CGAL's polygon mesh processing.
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include "towgeom/error.hpp"
#include "towgeom/triangle_mesh.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

double enclosedVolume(const TriangleMesh& mesh)
{
    using Kernel = CGAL::Simple_cartesian<double>;
    using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
    Mesh m;
    std::vector<Mesh::Vertex_index> ids;
    ids.reserve(mesh.vertices.size());
    for (const Point3& p : mesh.vertices) ids.push_back(m.add_vertex(Kernel::Point_3(p.x, p.y, p.z)));
    for (const auto& t : mesh.triangles) {
        if (t[0] >= ids.size() || t[1] >= ids.size() || t[2] >= ids.size())
            throw Error(ErrorCode::InvalidArgument, "triangle refers to a missing vertex");
        if (m.add_face(ids[t[0]], ids[t[1]], ids[t[2]]) == Mesh::null_face())
            throw Error(ErrorCode::InvalidArgument, "mesh is not an oriented 2-manifold: no enclosed volume");
    }
    if (!CGAL::is_closed(m)) throw Error(ErrorCode::InvalidArgument, "mesh is not closed: no enclosed volume");
    return CGAL::Polygon_mesh_processing::volume(m);
}

TOWGEOM_END_NAMESPACE
