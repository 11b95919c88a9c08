// resolve_textile(): loops, meshes and connected regions in one call, with the C++ options.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <array>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "interruptible.hpp"
#include "towgeom/connect_regions.hpp"
#include "towgeom/mesh_tows.hpp"
#include "towgeom/method_comparison.hpp"
#include "towgeom/resolve.hpp"

namespace towgeom::python {

namespace {

ResolutionMethod methodNamed(const std::string& name)
{
    return enumNamed(name, {ResolutionMethod::Connect, ResolutionMethod::Symmetric, ResolutionMethod::Shrink}, &resolutionMethodName,
                     "resolution method");
}

const char* unresolvedReasonName(UnresolvedPair::Reason reason)
{
    switch (reason) {
    case UnresolvedPair::Reason::MeshFailed: return "mesh_failed";
    case UnresolvedPair::Reason::LoopsMeet: return "loops_meet";
    case UnresolvedPair::Reason::RegionFailed: return "region_failed";
    case UnresolvedPair::Reason::NotSeparated: return "not_separated";
    }
    return "unknown";
}

const char* skippedReasonName(SkippedLoop::Reason reason)
{
    switch (reason) {
    case SkippedLoop::Reason::OpenCurve: return "open_curve";
    case SkippedLoop::Reason::AroundBothTows: return "around_both_tows";
    case SkippedLoop::Reason::AroundTowWithoutCaps: return "around_tow_without_caps";
    case SkippedLoop::Reason::BandsDoNotAlternate: return "bands_do_not_alternate";
    case SkippedLoop::Reason::CrossesCap: return "crosses_cap";
    case SkippedLoop::Reason::OutsideCell: return "outside_cell";
    case SkippedLoop::Reason::Contact: return "contact";
    }
    return "unknown";
}

using Triple = std::array<double, 3>;

void bindMeshOptions(py::module_& m)
{
    py::class_<MeshOptions>(m, "MeshOptions", "Size and quality of the parametric surface meshes (keyword arguments set the same names).")
        .def(py::init([](const py::kwargs& keywords) {
            py::object options = py::cast(MeshOptions{});
            applyKeywords(options, keywords);
            return options.cast<MeshOptions>();
        }))
        .def_static("for_volume", &MeshOptions::forVolume, "The preset for a volume mesh: sizes graded by curvature.")
        .def_readwrite("edge_length", &MeshOptions::edgeLength, "Target edge length (0: relative_edge_length times the tow size).")
        .def_readwrite("relative_edge_length", &MeshOptions::relativeEdgeLength)
        .def_readwrite("min_angle", &MeshOptions::minAngle, "Smallest triangle angle asked of the mesher, degrees.")
        .def_readwrite("loop_spacing", &MeshOptions::loopSpacing, "Node spacing along the loops (0: the edge length).")
        .def_readwrite("max_triangles", &MeshOptions::maxTriangles, "Refuse (towgeom.Error too_large) beyond this many triangles.")
        .def_readwrite("caps", &MeshOptions::caps, "Close each tow's ends with caps.")
        .def_readwrite("chord_deviation", &MeshOptions::chordDeviation, "Largest distance of a triangle from the surface (0: none).")
        .def_readwrite("relative_chord_deviation", &MeshOptions::relativeChordDeviation)
        .def_readwrite("min_edge_length", &MeshOptions::minEdgeLength)
        .def_readwrite("relative_min_edge_length", &MeshOptions::relativeMinEdgeLength);
}

void bindShrinkOptions(py::module_& m)
{
    py::class_<ShrinkOptions>(m, "ShrinkOptions", "Options of resolve method 'shrink' (sections scaled down until the tows part).")
        .def(py::init([](const py::kwargs& keywords) {
            py::object options = py::cast(ShrinkOptions{});
            applyKeywords(options, keywords);
            return options.cast<ShrinkOptions>();
        }))
        .def_readwrite("both", &ShrinkOptions::both, "Shrink both tows of a pair by the same factor (default: the lower-ranked only).")
        .def_readwrite("blend_length", &ShrinkOptions::blendLength, "Length over which the scale returns to 1 (0: the tow's size).")
        .def_readwrite("tolerance", &ShrinkOptions::tolerance, "The bisection's tolerance on the scale.")
        .def_readwrite("margin", &ShrinkOptions::margin, "Extra reduction that keeps a gap.")
        .def_readwrite("min_scale", &ShrinkOptions::minScale, "The smallest scale tried.");
}

void bindResolveOptions(py::module_& m)
{
    py::class_<ResolveOptions>(m, "ResolveOptions",
                               "Options of resolve_textile(); keyword arguments set these names, then MeshOptions' (mesh.*), "
                               "then IntersectionOptions' (intersection.*), then ShrinkOptions' (shrink.*).")
        .def(py::init([](const py::kwargs& keywords) {
            py::object options = py::cast(ResolveOptions{});
            applyKeywords(options, keywords, {"mesh", "intersection", "shrink"});
            return options.cast<ResolveOptions>();
        }))
        .def_readwrite("mesh", &ResolveOptions::mesh)
        .def_readwrite("intersection", &ResolveOptions::intersection)
        .def_readwrite("primary", &ResolveOptions::primaryPatterns, "Name globs of the tows ranked primary, first first.")
        .def_property("method", [](const ResolveOptions& o) { return resolutionMethodName(o.method); },
                      [](ResolveOptions& o, const std::string& name) { o.method = methodNamed(name); },
                      "'connect' (the rank rule), 'symmetric' (mid-surfaces) or 'shrink' (sections scaled until apart).")
        .def_readwrite("threads", &ResolveOptions::threads, "Worker threads (0: all hardware threads).")
        .def_readwrite("shrink", &ResolveOptions::shrink, "Options of method 'shrink'.")
        .def_property("cell", [](const ResolveOptions& o) { return o.cell; },  // a copy: the optional may be reset
                      [](ResolveOptions& o, std::optional<Cell> c) { o.cell = std::move(c); },
                      "A Cell to clip the meshes to, or None (reading gives a copy: assign a changed one back).");
}

void bindResult(py::module_& m)
{
    py::class_<ResolveResult>(m, "ResolveResult", "Loops, compatible meshes and what could not be resolved.")
        .def_readonly("intersections", &ResolveResult::intersections)
        .def_readonly("mesh", &ResolveResult::mesh)
        .def_property_readonly("method", [](const ResolveResult& r) { return resolutionMethodName(r.method); })
        .def_readonly("ranks", &ResolveResult::ranks, "Each tow's rank (0 ranks first).")
        .def_readonly("crossing_triangle_pairs", &ResolveResult::crossingTrianglePairs,
                      "Pairs of triangles of different tows that still cross (0 when resolved).")
        .def_property_readonly("tows", [](const ResolveResult& r) {
                py::list out;
                for (const TowResolution& t : r.tows)
                    out.append(py::dict(py::arg("role") = t.role(), py::arg("volume_before") = t.volumeBefore, py::arg("volume_after") = t.volumeAfter,
                                        py::arg("area") = t.area, py::arg("boundary_loops") = t.boundaryLoops, py::arg("pieces") = t.pieces,
                                        py::arg("mesh_size") = t.meshSize));
                return out;
            }, "Per tow: its role, volumes before and after, area, boundary loops, pieces and mesh size (dicts).")
        .def_property_readonly("unresolved", [](const ResolveResult& r) {
                py::list out;
                for (const UnresolvedPair& u : r.unresolved)
                    out.append(py::dict(py::arg("tow_a") = u.towA, py::arg("tow_b") = u.towB, py::arg("reason") = unresolvedReasonName(u.reason),
                                        py::arg("message") = u.message));
                return out;
            }, "Tow pairs left overlapping, with why (dicts).")
        .def_property_readonly("skipped_loops", [](const ResolveResult& r) {
                py::list out;
                for (const SkippedLoop& s : r.skippedLoops)
                    out.append(py::dict(py::arg("loop") = s.loop, py::arg("reason") = skippedReasonName(s.reason), py::arg("message") = s.message));
                return out;
            }, "Loops not used as region boundaries, with why (dicts).")
        .def_property_readonly("shrunk", [](const ResolveResult& r) {
                py::list out;
                for (const ShrunkTow& t : r.shrunk)
                    out.append(py::dict(py::arg("section_scale") = py::array_t<double>(t.sectionScale.size(), t.sectionScale.data()),
                                        py::arg("volume_before") = t.volumeBefore, py::arg("volume_after") = t.volumeAfter,
                                        py::arg("stack") = t.stack));
                return out;
            }, "Method 'shrink': per tow its section scales, volumes and shrunk stack (dicts; empty otherwise).")
        .def_property_readonly("min_angle", [](const ResolveResult& r) { return r.quality.minAngle; }, "Smallest triangle angle, degrees.")
        .def_property_readonly("timings", [](const ResolveResult& r) {
                return py::dict(py::arg("intersect") = r.timings.intersect, py::arg("mesh") = r.timings.mesh, py::arg("regions") = r.timings.regions);
            }, "Seconds per stage (dict).")
        .def("__repr__", [](const ResolveResult& r) {
            return "<towgeom.ResolveResult: " + std::to_string(r.intersections.loops.size()) + " loops, " + std::to_string(r.mesh.regions.size()) +
                   " regions, " + std::to_string(r.unresolved.size()) + " pairs unresolved>";
        });
}

/// The options of a stage call: OPTIONS (or the defaults) with the keyword arguments set.
ResolveOptions resolveOptions(const std::optional<ResolveOptions>& options, const py::kwargs& keywords)
{
    py::object chosen = py::cast(options.value_or(ResolveOptions{}));
    applyKeywords(chosen, keywords, {"mesh", "intersection", "shrink"});
    return chosen.cast<ResolveOptions>();
}

}  // namespace

void bindResolve(py::module_& m)
{
    bindMeshOptions(m);
    bindShrinkOptions(m);
    bindResolveOptions(m);
    bindResult(m);
    m.def("resolve_textile", [](const std::vector<TowSurface>& tows, std::optional<IntersectionReport> report, std::optional<ResolveOptions> options,
                                py::object progress, const py::kwargs& keywords) {
            ResolveOptions o = resolveOptions(options, keywords);
            PythonProgress monitor(progress);
            o.monitor = &monitor;
            return runInterruptible(monitor, [&] { return report ? resolveTextile(tows, *report, o) : resolveTextile(tows, o); });
        }, py::arg("tows"), py::arg("report") = py::none(), py::arg("options") = py::none(), py::arg("progress") = py::none(),
        "Resolves the tows' interpenetrations: loops (or the given report's), meshes with the loops as constraints and "
        "one shared surface per overlap. Options as a ResolveOptions and/or keyword arguments (edge_length=0.1, "
        "method='symmetric', primary=['warp*'], threads=2, ...); progress(stage, done, total) as the work goes on; "
        "Ctrl-C stops it and raises KeyboardInterrupt.");
    m.def("mesh_tows", [](const std::vector<TowSurface>& tows, const IntersectionReport& report, std::optional<ResolveOptions> options,
                          py::object progress, const py::kwargs& keywords) {
            ResolveOptions o = resolveOptions(options, keywords);
            PythonProgress monitor(progress);
            o.monitor = &monitor;
            return runInterruptible(monitor, [&] { return meshTows(tows, report, o); });
        }, py::arg("tows"), py::arg("report"), py::arg("options") = py::none(), py::arg("progress") = py::none(),
        "The first half of resolve_textile: every tow meshed with the report's loops as constraints, no region shared yet "
        "(then connect_regions). Options and progress as resolve_textile's.");
    m.def("connect_regions", [](const std::vector<TowSurface>& tows, const ResolveResult& meshed, std::optional<ResolveOptions> options,
                                py::object progress, const py::kwargs& keywords) {
            ResolveOptions o = resolveOptions(options, keywords);
            PythonProgress monitor(progress);
            o.monitor = &monitor;
            return runInterruptible(monitor, [&] { return connectRegions(tows, meshed, o); });
        }, py::arg("tows"), py::arg("meshed"), py::arg("options") = py::none(), py::arg("progress") = py::none(),
        "The second half: each overlap's surface shared by both tows in mesh_tows' result (given the same options).");
    // The peer of the binding's overhead benchmark (benchmarks/bench_python.py): the same call
    // made and timed in C++ alone (no worker thread, no conversions), its result dropped.
    m.def("_resolve_seconds_in_cpp", [](const std::vector<TowSurface>& tows, const IntersectionReport& report, const ResolveOptions& options) {
            const auto start = std::chrono::steady_clock::now();
            resolveTextile(tows, report, options);  // the result dropped inside the timing, as the Python side's
            return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        }, py::arg("tows"), py::arg("report"), py::arg("options"), py::call_guard<py::gil_scoped_release>());
}

void bindCell(py::module_& m)
{
    py::class_<Cell>(m, "Cell", "A box the meshes are clipped to (an FE cell); periodic for a unit cell.")
        .def(py::init([](const Triple& lo, const Triple& hi, bool periodic, const std::string& cut) {
                 Cell c;
                 c.min = {lo[0], lo[1], lo[2]};
                 c.max = {hi[0], hi[1], hi[2]};
                 c.periodic = periodic;
                 c.cut = enumNamed(cut, {CellCut::Auto, CellCut::Parametric, CellCut::Mesh}, &cellCutName, "cell cut");
                 c.validate();
                 return c;
             }), py::arg("min"), py::arg("max"), py::arg("periodic") = false, py::arg("cut") = "auto",
             "The box from corner MIN to corner MAX; cut 'auto' (mesh for a box that is not periodic), 'parametric' or 'mesh'.")
        .def_property_readonly("min", [](const Cell& c) { return Triple{c.min.x, c.min.y, c.min.z}; })
        .def_property_readonly("max", [](const Cell& c) { return Triple{c.max.x, c.max.y, c.max.z}; })
        .def_readwrite("periodic", &Cell::periodic)
        .def_property("cut", [](const Cell& c) { return cellCutName(c.cut); },
                      [](Cell& c, const std::string& name) { c.cut = enumNamed(name, {CellCut::Auto, CellCut::Parametric, CellCut::Mesh}, &cellCutName, "cell cut"); })
        .def_readwrite("period_tolerance", &Cell::periodTolerance)
        .def_readwrite("face_size_growth", &Cell::faceSizeGrowth)
        .def_readwrite("face_size_max", &Cell::faceSizeMax)
        .def("volume", &Cell::volume)
        .def("__repr__", [](const Cell& c) {
            std::ostringstream out;
            out << "<towgeom.Cell (" << c.min.x << ", " << c.min.y << ", " << c.min.z << ") - (" << c.max.x << ", " << c.max.y << ", " << c.max.z
                << ")" << (c.periodic ? ", periodic>" : ">");
            return out.str();
        });
}

}  // namespace towgeom::python
