// Exports beyond the meshes' own writers: each tow's closed surface as VTK or STL, the meshes
// with their tetrahedra (Gmsh, Abaqus/CalculiX), and the exact trimmed B-rep (STEP).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "bindings.hpp"
#include "path_argument.hpp"
#include "towgeom/mesh_export.hpp"
#include "towgeom/stl_writer.hpp"
#include "towgeom/trimmed_brep.hpp"
#include "towgeom/vtk_writer.hpp"

namespace towgeom::python {

namespace {

const TowMesh& towOf(const TextileMesh& mesh, std::size_t tow)
{
    if (tow >= mesh.tows.size()) throw py::index_error("tow " + std::to_string(tow) + " of " + std::to_string(mesh.tows.size()));
    return mesh.tows[tow];
}

void bindMeshWriters(py::module_& m)
{
    py::class_<TextileMesh> mesh = py::reinterpret_borrow<py::class_<TextileMesh>>(m.attr("TextileMesh"));
    mesh.def("write_tow_vtk", [](const TextileMesh& mesh, std::size_t tow, const Path& path) {
                writeVtk(mesh.closedTowSurface(tow), path.text, towOf(mesh, tow).name);
            }, py::arg("tow"), py::arg("path"), py::call_guard<py::gil_scoped_release>(),
            "Writes tow TOW's closed surface as legacy VTK polydata.")
        .def("write_tow_stl", [](const TextileMesh& mesh, std::size_t tow, const Path& path) {
                towOf(mesh, tow);
                writeStl(mesh.closedTowSurface(tow), path.text);
            }, py::arg("tow"), py::arg("path"), py::call_guard<py::gil_scoped_release>(), "Writes tow TOW's closed surface as binary STL.")
        .def("write_gmsh_volumes", [](const TextileMesh& mesh, const VolumeMesh& volumes, const Path& path) { writeGmsh(mesh, volumes, path.text); },
             py::arg("volumes"),
             py::arg("path"), py::call_guard<py::gil_scoped_release>(), "Writes the surfaces and the tetrahedra (mesh_volumes) as one Gmsh .msh.")
        .def("write_abaqus_volumes", [](const TextileMesh& mesh, const VolumeMesh& volumes, const Path& path, bool periodic) {
                if (periodic) writeAbaqusPeriodic(mesh, volumes, path.text);
                else writeAbaqus(mesh, volumes, path.text);
            }, py::arg("volumes"), py::arg("path"), py::arg("periodic") = false, py::call_guard<py::gil_scoped_release>(),
            "Writes the tetrahedra as an Abaqus/CalculiX .inp; periodic=True adds the periodic cell's node pairs (*EQUATION).");
}

void bindBrep(py::module_& m)
{
    py::class_<BrepSolid>(m, "BrepSolid", "One tow's (or the matrix's) solid of the trimmed B-rep.")
        .def_readonly("name", &BrepSolid::name)
        .def_readonly("volume", &BrepSolid::volume)
        .def_readonly("area", &BrepSolid::area)
        .def_readonly("faces", &BrepSolid::faces)
        .def_readonly("shared_faces", &BrepSolid::sharedFaces)
        .def_readonly("valid", &BrepSolid::valid, "OpenCASCADE's checker accepts the solid.")
        .def_readonly("max_tolerance", &BrepSolid::maxTolerance);
    py::class_<TrimmedBrep>(m, "TrimmedBrep", "The resolved tows as exact trimmed solids sharing their regions' faces.")
        .def_property_readonly("solids", &TrimmedBrep::solids)
        .def_property_readonly("shared_face_count", &TrimmedBrep::sharedFaceCount)
        .def_property_readonly("matrix", &TrimmedBrep::matrix)
        .def("write_step", [](const TrimmedBrep& b, const Path& path) { b.writeStep(path.text); }, py::arg("path"),
             py::call_guard<py::gil_scoped_release>(), "Writes the solids as STEP (AP214, named).")
        .def("write_brep", [](const TrimmedBrep& b, const Path& path) { b.writeBrep(path.text); }, py::arg("path"),
             py::call_guard<py::gil_scoped_release>(), "Writes OpenCASCADE's native .brep.");
    const BrepOptions defaults;
    m.def("trimmed_brep", [](const std::vector<TowSurface>& tows, const ResolveResult& resolved, double tolerance, double relativeTolerance,
                             bool matrix) {
            BrepOptions o;
            o.tolerance = tolerance, o.relativeTolerance = relativeTolerance, o.matrix = matrix;
            return trimmedBrep(tows, resolved, o);
        }, py::arg("tows"), py::arg("resolved"), py::arg("tolerance") = defaults.tolerance, py::arg("relative_tolerance") = defaults.relativeTolerance,
        py::arg("matrix") = defaults.matrix, py::call_guard<py::gil_scoped_release>(),
        "The resolved tows as exact trimmed B-spline solids (the regions' faces shared), for STEP.");
}

}  // namespace

void bindExports(py::module_& m)
{
    bindMeshWriters(m);
    bindBrep(m);
}

}  // namespace towgeom::python
