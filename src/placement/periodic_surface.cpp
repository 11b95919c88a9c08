// Tool surfaces made periodic where they close smoothly (OpenCASCADE's SetUPeriodic), and the
// box's sides where they do not.
#include "placement/periodic_surface.hpp"

#include <TColgp_Array2OfPnt.hxx>
#include <Standard_Failure.hxx>

#include <algorithm>
#include <cmath>

#include "placement/nurbs_geometry.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

/// Whether @p s closes smoothly across its u ends (@p alongU) or v ends: the end rows' points
/// and the derivative across them agree at 17 places along the seam.
bool closesSmoothly(const Handle(Geom_BSplineSurface)& s, bool alongU)
{
    double u0, u1, v0, v1;
    s->Bounds(u0, u1, v0, v1);
    // The poles' box: the surface's size (its corners may all coincide, as a torus's do).
    const TColgp_Array2OfPnt& poles = s->Poles();
    const double size = poleBoxSize(s);
    // A clamped B-spline's sides are the curves of its end rows of poles: unless those coincide
    // it is open (the quick test; the derivatives below decide).
    const int rows = alongU ? poles.RowLength() : poles.ColLength();
    for (int k = 0; k < rows; ++k) {
        const gp_Pnt& a = alongU ? poles(poles.LowerRow(), poles.LowerCol() + k) : poles(poles.LowerRow() + k, poles.LowerCol());
        const gp_Pnt& b = alongU ? poles(poles.UpperRow(), poles.LowerCol() + k) : poles(poles.LowerRow() + k, poles.UpperCol());
        if (a.Distance(b) > 1e-9 * size) return false;
        const int i = alongU ? poles.LowerRow() : poles.LowerRow() + k, j = alongU ? poles.LowerCol() + k : poles.LowerCol();
        const int i2 = alongU ? poles.UpperRow() : i, j2 = alongU ? j : poles.UpperCol();
        // Made periodic, the last row is dropped for the first, weights and all: they must agree.
        if (std::abs(s->Weight(i, j) - s->Weight(i2, j2)) > 1e-12 * s->Weight(i, j)) return false;
    }
    double largest = 0.0;
    for (int k = 0; k <= 16; ++k) {
        const double t = k / 16.0;
        gp_Pnt a, b;
        gp_Vec au, av, bu, bv;
        if (alongU) {
            const double v = v0 + t * (v1 - v0);
            s->D1(u0, v, a, au, av);
            s->D1(u1, v, b, bu, bv);
        } else {
            const double u = u0 + t * (u1 - u0);
            s->D1(u, v0, a, au, av);
            s->D1(u, v1, b, bu, bv);
        }
        const gp_Vec da = alongU ? au : av, db = alongU ? bu : bv;
        if (a.Distance(b) > 1e-9 * size) return false;
        largest = std::max({largest, da.Magnitude(), db.Magnitude()});
        if ((da - db).Magnitude() > 1e-7 * std::max(da.Magnitude(), db.Magnitude()) + 1e-12 * size) return false;
    }
    return largest > 0.0;
}

}  // namespace

double poleBoxSize(const Handle(Geom_BSplineSurface)& s)
{
    const TColgp_Array2OfPnt& poles = s->Poles();
    gp_XYZ lo = poles(poles.LowerRow(), poles.LowerCol()).XYZ(), hi = lo;
    for (int i = poles.LowerRow(); i <= poles.UpperRow(); ++i)
        for (int j = poles.LowerCol(); j <= poles.UpperCol(); ++j) {
            const gp_XYZ& p = poles(i, j).XYZ();
            lo.SetCoord(std::min(lo.X(), p.X()), std::min(lo.Y(), p.Y()), std::min(lo.Z(), p.Z()));
            hi.SetCoord(std::max(hi.X(), p.X()), std::max(hi.Y(), p.Y()), std::max(hi.Z(), p.Z()));
        }
    return (hi - lo).Modulus();
}

Handle(Geom_BSplineSurface) toolSurface(const NurbsSurface& surface)
{
    Handle(Geom_BSplineSurface) s = occtSurface(surface);
    try {
        if (closesSmoothly(s, true)) s->SetUPeriodic();
        if (closesSmoothly(s, false)) s->SetVPeriodic();
    } catch (const Standard_Failure&) {
        // OpenCASCADE's own closure test is stricter than ours: the surface stays bounded there.
    }
    return s;
}

UV nearestCopy(const Handle(Geom_BSplineSurface)& s, UV uv, const UV& near)
{
    if (s->IsUPeriodic()) {
        const double p = s->UPeriod();
        uv.u -= p * std::round((uv.u - near.u) / p);
    }
    if (s->IsVPeriodic()) {
        const double p = s->VPeriod();
        uv.v -= p * std::round((uv.v - near.v) / p);
    }
    return uv;
}

bool onSurface(const Handle(Geom_BSplineSurface)& s, const UV& uv)
{
    double u0, u1, v0, v1;
    s->Bounds(u0, u1, v0, v1);
    return (s->IsUPeriodic() ? std::isfinite(uv.u) : uv.u >= u0 && uv.u <= u1) && (s->IsVPeriodic() ? std::isfinite(uv.v) : uv.v >= v0 && uv.v <= v1);
}

std::string boundarySide(const Handle(Geom_BSplineSurface)& s, const UV& uv, double tolerance)
{
    double u0, u1, v0, v1;
    s->Bounds(u0, u1, v0, v1);
    const double du = tolerance * (u1 - u0), dv = tolerance * (v1 - v0);
    if (!s->IsUPeriodic()) {
        if (std::abs(uv.u - u0) <= du) return "u_min";
        if (std::abs(uv.u - u1) <= du) return "u_max";
    }
    if (!s->IsVPeriodic()) {
        if (std::abs(uv.v - v0) <= dv) return "v_min";
        if (std::abs(uv.v - v1) <= dv) return "v_max";
    }
    return {};
}

UV onSide(const Handle(Geom_BSplineSurface)& s, UV uv, const std::string& side)
{
    double u0, u1, v0, v1;
    s->Bounds(u0, u1, v0, v1);
    if (side == "u_min") uv.u = u0;
    else if (side == "u_max") uv.u = u1;
    else if (side == "v_min") uv.v = v0;
    else if (side == "v_max") uv.v = v1;
    return uv;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
