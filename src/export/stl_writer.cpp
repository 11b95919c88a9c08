#include "towgeom/stl_writer.hpp"

#include <CGAL/IO/STL.h>
#include <CGAL/IO/io.h>
#include <CGAL/Simple_cartesian.h>

#include "io/output_files.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

void writeStl(const TriangleMesh& mesh, std::ostream& out)
{
    using Point = CGAL::Simple_cartesian<double>::Point_3;
    std::vector<Point> points;
    points.reserve(mesh.vertices.size());
    for (const Point3& p : mesh.vertices) points.emplace_back(p.x, p.y, p.z);
    CGAL::IO::set_binary_mode(out);
    if (!CGAL::IO::write_STL(out, points, mesh.triangles)) throw Error(ErrorCode::WriteFailed, "CGAL could not write the STL");
}

void writeStl(const TriangleMesh& mesh, const std::string& path)
{
    detail::OutputFiles files;
    try {
        writeStl(mesh, files.open(path));
    } catch (const Error& e) {
        throw Error(e.code(), e.message(), path);
    }
    files.commit();
}

TOWGEOM_END_NAMESPACE
