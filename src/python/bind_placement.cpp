// Fibre placement: tool surfaces, reference curves and lay_courses().
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <sstream>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "path_argument.hpp"
#include "towgeom/course_coverage.hpp"
#include "towgeom/fibre_courses.hpp"
#include "towgeom/placement_surface.hpp"
#include "towgeom/reference_curve.hpp"

namespace towgeom::python {

namespace {

const char* offsetMethodName(SurfaceOffsetMethod method) noexcept
{
    return method == SurfaceOffsetMethod::Geodesic ? "geodesic" : "project-tangent";
}

py::array_t<double> uvArray(const std::vector<UV>& uv)
{
    py::array_t<double> out({uv.size(), std::size_t{2}});
    double* o = out.mutable_data();
    for (const UV& p : uv) *o++ = p.u, *o++ = p.v;
    return out;
}

py::array_t<double> valuesArray(const std::vector<double>& values) { return py::array_t<double>(values.size(), values.data()); }

Point3 toPoint(const std::array<double, 3>& x) { return {x[0], x[1], x[2]}; }

void bindCurves(py::module_& m)
{
    py::class_<CurveOnSurface>(m, "CurveOnSurface", "A curve on a tool surface: its (u, v) and its points, in order.")
        .def_property_readonly("points", [](const CurveOnSurface& c) { return pointsArray(c.points); }, "(n, 3) points.")
        .def_property_readonly("uv", [](const CurveOnSurface& c) { return uvArray(c.uv); }, "(n, 2) surface parameters.")
        .def("__len__", [](const CurveOnSurface& c) { return c.points.size(); });
    py::class_<PlacementSurface>(m, "PlacementSurface", "A tool surface for fibre placement: one face as a NURBS.")
        .def_readonly("name", &PlacementSurface::name)
        .def_readonly("face", &PlacementSurface::face, "Which face of the file (0-based).")
        .def_readonly("face_count", &PlacementSurface::faceCount, "Faces in the file (0 for a grid).")
        .def_readonly("fit_deviation", &PlacementSurface::fitDeviation, "Largest distance of a grid's points from the surface fitted to them.")
        .def_readonly("trim_edges", &PlacementSurface::trimEdges,
                      "Edges trimming the face where its boundary is not its (u,v) box (0: untrimmed); tows end on 'edge K'.")
        .def_readonly("faces", &PlacementSurface::faces, "The faces the surface is made of (several: joined side to side; empty for a grid).");
    m.def("read_placement_surface", [](const Path& path, std::size_t face) { return readPlacementSurface(path.text, face); }, py::arg("path"),
          py::arg("face") = 0,
          py::call_guard<py::gil_scoped_release>(), "Face FACE of a STEP or IGES file (or a .grid file of points) as a tool surface.");
    m.def("read_placement_surface", [](const Path& path, const std::vector<std::size_t>& faces) { return readPlacementSurface(path.text, faces); },
          py::arg("path"), py::arg("faces"), py::call_guard<py::gil_scoped_release>(),
          "Faces FACES of a STEP or IGES file joined side to side into one tool surface (courses cross the edges they share).");
    m.def("fit_placement_surface", [](const DoubleArray& grid, double tolerance) {
            if (grid.ndim() != 3 || grid.shape(2) != 3) throw py::value_error("grid must be an array of shape (nu, nv, 3)");
            const std::size_t nu = static_cast<std::size_t>(grid.shape(0)), nv = static_cast<std::size_t>(grid.shape(1));
            std::vector<Point3> points(nu * nv);
            if (!points.empty()) std::copy_n(grid.data(), 3 * points.size(), &points.front().x);
            py::gil_scoped_release released;
            return fitPlacementSurface(points, nu, nv, tolerance);
        }, py::arg("grid"), py::arg("tolerance") = 0.0,
        "A tool surface through a grid of points of shape (nu, nv, 3) (v fastest, as a .grid file), a bicubic B-spline.");
    m.def("reference_from_plane", [](const PlacementSurface& s, const std::array<double, 3>& origin, const std::array<double, 3>& normal,
                                     std::size_t points, bool reverse) {
            return referenceFromPlane(s, toPoint(origin), toPoint(normal), points, reverse);
        }, py::arg("surface"), py::arg("origin"), py::arg("normal"), py::arg("points") = 41, py::arg("reverse") = false,
        py::call_guard<py::gil_scoped_release>(),
        "The surface cut by the plane through ORIGIN of normal NORMAL (the cut nearest ORIGIN; on a trimmed face its run on the face), POINTS points by arc length.");
    m.def("reference_from_points", [](const PlacementSurface& s, const DoubleArray& points, double maxDistance) {
            const std::vector<Point3> p = toPoints(points, "points");
            py::gil_scoped_release released;
            return referenceFromPoints(s.surface, p, maxDistance);
        }, py::arg("surface"), py::arg("points"), py::arg("max_distance") = 0.0, "The curve through the surface points nearest an (n, 3) array.");
}

void bindPlan(py::module_& m)
{
    py::class_<TowPath>(m, "TowPath", "One tow of a course plan: its centreline and edges on the surface.")
        .def_readonly("name", &TowPath::name, "c<course>_t<tow>, both from 1, tows from right to left.")
        .def_readonly("course", &TowPath::course)
        .def_readonly("centreline", &TowPath::centreline)
        .def_readonly("left", &TowPath::left)
        .def_readonly("right", &TowPath::right)
        .def_readonly("length", &TowPath::length, "The centreline's length along the surface.")
        .def_readonly("start_boundary", &TowPath::startBoundary,
                      "The side of the face the centreline starts on (cut, carried or there already): a side of its (u,v) box ('u_min', "
                      "'u_max', 'v_min', 'v_max') or a trimmed face's 'edge K'; '' where it starts inside the face.")
        .def_readonly("end_boundary", &TowPath::endBoundary, "As start_boundary, at its end.")
        .def_property_readonly("geodesic_curvature", [](const TowPath& t) { return valuesArray(t.geodesicCurvature); },
                               "Per centreline point, its geodesic (in-plane, steering) curvature; positive turning left.")
        .def_readonly("steering_radius", &TowPath::steeringRadius, "1 / the largest |geodesic curvature| (inf for a geodesic).")
        .def_property_readonly("geodesic_distance", [](const TowPath& t) { return valuesArray(t.step.geodesicDistance); },
                               "Per centreline point, the measured distance along the surface from the curve it was offset from.");
    py::class_<CoursePlan>(m, "CoursePlan", "Courses of tows laid on a tool surface from a reference curve.")
        .def_readonly("reference", &CoursePlan::reference)
        .def_readonly("tows", &CoursePlan::tows)
        .def_readonly("tow_width", &CoursePlan::towWidth)
        .def_readonly("spacing", &CoursePlan::spacing)
        .def_readonly("tolerance", &CoursePlan::tolerance)
        .def_readonly("largest_step_error", &CoursePlan::largestStepError)
        .def_readonly("within_tolerance", &CoursePlan::withinTolerance)
        .def_readonly("off_surface", &CoursePlan::offSurface, "Courses and tows (names) wholly off the face: not laid.")
        .def_readonly("min_steering_radius", &CoursePlan::minSteeringRadius)
        .def_readonly("below_steering_radius", &CoursePlan::belowSteeringRadius,
                      "Tows (names) whose steering radius is below min_steering_radius.")
        .def_property_readonly("gaps", [](const CoursePlan& p) {
                py::list out;
                for (const TowGap& g : p.gaps)
                    out.append(py::dict(py::arg("right") = g.right, py::arg("left") = g.left, py::arg("between_courses") = g.betweenCourses,
                                        py::arg("width") = valuesArray(g.width), py::arg("min") = g.minWidth, py::arg("max") = g.maxWidth));
                return out;
            }, "Between neighbouring tows: per centreline point the gap (+) or overlap (-), and its extremes (dicts).")
        .def("to_json", [](const CoursePlan& p) {
            std::ostringstream out;
            writeCoursePlanJson(p, out);
            return out.str();
        }, "The plan as the CLI's courses.json.");
    py::class_<CourseCoverage>(m, "CourseCoverage", "How many tows cover each triangle of a tool surface's tessellation.")
        .def_property_readonly("nodes", [](const CourseCoverage& c) { return pointsArray(c.nodes); }, "(n, 3) nodes.")
        .def_property_readonly("triangles", [](const CourseCoverage& c) { return trianglesArray(c.triangles); }, "(m, 3) node indices.")
        .def_property_readonly("count", [](const CourseCoverage& c) {
                return py::array_t<std::size_t>(c.count.size(), c.count.data());
            }, "Per triangle, the tows covering it.")
        .def_property_readonly("area", [](const CourseCoverage& c) { return valuesArray(c.area); }, "Per triangle, its area.")
        .def_readonly("total_area", &CourseCoverage::totalArea)
        .def_readonly("uncovered", &CourseCoverage::uncovered, "Fraction of the area no tow covers.")
        .def_readonly("once", &CourseCoverage::once, "Fraction covered by one tow.")
        .def_readonly("several", &CourseCoverage::several, "Fraction covered by two or more.");
    m.def("course_coverage", [](const PlacementSurface& surface, const CoursePlan& plan, std::size_t cells) {
            py::gil_scoped_release released;
            return courseCoverage(surface, plan, cells);
        }, py::arg("surface"), py::arg("plan"), py::arg("cells") = 200,
        "The surface's (u,v) box as cells x cells cells (two triangles each; those off a trimmed face left out), each triangle's tows counted at its centroid.");
    const CourseOptions defaults;
    m.def("lay_courses", [](const PlacementSurface& surface, const CurveOnSurface& reference, double towWidth, std::size_t towsPerCourse,
                            std::size_t courses, double spacing, const std::string& method, double tolerance, int geodesicSteps,
                            double minSteeringRadius) {
            CourseOptions o;
            o.towWidth = towWidth, o.towsPerCourse = towsPerCourse, o.courses = courses, o.spacing = spacing, o.tolerance = tolerance;
            o.geodesicSteps = geodesicSteps;
            o.minSteeringRadius = minSteeringRadius;
            o.method = enumNamed(method, {SurfaceOffsetMethod::ProjectTangent, SurfaceOffsetMethod::Geodesic}, &offsetMethodName, "offset method");
            py::gil_scoped_release released;
            return layCourses(surface, reference, o);
        }, py::arg("surface"), py::arg("reference"), py::arg("tow_width"), py::arg("tows_per_course") = defaults.towsPerCourse,
        py::arg("courses") = defaults.courses, py::arg("spacing") = defaults.spacing, py::arg("method") = offsetMethodName(defaults.method),
        py::arg("tolerance") = defaults.tolerance, py::arg("geodesic_steps") = defaults.geodesicSteps,
        py::arg("min_steering_radius") = defaults.minSteeringRadius,
        "K courses of N tows of width W on the surface, the first course's centreline the reference, each next course to its "
        "left; method 'project-tangent' (Schueler et al.) or 'geodesic' (exact). Tows end at the face's boundary (its trimming "
        "curves where it has them).");
}

}  // namespace

void bindPlacement(py::module_& m)
{
    bindCurves(m);
    bindPlan(m);
}

}  // namespace towgeom::python
