// towgeom courses: fibre-placement courses on a tool surface (STEP or IGES), offset from a
// reference curve, with their errors, the gaps and overlaps between tows, and each tow as a
// .stw ribbon for towgeom detect.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/json_text.hpp"
#include "cli/tool_surface.hpp"
#include "io/output_files.hpp"
#include "towgeom/towgeom.hpp"

namespace towgeom::cli {

namespace {

const char* kCoursesHelp = R"(Usage: towgeom courses SURFACE.step --reference REF --tow-width W --out DIR [options]

Plans fibre-placement courses on a tool surface (a face of a STEP or IGES file, converted
exactly to a NURBS, or a .grid file of points: '#' comments, 'grid NU NV', then NU x NV
lines 'x y z', v fastest, interpolated by a bicubic B-spline): K courses of N tows of width
W, the first course's centreline the reference curve, each next course to the reference's
left (seen from the face's outer side).
Centrelines are offset along the surface as Schueler, Miller & Hale (2004) do: each point
moved by d along O = N x T and projected back (their Eq. 2 estimates what a step loses on a
curved surface), or with --exact along the geodesic perpendicular to the curve. Every step's
true distance along the surface is measured (geodesic shooting) next to the estimate. Each
tow covers the band W wide about its centreline; the gap (+) or overlap (-) between
neighbouring tows is measured along the surface at every centreline point.

The face's boundary ends tows rather than refusing them: a tow whose offset leaves the face is
cut exactly where it meets the boundary, and one whose course runs to the boundary is carried
on to it (the summary's "trimmed" lists each such tow with its length and the side where it
ends: a side of the face's (u,v) box, "u_min", "u_max", "v_min" or "v_max", or, on a trimmed
face, "edge K", K the edge's index among the face's edges; "off_surface" the tows and courses
wholly off the face). The boundary is the face's own: its trimming curves where it has them
(an outer boundary cutting into its box, holes; "trim_edges" counts the edges that bound it),
else its (u,v) box. A reference from a plane is the cut's run on the face nearest the plane's
point; a tow crossing a hole keeps its longest run on the face. Where the face closes smoothly
on itself (a cylinder's, sphere's or torus's angle) courses cross the seam, and a closed
reference (a plane cut around a cylinder or through a sphere's equator) gives closed courses.
A geodesic that meets a pole of the face's parametrisation (a sphere's) is refused, naming the
place.

With --angle THETA the plan is a laminate-family ply: the 0 degree tows are laid first (as
above; at least two), a curve is traced from the middle of the first tow's centreline (c1_t1)
across all their centrelines at THETA to every one (integrated on the surface), and the
courses are laid from that curve.

Writes, all or nothing:

  DIR/courses.json  the plan: every course and tow centreline and edge ((u,v) and xyz), the
                    edges as cubic B-splines in (u,v), per point the step's measured distance
                    and Eq. 2 estimate, and the gaps ("width" per point: + gap, - overlap)
  DIR/courses.vtk   centrelines and edges as polylines for ParaView (cell data "tow",
                    "kind"; point data "gap")
  DIR/courses.step  every tow's centreline and edges, each a named product ("c1_t1/left",
                    ...): curves on the surface, their 3D curves within 1e-6 W (AP214)
  DIR/coverage.vtk  the surface's tessellation (--coverage-cells a side, two triangles a
                    cell) with cell data "coverage": how many tows cover each triangle
  DIR/NAME.stw      each tow as a ribbon W wide and --thickness thick lying on the surface
                    (racetrack sections), NAME c<course>_t<tow>: 'towgeom detect DIR/*.stw'
                    finds the overlaps (ribbons of an earlier plan in DIR are removed)

and prints one JSON object on stdout:

