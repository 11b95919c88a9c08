// Legacy ASCII VTK POLYDATA. CGAL writes only the XML (.vtp) flavour; the legacy format is the
// one every ParaView and VisIt version reads and that FE pre-processors import.
#include "towgeom/vtk_writer.hpp"

#include <iomanip>
#include <limits>

#include "export/vtk_format.hpp"
#include "io/output_files.hpp"

namespace towgeom {

namespace detail {

void writeVtkPolyData(std::ostream& out, const TriangleMesh& mesh, const std::string& title, const VtkCellData& cellData,
                      const VtkCellData& pointData)
{
    std::string header = title.substr(0, 255);
    for (char& c : header)
        if (c == '\n' || c == '\r') c = ' ';
    out << "# vtk DataFile Version 3.0\n" << header << "\nASCII\nDATASET POLYDATA\n";
    out << std::setprecision(std::numeric_limits<double>::max_digits10);
    out << "POINTS " << mesh.vertices.size() << " double\n";
    for (const Point3& p : mesh.vertices) out << p.x << ' ' << p.y << ' ' << p.z << '\n';
    out << "POLYGONS " << mesh.triangles.size() << ' ' << 4 * mesh.triangles.size() << '\n';
    for (const auto& t : mesh.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    const bool normals = !mesh.normals.empty() && mesh.normals.size() == mesh.vertices.size();
    if (normals || !pointData.empty()) out << "POINT_DATA " << mesh.vertices.size() << '\n';
    if (normals) {
        out << "NORMALS normals double\n";
        for (const Vector3& n : mesh.normals) out << n.x << ' ' << n.y << ' ' << n.z << '\n';
    }
    for (const auto& [name, values] : pointData) {
        out << "SCALARS " << name << " int 1\nLOOKUP_TABLE default\n";
        for (long v : values) out << v << '\n';
    }
    if (!cellData.empty()) {
        out << "CELL_DATA " << mesh.triangles.size() << '\n';
        for (const auto& [name, values] : cellData) {
            out << "SCALARS " << name << " int 1\nLOOKUP_TABLE default\n";
            for (long v : values) out << v << '\n';
        }
    }
}

}  // namespace detail

void writeVtk(const TriangleMesh& mesh, const std::string& path, const std::string& title)
{
    detail::OutputFiles files;
    detail::writeVtkPolyData(files.open(path), mesh, title);
    files.commit();
}

}  // namespace towgeom
