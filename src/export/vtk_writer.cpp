// Legacy ASCII VTK POLYDATA. CGAL writes only the XML (.vtp) flavour; the legacy format is the
// one every ParaView and VisIt version reads and that FE pre-processors import.
#include "towgeom/vtk_writer.hpp"

#include <ostream>

#include "export/number_writer.hpp"
#include "io/output_files.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

void writeVtk(const TriangleMesh& mesh, std::ostream& out, const std::string& title, const VtkIntegerFields& cellData,
              const VtkIntegerFields& pointData)
{
    for (const VtkIntegerFields* fs : {&cellData, &pointData})
        for (const auto& [name, values] : *fs)
            if (name.empty() || name.find_first_of(" \t\r\n") != std::string::npos)
                throw Error(ErrorCode::InvalidArgument, "VTK field name '" + name + "' is empty or holds white space");
    for (const auto& [name, values] : cellData)
        if (values.size() != mesh.triangles.size())
            throw Error(ErrorCode::InvalidArgument, "VTK cell field '" + name + "' has " + std::to_string(values.size()) +
                                                        " values for " + std::to_string(mesh.triangles.size()) + " triangles");
    for (const auto& [name, values] : pointData)
        if (values.size() != mesh.vertices.size())
            throw Error(ErrorCode::InvalidArgument, "VTK point field '" + name + "' has " + std::to_string(values.size()) +
                                                        " values for " + std::to_string(mesh.vertices.size()) + " vertices");
    std::string header = title.substr(0, 255);
    for (char& c : header)
        if (c == '\n' || c == '\r') c = ' ';
    out << "# vtk DataFile Version 3.0\n" << header << "\nASCII\nDATASET POLYDATA\n";
    detail::NumberWriter w(out);
    w.text("POINTS ").number(mesh.vertices.size()).text(" double").end();
    for (const Point3& p : mesh.vertices) w.number(p.x).text(" ").number(p.y).text(" ").number(p.z).end();
    w.text("POLYGONS ").number(mesh.triangles.size()).text(" ").number(4 * mesh.triangles.size()).end();
    for (const auto& t : mesh.triangles) w.text("3 ").number(t[0]).text(" ").number(t[1]).text(" ").number(t[2]).end();
    const bool normals = !mesh.normals.empty() && mesh.normals.size() == mesh.vertices.size();
    if (normals || !pointData.empty()) w.text("POINT_DATA ").number(mesh.vertices.size()).end();
    if (normals) {
        w.text("NORMALS normals double").end();
        for (const Vector3& n : mesh.normals) w.number(n.x).text(" ").number(n.y).text(" ").number(n.z).end();
    }
    // Integer fields as one FIELD block per section: a legacy reader (VTK's vtkPolyDataReader,
    // ParaView, VisIt) reads every array of a FIELD, but by default only the first of several
    // SCALARS blocks (a second field, e.g. region_id, did not show).
    const auto fields = [&](const VtkIntegerFields& fs) {
        w.text("FIELD FieldData ").number(fs.size()).end();
        for (const auto& [name, values] : fs) {
            w.text(name.c_str()).text(" 1 ").number(values.size()).text(" int").end();
            for (long v : values) w.number(v).end();
        }
    };
    if (!pointData.empty()) fields(pointData);
    if (!cellData.empty()) {
        w.text("CELL_DATA ").number(mesh.triangles.size()).end();
        fields(cellData);
    }
}

void writeVtk(const TriangleMesh& mesh, const std::string& path, const std::string& title)
{
    detail::OutputFiles files;
    writeVtk(mesh, files.open(path), title);
    files.commit();
}

TOWGEOM_END_NAMESPACE
