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

#include "placement/nurbs_geometry.hpp"
#include "surface/occt_convert.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

/// A point moving along a geodesic: its parameters and their rates per unit length.
using State = std::array<double, 4>;  // u, v, u', v'

struct Frame {
    gp_Pnt p;
    gp_Vec su, sv, n;  // n: unit normal
};

Frame frameAt(const Handle(Geom_BSplineSurface)& s, double u, double v)
{
    Frame f;
    s->D1(u, v, f.p, f.su, f.sv);
    f.n = f.su.Crossed(f.sv);
    // Relative: at a collapsed row of poles the cross product vanishes only up to rounding.
    if (!(f.n.Magnitude() > 1e-10 * f.su.Magnitude() * f.sv.Magnitude())) throw Error(ErrorCode::InvalidArgument, "the surface has no normal at (" + std::to_string(u) + ", " + std::to_string(v) + ")");
    f.n.Normalize();
    return f;
}

/// (du, dv) with S_u du + S_v dv the tangent-plane part of @p t.
std::array<double, 2> parameterRates(const Frame& f, const gp_Vec& t)
{
    const double e = f.su.Dot(f.su), g = f.sv.Dot(f.sv), c = f.su.Dot(f.sv);
    const double a = f.su.Dot(t), b = f.sv.Dot(t), det = e * g - c * c;
    if (!(det > 1e-20 * e * g)) throw Error(ErrorCode::InvalidArgument, "the surface's parametrisation is singular there");
    return {(g * a - c * b) / det, (e * b - c * a) / det};
}

/// d/ds of a geodesic's state: the parameters' second derivatives keep the 3D acceleration
/// normal to the surface.
State rates(const Handle(Geom_BSplineSurface)& s, const State& x)
{
    gp_Pnt p;
    gp_Vec su, sv, suu, svv, suv;
    s->D2(x[0], x[1], p, su, sv, suu, svv, suv);
    const gp_Vec a = suu * (x[2] * x[2]) + suv * (2.0 * x[2] * x[3]) + svv * (x[3] * x[3]);
    const double e = su.Dot(su), g = sv.Dot(sv), c = su.Dot(sv), det = e * g - c * c;
    if (!(det > 1e-20 * e * g)) throw Error(ErrorCode::InvalidArgument, "a geodesic reaches a point where the surface's parametrisation is singular");
    const double r1 = -su.Dot(a), r2 = -sv.Dot(a);
    return {x[2], x[3], (g * r1 - c * r2) / det, (e * r2 - c * r1) / det};
}

bool inside(const Handle(Geom_BSplineSurface)& s, double u, double v)
{
    double u0, u1, v0, v1;
    s->Bounds(u0, u1, v0, v1);
    return u >= u0 && u <= u1 && v >= v0 && v <= v1;
}

/// The end of the geodesic of length @p length from @p from in the 3D tangent direction @p t.
UV shoot(const Handle(Geom_BSplineSurface)& s, const UV& from, const gp_Vec& t, double length, int steps)
{
    const Frame f = frameAt(s, from.u, from.v);
    gp_Vec dir = t - f.n * t.Dot(f.n);
    if (!(dir.Magnitude() > 0.0)) throw Error(ErrorCode::InvalidArgument, "a geodesic's direction is along the surface's normal");
    dir.Normalize();
    const std::array<double, 2> r = parameterRates(f, dir);
    State x{from.u, from.v, r[0], r[1]};
    // RK4 with step doubling: a step is kept when its two halves agree to 1e-12 of the
    // parameter box, in position and in what the velocity's difference makes of it over the rest
    // of the way (then with Richardson's correction), else halved. The right-hand side jumps
    // where the surface's second derivatives do (knots of multiplicity > degree - 2, as at a
    // rational circle's quarter points): the steps shrink there.
    double u0, u1, v0, v1;
    s->Bounds(u0, u1, v0, v1);
    const double tol = 1e-12 * std::max(u1 - u0, v1 - v0);
    const auto add = [](const State& a, const State& b, double k) {
        return State{a[0] + k * b[0], a[1] + k * b[1], a[2] + k * b[2], a[3] + k * b[3]};
    };
    const auto rk4 = [&](const State& y, double h) {
        const State k1 = rates(s, y), k2 = rates(s, add(y, k1, 0.5 * h)), k3 = rates(s, add(y, k2, 0.5 * h)), k4 = rates(s, add(y, k3, h));
        State z = y;
        for (std::size_t c = 0; c < 4; ++c) z[c] += h / 6.0 * (k1[c] + 2.0 * k2[c] + 2.0 * k3[c] + k4[c]);
        return z;
    };
    const double largest = length / steps, smallest = 1e-9 * length;
    double left = length, h = largest;
    while (left > 0.0) {
        h = std::min(h, left);
        const State big = rk4(x, h), half = rk4(rk4(x, 0.5 * h), 0.5 * h);
        // The position's error, and the velocity's as the position error it makes over the rest.
        const double error = std::max({std::abs(big[0] - half[0]), std::abs(big[1] - half[1]), left * std::abs(big[2] - half[2]),
                                       left * std::abs(big[3] - half[3])});
        if (error > tol && h > smallest) {
            h *= 0.5;
            continue;
        }
        for (std::size_t c = 0; c < 4; ++c) x[c] = half[c] + (half[c] - big[c]) / 15.0;
        left -= h;
        h = std::min(largest, 2.0 * h);
        if (!inside(s, x[0], x[1])) throw Error(ErrorCode::InvalidArgument, "a geodesic leaves the surface");
    }
    return {x[0], x[1]};
}

