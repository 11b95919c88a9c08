// Fibre-placement courses: centrelines offset from a reference (Schueler et al. or geodesic),
// each tow's edges at exactly W/2 along the surface, and the gap between neighbours measured
// along geodesics perpendicular to the right-hand tow.
#include "towgeom/fibre_courses.hpp"

#include <Geom2d_BSplineCurve.hxx>
#include <Standard_Failure.hxx>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <tuple>

#include "placement/curve_derivatives.hpp"
#include "placement/geodesics.hpp"
#include "placement/nurbs_geometry.hpp"
#include "placement/offset_point.hpp"
#include "placement/periodic_surface.hpp"
#include "placement/tool_face.hpp"
#include "placement/trimmed_offset.hpp"
#include "placement/uv_interpolation.hpp"
#include "surface/occt_convert.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// @p curve offset by @p d from the curve named @p from, with the step's record: kept on the
/// surface (cut at, or carried to, its boundary; see detail::offsetWithinSurface()).
detail::TrimmedOffset offsetStep(const detail::ToolFace& f, const CurveOnSurface& curve, double d, SurfaceOffsetMethod method, int steps,
                                 const std::string& what)
{
    if (d == 0.0) {
        detail::TrimmedOffset same;
        same.curve = curve;
        same.geodesicDistance.assign(curve.uv.size(), 0.0);
        same.estimatedError.assign(curve.uv.size(), 0.0);
        return same;
    }
    SurfaceOffsetOptions o;
    o.method = method;
    o.geodesicSteps = steps;
    try {
        return detail::offsetWithinSurface(f, curve, d, o);
    } catch (const Error& e) {
        throw Error(e.code(), what + ": " + e.what());
    }
}

CourseStep stepRecord(const std::string& from, double d, detail::TrimmedOffset& t)
{
    CourseStep step;
    step.from = from;
    step.distance = d;
    step.geodesicDistance = std::move(t.geodesicDistance);
    step.estimatedError = std::move(t.estimatedError);
    return step;
}

/// The cubic B-spline in (u,v) through @p uv (chord-length parameters), poles as (u, v, 0).
/// @throws towgeom::Error (InvalidArgument) naming @p what when the points repeat.
NurbsCurve parameterCurve(const std::vector<UV>& uv, const std::string& what)
{
    const Handle(Geom2d_BSplineCurve) c = detail::interpolateUV(uv, detail::chordParameters(uv));
    if (c.IsNull()) throw Error(ErrorCode::InvalidArgument, what + ": its points repeat (the reference's points must be distinct)");
    NurbsCurve out;
    out.degree = c->Degree();
    for (int i = 1; i <= c->NbKnots(); ++i)
        for (int m = 0; m < c->Multiplicity(i); ++m) out.knots.push_back(c->Knot(i));
    for (int i = 1; i <= c->NbPoles(); ++i) {
        out.poles.push_back({c->Pole(i).X(), c->Pole(i).Y(), 0.0});
        out.weights.push_back(c->Weight(i));
    }
    return out;
}

/// The width between tow @p a (right) and tow @p b (left) at each of a's centreline points.
TowGap measureGap(const Handle(Geom_BSplineSurface)& s, const TowPath& a, const TowPath& b, double width, double spacing, int steps)
{
    TowGap gap;
    const std::size_t n = a.centreline.uv.size();
    // b's centreline as its (u,v) cubic: where a perpendicular meets it between its points (as at
    // ends the boundary cut, where the two tows' points do not pair up) its polyline would be off by
    // the chords' sagitta.
    const Handle(Geom2d_BSplineCurve) other = detail::interpolateUV(b.centreline.uv, detail::chordParameters(b.centreline.uv));
    const auto sideOf = [&](const UV& p) { return detail::sideOfCurve(other, p); };
    const std::vector<gp_Vec> tangents = detail::curveTangents(s, a.centreline);
    gap.width.assign(n, kNaN);
    for (std::size_t i = 0; i < n && !other.IsNull(); ++i) {
        try {
            const UV at = a.centreline.uv[i];
            const detail::SurfaceFrame f = detail::frameAt(s, at.u, at.v);
            gp_Vec t = tangents[i];
            t -= f.n * t.Dot(f.n);
            if (!(t.Magnitude() > 0.0)) continue;
            const gp_Vec o = f.n.Crossed(t.Normalized());
            bool within = false;  // whether the last shot's nearest point on b lies within b
            const auto g = [&](double length) {
                const auto [side, inside] = sideOf(detail::shootGeodesic(s, at, o, length, steps));
                within = inside;
                return side;
            };
            // Bracket the crossing: the point itself lies to the right of b.
            double lo = 0.0, glo = sideOf(at).first, hi = spacing, ghi = g(hi);
            if (!(glo < 0.0)) continue;
            for (int grow = 0; ghi < 0.0 && grow < 4; ++grow) lo = hi, glo = ghi, hi *= 1.5, ghi = g(hi);
            if (!(ghi >= 0.0)) continue;
            // Illinois regula falsi.
            double x = hi;
            int side = 0;
            for (int it = 0; it < 100 && ghi != 0.0 && hi - lo > 1e-12 * spacing; ++it) {
                x = (lo * ghi - hi * glo) / (ghi - glo);
                const double gx = g(x);
                if (gx == 0.0) break;
                if (gx < 0.0) {
                    lo = x, glo = gx;
                    if (side == -1) ghi *= 0.5;
                    side = -1;
                } else {
                    hi = x, ghi = gx;
                    if (side == 1) glo *= 0.5;
                    side = 1;
                }
            }
            if (!within) continue;  // the last shot was at x (g(hi) before the loop, g(x) in it)
            gap.width[i] = x - width;
        } catch (const Error&) {
            // The perpendicular leaves the surface: not measured here.
        }
    }
    gap.minWidth = std::numeric_limits<double>::infinity();
    gap.maxWidth = -gap.minWidth;
    for (const double w : gap.width)
        if (!std::isnan(w)) {
            ++gap.measured;
            gap.minWidth = std::min(gap.minWidth, w);
            gap.maxWidth = std::max(gap.maxWidth, w);
        }
    if (gap.measured == 0) gap.minWidth = gap.maxWidth = kNaN;
    return gap;
}

