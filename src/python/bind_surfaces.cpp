// Tow stacks (from NumPy arrays or files) and the fitted TowSurface.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <fstream>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "path_argument.hpp"
#include "towgeom/error.hpp"
#include "towgeom/stack_reader.hpp"
#include "towgeom/tow_stack.hpp"
#include "towgeom/tow_surface.hpp"

namespace towgeom::python {

namespace {

/// A stack from an array of shape (sections, points, 3).
TowStack stackFromArray(const std::string& name, const DoubleArray& sections, const std::string& source)
{
    if (sections.ndim() != 3 || sections.shape(2) != 3)
        throw py::value_error("a stack's sections must be an array of shape (sections, points, 3)");
    TowStack stack;
    stack.name = name;
    stack.source = source.empty() ? "<array " + name + ">" : source;
    const std::size_t count = static_cast<std::size_t>(sections.shape(0)), points = static_cast<std::size_t>(sections.shape(1));
    const double* x = sections.data();
    stack.sections.assign(count, std::vector<Point3>(points));
    for (std::size_t i = 0; i < count; ++i)
        for (std::size_t j = 0; j < points; ++j, x += 3) stack.sections[i][j] = {x[0], x[1], x[2]};
    return stack;
}

/// The stack's sections as a new array of shape (sections, points, 3); ragged stacks (invalid
/// ones) raise ValueError.
py::array_t<double> sectionsArray(const std::vector<std::vector<Point3>>& sections)
{
    const std::size_t points = sections.empty() ? 0 : sections.front().size();
    py::array_t<double> out({sections.size(), points, std::size_t{3}});
    double* x = out.mutable_data();
    for (const auto& section : sections) {
        if (section.size() != points) throw py::value_error("the sections hold different numbers of points");
        for (const Point3& p : section) *x++ = p.x, *x++ = p.y, *x++ = p.z;
    }
    return out;
}

/// Evaluates @p f(u, v) at every pair of the broadcast arrays u and v into an (..., 3) array.
template <class F>
py::array_t<double> evaluateAt(const DoubleArray& u, const DoubleArray& v, F&& f)
{
    const py::tuple broadcast = py::module_::import("numpy").attr("broadcast_arrays")(u, v);
    const auto bu = broadcast[0].cast<DoubleArray>(), bv = broadcast[1].cast<DoubleArray>();  // contiguous copies
    std::vector<py::ssize_t> shape(bu.shape(), bu.shape() + bu.ndim());
    shape.push_back(3);
    py::array_t<double> out(shape);
    const std::size_t n = static_cast<std::size_t>(bu.size());
    double* o = out.mutable_data();
    {
        py::gil_scoped_release released;
        for (std::size_t k = 0; k < n; ++k, o += 3) {
            const Point3 p = f(bu.data()[k], bv.data()[k]);
            o[0] = p.x, o[1] = p.y, o[2] = p.z;
        }
    }
    return out;
}

void bindStack(py::module_& m)
{
    py::class_<TowStack>(m, "Stack", "A tow as a stack of cross-section polygons (the input of TowSurface.fit).")
        .def(py::init(&stackFromArray), py::arg("name"), py::arg("sections"), py::arg("source") = "",
             "A stack named NAME from an array of shape (sections, points, 3): point j of section i at [i, j].")
        .def_readwrite("name", &TowStack::name, "The tow's name (output files are named after it).")
        .def_readonly("source", &TowStack::source, "Where the stack came from (a path), for messages.")
        .def_property_readonly("sections", [](const TowStack& s) { return sectionsArray(s.sections); },
                               "A copy of the sections, shape (sections, points, 3).")
        .def_property_readonly("section_count", &TowStack::sectionCount)
        .def_property_readonly("points_per_section", &TowStack::pointsPerSection)
        .def("validate", &validateStack, "Raises towgeom.Error naming the first defect (the checks fit() makes).")
        .def("write", [](const TowStack& s, const Path& path) {
                std::ofstream out(path.text);
                if (!out) throw Error(ErrorCode::WriteFailed, "cannot be opened for writing", path.text);
                writeStack(out, s);
                if (!out.flush()) throw Error(ErrorCode::WriteFailed, "writing failed", path.text);
            }, py::arg("path"), "Writes the stack as a .stw file.")
        .def("__repr__", [](const TowStack& s) {
            return "<towgeom.Stack '" + s.name + "': " + std::to_string(s.sectionCount()) + " sections of " +
                   std::to_string(s.pointsPerSection()) + " points>";
        });
    m.def("read_stack", [](const Path& path) { return readStackFile(path.text); }, py::arg("path"), py::call_guard<py::gil_scoped_release>(),
          "Reads a stack file (.stw); a defect raises towgeom.Error with the file and line.");
}

void bindSurface(py::module_& m)
{
    py::class_<TowSurface>(m, "TowSurface", "The exact periodic B-spline surface of one tow (u along it, v around it).")
        .def_static("fit", [](const TowStack& stack, const std::string& mode, double tolerance, double relativeTolerance) {
                FitOptions options;
                options.mode = enumNamed(mode, {FitMode::Interpolate, FitMode::Approximate, FitMode::ControlNet}, &fitModeName, "fit mode");
                options.tolerance = tolerance;
                options.relativeTolerance = relativeTolerance;
                py::gil_scoped_release released;
                return TowSurface::fit(stack, options);
            }, py::arg("stack"), py::arg("mode") = "interpolate", py::arg("tolerance") = 0.0, py::arg("relative_tolerance") = 1e-3,
            "Fits the surface through (interpolate), near (approximate, within tolerance or relative_tolerance times "
            "the tow size) or with the points as control net (controlnet) of the stack.")
        .def_property_readonly("name", &TowSurface::name)
        .def_property_readonly("section_count", &TowSurface::sectionCount)
        .def_property_readonly("points_per_section", &TowSurface::pointsPerSection)
        .def_property_readonly("tow_size", &TowSurface::towSize, "The tow's size: the scale of the relative tolerances.")
        .def_property_readonly("sections", [](const TowSurface& s) { return sectionsArray(s.sections()); },
                               "The fitted sections (the input, possibly reordered), shape (sections, points, 3).")
        .def_property_readonly("section_parameters", [](const TowSurface& s) { return py::array_t<double>(py::cast(s.sectionParameters())); },
                               "u of each section (the sections property's first index).")
        .def_property_readonly("point_parameters", [](const TowSurface& s) { return py::array_t<double>(py::cast(s.pointParameters())); },
                               "v of each point of a section (the sections property's second index).")
        .def_property_readonly("parameter_range", [](const TowSurface& s) {
                const ParameterRange r = s.parameterRange();
                return py::make_tuple(r.uMin, r.uMax, r.vMin, r.vMax);
            }, "(u_min, u_max, v_min, v_max); v is periodic with period v_max - v_min.")
        .def("points", [](const TowSurface& s, const DoubleArray& u, const DoubleArray& v) {
                return evaluateAt(u, v, [&](double a, double b) { return s.point(a, b); });
            }, py::arg("u"), py::arg("v"), "S(u, v) at every pair of the broadcast arrays u and v: shape (..., 3).")
        .def("normals", [](const TowSurface& s, const DoubleArray& u, const DoubleArray& v) {
                return evaluateAt(u, v, [&](double a, double b) { return s.normal(a, b); });
            }, py::arg("u"), py::arg("v"), "Unit outward normals at (u, v): shape (..., 3).")
        .def("closest_parameters", [](const TowSurface& s, const DoubleArray& points) {
                const std::vector<Point3> p = toPoints(points, "points");
                py::array_t<double> out({p.size(), std::size_t{2}});
                double* o = out.mutable_data();
                py::gil_scoped_release released;
                for (const Point3& q : p) {
                    const UV uv = s.closestParameters(q);
                    *o++ = uv.u, *o++ = uv.v;
                }
                return out;
            }, py::arg("points"), "(u, v) of the surface's point closest to each row of an (n, 3) array: shape (n, 2).")
        .def("section_area", &TowSurface::sectionArea, py::arg("u"))
        .def("volume", &TowSurface::volume, py::call_guard<py::gil_scoped_release>(), "Volume enclosed by the surface and its end sections.")
        .def("area", &TowSurface::area, py::call_guard<py::gil_scoped_release>(), "Area of the side surface.")
        .def("deviation", [](const TowSurface& s) {
                const Deviation d = s.deviation();
                return py::dict(py::arg("max") = d.max, py::arg("rms") = d.rms, py::arg("worst_section") = d.worstSection,
                                py::arg("worst_point") = d.worstPoint);
            }, "Distance of the input points to the surface: max, rms and where the largest is.")
        .def("tessellate", [](const TowSurface& s, std::size_t nu, std::size_t nv) {
                TriangleMesh mesh;
                {
                    py::gil_scoped_release released;
                    mesh = s.tessellate(nu, nv);
                }
                return py::make_tuple(pointsArray(mesh.vertices), trianglesArray(mesh.triangles));
            }, py::arg("nu"), py::arg("nv"), "A regular nu x nv grid of the side surface: (vertices (n, 3), triangles (m, 3)).")
        .def("__repr__", [](const TowSurface& s) { return "<towgeom.TowSurface '" + s.name() + "'>"; });
}

}  // namespace

void bindSurfaces(py::module_& m)
{
    bindStack(m);
    bindSurface(m);
}

}  // namespace towgeom::python
