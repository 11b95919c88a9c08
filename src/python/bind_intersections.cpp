// intersect_tows(): the loops of every interpenetration, with their curves in both tows' (u, v).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <sstream>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "path_argument.hpp"
#include "interruptible.hpp"
#include "towgeom/intersection_report_json.hpp"
#include "towgeom/tow_intersection.hpp"

namespace towgeom::python {

namespace {

/// The loop's points as columns: which = 0 the 3D points (n, 3), 1 (u, v) on tow A, 2 on tow B (n, 2).
py::array_t<double> loopColumns(const IntersectionLoop& loop, int which)
{
    const std::vector<LoopPoint>& points = loop.points();
    const std::size_t width = which == 0 ? 3 : 2;
    py::array_t<double> out({points.size(), width});
    double* o = out.mutable_data();
    for (const LoopPoint& p : points) {
        if (which == 0) *o++ = p.point.x, *o++ = p.point.y, *o++ = p.point.z;
        const UV uv = which == 1 ? p.onA : p.onB;
        if (which != 0) *o++ = uv.u, *o++ = uv.v;
    }
    return out;
}

const char* openKindName(IntersectionLoop::OpenKind kind)
{
    switch (kind) {
    case IntersectionLoop::OpenKind::None: return "none";
    case IntersectionLoop::OpenKind::ReachesEndOfA: return "reaches_end_of_a";
    case IntersectionLoop::OpenKind::ReachesEndOfB: return "reaches_end_of_b";
    case IntersectionLoop::OpenKind::WalkStops: return "walk_stops";
    case IntersectionLoop::OpenKind::DoesNotClose: return "does_not_close";
    }
    return "unknown";
}

const char* findingKindName(PairFinding::Kind kind)
{
    switch (kind) {
    case PairFinding::Kind::Touching: return "touching";
    case PairFinding::Kind::Nested: return "nested";
    case PairFinding::Kind::Contact: return "contact";
    case PairFinding::Kind::Incomplete: return "incomplete";
    }
    return "unknown";
}

void bindOptions(py::module_& m)
{
    py::class_<IntersectionOptions>(m, "IntersectionOptions",
                                    "Tolerances and threads of intersect_tows() (keyword arguments set the same names).")
        .def(py::init([](const py::kwargs& keywords) {
                 py::object options = py::cast(IntersectionOptions{});
                 applyKeywords(options, keywords);
                 return options.cast<IntersectionOptions>();
             }))
        .def_readwrite("tolerance", &IntersectionOptions::tolerance, "Absolute distance tolerance of the loops' points (0: relative).")
        .def_readwrite("relative_tolerance", &IntersectionOptions::relativeTolerance, "The same relative to the tow size.")
        .def_readwrite("chordal_tolerance", &IntersectionOptions::chordalTolerance, "Absolute chordal tolerance of the curves (0: relative).")
        .def_readwrite("relative_chordal_tolerance", &IntersectionOptions::relativeChordalTolerance)
        .def_readwrite("threads", &IntersectionOptions::threads, "Worker threads (0: all hardware threads).");
}

LoopSide sideNamed(const std::string& side)
{
    if (side == "a" || side == "A") return LoopSide::A;
    if (side == "b" || side == "B") return LoopSide::B;
    throw py::value_error("side is 'a' or 'b', not '" + side + "'");
}

void bindLoop(py::module_& m)
{
    py::class_<IntersectionLoop>(m, "IntersectionLoop", "One intersection curve of two tows, in 3D and in both tows' (u, v).")
        .def_property_readonly("tow_a", &IntersectionLoop::towA, "Index of tow A (the lower index).")
        .def_property_readonly("tow_b", &IntersectionLoop::towB)
        .def_property_readonly("closed", &IntersectionLoop::closed)
        .def_property_readonly("open_reason", &IntersectionLoop::openReason, "Why the curve is open (empty when closed).")
        .def_property_readonly("open_kind", [](const IntersectionLoop& l) { return openKindName(l.openKind()); })
        .def_property_readonly("points", [](const IntersectionLoop& l) { return loopColumns(l, 0); }, "The curve's points, (n, 3).")
        .def_property_readonly("uv_a", [](const IntersectionLoop& l) { return loopColumns(l, 1); }, "(u, v) on tow A, (n, 2).")
        .def_property_readonly("uv_b", [](const IntersectionLoop& l) { return loopColumns(l, 2); }, "(u, v) on tow B, (n, 2).")
        .def("length", &IntersectionLoop::length)
        .def("winds_around", [](const IntersectionLoop& l, const std::string& side) {
                return l.windsAround(sideNamed(side));
            }, py::arg("side"), "Whether the curve goes around tow 'a' or 'b' (around its v direction).")
        .def("max_distance", [](const IntersectionLoop& l, const std::string& side) {
                return l.maxDistance(sideNamed(side));
            }, py::arg("side"), "Largest distance of the points to tow 'a' or 'b'.")
        .def("__repr__", [](const IntersectionLoop& l) {
            return "<towgeom.IntersectionLoop tows " + std::to_string(l.towA()) + "-" + std::to_string(l.towB()) + ", " +
                   std::to_string(l.points().size()) + " points, " + (l.closed() ? "closed>" : "open>");
        });
}

void bindReport(py::module_& m)
{
    py::class_<IntersectionReport>(m, "IntersectionReport", "Every intersection loop of a set of tows, and what else was found.")
        .def_readonly("loops", &IntersectionReport::loops)
        .def_readonly("tow_pairs", &IntersectionReport::towPairs)
        .def_readonly("pairs_tested", &IntersectionReport::pairsTested)
        .def_readonly("seeds", &IntersectionReport::seeds)
        .def_readonly("walks", &IntersectionReport::walks)
        .def_property_readonly("open_count", &IntersectionReport::openCount)
        .def_property_readonly("findings", [](const IntersectionReport& r) {
                py::list out;
                for (const PairFinding& f : r.findings)
                    out.append(py::dict(py::arg("tow_a") = f.towA, py::arg("tow_b") = f.towB, py::arg("kind") = findingKindName(f.kind),
                                        py::arg("message") = f.message));
                return out;
            }, "Pairs that touch, nest, press in contact or were searched incompletely (dicts).")
        .def_property_readonly("timings", [](const IntersectionReport& r) {
                return py::dict(py::arg("broad_phase") = r.timings.broadPhase, py::arg("exact") = r.timings.exact);
            }, "Seconds spent (dict).")
        .def("to_json", [](const IntersectionReport& r, const std::vector<TowSurface>& tows) {
                std::ostringstream out;
                writeIntersectionReport(r, tows, out);
                return out.str();
            }, py::arg("tows"), "The report as JSON text (the CLI's report format).")
        .def("write", [](const IntersectionReport& r, const std::vector<TowSurface>& tows, const Path& path) { writeIntersectionReport(r, tows, path.text); },
             py::arg("tows"), py::arg("path"), py::call_guard<py::gil_scoped_release>(), "Writes the report as JSON.")
        .def_static("from_json", [](const std::string& text, const std::vector<TowSurface>& tows) {
                std::istringstream in(text);
                return readIntersectionReport(in, tows, "<json text>");
            }, py::arg("text"), py::arg("tows"), py::call_guard<py::gil_scoped_release>(), "A report from to_json()'s text, for the same tows.")
        .def("__len__", [](const IntersectionReport& r) { return r.loops.size(); })
        .def("__repr__", [](const IntersectionReport& r) {
            return "<towgeom.IntersectionReport: " + std::to_string(r.loops.size()) + " loops, " + std::to_string(r.openCount()) + " open>";
        });
    m.def("read_intersection_report", [](const Path& path, const std::vector<TowSurface>& tows) { return readIntersectionReport(path.text, tows); },
          py::arg("path"), py::arg("tows"), py::call_guard<py::gil_scoped_release>(),
          "Reads a report written by IntersectionReport.write() (or the CLI) for the same tows.");
}

}  // namespace

void bindIntersections(py::module_& m)
{
    bindOptions(m);
    bindLoop(m);
    bindReport(m);
    m.def("intersect_tows", [](const std::vector<TowSurface>& tows, std::optional<IntersectionOptions> options, py::object progress,
                               const py::kwargs& keywords) {
            py::object chosen = py::cast(options.value_or(IntersectionOptions{}));
            applyKeywords(chosen, keywords);
            IntersectionOptions o = chosen.cast<IntersectionOptions>();
            PythonProgress monitor(progress);
            o.monitor = &monitor;
            return runInterruptible(monitor, [&] { return intersectTows(tows, o); });
        }, py::arg("tows"), py::arg("options") = py::none(), py::arg("progress") = py::none(),
        "Every intersection loop of the tows (a list of TowSurface). Options as an IntersectionOptions and/or keyword "
        "arguments (tolerance=..., threads=...); progress(stage, done, total) is called as the work goes on; Ctrl-C "
        "stops it and raises KeyboardInterrupt.");
}

}  // namespace towgeom::python
