#include "towgeom/stl_writer.hpp"

#include <CGAL/IO/STL.h>
#include <CGAL/IO/io.h>
#include <CGAL/Simple_cartesian.h>

#include "export/stl_format.hpp"
#include "io/output_files.hpp"
#include "towgeom/error.hpp"

namespace towgeom {

namespace detail {

bool writeStlBinary(std::ostream& out, const TriangleMesh& mesh)
{
    using Point = CGAL::Simple_cartesian<double>::Point_3;
    std::vector<Point> points;
    points.reserve(mesh.vertices.size());
    for (const Point3& p : mesh.vertices) points.emplace_back(p.x, p.y, p.z);
    CGAL::IO::set_binary_mode(out);
    return CGAL::IO::write_STL(out, points, mesh.triangles);
}

}  // namespace detail

void writeStl(const TriangleMesh& mesh, const std::string& path)
{
    detail::OutputFiles files;
    if (!detail::writeStlBinary(files.open(path), mesh)) throw Error(ErrorCode::WriteFailed, "STL writer failed", path);
    files.commit();
}

}  // namespace towgeom