/// The normal curvature of @p s at @p f along the tangent direction @p t.
double normalCurvature(const Handle(Geom_BSplineSurface)& s, double u, double v, const gp_Vec& t)
{
    gp_Pnt p;
    gp_Vec su, sv, suu, svv, suv;
    s->D2(u, v, p, su, sv, suu, svv, suv);
    const Frame f = frameAt(s, u, v);
    const std::array<double, 2> r = parameterRates(f, t);
    const double second = suu.Dot(f.n) * r[0] * r[0] + 2.0 * suv.Dot(f.n) * r[0] * r[1] + svv.Dot(f.n) * r[1] * r[1];
    const gp_Vec along = su * r[0] + sv * r[1];
    return second / along.SquareMagnitude();
}

double geodesicDistanceOn(const Handle(Geom_BSplineSurface)& s, const UV& from, const UV& to, int steps)
{
    const Frame f = frameAt(s, from.u, from.v);
    const gp_Vec chord(f.p, s->Value(to.u, to.v));
    if (chord.Magnitude() == 0.0) return 0.0;
    // Unknowns: the direction's angle in the tangent plane (about e1) and the length.
    gp_Vec e1 = f.su.Normalized(), e2 = f.n.Crossed(e1);
    gp_Vec t0 = chord - f.n * chord.Dot(f.n);
    double angle = std::atan2(t0.Dot(e2), t0.Dot(e1)), length = chord.Magnitude();
    const auto end = [&](double a, double l) { return shoot(s, from, e1 * std::cos(a) + e2 * std::sin(a), l, steps); };
    for (int it = 0; it < 30; ++it) {
        const UV x = end(angle, length);
        const double fu = x.u - to.u, fv = x.v - to.v;
        if (std::hypot(fu, fv) <= 1e-13 * (1.0 + std::hypot(to.u, to.v))) return length;
        const double da = 1e-7, dl = 1e-7 * length;
        const UV xa = end(angle + da, length), xl = end(angle, length + dl);
        const double j11 = (xa.u - x.u) / da, j21 = (xa.v - x.v) / da, j12 = (xl.u - x.u) / dl, j22 = (xl.v - x.v) / dl;
        const double det = j11 * j22 - j12 * j21;
        if (!(std::abs(det) > 0.0)) break;
        angle -= (j22 * fu - j12 * fv) / det;
        length -= (j11 * fv - j21 * fu) / det;
        if (!(length > 0.0)) break;
    }
    const UV x = end(angle, length);
    if (std::hypot(x.u - to.u, x.v - to.v) <= 1e-9 * (1.0 + std::hypot(to.u, to.v))) return length;
    throw Error(ErrorCode::InvalidArgument, "geodesicDistance: shooting did not converge (points too far apart for their curvature?)");
}

}  // namespace

CurveOnSurface curveOnSurface(const NurbsSurface& surface, const std::vector<UV>& uv)
{
    CurveOnSurface c;
    c.uv = uv;
    const Handle(Geom_BSplineSurface) s = detail::occtSurface(surface);
    for (const UV& p : uv) {
        if (!inside(s, p.u, p.v)) throw Error(ErrorCode::InvalidArgument, "curveOnSurface: a point lies off the surface's parameter range");
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
            if (!inside(s, at.u, at.v)) throw Error(ErrorCode::InvalidArgument, "offsetOnSurface: a point lies off the surface's parameter range");
            const Frame f = frameAt(s, at.u, at.v);
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
                moved = shoot(s, at, d >= 0.0 ? o : o.Reversed(), std::abs(d), options.geodesicSteps);
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
