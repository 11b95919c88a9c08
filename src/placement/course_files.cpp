// A course plan as JSON (nlohmann-json, keys in the order written) and as legacy VTK polylines.
#include <nlohmann/json.hpp>

#include <cmath>
#include <ostream>

#include "towgeom/error.hpp"
#include "towgeom/fibre_courses.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

using Json = nlohmann::ordered_json;

Json curveJson(const CurveOnSurface& c)
{
    Json uv = Json::array(), points = Json::array();
    for (const UV& p : c.uv) uv.push_back({p.u, p.v});
    for (const Point3& p : c.points) points.push_back({p.x, p.y, p.z});
    return {{"uv", std::move(uv)}, {"points", std::move(points)}};
}

Json nurbsJson(const NurbsCurve& c)
{
    Json poles = Json::array();
    for (std::size_t i = 0; i < c.poles.size(); ++i) poles.push_back({c.poles[i].x, c.poles[i].y, c.weights[i]});
    return {{"degree", c.degree}, {"knots", c.knots}, {"poles", std::move(poles)}};
}

/// Refuses a plan whose gaps do not index its tows' points.
void checkPlan(const CoursePlan& plan)
{
    for (const TowGap& g : plan.gaps)
        if (g.right >= plan.tows.size() || g.left >= plan.tows.size() || g.width.size() != plan.tows[g.right].centreline.points.size())
            throw Error(ErrorCode::InvalidArgument, "course plan: a gap does not match its tows");
}

const char* methodName(SurfaceOffsetMethod m) { return m == SurfaceOffsetMethod::Geodesic ? "geodesic" : "project_tangent"; }

}  // namespace

void writeCoursePlanJson(const CoursePlan& plan, std::ostream& out)
{
    checkPlan(plan);
    Json j;
    j["method"] = methodName(plan.method);
    j["tow_width"] = plan.towWidth;
    j["spacing"] = plan.spacing;
    j["tolerance"] = plan.tolerance;
    j["largest_step_error"] = plan.largestStepError;
    j["within_tolerance"] = plan.withinTolerance;
    j["reference"] = curveJson(plan.reference);
    Json courses = Json::array();
    for (const CourseCentre& c : plan.courses) {
        Json e = {{"name", c.name}, {"from", c.step.from}, {"distance", c.step.distance}};
        e["centreline"] = curveJson(c.curve);
        e["geodesic_distance"] = c.step.geodesicDistance;
        e["estimated_error"] = c.step.estimatedError;
        courses.push_back(std::move(e));
    }
    j["courses"] = std::move(courses);
    Json tows = Json::array();
    for (const TowPath& t : plan.tows) {
        Json e = {{"name", t.name}, {"course", t.course}, {"from", t.step.from}, {"distance", t.step.distance}};
        e["centreline"] = curveJson(t.centreline);
        e["right"] = curveJson(t.right);
        e["left"] = curveJson(t.left);
        e["right_curve"] = nurbsJson(t.rightCurve);
        e["left_curve"] = nurbsJson(t.leftCurve);
        e["geodesic_distance"] = t.step.geodesicDistance;
        e["estimated_error"] = t.step.estimatedError;
        e["length"] = t.length;
        e["start_boundary"] = t.startBoundary.empty() ? Json() : Json(t.startBoundary);
        e["end_boundary"] = t.endBoundary.empty() ? Json() : Json(t.endBoundary);
        e["geodesic_curvature"] = t.geodesicCurvature;
        e["steering_radius"] = std::isfinite(t.steeringRadius) ? Json(t.steeringRadius) : Json();
        tows.push_back(std::move(e));
    }
    j["tows"] = std::move(tows);
    Json gaps = Json::array();
    for (const TowGap& g : plan.gaps)
        gaps.push_back({{"right", plan.tows[g.right].name},
                        {"left", plan.tows[g.left].name},
                        {"between_courses", g.betweenCourses},
                        {"min", g.minWidth},
                        {"max", g.maxWidth},
                        {"measured", g.measured},
                        {"width", g.width}});
    j["gaps"] = std::move(gaps);
    j["off_surface"] = plan.offSurface;
    j["min_steering_radius"] = plan.minSteeringRadius;
    j["below_steering_radius"] = plan.belowSteeringRadius;
    out << j.dump(-1, ' ', false, Json::error_handler_t::replace) << "\n";
    if (!out) throw Error(ErrorCode::WriteFailed, "could not write the course plan's JSON");
}

void writeCoursePlanVtk(const CoursePlan& plan, std::ostream& out)
{
    checkPlan(plan);
    const std::streamsize precision = out.precision();
    std::size_t points = 0, lines = 0, entries = 0;
    for (const TowPath& t : plan.tows)
        for (const CurveOnSurface* c : {&t.centreline, &t.right, &t.left}) {
            points += c->points.size();
            ++lines;
            entries += c->points.size() + 1;
        }
    out.precision(17);
    out << "# vtk DataFile Version 3.0\ntowgeom course plan: tow centrelines and edges\nASCII\nDATASET POLYDATA\n";
    out << "POINTS " << points << " double\n";
    for (const TowPath& t : plan.tows)
        for (const CurveOnSurface* c : {&t.centreline, &t.right, &t.left})
            for (const Point3& p : c->points) out << p.x << " " << p.y << " " << p.z << "\n";
    out << "LINES " << lines << " " << entries << "\n";
    std::size_t next = 0;
    for (const TowPath& t : plan.tows)
        for (const CurveOnSurface* c : {&t.centreline, &t.right, &t.left}) {
            out << c->points.size();
            for (std::size_t k = 0; k < c->points.size(); ++k) out << " " << next++;
            out << "\n";
        }
    out << "CELL_DATA " << lines << "\nFIELD attributes 2\ntow 1 " << lines << " int\n";
    for (std::size_t k = 0; k < plan.tows.size(); ++k) out << k << "\n" << k << "\n" << k << "\n";
    out << "kind 1 " << lines << " int\n";
    for (std::size_t k = 0; k < plan.tows.size(); ++k) out << "0\n1\n2\n";
    out << "POINT_DATA " << points << "\nFIELD attributes 1\ngap 1 " << points << " double\n";
    for (std::size_t k = 0; k < plan.tows.size(); ++k) {
        const TowPath& t = plan.tows[k];
        for (std::size_t i = 0; i < t.centreline.points.size(); ++i) {
            const double w = k < plan.gaps.size() && plan.gaps[k].right == k ? plan.gaps[k].width[i] : 0.0;
            out << (std::isnan(w) ? 0.0 : w) << "\n";
        }
        for (std::size_t i = 0; i < t.right.points.size() + t.left.points.size(); ++i) out << "0\n";
    }
    out.precision(precision);
    if (!out) throw Error(ErrorCode::WriteFailed, "could not write the course plan's VTK");
}

TOWGEOM_END_NAMESPACE
