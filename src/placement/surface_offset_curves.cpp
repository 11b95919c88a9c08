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
#include <string>

#include "placement/geodesics.hpp"
#include "placement/nurbs_geometry.hpp"
#include "surface/occt_convert.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

using namespace detail;

CurveOnSurface curveOnSurface(const NurbsSurface& surface, const std::vector<UV>& uv)
{
    CurveOnSurface c;
    c.uv = uv;
    const Handle(Geom_BSplineSurface) s = detail::occtSurface(surface);
    for (const UV& p : uv) {
        if (!insideParameters(s, p.u, p.v)) throw Error(ErrorCode::InvalidArgument, "curveOnSurface: a point lies off the surface's parameter range");
        c.points.push_back(detail::fromOcct(s->Value(p.u, p.v)));
    }
    return c;
}

double geodesicDistance(const NurbsSurface& surface, const UV& from, const UV& to, int steps)
{
    if (steps < 1) throw Error(ErrorCode::InvalidArgument, "geodesicDistance: at least one step");
    const Handle(Geom_BSplineSurface) s = detail::occtSurface(surface);
    try {
        return geodesicDistanceOn(s, from, to, steps);
    } catch (const Standard_Failure& e) {
        throw Error(ErrorCode::Internal, std::string("geodesicDistance: OpenCASCADE failed: ") + e.GetMessageString());
    }
}

SurfaceOffsetStep offsetOnSurface(const NurbsSurface& surface, const CurveOnSurface& curve, double d, const SurfaceOffsetOptions& options)
{
    if (curve.uv.size() < 2 || curve.points.size() != curve.uv.size())
        throw Error(ErrorCode::InvalidArgument, "offsetOnSurface: a curve of at least 2 points, each with its (u,v)");
    if (!std::isfinite(d) || options.geodesicSteps < 1) throw Error(ErrorCode::InvalidArgument, "offsetOnSurface: a finite distance, at least one step");
    const Handle(Geom_BSplineSurface) s = detail::occtSurface(surface);
    SurfaceOffsetStep out;
    try {
        const std::size_t n = curve.uv.size();
        for (std::size_t i = 0; i < n; ++i) {
            const UV at = curve.uv[i];
            if (!insideParameters(s, at.u, at.v)) throw Error(ErrorCode::InvalidArgument, "offsetOnSurface: a point lies off the surface's parameter range");
            const SurfaceFrame f = frameAt(s, at.u, at.v);
            // The curve's tangent from its neighbours, in the tangent plane; O = N x T.
            const Point3 a = curve.points[i > 0 ? i - 1 : i], b = curve.points[i + 1 < n ? i + 1 : i];
            gp_Vec t(detail::toOcct(a), detail::toOcct(b));
            t -= f.n * t.Dot(f.n);
            if (!(t.Magnitude() > 0.0)) throw Error(ErrorCode::InvalidArgument, "offsetOnSurface: two consecutive points coincide");
            t.Normalize();
            const gp_Vec o = f.n.Crossed(t);
            const double kappa = normalCurvature(s, at.u, at.v, o);
            const double psi = std::atan(std::abs(d * kappa));
            out.estimatedError.push_back(psi > 1e-8 ? std::abs(d) * (1.0 - psi / std::tan(psi)) : std::abs(d) * psi * psi / 3.0);
            UV moved;
            if (options.method == SurfaceOffsetMethod::Geodesic) {
                moved = shootGeodesic(s, at, d >= 0.0 ? o : o.Reversed(), std::abs(d), options.geodesicSteps);
                double u0, u1, v0, v1;  // a geodesic along the edge may end a rounding outside
                s->Bounds(u0, u1, v0, v1);
                moved = {std::clamp(moved.u, u0, u1), std::clamp(moved.v, v0, v1)};
            } else {
                const gp_Pnt target = f.p.Translated(o * d);
                GeomAPI_ProjectPointOnSurf projection(target, s);
                if (!projection.IsDone() || projection.NbPoints() == 0)
                    throw Error(ErrorCode::InvalidArgument, "offsetOnSurface: an offset point does not project onto the surface");
                projection.LowerDistanceParameters(moved.u, moved.v);
                // The nearest foot may lie on another part of the surface (the true one past the
                // surface's edge, or across a closed surface's seam): a foot farther from the
                // point than twice the step is not this offset.
                if (s->Value(moved.u, moved.v).Distance(f.p) > 2.0 * std::abs(d))
                    throw Error(ErrorCode::InvalidArgument, "offsetOnSurface: an offset point's nearest point on the surface is not "
                                                            "near it (the offset leaves the surface, or crosses its seam)");
            }
            out.curve.uv.push_back(moved);
            out.curve.points.push_back(detail::fromOcct(s->Value(moved.u, moved.v)));
            out.geodesicDistance.push_back(geodesicDistanceOn(s, at, moved, options.geodesicSteps));
        }
    } catch (const Standard_Failure& e) {
        throw Error(ErrorCode::Internal, std::string("offsetOnSurface: OpenCASCADE failed: ") + e.GetMessageString());
    }
    return out;
}

TOWGEOM_END_NAMESPACE
