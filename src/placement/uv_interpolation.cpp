// Cubic B-splines in (u,v) through points.
#include "placement/uv_interpolation.hpp"

#include <Geom2dAPI_Interpolate.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TColgp_HArray1OfPnt2d.hxx>

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

}  // namespace detail
TOWGEOM_END_NAMESPACE