  {"file", "face", "face_name", "trim_edges", "faces", "method", "tows", "courses", "tow_width", "spacing", "tolerance",
   "largest_step_error", "within_tolerance", "gaps":[{"right", "left", "between_courses",
   "min", "max"}], "trimmed":[{"tow", "length", "start_boundary", "end_boundary"}],
   "off_surface":[names], "no_ribbon":[names], "coverage":{"cells", "area", "uncovered",
   "once", "several"} (fractions of the area, adding to 1), "steering":{"smallest_radius",
   "min_radius", "below":[names]}, "angle":{"theta", "crossings":[{"curve", "angle"}]}
   (with --angle)}

Options:
  --reference REF   the first course's centreline, one of:
                      plane:X,Y,Z,NX,NY,NZ  the surface cut by the plane through (X,Y,Z) of
                                            normal (NX,NY,NZ) (the cut passing nearest it),
                                            sampled at --points points by arc length
                      points:FILE           points 'x y z', one per line, projected onto the
                                            surface (each within 1e-3 of the surface's size)
                      uv:FILE               surface parameters 'u v', one per line
                    ('#' starts a comment in FILE)
  --reverse         run the reference the other way (courses go to its other side)
  --tow-width W     the width of one tow along the surface (mm: see below)
  --tows N          tows per course (default 1)
  --courses K       courses (default 1)
  --spacing S       distance between neighbouring tows' centrelines (default W: edge to
                    edge; less overlaps, more leaves gaps)
  --exact           place centrelines by geodesics (no step error) instead of Schueler's
                    tangent-and-project
  --tolerance E     the step error allowed (default 1e-3 W); within_tolerance says whether
                    every step met it (a warning on stderr if not)
  --coverage-cells N
                    the coverage's tessellation: N x N cells of the face's (u,v) box (default
                    200; the fractions are accurate to about a cell along each band's border)
  --min-steering-radius R
                    the smallest radius the head can steer a tow on: tows whose centreline's
                    geodesic curvature needs less are listed ("steering": "below") with a
                    warning (each tow's "steering_radius" and per-point "geodesic_curvature"
                    are in courses.json whether or not this is given)
  --angle THETA     a laminate-family ply at THETA degrees (0 < THETA < 180) to the 0 degree
                    tows the reference and the options above lay
  --points N        points along a plane reference (default 41)
  --thickness T     the ribbons' thickness, at most W (default W / 10)
  --face N|NAME     which face of the file: its index (0-based, default 0) or its name in
                    the file (a STEP ADVANCED_FACE's or IGES entity's name; digits only
                    are an index); several, 'N,M,...' or 'all': joined into one surface
                    where each meets the ones before side to side (whole faces, sides
                    parametrised alike: a revolved or extruded profile's faces, patches
                    sewn side to side), courses running across the edges they share (the
                    box sides named are then the joined surface's; 'all' is never a name)
  --out DIR         where to write (created if needed)
  --quiet           no progress lines on stderr
  -h, --help        this help

Lengths are millimetres: OpenCASCADE reads STEP and IGES lengths as mm whatever unit the file
uses. Exit status: 0 success (even beyond tolerance: see within_tolerance); 2 invalid input or
usage (one line on stderr naming the file or tow); 1 an output could not be written, or an
internal failure of OpenCASCADE.

Examples:
  towgeom courses tool.step --reference plane:0,0,0,0,1,0 --tow-width 6.35 --tows 8 \
      --courses 4 --out plan
  towgeom courses tool.step --reference uv:ref.txt --tow-width 6.35 --tows 8 --exact \
      --angle 45 --out plan45
)";

/// One line of a reference file: its numbers and its line number.
struct Row {
    std::vector<double> x;
    std::size_t line = 0;
};

/// The numbers of each line of @p path ('#' comments, blank lines skipped), @p count per line.
std::vector<Row> readColumns(const std::string& path, std::size_t count)
{
    std::ifstream in(path);
    if (!in) throw Error(ErrorCode::FileNotFound, "cannot open the reference file", path);
    std::vector<Row> rows;
    std::string line;
    for (std::size_t number = 1; std::getline(in, line); ++number) {
        line = line.substr(0, line.find('#'));
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        std::istringstream words(line);
        Row row;
        row.line = number;
        double x = 0.0;
        while (words >> x) row.x.push_back(x);
        if (row.x.size() != count || !words.eof())
            throw Error(ErrorCode::InvalidArgument, "expected " + std::to_string(count) + " numbers on the line", path, number);
        rows.push_back(row);
    }
    if (rows.size() < 4) throw Error(ErrorCode::InvalidArgument, "a reference needs at least 4 points, the file has " + std::to_string(rows.size()), path);
    return rows;
}

/// The six numbers of "X,Y,Z,NX,NY,NZ".
std::vector<double> planeNumbers(const std::string& text)
{
    const std::vector<double> x = numberList(text);
    if (x.size() != 6) throw UsageError("--reference plane:X,Y,Z,NX,NY,NZ takes six numbers, got '" + text + "'");
    return x;
}

CurveOnSurface readReference(const PlacementSurface& tool, const std::string& text, std::size_t points, bool reverse)
{
    const NurbsSurface& surface = tool.surface;
    const std::size_t colon = text.find(':');
    const std::string kind = text.substr(0, colon), rest = colon == std::string::npos ? "" : text.substr(colon + 1);
    if (kind == "plane") {
        const std::vector<double> x = planeNumbers(rest);
        return referenceFromPlane(tool, {x[0], x[1], x[2]}, {x[3], x[4], x[5]}, points, reverse);
    }
    CurveOnSurface c;
    if (kind == "points") {
        const std::vector<Row> rows = readColumns(rest, 3);
        std::vector<Point3> p;
        for (const Row& r : rows) p.push_back({r.x[0], r.x[1], r.x[2]});
        try {
            c = referenceFromPoints(surface, p);
        } catch (const Error& e) {
            // "point I ..." or "points I and J ...": the line of point I, or of J.
            std::size_t index = 0, second = 0;
            const std::string m = e.message();
            const std::size_t at = m.find("point");
            if (at != std::string::npos && std::sscanf(m.c_str() + at, "points %zu and %zu", &index, &second) == 2) index = second;
            else if (at == std::string::npos || std::sscanf(m.c_str() + at, "point %zu", &index) != 1) index = rows.size();
            if (index < rows.size()) throw Error(e.code(), m, rest, rows[index].line);
            throw Error(e.code(), m, rest);
        }
    } else if (kind == "uv") {
        const std::vector<Row> rows = readColumns(rest, 2);
        std::vector<UV> uv;
        for (const Row& r : rows) {
            uv.push_back({r.x[0], r.x[1]});
            if (uv.size() > 1 && uv.back().u == uv[uv.size() - 2].u && uv.back().v == uv[uv.size() - 2].v)
                throw Error(ErrorCode::InvalidArgument, "the point repeats the one before it", rest, r.line);
            try {
                curveOnSurface(surface, {uv.back()});
            } catch (const Error& e) {
                throw Error(e.code(), e.message(), rest, r.line);
            }
        }
        c = curveOnSurface(surface, uv);
    } else {
        throw UsageError("--reference is plane:X,Y,Z,NX,NY,NZ, points:FILE or uv:FILE");
    }
    if (reverse) {
        std::reverse(c.uv.begin(), c.uv.end());
        std::reverse(c.points.begin(), c.points.end());
    }
    return c;
}

/// @p c with at most @p count of its points, evenly by index, both ends kept.
CurveOnSurface thinned(const CurveOnSurface& c, std::size_t count)
{
    if (c.uv.size() <= count) return c;
    CurveOnSurface out;
    for (std::size_t k = 0; k < count; ++k) {
        const std::size_t i = (k * (c.uv.size() - 1) + (count - 1) / 2) / (count - 1);
        out.uv.push_back(c.uv[i]);
        out.points.push_back(c.points[i]);
    }
    return out;
}

}  // namespace

int runCourses(int argc, char** argv, int first)
{
    try {
        const Args args(argc, argv, first,
                        {{"help"}, {"quiet"}, {"exact"}, {"reverse"}, {"reference", true}, {"tow-width", true}, {"tows", true}, {"courses", true},
                         {"spacing", true}, {"tolerance", true}, {"angle", true}, {"points", true}, {"thickness", true}, {"face", true},
                         {"min-steering-radius", true}, {"coverage-cells", true}, {"out", true}});
        if (args.has("help")) {
            std::cout << kCoursesHelp;
            return kExitOk;
        }
        if (args.positional().size() != 1) throw UsageError("one STEP or IGES file, the tool surface");
        const auto reference = args.value("reference");
        if (!reference) throw UsageError("--reference REF is needed");
        CourseOptions options;
        options.towWidth = args.positive("tow-width");
        if (options.towWidth == 0.0) throw UsageError("--tow-width W is needed");
        options.towsPerCourse = args.whole("tows", 1, 1, 10000, "1 to 10000");
        options.courses = args.whole("courses", 1, 1, 10000, "1 to 10000");
        options.spacing = args.positive("spacing");
        options.tolerance = args.positive("tolerance");
        options.minSteeringRadius = args.positive("min-steering-radius");
        if (args.has("exact")) options.method = SurfaceOffsetMethod::Geodesic;
        const auto angle = args.number("angle");
        if (angle && !(*angle > 0.0 && *angle < 180.0)) throw UsageError("--angle takes degrees between 0 and 180");
        const std::size_t points = args.whole("points", 41, 4, 100000, "4 to 100000");
        const std::size_t coverageCells = args.whole("coverage-cells", 200, 2, 4000, "2 to 4000");
        const double thickness = args.has("thickness") ? args.positive("thickness") : 0.1 * options.towWidth;
        if (thickness > options.towWidth) throw UsageError("--thickness must not exceed --tow-width (the ribbons' sections are racetracks)");
        if (angle && options.towsPerCourse * options.courses < 2)
            throw UsageError("--angle needs at least two 0 degree tows (--tows N x --courses K >= 2) to cross");
        const auto outDir = args.value("out");
        if (!outDir) throw UsageError("--out DIR is needed");
        const bool quiet = args.has("quiet");
        const auto say = [&](const std::string& s) {
            if (!quiet) std::cerr << "towgeom courses: " << s << "\n";
        };

        const std::string& file = args.positional().front();
        const PlacementSurface tool = readToolSurface(args, file);
        CurveOnSurface start = readReference(tool, *reference, points, args.has("reverse"));
        Json report;
        report["file"] = file;
        report["face"] = tool.face;
        report["face_name"] = tool.name;
        report["trim_edges"] = tool.trimEdges;
        report["faces"] = tool.faces;
        FixedAngleCurve family;
        if (angle) {
            say("laying the 0 degree tows");
            const CoursePlan zero = layCourses(tool, start, options);
            std::vector<CurveOnSurface> centrelines;
            for (const TowPath& t : zero.tows) centrelines.push_back(t.centreline);
            say("tracing the curve at " + std::to_string(*angle) + " degrees across them");
            family = fixedAngleCurve(tool.surface, centrelines, *angle);
            start = thinned(family.curve, start.uv.size());
        }
        say("laying " + std::to_string(options.courses) + " course(s) of " + std::to_string(options.towsPerCourse) + " tow(s)");
        const CoursePlan plan = layCourses(tool, start, options);
        CrossSection section;
        section.shape = SectionShape::Racetrack;
        section.width = options.towWidth;
        section.height = thickness;
        std::vector<TowStack> ribbons;
        std::vector<std::string> noRibbon;  // tows the face cut too short for a ribbon's sections
        for (const TowPath& t : plan.tows) {
            if (t.centreline.uv.size() < TowStack::kMinSections) noRibbon.push_back(t.name);
            else ribbons.push_back(towRibbon(tool.surface, t.centreline, section, 16, t.name));
        }

        report["method"] = plan.method == SurfaceOffsetMethod::Geodesic ? "geodesic" : "project_tangent";
        report["tows"] = options.towsPerCourse;
        report["courses"] = options.courses;
        report["tow_width"] = plan.towWidth;
        report["spacing"] = plan.spacing;
        report["tolerance"] = plan.tolerance;
        report["largest_step_error"] = plan.largestStepError;
        report["within_tolerance"] = plan.withinTolerance;
        report["gaps"] = Json::array();
        for (const TowGap& g : plan.gaps)
            report["gaps"].push_back({{"right", plan.tows[g.right].name}, {"left", plan.tows[g.left].name}, {"between_courses", g.betweenCourses},
                                      {"min", g.minWidth}, {"max", g.maxWidth}});
        // Where the face's boundary ended a tow, and what it left off.
        report["trimmed"] = Json::array();
        for (const TowPath& t : plan.tows)
            if (!t.startBoundary.empty() || !t.endBoundary.empty())
                report["trimmed"].push_back({{"tow", t.name}, {"length", t.length},
                                             {"start_boundary", t.startBoundary.empty() ? Json() : Json(t.startBoundary)},
                                             {"end_boundary", t.endBoundary.empty() ? Json() : Json(t.endBoundary)}});
        report["off_surface"] = plan.offSurface;
        say("measuring the coverage on " + std::to_string(coverageCells) + " x " + std::to_string(coverageCells) + " cells");
        const CourseCoverage coverage = courseCoverage(tool, plan, coverageCells);
        report["coverage"] = {{"cells", coverageCells}, {"area", coverage.totalArea}, {"uncovered", coverage.uncovered}, {"once", coverage.once},
                              {"several", coverage.several}};
        double smallest = std::numeric_limits<double>::infinity();
        for (const TowPath& t : plan.tows) smallest = std::min(smallest, t.steeringRadius);
        report["steering"] = {{"smallest_radius", std::isfinite(smallest) ? Json(smallest) : Json()},
                              {"min_radius", plan.minSteeringRadius},
                              {"below", plan.belowSteeringRadius}};
        report["no_ribbon"] = noRibbon;
        if (angle) {
            Json crossings = Json::array();
            for (const FamilyCrossing& c : family.crossings) crossings.push_back({{"curve", c.curve}, {"angle", c.angle}});
            report["angle"] = {{"theta", *angle}, {"crossings", std::move(crossings)}};
        }

        detail::OutputFiles files;
        files.makeDirectory(*outDir);
        const std::filesystem::path dir(*outDir);
        writeCoursePlanJson(plan, files.open((dir / "courses.json").string()));
        writeCoursePlanVtk(plan, files.open((dir / "courses.vtk").string()));
        writeCourseCoverageVtk(coverage, files.open((dir / "coverage.vtk").string()));
        for (const TowStack& r : ribbons) writeStack(files.open((dir / (r.name + ".stw")).string()), r);
        writeCoursePlanStep(tool.surface, plan, files.open((dir / "courses.step").string()));
        files.commit();
        // Ribbons of an earlier, larger plan in DIR would join 'detect DIR/*.stw': removed.
        std::set<std::string> written;
        for (const TowStack& r : ribbons) written.insert(r.name + ".stw");
        for (const auto& entry : std::filesystem::directory_iterator(dir)) {
            const std::string name = entry.path().filename().string();
            if (entry.is_regular_file() && std::regex_match(name, std::regex("c[0-9]+_t[0-9]+\\.stw")) && !written.count(name))
                std::filesystem::remove(entry.path());
        }
        if (!plan.offSurface.empty() && !quiet)
            std::cerr << "towgeom courses: note: " << plan.offSurface.size() << " course(s) or tow(s) lie off the face and were not laid (\"off_surface\")\n";
        if (!noRibbon.empty())
            std::cerr << "towgeom courses: warning: " << noRibbon.size() << " tow(s) cut by the face's boundary to fewer than " << TowStack::kMinSections
                      << " points have no .stw ribbon (\"no_ribbon\"; give more --points)\n";
        if (!plan.belowSteeringRadius.empty())
            std::cerr << "towgeom courses: warning: " << plan.belowSteeringRadius.size() << " tow(s) must be steered on a radius below --min-steering-radius "
                      << plan.minSteeringRadius << " (smallest " << smallest << "; \"steering\" lists them)\n";
        if (!plan.withinTolerance)
            std::cerr << "towgeom courses: warning: a step is " << plan.largestStepError << " from its distance along the surface, more than --tolerance "
                      << plan.tolerance << " (--exact places them by geodesics)\n";
        std::cout << jsonText(report) << "\n";
        return kExitOk;
    } catch (const std::exception& e) {
        return reportError("courses", e);
    }
}

}  // namespace towgeom::cli
