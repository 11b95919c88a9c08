// Curves on a NURBS surface offset along it: Schueler et al.'s tangent step and projection with
// their error estimate, or a geodesic perpendicular to the curve; geodesics integrated on the
// exact surface (OCCT's second derivatives, RK4) and shot to a target by Newton's method.
#include "towgeom/surface_offset_curves.hpp"

#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Standard_Failure.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "placement/geodesics.hpp"
#include "placement/nurbs_geometry.hpp"
#include "placement/curve_derivatives.hpp"
#include "placement/offset_point.hpp"
#include "placement/periodic_surface.hpp"
#include "placement/uv_interpolation.hpp"
#include "surface/occt_convert.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

using namespace detail;

CurveOnSurface curveOnSurface(const NurbsSurface& surface, const std::vector<UV>& uv)
{
    CurveOnSurface c;
    c.uv = uv;
    const Handle(Geom_BSplineSurface) s = detail::toolSurface(surface);
    for (const UV& p : uv) {
        if (!insideParameters(s, p.u, p.v)) throw Error(ErrorCode::InvalidArgument, "curveOnSurface: a point lies off the surface's parameter range");  // any u or v where periodic
        c.points.push_back(detail::fromOcct(s->Value(p.u, p.v)));
    }
    return c;
}

double geodesicDistance(const NurbsSurface& surface, const UV& from, const UV& to, int steps)
{
    if (steps < 1) throw Error(ErrorCode::InvalidArgument, "geodesicDistance: at least one step");
    const Handle(Geom_BSplineSurface) s = detail::toolSurface(surface);
    try {
        return geodesicDistanceOn(s, from, to, steps);
    } catch (const Standard_Failure& e) {
        throw Error(ErrorCode::Internal, std::string("geodesicDistance: OpenCASCADE failed: ") + e.GetMessageString());
    }
}