double largestError(const CourseStep& step)
{
    double worst = 0.0;
    for (const double g : step.geodesicDistance) worst = std::max(worst, std::abs(std::abs(step.distance) - g));
    return worst;
}

/// The tow @p name whose centreline is @p base's curve offset by @p d, with its edges, length and
/// steering; nothing when the centreline lies off the face.
std::optional<TowPath> layTow(const detail::ToolFace& f, const CourseCentre& base, double d, const std::string& name,
                              const CourseOptions& options, double w)
{
    const Handle(Geom_BSplineSurface)& s = f.surface;
    const int steps = options.geodesicSteps;
    detail::TrimmedOffset line = offsetStep(f, base.curve, d, options.method, steps, "tow " + name);
    if (line.curve.uv.size() < 2) return std::nullopt;
    TowPath tow;
    tow.name = name;
    tow.centreline = line.curve;
    // The side each end lies on: cut or carried there, or there already.
    tow.startBoundary = line.startSide.empty() ? detail::faceSide(f, line.curve.uv.front(), 1e-9) : line.startSide;
    tow.endBoundary = line.endSide.empty() ? detail::faceSide(f, line.curve.uv.back(), 1e-9) : line.endSide;
    tow.step = stepRecord(base.name, d, line);
    tow.length = detail::lengthOnSurface(s, tow.centreline);
    tow.geodesicCurvature = detail::geodesicCurvatures(s, tow.centreline);
    double sharpest = 0.0;
    for (const double k : tow.geodesicCurvature) sharpest = std::max(sharpest, std::abs(k));
    tow.steeringRadius = sharpest > 0.0 ? 1.0 / sharpest : std::numeric_limits<double>::infinity();
    // Each edge, and its (u,v) B-spline; none where the whole edge hangs off the face.
    const auto edge = [&](double side, const char* which, CurveOnSurface& e, NurbsCurve& curve) {
        const std::string what = "tow " + name + "'s " + which + " edge";
        e = offsetStep(f, tow.centreline, side, SurfaceOffsetMethod::Geodesic, steps, what).curve;
        if (e.uv.size() < 2) e = CurveOnSurface();
        else curve = parameterCurve(e.uv, what);
    };
    edge(-0.5 * w, "right", tow.right, tow.rightCurve);
    edge(0.5 * w, "left", tow.left, tow.leftCurve);
    return tow;
}

}  // namespace

