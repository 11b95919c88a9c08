// A course's reference curve: points projected onto the surface, or the surface cut by a plane
// (OCCT's surface-surface intersection, sampled evenly by arc length).
#include "towgeom/reference_curve.hpp"

#include <GCPnts_UniformAbscissa.hxx>
#include <GeomAPI_IntSS.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <Geom_Plane.hxx>
#include <Standard_Failure.hxx>
#include <gp_Pln.hxx>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "placement/nurbs_geometry.hpp"
#include "placement/periodic_surface.hpp"
#include "placement/tool_face.hpp"
#include "placement/trimmed_offset.hpp"
#include "surface/occt_convert.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

/// The diagonal of the box of @p s's poles.
double netSize(const NurbsSurface& s)
{
    BoundingBox box;
    for (const Point3& p : s.poles) box.add(p);
    return distance(box.min, box.max);
}

/// The (u,v) of @p p's nearest point on @p s and its distance.
std::pair<UV, double> nearest(const Handle(Geom_BSplineSurface)& s, const gp_Pnt& p)
{
    GeomAPI_ProjectPointOnSurf projection(p, s);
    if (!projection.IsDone() || projection.NbPoints() == 0) return {UV{}, std::numeric_limits<double>::infinity()};
    UV uv;
    projection.LowerDistanceParameters(uv.u, uv.v);
    return {uv, projection.LowerDistance()};
}

}  // namespace

CurveOnSurface referenceFromPoints(const NurbsSurface& surface, const std::vector<Point3>& points, double maxDistance)
{
    if (points.size() < 2) throw Error(ErrorCode::InvalidArgument, "referenceFromPoints: at least 2 points");
    if (!(maxDistance >= 0.0)) throw Error(ErrorCode::InvalidArgument, "referenceFromPoints: a distance of 0 or more");
    const Handle(Geom_BSplineSurface) s = detail::toolSurface(surface);
    const double allowed = maxDistance > 0.0 ? maxDistance : 1e-3 * netSize(surface);
    std::vector<UV> uv;
    try {
        for (std::size_t i = 0; i < points.size(); ++i) {
            const auto [at, away] = nearest(s, detail::toOcct(points[i]));
            if (!(away <= allowed))
                throw Error(ErrorCode::InvalidArgument, "referenceFromPoints: point " + std::to_string(i) + " lies " + std::to_string(away) +
                                                            " from the surface (more than " + std::to_string(allowed) + ")");
            const UV next = uv.empty() ? at : detail::nearestCopy(s, at, uv.back());  // across a seam: on from the last
            if (!uv.empty() && next.u == uv.back().u && next.v == uv.back().v)
                throw Error(ErrorCode::InvalidArgument, "referenceFromPoints: points " + std::to_string(i - 1) + " and " + std::to_string(i) +
                                                            " have the same nearest point on the surface");
            uv.push_back(next);
        }
    } catch (const Standard_Failure& e) {
        throw Error(ErrorCode::Internal, std::string("referenceFromPoints: OpenCASCADE failed: ") + e.GetMessageString());
    }
    return curveOnSurface(surface, uv);
}

