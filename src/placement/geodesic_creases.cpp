// Geodesics across a crease: the tangent's component along the crease and its speed kept, its
// part across the crease turned into the other face.
#include "placement/geodesic_creases.hpp"

#include <cmath>

#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

std::vector<double> creaseKnots(const Handle(Geom_BSplineSurface)& s, bool alongU)
{
    std::vector<double> out;
    if (alongU ? s->IsUPeriodic() : s->IsVPeriodic()) return out;
    const int n = alongU ? s->NbUKnots() : s->NbVKnots(), degree = alongU ? s->UDegree() : s->VDegree();
    for (int k = 2; k < n; ++k)
        if ((alongU ? s->UMultiplicity(k) : s->VMultiplicity(k)) >= degree) out.push_back(alongU ? s->UKnot(k) : s->VKnot(k));
    return out;
}

std::array<double, 2> ratesAcrossCrease(const Handle(Geom_BSplineSurface)& s, double u, double v, double du, double dv, bool creaseInU, int towards)
{
    double u0, u1, v0, v1;
    s->Bounds(u0, u1, v0, v1);
    const double step = 1e-12 * (creaseInU ? u1 - u0 : v1 - v0);
    const auto derivatives = [&](int side, gp_Vec& su, gp_Vec& sv) {
        gp_Pnt p;
        s->D1(creaseInU ? u + side * step : u, creaseInU ? v : v + side * step, p, su, sv);
    };
    gp_Vec suA, svA, suB, svB;
    derivatives(-towards, suA, svA);
    derivatives(towards, suB, svB);
    const gp_Vec t = suA * du + svA * dv;  // the tangent, on the side it comes from
    // Along the crease (the same curve on both sides), and across it on each side.
    gp_Vec along = creaseInU ? (svA + svB) * 0.5 : (suA + suB) * 0.5;
    if (!(along.Magnitude() > 0.0)) throw Error(ErrorCode::InvalidArgument, "a geodesic crosses a crease where the surface's parametrisation is singular");
    along.Normalize();
    gp_Vec acrossB = creaseInU ? suB : svB;
    acrossB -= along * acrossB.Dot(along);
    if (!(acrossB.Magnitude() > 0.0)) throw Error(ErrorCode::InvalidArgument, "a geodesic crosses a crease where the surface folds back on itself");
    acrossB.Normalize();
    if (towards < 0) acrossB.Reverse();
    const double a = t.Dot(along), b = (t - along * a).Magnitude();
    const gp_Vec turned = along * a + acrossB * b;
    // Its rates on the far side: S_u du + S_v dv = turned (exact in the tangent plane there).
    const double e = suB.Dot(suB), g = svB.Dot(svB), c = suB.Dot(svB), det = e * g - c * c;
    if (!(det > 1e-20 * e * g)) throw Error(ErrorCode::InvalidArgument, "a geodesic crosses a crease where the surface's parametrisation is singular");
    const double pa = suB.Dot(turned), pb = svB.Dot(turned);
    return {(g * pa - c * pb) / det, (e * pb - c * pa) / det};
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