namespace {

/// layCourses() on the face @p f (the reference trimmed to it).
CoursePlan layCoursesOn(const detail::ToolFace& f, const CurveOnSurface& reference, const CourseOptions& options)
{
    const double w = options.towWidth;
    if (!(w > 0.0) || !std::isfinite(w)) throw Error(ErrorCode::InvalidArgument, "layCourses: the tow width must be positive");
    if (options.towsPerCourse < 1 || options.courses < 1) throw Error(ErrorCode::InvalidArgument, "layCourses: at least one tow and one course");
    if (!(options.spacing >= 0.0) || !std::isfinite(options.spacing) || !(options.tolerance >= 0.0) || !std::isfinite(options.tolerance))
        throw Error(ErrorCode::InvalidArgument, "layCourses: the spacing and tolerance must be finite, 0 or more");
    if (options.geodesicSteps < 1) throw Error(ErrorCode::InvalidArgument, "layCourses: at least one geodesic step");
    if (!(options.minSteeringRadius >= 0.0) || !std::isfinite(options.minSteeringRadius))
        throw Error(ErrorCode::InvalidArgument, "layCourses: the smallest steering radius must be finite, 0 or more");
    if (reference.uv.size() < 4 || reference.points.size() != reference.uv.size())
        throw Error(ErrorCode::InvalidArgument, "layCourses: a reference of at least 4 points, each with its (u,v)");
    for (std::size_t i = 0; i < reference.uv.size(); ++i) {
        if (!std::isfinite(reference.uv[i].u) || !std::isfinite(reference.uv[i].v))
            throw Error(ErrorCode::InvalidArgument, "layCourses: reference point " + std::to_string(i) + " is not finite");
        if (i > 0 && distance(reference.points[i], reference.points[i - 1]) == 0.0)
            throw Error(ErrorCode::InvalidArgument, "layCourses: reference points " + std::to_string(i - 1) + " and " + std::to_string(i) + " coincide");
    }
    const Handle(Geom_BSplineSurface)& s = f.surface;
    CoursePlan plan;
    try {
        plan.reference = f.trim ? detail::trimToFace(f, reference) : reference;
    } catch (const Standard_Failure& e) {
        throw Error(ErrorCode::Internal, std::string("layCourses: OpenCASCADE failed trimming the reference: ") + e.GetMessageString());
    }
    if (plan.reference.uv.size() < 4)
        throw Error(ErrorCode::InvalidArgument, "layCourses: " + std::to_string(plan.reference.uv.size()) +
                                                    " of the reference's points lie on the face (at least 4 must: a reference sampled within the face, see referenceFromPlane())");
    plan.towWidth = w;
    plan.spacing = options.spacing > 0.0 ? options.spacing : w;
    plan.tolerance = options.tolerance > 0.0 ? options.tolerance : 1e-3 * w;
    plan.method = options.method;
    plan.minSteeringRadius = options.minSteeringRadius;
    const std::size_t nTows = options.towsPerCourse;
    const int steps = options.geodesicSteps;
    try {
        for (std::size_t c = 0; c < options.courses; ++c) {
            CourseCentre centre;
            centre.name = "c" + std::to_string(c + 1);
            // Where this course's tows are offset from, and by how much more than their place in it.
            CourseCentre base;
            double beyond = 0.0;
            if (c == 0) {
                centre.curve = plan.reference;
                centre.step.from = "reference";
            } else {
                const CourseCentre& last = plan.courses.back();
                detail::TrimmedOffset next = offsetStep(f, last.curve, nTows * plan.spacing, options.method, steps, "course " + centre.name);
                if (next.curve.uv.size() < 2) {  // its centreline is off the face: its tows from the last one's
                    base = last;
                    beyond = nTows * plan.spacing;
                } else {
                    centre.curve = next.curve;
                    centre.step = stepRecord(last.name, nTows * plan.spacing, next);
                }
            }
            const bool centreOff = beyond > 0.0;
            if (centreOff) {
                plan.offSurface.push_back(centre.name);
            } else {
                plan.courses.push_back(centre);
                base = centre;
            }
            for (std::size_t i = 0; i < nTows; ++i) {
                const std::string name = centre.name + "_t" + std::to_string(i + 1);
                const double d = (static_cast<double>(i) - 0.5 * static_cast<double>(nTows - 1)) * plan.spacing + beyond;
                std::optional<TowPath> tow = layTow(f, base, d, name, options, w);
                if (!tow) {
                    plan.offSurface.push_back(name);
                    continue;
                }
                tow->course = c;
                if (options.minSteeringRadius > 0.0 && tow->steeringRadius < options.minSteeringRadius) plan.belowSteeringRadius.push_back(name);
                plan.tows.push_back(std::move(*tow));
            }
            if (centreOff) {  // later courses lie farther off
                for (std::size_t k = c + 1; k < options.courses; ++k) plan.offSurface.push_back("c" + std::to_string(k + 1));
                break;
            }
        }
        if (plan.tows.empty()) throw Error(ErrorCode::InvalidArgument, "layCourses: every tow lies off the surface");
        for (std::size_t j = 0; j + 1 < plan.tows.size(); ++j) {
            TowGap gap = measureGap(s, plan.tows[j], plan.tows[j + 1], w, plan.spacing, steps);
            gap.right = j;
            gap.left = j + 1;
            gap.betweenCourses = plan.tows[j].course != plan.tows[j + 1].course;
            plan.gaps.push_back(std::move(gap));
        }
    } catch (const Standard_Failure& e) {
        throw Error(ErrorCode::Internal, std::string("layCourses: OpenCASCADE failed: ") + e.GetMessageString());
    }
    for (const CourseCentre& c : plan.courses) plan.largestStepError = std::max(plan.largestStepError, largestError(c.step));
    for (const TowPath& t : plan.tows) plan.largestStepError = std::max(plan.largestStepError, largestError(t.step));
    plan.withinTolerance = plan.largestStepError <= plan.tolerance;
    return plan;
}

}  // namespace

CoursePlan layCourses(const NurbsSurface& surface, const CurveOnSurface& reference, const CourseOptions& options)
{
    return layCoursesOn(detail::toolFace(surface), reference, options);
}

CoursePlan layCourses(const PlacementSurface& tool, const CurveOnSurface& reference, const CourseOptions& options)
{
    return layCoursesOn(detail::toolFace(tool.surface, tool.trim), reference, options);
}

TOWGEOM_END_NAMESPACE