namespace {

/// A run of a cut on the face: its parameters and how near it passes the plane's point.
struct Run {
    double first = 0.0, last = 0.0;
    double distance = std::numeric_limits<double>::infinity();
};

/// The run [first, last] of @p c on the trimmed face @p f passing nearest @p o (200 samples,
/// then each end bisected to 1e-15 of the curve's range; on a periodic curve the run may pass
/// its start, then last > the curve's last parameter); nothing when no sample lies on the face.
std::optional<Run> runOnFace(const detail::ToolFace& f, const Handle(Geom_Curve)& c, const gp_Pnt& o, double size)
{
    const double t0 = c->FirstParameter(), t1 = c->LastParameter(), period = t1 - t0;
    const auto on = [&](double t) {
        const auto [at, away] = nearest(f.surface, c->Value(t));
        return away <= 1e-6 * size && detail::onFace(f, at, 1e-9);
    };
    constexpr int m = 200;
    std::vector<double> ts(m + 1);
    std::vector<bool> in(m + 1);
    for (int k = 0; k <= m; ++k) ts[k] = t0 + period * k / m, in[k] = on(ts[k]);
    if (std::all_of(in.begin(), in.end(), [](bool b) { return b; })) {
        double d = std::numeric_limits<double>::infinity();
        for (const double t : ts) d = std::min(d, o.Distance(c->Value(t)));
        return Run{t0, t1, d};
    }
    // A periodic curve's samples from one off the face, round to it: every run is contiguous.
    if (c->IsPeriodic() && in[0]) {
        const int off = static_cast<int>(std::find(in.begin(), in.end(), false) - in.begin());
        std::vector<double> turned;
        for (int k = off; k <= m; ++k) turned.push_back(ts[k]);
        for (int k = 1; k <= off; ++k) turned.push_back(ts[k] + period);
        ts = turned;
        for (int k = 0; k <= m; ++k) in[k] = on(ts[k]);
    }
    int bestFirst = -1, bestLast = -1;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (int k = 0; k <= m;) {
        if (!in[k]) {
            ++k;
            continue;
        }
        int j = k;
        double d = o.Distance(c->Value(ts[k]));
        while (j + 1 <= m && in[j + 1]) d = std::min(d, o.Distance(c->Value(ts[++j])));
        if (d < bestDistance) bestDistance = d, bestFirst = k, bestLast = j;
        k = j + 1;
    }
    if (bestFirst < 0) return std::nullopt;
    const auto crossing = [&](double inside, double outside) {
        for (int it = 0; it < 200 && std::abs(outside - inside) > 1e-15 * period; ++it) {
            const double mid = 0.5 * (inside + outside);
            (on(mid) ? inside : outside) = mid;
        }
        return inside;
    };
    const double first = bestFirst > 0 ? crossing(ts[bestFirst], ts[bestFirst - 1]) : ts[bestFirst];
    const double last = bestLast < m ? crossing(ts[bestLast], ts[bestLast + 1]) : ts[bestLast];
    return Run{first, last, bestDistance};
}

/// @p c made periodic where it is a closed B-spline (as a plane's cut round a closed surface
/// comes back from the intersection), so that a run on the face may pass its start.
Handle(Geom_Curve) periodicWhereClosed(const Handle(Geom_Curve)& c)
{
    const Handle(Geom_BSplineCurve) b = Handle(Geom_BSplineCurve)::DownCast(c);
    if (b.IsNull() || b->IsPeriodic() || !b->IsClosed()) return c;
    const Handle(Geom_BSplineCurve) copy = Handle(Geom_BSplineCurve)::DownCast(b->Copy());
    try {
        copy->SetPeriodic();
    } catch (const Standard_Failure&) {
        return c;  // OpenCASCADE cannot: the run stops at its start
    }
    return Handle(Geom_Curve)(copy);
}

/// referenceFromPlane() on the face @p f of @p surface.
CurveOnSurface planeCut(const NurbsSurface& surface, const detail::ToolFace& f, const Point3& origin, const Vector3& normal, std::size_t points,
                        bool reverse)
{
    const auto finite = [](const Point3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); };
    if (!finite(origin) || !finite(normal)) throw Error(ErrorCode::InvalidArgument, "referenceFromPlane: the plane's point and normal must be finite");
    // Scaled by its largest component: a huge normal is still a direction.
    const double largest = std::max({std::abs(normal.x), std::abs(normal.y), std::abs(normal.z)});
    if (!(largest > 0.0)) throw Error(ErrorCode::InvalidArgument, "referenceFromPlane: the plane's normal is zero");
    const Vector3 direction = (1.0 / largest) * normal;
    if (points < 2 || points > 10000000) throw Error(ErrorCode::InvalidArgument, "referenceFromPlane: 2 to 10,000,000 points");
    const Handle(Geom_BSplineSurface)& s = f.surface;
    const double size = netSize(surface);
    std::vector<UV> uv;
    try {
        const gp_Pnt o = detail::toOcct(origin);
        const Handle(Geom_Plane) plane = new Geom_Plane(gp_Pln(o, gp_Dir(direction.x, direction.y, direction.z)));
        GeomAPI_IntSS cut(s, plane, 1e-9 * size);
        if (!cut.IsDone() || cut.NbLines() == 0) throw Error(ErrorCode::InvalidArgument, "referenceFromPlane: the plane does not cut the surface");
        // The cut (on a trimmed face: its run on the face) passing nearest the plane's point.
        Handle(Geom_Curve) best;
        Run run;
        for (int k = 1; k <= cut.NbLines(); ++k) {
            const Handle(Geom_Curve) c = f.trim ? periodicWhereClosed(cut.Line(k)) : cut.Line(k);
            Run here{c->FirstParameter(), c->LastParameter()};
            if (f.trim) {
                const std::optional<Run> on = runOnFace(f, c, o, size);
                if (!on) continue;
                here = *on;
            } else {
                GeomAPI_ProjectPointOnCurve onCurve(o, c);
                here.distance = std::min(o.Distance(c->Value(c->FirstParameter())), o.Distance(c->Value(c->LastParameter())));
                if (onCurve.NbPoints() > 0) here.distance = std::min(here.distance, onCurve.LowerDistance());
            }
            if (here.distance < run.distance) run = here, best = c;
        }
        if (best.IsNull()) throw Error(ErrorCode::InvalidArgument, "referenceFromPlane: the plane's cut lies off the face (outside its trimming curves)");
        // A run past a periodic curve's start: the curve trimmed to it (OpenCASCADE samples a
        // curve within its own range).
        Handle(Geom_Curve) piece = best;
        if (run.last > best->LastParameter() && best->IsPeriodic()) piece = new Geom_TrimmedCurve(best, run.first, run.last);
        const double first = piece == best ? run.first : piece->FirstParameter(), last = piece == best ? run.last : piece->LastParameter();
        GeomAdaptor_Curve adaptor(piece);
        GCPnts_UniformAbscissa sampler(adaptor, static_cast<int>(points), first, last, 1e-9 * size);
        if (!sampler.IsDone() || sampler.NbPoints() != static_cast<int>(points))
            throw Error(ErrorCode::Internal, "referenceFromPlane: the intersection curve could not be sampled");
        for (int k = 1; k <= sampler.NbPoints(); ++k) {
            const auto [at, away] = nearest(s, piece->Value(sampler.Parameter(k)));
            if (!(away <= 1e-6 * size)) throw Error(ErrorCode::Internal, "referenceFromPlane: an intersection point lies off the surface");
            // Across a periodic seam the parameters run on (a closed cut ends one period on).
            uv.push_back(uv.empty() ? at : detail::nearestCopy(s, at, uv.back()));
        }
    } catch (const Standard_Failure& e) {
        throw Error(ErrorCode::Internal, std::string("referenceFromPlane: OpenCASCADE failed: ") + e.GetMessageString());
    }
    if (reverse) std::reverse(uv.begin(), uv.end());
    // A hole of a trimmed face between two of the points (the run was found from 200 samples):
    // cut there too.
    return f.trim ? detail::trimToFace(f, curveOnSurface(surface, uv)) : curveOnSurface(surface, uv);
}

}  // namespace

CurveOnSurface referenceFromPlane(const NurbsSurface& surface, const Point3& origin, const Vector3& normal, std::size_t points, bool reverse)
{
    return planeCut(surface, detail::toolFace(surface), origin, normal, points, reverse);
}

CurveOnSurface referenceFromPlane(const PlacementSurface& tool, const Point3& origin, const Vector3& normal, std::size_t points, bool reverse)
{
    return planeCut(tool.surface, detail::toolFace(tool.surface, tool.trim), origin, normal, points, reverse);
}

TOWGEOM_END_NAMESPACE
