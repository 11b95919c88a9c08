// Cubic B-splines in (u,v) through points.
#include "placement/uv_interpolation.hpp"

#include <Geom2dAPI_Interpolate.hxx>
#include <Geom2dAPI_ProjectPointOnCurve.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TColgp_HArray1OfPnt2d.hxx>

#include <cmath>
#include <limits>

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

Handle(Geom2d_BSplineCurve) interpolateUV(const std::vector<UV>& uv, const std::vector<double>& params)
{
    const int n = static_cast<int>(uv.size());
    if (n < 2 || params.size() != uv.size()) return {};
    Handle(TColgp_HArray1OfPnt2d) points = new TColgp_HArray1OfPnt2d(1, n);
    Handle(TColStd_HArray1OfReal) t = new TColStd_HArray1OfReal(1, n);
    for (int i = 0; i < n; ++i) {
        points->SetValue(i + 1, gp_Pnt2d(uv[i].u, uv[i].v));
        t->SetValue(i + 1, params[i]);
    }
    try {
        Geom2dAPI_Interpolate c(points, t, Standard_False, 1e-14);
        c.Perform();
        if (c.IsDone()) return c.Curve();
    } catch (const Standard_Failure&) {
        // Points closer than the tolerance (OpenCASCADE throws from the constructor).
    }
    return {};
}

std::vector<double> chordParameters(const std::vector<UV>& uv)
{
    std::vector<double> params;
    if (uv.empty()) return params;
    params.push_back(0.0);
    for (std::size_t i = 1; i < uv.size(); ++i) params.push_back(params.back() + std::hypot(uv[i].u - uv[i - 1].u, uv[i].v - uv[i - 1].v));
    return params;
}

std::pair<double, bool> sideOfCurve(const Handle(Geom2d_BSplineCurve)& c, const UV& p)
{
    const gp_Pnt2d q(p.u, p.v);
    const double t0 = c->FirstParameter(), t1 = c->LastParameter();
    double best = std::numeric_limits<double>::infinity(), at = t0;
    bool foot = false;
    for (const double t : {t0, t1}) {
        const double d = c->Value(t).Distance(q);
        if (d < best) best = d, at = t;
    }
    Geom2dAPI_ProjectPointOnCurve projection(q, c);
    for (int k = 1; k <= projection.NbPoints(); ++k)
        if (projection.Distance(k) < best) best = projection.Distance(k), at = projection.Parameter(k), foot = true;
    gp_Pnt2d on;
    gp_Vec2d d;
    c->D1(at, on, d);
    const gp_Vec2d away(on, q);
    const double side = d.Magnitude() > 0.0 ? d.Crossed(away) / d.Magnitude() : 0.0;
    // Within: an orthogonal foot short of the ends, or an end with the point not past it along
    // the curve (a point on the curve's end itself is within).
    const double slack = 1e-9 * (t1 - t0);
    if (foot && at > t0 + slack && at < t1 - slack) return {side, true};
    const double along = d.Magnitude() > 0.0 ? d.Dot(away) / d.Magnitude() : 0.0;
    const double reach = 1e-9 * c->Value(t0).Distance(c->Value(t1)) + 1e-12;
    return {side, at - t0 < t1 - at ? along >= -reach : along <= reach};
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