namespace detail {

/// A tangent step's foot found far from where it should be: past the surface's edge (another
/// orthogonal foot elsewhere: the offset leaves the surface) where it has an edge, else (a closed
/// surface) a step too long for its curvature: an error.
[[noreturn]] void throwFarFoot(const Handle(Geom_BSplineSurface)& s, ErrorCode code, const std::string& message)
{
    if (!s->IsUPeriodic() || !s->IsVPeriodic()) throw OffSurface(code, message);
    throw Error(code, message);
}

OffsetPoint offsetPoint(const Handle(Geom_BSplineSurface)& s, const UV& at, const gp_Vec& tangent, double d, const SurfaceOffsetOptions& options,
                        bool measure)
{
    const SurfaceFrame f = frameAt(s, at.u, at.v);
    gp_Vec t = tangent - f.n * tangent.Dot(f.n);
    if (!(t.Magnitude() > 0.0)) throw Error(ErrorCode::InvalidArgument, "offsetOnSurface: two consecutive points coincide");
    t.Normalize();
    const gp_Vec o = f.n.Crossed(t);
    OffsetPoint out;
    const double kappa = normalCurvature(s, at.u, at.v, o);
    const double psi = std::atan(std::abs(d * kappa));
    out.estimatedError = psi > 1e-8 ? std::abs(d) * (1.0 - psi / std::tan(psi)) : std::abs(d) * psi * psi / 3.0;
    double u0, u1, v0, v1;
    s->Bounds(u0, u1, v0, v1);
    if (options.method == SurfaceOffsetMethod::Geodesic) {
        out.raw = shootGeodesic(s, at, d >= 0.0 ? o : o.Reversed(), std::abs(d), options.geodesicSteps);
    } else {
        const gp_Pnt target = f.p.Translated(o * d);
        GeomAPI_ProjectPointOnSurf projection(target, s);
        if (!projection.IsDone() || projection.NbPoints() == 0)
            throw OffSurface(ErrorCode::InvalidArgument, "offsetOnSurface: an offset point does not project onto the surface (it leaves the surface)");
        projection.LowerDistanceParameters(out.raw.u, out.raw.v);
        out.raw = nearestCopy(s, out.raw, at);  // across a periodic seam: the copy next to the start
        // The nearest foot may lie on another part of the surface (the true one past the
        // surface's edge): a foot farther from the point than twice the step is not this offset.
        // The same past the surface's edge, where the foot found is some other orthogonal one:
        // a true foot lies within d^2 kappa / 2 <= |d| / 2 of the target while |d kappa| <= 1
        // (a longer step than the radius of curvature is no tangent step).
        // Past the box's edge the nearest point is on the edge, not an orthogonal foot: the
        // surface ends before the offset does.
        const SurfaceFrame at2 = frameAt(s, out.raw.u, out.raw.v);
        const gp_Vec miss(at2.p, target);
        const double across = (miss - at2.n * miss.Dot(at2.n)).Magnitude();
        if (across > 1e-7 * std::abs(d) + 1e-9 * miss.Magnitude())
            throw OffSurface(ErrorCode::InvalidArgument, "offsetOnSurface: an offset point's foot on the surface is not orthogonal (the offset leaves the surface)");
        const gp_Pnt foot = at2.p;
        if (foot.Distance(f.p) > 2.0 * std::abs(d) || foot.Distance(target) > 0.5 * std::abs(d))
            throwFarFoot(s, ErrorCode::InvalidArgument, "offsetOnSurface: an offset point's nearest point on the surface is not "
                                                    "near it (the offset leaves the surface)");
    }
    // A geodesic along the edge may end a rounding outside: clamped where the box is the surface.
    out.uv = out.raw;
    if (!s->IsUPeriodic()) out.uv.u = std::clamp(out.uv.u, u0, u1);
    if (!s->IsVPeriodic()) out.uv.v = std::clamp(out.uv.v, v0, v1);
    if (!measure) {
        out.geodesicDistance = std::numeric_limits<double>::quiet_NaN();
        return out;
    }
    // From the geodesic shot (converged at once when it ended where it was kept), or the chord.
    const gp_Vec shot = d >= 0.0 ? o : o.Reversed();
    const bool geodesic = options.method == SurfaceOffsetMethod::Geodesic;
    out.geodesicDistance = geodesicDistanceOn(s, at, out.uv, options.geodesicSteps, geodesic ? &shot : nullptr, geodesic ? std::abs(d) : 0.0);
    // A foot on another part of the surface is not d away along it (Eq. 2's shortfall is a small
    // part of d while |d kappa| <= 1).
    if (options.method != SurfaceOffsetMethod::Geodesic && std::abs(out.geodesicDistance - std::abs(d)) > 0.25 * std::abs(d))
        throwFarFoot(s, ErrorCode::InvalidArgument, "offsetOnSurface: an offset point's nearest point on the surface is not "
                                                "near it along the surface (the offset leaves the surface)");
    return out;
}

}  // namespace detail

SurfaceOffsetStep offsetOnSurface(const NurbsSurface& surface, const CurveOnSurface& curve, double d, const SurfaceOffsetOptions& options)
{
    if (curve.uv.size() < 2 || curve.points.size() != curve.uv.size())
        throw Error(ErrorCode::InvalidArgument, "offsetOnSurface: a curve of at least 2 points, each with its (u,v)");
    if (!std::isfinite(d) || options.geodesicSteps < 1) throw Error(ErrorCode::InvalidArgument, "offsetOnSurface: a finite distance, at least one step");
    const Handle(Geom_BSplineSurface) s = detail::toolSurface(surface);
    SurfaceOffsetStep out;
    try {
        for (const UV& at : curve.uv)
            if (!insideParameters(s, at.u, at.v)) throw Error(ErrorCode::InvalidArgument, "offsetOnSurface: a point lies off the surface's parameter range");
        const std::vector<gp_Vec> tangents = curveTangents(s, curve);
        for (std::size_t i = 0; i < curve.uv.size(); ++i) {
            const OffsetPoint p = offsetPoint(s, curve.uv[i], tangents[i], d, options);
            out.curve.uv.push_back(p.uv);
            out.curve.points.push_back(detail::fromOcct(s->Value(p.uv.u, p.uv.v)));
            out.geodesicDistance.push_back(p.geodesicDistance);
            out.estimatedError.push_back(p.estimatedError);
        }
    } catch (const Standard_Failure& e) {
        throw Error(ErrorCode::Internal, std::string("offsetOnSurface: OpenCASCADE failed: ") + e.GetMessageString());
    }
    return out;
}

TOWGEOM_END_NAMESPACE
