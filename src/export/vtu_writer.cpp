// The tetrahedra of a volume mesh as a VTK XML unstructured grid (ASCII) for ParaView.
#include <ostream>

#include "export/number_writer.hpp"
#include "export/volume_mesh_checks.hpp"
#include "io/output_files.hpp"
#include "towgeom/error.hpp"
#include "towgeom/mesh_export.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

void writeVtu(const TextileMesh& mesh, const VolumeMesh& volumes, std::ostream& out)
{
    detail::checkVolumeMeshOf(mesh, volumes);
    const bool fibres = !volumes.fibreDirection.empty();
    const std::size_t towCount = mesh.tows.size();
    detail::NumberWriter w(out);
    w.text("<?xml version=\"1.0\"?>").end();
    w.text("<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">").end();
    w.text("<UnstructuredGrid>").end();
    w.text("<Piece NumberOfPoints=\"").number(volumes.nodes.size()).text("\" NumberOfCells=\"").number(volumes.tetrahedra.size()).text("\">").end();
    w.text("<Points>").end().text("<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">").end();
    for (const Point3& p : volumes.nodes) w.number(p.x).text(" ").number(p.y).text(" ").number(p.z).end();
    w.text("</DataArray>").end().text("</Points>").end();
    w.text("<Cells>").end().text("<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">").end();
    // Quadratic tetrahedra (VTK_QUADRATIC_TETRA): the middle nodes in edgeNodes' order, VTK's.
    const bool quadratic = !volumes.edgeNodes.empty();
    for (std::size_t k = 0; k < volumes.tetrahedra.size(); ++k) {
        const auto& t = volumes.tetrahedra[k];
        w.number(t[0]).text(" ").number(t[1]).text(" ").number(t[2]).text(" ").number(t[3]);
        if (quadratic)
            for (std::size_t m : volumes.edgeNodes[k]) w.text(" ").number(m);
        w.end();
    }
    const std::size_t per = quadratic ? 10 : 4;
    w.text("</DataArray>").end().text("<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">").end();
    for (std::size_t k = 0; k < volumes.tetrahedra.size(); ++k) w.number(per * (k + 1)).end();
    w.text("</DataArray>").end().text("<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">").end();
    for (std::size_t k = 0; k < volumes.tetrahedra.size(); ++k) w.text(quadratic ? "24" : "10").end();  // VTK_(QUADRATIC_)TETRA
    w.text("</DataArray>").end().text("</Cells>").end();
    w.text("<CellData Scalars=\"tow_id\"").text(fibres ? " Vectors=\"fibre_direction\">" : ">").end();
    w.text("<DataArray type=\"Int32\" Name=\"tow_id\" format=\"ascii\">").end();
    for (std::size_t t : volumes.tow) {
        if (t == towCount)
            w.text("-1").end();
        else
            w.number(t).end();
    }
    w.text("</DataArray>").end().text("<DataArray type=\"Int32\" Name=\"material\" format=\"ascii\">").end();
    for (std::size_t t : volumes.tow) w.text(t == towCount ? "0" : "1").end();
    w.text("</DataArray>").end();
    if (fibres) {
        w.text("<DataArray type=\"Float64\" Name=\"fibre_direction\" NumberOfComponents=\"3\" format=\"ascii\">").end();
        for (const Vector3& d : volumes.fibreDirection) w.number(d.x).text(" ").number(d.y).text(" ").number(d.z).end();
        w.text("</DataArray>").end();
    }
    w.text("</CellData>").end().text("</Piece>").end().text("</UnstructuredGrid>").end().text("</VTKFile>").end();
    w.flush();
}

void writeVtu(const TextileMesh& mesh, const VolumeMesh& volumes, const std::string& path)
{
    detail::OutputFiles files;
    writeVtu(mesh, volumes, files.open(path));
    files.commit();
}

TOWGEOM_END_NAMESPACE
