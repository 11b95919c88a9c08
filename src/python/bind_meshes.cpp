// The compatible surface meshes (TextileMesh), the tetrahedra inside them (VolumeMesh) and their
// writers. Node, triangle and per-triangle arrays are read-only views of the library's vectors
// (no copy), kept alive by the mesh they come from.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <type_traits>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "path_argument.hpp"
#include "towgeom/mesh_export.hpp"
#include "towgeom/resolve.hpp"
#include "towgeom/textile_mesh.hpp"
#include "towgeom/volume_mesh.hpp"
#include "towgeom/vtk_writer.hpp"

namespace towgeom::python {

namespace {

const char* towFaceName(TowFace face)
{
    switch (face) {
    case TowFace::Side: return "side";
    case TowFace::Start: return "start";
    case TowFace::End: return "end";
    case TowFace::Cell: return "cell";
    }
    return "unknown";
}

/// The tows of @p self (a TextileMesh) as a list of TowMesh objects referring into it.
py::list towMeshes(py::object self)
{
    TextileMesh& mesh = self.cast<TextileMesh&>();
    py::list out;
    for (TowMesh& tow : mesh.tows) out.append(py::cast(&tow, py::return_value_policy::reference_internal, self));
    return out;
}

/// Per triangle values of a tow given from Python: an integer array of @p count entries.
std::vector<long long> perTriangle(const py::handle& values, std::size_t count, const std::string& what)
{
    const py::array given = py::array::ensure(values);
    if (!given || (given.dtype().kind() != 'i' && given.dtype().kind() != 'u') || given.ndim() != 1 ||
        static_cast<std::size_t>(given.shape(0)) != count)
        throw py::type_error(what + " must be an integer array of one entry per triangle (" + std::to_string(count) + ")");
    const auto array = given.cast<py::array_t<long long, py::array::c_style | py::array::forcecast>>();
    return {array.data(), array.data() + count};
}

/// A mesh made from arrays: nodes (n, 3) and per tow a tuple (name, triangles (m, 3)[, region
/// (m,)[, face (m,)]]): regions -1 and side faces where not given.
TextileMesh meshFromArrays(const DoubleArray& nodes, const std::vector<py::tuple>& tows)
{
    TextileMesh mesh;
    mesh.nodes = toPoints(nodes, "nodes");
    for (const py::tuple& given : tows) {
        if (given.size() < 2 || given.size() > 4) throw py::type_error("each tow is (name, triangles[, region[, face]])");
        TowMesh tow;
        tow.name = given[0].cast<std::string>();
        const std::string what = "tow '" + tow.name + "'";
        tow.triangles = toTriangles(given[1], mesh.nodes.size(), what);
        const std::size_t m = tow.triangles.size();
        tow.region.assign(m, -1);
        tow.face.assign(m, TowFace::Side);
        if (given.size() > 2) {
            const std::vector<long long> region = perTriangle(given[2], m, what + "'s region");
            for (std::size_t t = 0; t < m; ++t) tow.region[t] = static_cast<long>(region[t]);
        }
        if (given.size() > 3) {
            const std::vector<long long> face = perTriangle(given[3], m, what + "'s face");
            for (std::size_t t = 0; t < m; ++t) {
                if (face[t] < 0 || face[t] > static_cast<long long>(TowFace::Cell)) throw py::value_error(what + ": a face is 0 to 3 (FACE_NAMES)");
                tow.face[t] = static_cast<TowFace>(face[t]);
            }
        }
        mesh.tows.push_back(std::move(tow));
    }
    return mesh;
}

void bindTowMesh(py::module_& m)
{
    static_assert(sizeof(TowFace) == 1 && std::is_same_v<std::underlying_type_t<TowFace>, unsigned char>);
    py::class_<TowMesh>(m, "TowMesh", "One tow's triangles in a TextileMesh (indices into TextileMesh.nodes).")
        .def_readonly("name", &TowMesh::name)
        .def_property_readonly("triangles", [](py::object self) { return trianglesView(self.cast<TowMesh&>().triangles, self); },
                               "(m, 3) uint64 node indices, a read-only view.")
        .def_property_readonly("region", [](py::object self) {
                const auto& r = self.cast<TowMesh&>().region;
                return vectorView(r.data(), r.size(), self);
            }, "Per triangle the index of its connected region in TextileMesh.regions, or -1 (int64 view).")
        .def_property_readonly("face", [](py::object self) {
                const auto& f = self.cast<TowMesh&>().face;
                return vectorView(reinterpret_cast<const unsigned char*>(f.data()), f.size(), self);
            }, "Per triangle: 0 the side surface, 1 the start cap, 2 the end cap, 3 a cell face (uint8 view; FACE_NAMES names them).")
        .def_property_readonly("fibre_direction", [](py::object self) {
                const auto& d = self.cast<TowMesh&>().fibreDirection;
                return pointsView(d, self);
            }, "Per triangle the unit fibre direction, (m, 3) view (empty when not computed).")
        .def_property_readonly("parameters", [](const TowMesh& t) {
                py::array_t<std::size_t> nodes(t.parameters.size());
                py::array_t<double> uv({t.parameters.size(), std::size_t{2}});
                std::size_t* n = nodes.mutable_data();
                double* p = uv.mutable_data();
                for (const auto& [node, at] : t.parameters) *n++ = node, *p++ = at.u, *p++ = at.v;
                return py::make_tuple(nodes, uv);
            }, "(nodes (k,), uv (k, 2)): the nodes on this tow's own surface and their (u, v) there.")
        .def("__len__", [](const TowMesh& t) { return t.triangles.size(); })
        .def("__repr__", [](const TowMesh& t) { return "<towgeom.TowMesh '" + t.name + "': " + std::to_string(t.triangles.size()) + " triangles>"; });
    m.attr("FACE_NAMES") = py::make_tuple(towFaceName(TowFace::Side), towFaceName(TowFace::Start), towFaceName(TowFace::End),
                                          towFaceName(TowFace::Cell));
}

void bindRegion(py::module_& m)
{
    py::class_<ConnectedRegion>(m, "ConnectedRegion", "Where two tows overlapped: one surface both tows' meshes share.")
        .def_readonly("primary", &ConnectedRegion::primary, "Tow index whose surface the region is (the rank rule).")
        .def_readonly("secondary", &ConnectedRegion::secondary)
        .def_readonly("loop", &ConnectedRegion::loop, "Index of its outer loop in the intersection report.")
        .def_readonly("holes", &ConnectedRegion::holes)
        .def_property_readonly("triangles", [](py::object self) {
                const auto& t = self.cast<ConnectedRegion&>().triangles;
                return vectorView(t.data(), t.size(), self);
            }, "Indices into the primary's TowMesh.triangles (uint64 view).")
        .def_property_readonly("nodes", [](py::object self) {
                const auto& n = self.cast<ConnectedRegion&>().nodes;
                return vectorView(n.data(), n.size(), self);
            })
        .def_readonly("area", &ConnectedRegion::area)
        .def_readonly("volume_removed", &ConnectedRegion::volumeRemoved)
        .def_readonly("note", &ConnectedRegion::note);
}

void bindCellMesh(py::module_& m)
{
    py::class_<CellMesh>(m, "CellMesh", "The faces of a cell's box meshed around the tows (the matrix's boundary).")
        .def_readonly("box", &CellMesh::box)
        .def_property_readonly("triangles", [](py::object self) { return trianglesView(self.cast<CellMesh&>().triangles, self); },
                               "(m, 3) node indices into TextileMesh.nodes (view).")
        .def_property_readonly("face", [](py::object self) {
                const auto& f = self.cast<CellMesh&>().face;
                return vectorView(reinterpret_cast<const unsigned char*>(f.data()), f.size(), self);
            }, "Per triangle the box's face: 0 xmin, 1 xmax, 2 ymin, 3 ymax, 4 zmin, 5 zmax (uint8 view).")
        .def_property_readonly("periodic_pairs", [](const CellMesh& c) {
                py::list out;
                for (const auto& pairs : c.periodicPairs) {
                    py::array_t<std::size_t> a({pairs.size(), std::size_t{2}});
                    std::size_t* o = a.mutable_data();
                    for (const auto& [lo, hi] : pairs) *o++ = lo, *o++ = hi;
                    out.append(a);
                }
                return out;
            }, "For x, y and z: the node pairs (min face, max face) a periodic cell's faces match, three (k, 2) arrays.");
}

void bindTextileMesh(py::module_& m)
{
    py::class_<TextileMesh>(m, "TextileMesh", "The tows' compatible surface meshes: one node array, triangles per tow.")
        .def_static("from_arrays", &meshFromArrays, py::arg("nodes"), py::arg("tows"),
                    "A mesh from nodes (n, 3) and per tow a tuple (name, triangles (m, 3)[, region (m,)[, face (m,)]]), "
                    "e.g. read back from meshio; regions -1 and side faces where not given.")
        .def_property_readonly("nodes", [](py::object self) { return pointsView(self.cast<TextileMesh&>().nodes, self); },
                               "(n, 3) float64 node positions, a read-only view.")
        .def_property_readonly("tows", &towMeshes, "The tows' meshes, in input order.")
        .def_property_readonly("regions", [](py::object self) {
                TextileMesh& mesh = self.cast<TextileMesh&>();
                py::list out;
                for (ConnectedRegion& r : mesh.regions) out.append(py::cast(&r, py::return_value_policy::reference_internal, self));
                return out;
            })
        .def_property_readonly("cell", [](py::object self) -> py::object {
                const auto& cell = self.cast<TextileMesh&>().cell;
                if (!cell) return py::none();
                return py::cast(&*cell, py::return_value_policy::reference_internal, self);
            }, "The cell's faces (a CellMesh) when the meshes were clipped to a cell, else None.")
        .def("tow_surface", [](const TextileMesh& mesh, std::size_t tow) {
                if (tow >= mesh.tows.size()) throw py::index_error("tow " + std::to_string(tow) + " of " + std::to_string(mesh.tows.size()));
                const TriangleMesh s = mesh.towSurface(tow);
                return py::make_tuple(pointsArray(s.vertices), trianglesArray(s.triangles));
            }, py::arg("tow"), "Tow TOW's surface with its own compact node numbering: (vertices, triangles).")
        .def("enclosed_volume", [](const TextileMesh& mesh, std::size_t tow) {
                if (tow >= mesh.tows.size()) throw py::index_error("tow " + std::to_string(tow) + " of " + std::to_string(mesh.tows.size()));
                return enclosedVolume(mesh.closedTowSurface(tow));
            }, py::arg("tow"), "Volume enclosed by tow TOW's closed mesh.")
        .def("write_gmsh", [](const TextileMesh& mesh, const Path& path) { writeGmsh(mesh, path.text); }, py::arg("path"),
             py::call_guard<py::gil_scoped_release>(), "Writes a Gmsh .msh (4.1) file: one physical surface per tow.")
        .def("write_abaqus", [](const TextileMesh& mesh, const Path& path) { writeAbaqus(mesh, path.text); }, py::arg("path"),
             py::call_guard<py::gil_scoped_release>(), "Writes an Abaqus/CalculiX .inp of the surfaces.")
        .def("__repr__", [](const TextileMesh& mesh) {
            return "<towgeom.TextileMesh: " + std::to_string(mesh.nodes.size()) + " nodes, " + std::to_string(mesh.tows.size()) + " tows, " +
                   std::to_string(mesh.regions.size()) + " regions>";
        });
}

void bindVolumeMesh(py::module_& m)
{
    py::class_<VolumeMesh>(m, "VolumeMesh", "Tetrahedra filling each tow (and the matrix of a cell), conforming at shared surfaces.")
        .def_property_readonly("nodes", [](py::object self) { return pointsView(self.cast<VolumeMesh&>().nodes, self); })
        .def_readonly("surface_nodes", &VolumeMesh::surfaceNodes, "How many leading nodes are the surface mesh's.")
        .def_property_readonly("tetrahedra", [](py::object self) {
                const auto& t = self.cast<VolumeMesh&>().tetrahedra;
                return rowsView(t.empty() ? nullptr : t.front().data(), t.size(), 4, self);
            }, "(k, 4) uint64 corner nodes, positively oriented (view).")
        .def_property_readonly("tow", [](py::object self) {
                const auto& t = self.cast<VolumeMesh&>().tow;
                return vectorView(t.data(), t.size(), self);
            }, "Per tetrahedron its tow index (the number of tows for a cell's matrix).")
        .def_property_readonly("edge_nodes", [](py::object self) {
                const auto& e = self.cast<VolumeMesh&>().edgeNodes;
                return rowsView(e.empty() ? nullptr : e.front().data(), e.size(), 6, self);
            }, "Quadratic tetrahedra (order=2): per tetrahedron its edges' middle nodes, (k, 6) in the order (0,1), (1,2), (2,0), "
               "(0,3), (1,3), (2,3) (Abaqus C3D10, VTK); empty for linear ones.")
        .def_property_readonly("fibre_direction", [](py::object self) { return pointsView(self.cast<VolumeMesh&>().fibreDirection, self); },
                               "Per tetrahedron its unit fibre direction once add_fibre_directions() set them, (k, 3); empty before.")
        .def_readonly("with_matrix", &VolumeMesh::withMatrix)
        .def_readonly("gmsh_seconds", &VolumeMesh::gmshSeconds)
        .def("tow_volume", &VolumeMesh::towVolume, py::arg("tow"))
        .def("__repr__", [](const VolumeMesh& v) { return "<towgeom.VolumeMesh: " + std::to_string(v.tetrahedra.size()) + " tetrahedra>"; });
}

}  // namespace

void bindMeshes(py::module_& m)
{
    bindTowMesh(m);
    bindRegion(m);
    bindCellMesh(m);
    bindTextileMesh(m);
    bindVolumeMesh(m);
}

void bindVolumes(py::module_& m)
{
    const VolumeMeshOptions defaults;
    m.def("mesh_volumes", [](const ResolveResult& result, bool optimize, int order, std::size_t threads, double growthRate, double maxSize) {
            VolumeMeshOptions o;
            o.optimize = optimize, o.order = order, o.threads = threads, o.growthRate = growthRate, o.maxSize = maxSize;
            return meshVolumes(result, o);
        }, py::arg("result"), py::arg("optimize") = defaults.optimize, py::arg("order") = defaults.order, py::arg("threads") = defaults.threads,
        py::arg("growth_rate") = defaults.growthRate, py::arg("max_size") = defaults.maxSize, py::call_guard<py::gil_scoped_release>(),
        "Tetrahedra inside the resolved surfaces (Gmsh's HXT); raises towgeom.Error where tows still overlap.");
    m.def("add_fibre_directions", &addFibreDirections, py::arg("volumes"), py::arg("tows"), py::arg("threads") = 0,
          py::call_guard<py::gil_scoped_release>(), "Sets each tetrahedron's fibre direction from its tow's surface.");
    m.def("write_vtu", [](const TextileMesh& mesh, const VolumeMesh& volumes, const Path& path) { writeVtu(mesh, volumes, path.text); }, py::arg("mesh"),
          py::arg("volumes"), py::arg("path"), py::call_guard<py::gil_scoped_release>(), "Writes the tetrahedra as a VTK .vtu file.");
}

}  // namespace towgeom::python
