// towgeom courses: fibre-placement courses on a tool surface (STEP or IGES), offset from a
// reference curve, with their errors, the gaps and overlaps between tows, and each tow as a
// .stw ribbon for towgeom detect.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/json_text.hpp"
#include "io/output_files.hpp"
#include "towgeom/towgeom.hpp"

namespace towgeom::cli {

namespace {

const char* kCoursesHelp = R"(Usage: towgeom courses SURFACE.step --reference REF --tow-width W --out DIR [options]

Plans fibre-placement courses on a tool surface (a face of a STEP or IGES file, converted
exactly to a NURBS): K courses of N tows of width W, the first course's centreline the
reference curve, each next course to the reference's left (seen from the face's outer side).
Centrelines are offset along the surface as Schueler, Miller & Hale (2004) do: each point
moved by d along O = N x T and projected back (their Eq. 2 estimates what a step loses on a
curved surface), or with --exact along the geodesic perpendicular to the curve. Every step's
true distance along the surface is measured (geodesic shooting) next to the estimate. Each
tow covers the band W wide about its centreline; the gap (+) or overlap (-) between
neighbouring tows is measured along the surface at every centreline point.

With --angle THETA the plan is a laminate-family ply: the 0 degree tows are laid first (as
above), a curve is traced from the middle of the reference across them at THETA to every one
(integrated on the surface), and the courses are laid from that curve.

Writes, all or nothing:

  DIR/courses.json  the plan: every course and tow centreline and edge ((u,v) and xyz), the
                    edges as cubic B-splines in (u,v), per point the step's measured distance
                    and Eq. 2 estimate, and the gaps ("width" per point: + gap, - overlap)
  DIR/courses.vtk   centrelines and edges as polylines for ParaView (cell data "tow",
                    "kind"; point data "gap")
  DIR/NAME.stw      each tow as a ribbon W wide and --thickness thick lying on the surface
                    (racetrack sections): 'towgeom detect DIR/*.stw' finds the overlaps

and prints one JSON object on stdout:

  {"file", "face", "method", "tows", "courses", "tow_width", "spacing", "tolerance",
   "largest_step_error", "within_tolerance", "gaps":[{"right", "left", "between_courses",
   "min", "max"}], "angle":{"theta", "crossings":[{"curve", "angle"}]} (with --angle)}

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
  --angle THETA     a laminate-family ply at THETA degrees (0 < THETA < 180) to the 0 degree
                    tows the reference and the options above lay
  --points N        points along a plane reference (default 41)
  --thickness T     the ribbons' thickness (default W / 10)
  --face N          which face of the file (0-based, default 0)
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

/// The numbers of each line of @p path ('#' comments, blank lines skipped), @p count per line.
std::vector<std::vector<double>> readColumns(const std::string& path, std::size_t count)
{
    std::ifstream in(path);
    if (!in) throw Error(ErrorCode::FileNotFound, "cannot open the reference file", path);
    std::vector<std::vector<double>> rows;
    std::string line;
    for (std::size_t number = 1; std::getline(in, line); ++number) {
        line = line.substr(0, line.find('#'));
        std::istringstream words(line);
        std::vector<double> row;
        double x = 0.0;
        while (words >> x) row.push_back(x);
        if (row.empty() && words.eof() && line.find_first_not_of(" \t\r") == std::string::npos) continue;
        if (row.size() != count || !words.eof())
            throw Error(ErrorCode::InvalidArgument, "expected " + std::to_string(count) + " numbers on the line", path, number);
        rows.push_back(row);
    }
    return rows;
}

CurveOnSurface readReference(const NurbsSurface& surface, const std::string& text, std::size_t points, bool reverse)
{
    const std::size_t colon = text.find(':');
    const std::string kind = text.substr(0, colon), rest = colon == std::string::npos ? "" : text.substr(colon + 1);
    if (kind == "plane") {
        std::vector<double> x;
        std::istringstream in(rest);
        for (std::string word; std::getline(in, word, ',');) {
            try {
                std::size_t used = 0;
                x.push_back(std::stod(word, &used));
                if (used != word.size()) x.clear();
            } catch (const std::exception&) {
                x.clear();
                break;
            }
        }
        if (x.size() != 6) throw UsageError("--reference plane:X,Y,Z,NX,NY,NZ takes six numbers");
        return referenceFromPlane(surface, {x[0], x[1], x[2]}, {x[3], x[4], x[5]}, points, reverse);
    }
    CurveOnSurface c;
    if (kind == "points") {
        std::vector<Point3> p;
        for (const auto& r : readColumns(rest, 3)) p.push_back({r[0], r[1], r[2]});
        try {
            c = referenceFromPoints(surface, p);
        } catch (const Error& e) {
            throw Error(e.code(), e.what(), rest);
        }
    } else if (kind == "uv") {
        std::vector<UV> uv;
        for (const auto& r : readColumns(rest, 2)) uv.push_back({r[0], r[1]});
        try {
            c = curveOnSurface(surface, uv);
        } catch (const Error& e) {
            throw Error(e.code(), e.what(), rest);
        }
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
                         {"out", true}});
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
        if (args.has("exact")) options.method = SurfaceOffsetMethod::Geodesic;
        const auto angle = args.number("angle");
        if (angle && !(*angle > 0.0 && *angle < 180.0)) throw UsageError("--angle takes degrees between 0 and 180");
        const std::size_t points = args.whole("points", 41, 4, 100000, "4 to 100000"), face = args.whole("face", 0, 0, 1e6, "0 to 1000000");
        const double thickness = args.has("thickness") ? args.positive("thickness") : 0.1 * options.towWidth;
        const auto outDir = args.value("out");
        if (!outDir) throw UsageError("--out DIR is needed");
        const bool quiet = args.has("quiet");
        const auto say = [&](const std::string& s) {
            if (!quiet) std::cerr << "towgeom courses: " << s << "\n";
        };

        const std::string& file = args.positional().front();
        const PlacementSurface tool = readPlacementSurface(file, face);
        CurveOnSurface start = readReference(tool.surface, *reference, points, args.has("reverse"));
        Json report;
        report["file"] = file;
        report["face"] = tool.face;
        FixedAngleCurve family;
        if (angle) {
            say("laying the 0 degree tows");
            const CoursePlan zero = layCourses(tool.surface, start, options);
            std::vector<CurveOnSurface> centrelines;
            for (const TowPath& t : zero.tows) centrelines.push_back(t.centreline);
            say("tracing the curve at " + std::to_string(*angle) + " degrees across them");
            family = fixedAngleCurve(tool.surface, centrelines, *angle);
            start = thinned(family.curve, start.uv.size());
        }
        say("laying " + std::to_string(options.courses) + " course(s) of " + std::to_string(options.towsPerCourse) + " tow(s)");
        const CoursePlan plan = layCourses(tool.surface, start, options);
        CrossSection section;
        section.shape = SectionShape::Racetrack;
        section.width = options.towWidth;
        section.height = std::min(thickness, options.towWidth);
        std::vector<TowStack> ribbons;
        for (const TowPath& t : plan.tows) ribbons.push_back(towRibbon(tool.surface, t.centreline, section, 16, t.name));

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
        for (const TowStack& r : ribbons) writeStack(files.open((dir / (r.name + ".stw")).string()), r);
        files.commit();
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
