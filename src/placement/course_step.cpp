// A course plan's tow curves as STEP: each centreline and edge an edge on the tool surface (its
// (u,v) cubic as the curve on the surface, the 3D curve built from it by OpenCASCADE), each its
// own named product.
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepLib.hxx>
#include <BRep_Tool.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <TopoDS_Edge.hxx>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "brep/named_step.hpp"
#include "placement/periodic_surface.hpp"
#include "placement/uv_interpolation.hpp"
#include "towgeom/error.hpp"
#include "towgeom/fibre_courses.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

/// @p c as an edge on @p s: its (u,v) cubic, the 3D curve approximated from it to @p tolerance.
TopoDS_Edge edgeOn(const Handle(Geom_BSplineSurface)& s, const CurveOnSurface& c, double tolerance, const std::string& what)
{
    const Handle(Geom2d_BSplineCurve) cubic = detail::interpolateUV(c.uv, detail::chordParameters(c.uv));
    if (cubic.IsNull()) throw Error(ErrorCode::InvalidArgument, "writeCoursePlanStep: " + what + "'s points repeat");
    BRepBuilderAPI_MakeEdge make(cubic, s, cubic->FirstParameter(), cubic->LastParameter());
    if (!make.IsDone()) throw Error(ErrorCode::Internal, "writeCoursePlanStep: OpenCASCADE could not make " + what + " an edge");
    TopoDS_Edge edge = make.Edge();
    // BuildCurve3d records the deviation it reached as the edge's tolerance: checked, not assumed.
    if (!BRepLib::BuildCurve3d(edge, tolerance, GeomAbs_C2, 14, 256) || !(BRep_Tool::Tolerance(edge) <= tolerance))
        throw Error(ErrorCode::Internal, "writeCoursePlanStep: OpenCASCADE could not build " + what + "'s 3D curve within " + std::to_string(tolerance) +
                                             " (reached " + std::to_string(BRep_Tool::Tolerance(edge)) + ")");
    return edge;
}

}  // namespace

void writeCoursePlanStep(const NurbsSurface& surface, const CoursePlan& plan, const std::string& path, double asked)
{
    if (!(asked >= 0.0) || !std::isfinite(asked)) throw Error(ErrorCode::InvalidArgument, "writeCoursePlanStep: a tolerance of 0 or more", path);
    // Not below OpenCASCADE's confusion (1e-7), the least tolerance an edge records.
    const double tolerance = std::max(asked > 0.0 ? asked : 1e-6 * plan.towWidth, Precision::Confusion());
    if (!(tolerance > 0.0)) throw Error(ErrorCode::InvalidArgument, "writeCoursePlanStep: the plan has no tow width", path);
    const Handle(Geom_BSplineSurface) s = detail::toolSurface(surface);
    std::vector<std::pair<TopoDS_Shape, std::string>> parts;
    try {
        for (const TowPath& t : plan.tows)
            for (const auto& [curve, kind] : {std::pair{&t.centreline, "centreline"}, std::pair{&t.right, "right"}, std::pair{&t.left, "left"}}) {
                if (curve->uv.size() < 2) continue;  // an edge wholly off the face
                const std::string name = t.name + "/" + kind;
                const TopoDS_Edge edge = edgeOn(s, *curve, tolerance, "tow " + name);
                parts.emplace_back(edge, name);
            }
    } catch (const Standard_Failure& e) {
        throw Error(ErrorCode::Internal, std::string("writeCoursePlanStep: OpenCASCADE failed: ") + e.GetMessageString(), path);
    }
    detail::writeReplacing(path, [&](const std::string& file) { return detail::writeNamedStep(parts, file); });
}

void writeCoursePlanStep(const NurbsSurface& surface, const CoursePlan& plan, std::ostream& out, double tolerance)
{
    // OpenCASCADE writes files: a temporary one, copied into the stream.
    const std::string file = detail::uniqueFile((std::filesystem::temp_directory_path() / "towgeom-courses-").string(), ".step");
    try {
        writeCoursePlanStep(surface, plan, file, tolerance);
        std::ifstream in(file, std::ios::binary);
        out << in.rdbuf();
        const bool ok = static_cast<bool>(in) && static_cast<bool>(out);
        std::remove(file.c_str());
        if (!ok) throw Error(ErrorCode::WriteFailed, "could not copy the course plan's STEP into the stream");
    } catch (...) {
        std::remove(file.c_str());
        throw;
    }
}

TOWGEOM_END_NAMESPACE
