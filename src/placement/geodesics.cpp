// Geodesics on a NURBS surface: the geodesic equation (OCCT's second derivatives) integrated
// by RK4 with step doubling, and shot to a target by Newton's method.
#include "placement/geodesics.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>
#include <string>

#include "placement/geodesic_creases.hpp"
#include "placement/periodic_surface.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// A point moving along a geodesic: its parameters and their rates per unit length.
using State = std::array<double, 4>;  // u, v, u', v'

SurfaceFrame frameAt(const Handle(Geom_BSplineSurface)& s, double u, double v)
{
    SurfaceFrame f;
    s->D1(u, v, f.p, f.su, f.sv);
    f.n = f.su.Crossed(f.sv);
    // Relative: at a collapsed row of poles the cross product vanishes only up to rounding.
    if (!(f.n.Magnitude() > 1e-10 * f.su.Magnitude() * f.sv.Magnitude())) throw Error(ErrorCode::InvalidArgument, "the surface has no normal at " + singularPlace(s, u, v));
    f.n.Normalize();
    return f;
}

/// (du, dv) with S_u du + S_v dv the tangent-plane part of @p t.
std::array<double, 2> parameterRates(const SurfaceFrame& f, const gp_Vec& t)
{
    const double e = f.su.Dot(f.su), g = f.sv.Dot(f.sv), c = f.su.Dot(f.sv);
    const double a = f.su.Dot(t), b = f.sv.Dot(t), det = e * g - c * c;
    if (!(det > 1e-20 * e * g)) throw Error(ErrorCode::InvalidArgument, "the surface's parametrisation is singular there");
    return {(g * a - c * b) / det, (e * b - c * a) / det};
}

/// Names the singular point of @p s's parametrisation at (@p u, @p v): a pole (a side of the box
/// collapsed to a point, as a sphere's) or another degenerate point, with its position.
std::string singularPlace(const Handle(Geom_BSplineSurface)& s, double u, double v)
{
    const gp_Pnt p = s->Value(u, v);
    const std::string at = "(" + std::to_string(p.X()) + ", " + std::to_string(p.Y()) + ", " + std::to_string(p.Z()) + ")";
    double u0, u1, v0, v1;
    s->Bounds(u0, u1, v0, v1);
    const auto collapsed = [&](bool alongU, double fixed) {  // the side at `fixed` is one point
        const gp_Pnt a = alongU ? s->Value(u0, fixed) : s->Value(fixed, v0), b = alongU ? s->Value(0.5 * (u0 + u1), fixed) : s->Value(fixed, 0.5 * (v0 + v1));
        return a.Distance(b) <= 1e-9 * (1.0 + a.Distance(gp_Pnt(0, 0, 0)));
    };
    const double nearV = std::abs(v - v0) < std::abs(v - v1) ? v0 : v1, nearU = std::abs(u - u0) < std::abs(u - u1) ? u0 : u1;
    if (std::abs(v - nearV) <= 1e-3 * (v1 - v0) && collapsed(true, nearV))
        return std::string("the pole at ") + at + " (the side v = " + (nearV == v0 ? "v_min" : "v_max") + " of the parameters is one point)";
    if (std::abs(u - nearU) <= 1e-3 * (u1 - u0) && collapsed(false, nearU))
        return std::string("the pole at ") + at + " (the side u = " + (nearU == u0 ? "u_min" : "u_max") + " of the parameters is one point)";
    return "a point where the surface's parametrisation is singular, at " + at;
}

/// d/ds of a geodesic's state: the parameters' second derivatives keep the 3D acceleration
/// normal to the surface.
static State rates(const Handle(Geom_BSplineSurface)& s, const State& x)
{
    gp_Pnt p;
    gp_Vec su, sv, suu, svv, suv;
    s->D2(x[0], x[1], p, su, sv, suu, svv, suv);
    const gp_Vec a = suu * (x[2] * x[2]) + suv * (2.0 * x[2] * x[3]) + svv * (x[3] * x[3]);
    const double e = su.Dot(su), g = sv.Dot(sv), c = su.Dot(sv), det = e * g - c * c;
    if (!(det > 1e-20 * e * g)) throw Error(ErrorCode::InvalidArgument, "a geodesic reaches " + singularPlace(s, x[0], x[1]));
    const double r1 = -su.Dot(a), r2 = -sv.Dot(a);
    return {x[2], x[3], (g * r1 - c * r2) / det, (e * r2 - c * r1) / det};
}

bool insideParameters(const Handle(Geom_BSplineSurface)& s, double u, double v) { return onSurface(s, {u, v}); }

namespace {

/// A crease a step crosses: the knot, and whether it is a line u = at (else v = at).
struct Crease {
    double at = 0.0;
    bool inU = false;
};

/// The first crease (of @p uCreases, @p vCreases) the step from @p x to @p next crosses.
std::optional<Crease> firstCrease(const State& x, const State& next, const std::vector<double>& uCreases, const std::vector<double>& vCreases)
{
    std::optional<Crease> first;
    double soonest = 2.0;
    for (const bool inU : {true, false}) {
        const std::size_t k = inU ? 0 : 1;
        for (const double c : inU ? uCreases : vCreases) {
            if ((x[k] < c) == (next[k] < c)) continue;
            const double fraction = (c - x[k]) / (next[k] - x[k]);
            if (fraction < soonest) soonest = fraction, first = Crease{c, inU};
        }
    }
    return first;
}

}  // namespace

/// The end of the geodesic of length @p length from @p from in the 3D tangent direction @p t.
UV shootGeodesic(const Handle(Geom_BSplineSurface)& s, const UV& from, const gp_Vec& t, double length, int steps)
{
    const SurfaceFrame f = frameAt(s, from.u, from.v);
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
    // Creases (faces joined side to side): a step ends just short of one, and the geodesic is
    // carried across it (ratesAcrossCrease()), this far past it.
    const std::vector<double> uCreases = creaseKnots(s, true), vCreases = creaseKnots(s, false);
    const double creaseGap = 1e-13 * std::max(u1 - u0, v1 - v0);
    double left = length, h = largest;
    int approaches = 0;  // steps shortened towards one crease (bounded: then it is crossed)
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
        State next;
        for (std::size_t c = 0; c < 4; ++c) next[c] = half[c] + (half[c] - big[c]) / 15.0;
        if (const std::optional<Crease> crease = firstCrease(x, next, uCreases, vCreases)) {
            const std::size_t along = crease->inU ? 0 : 1;
            const double gap = crease->at - x[along];
            // At least a few doubles at the crease's value (a surface far from the origin).
            const double near = std::max(creaseGap, 8.0 * (std::nextafter(std::abs(crease->at), HUGE_VAL) - std::abs(crease->at)));
            const double shorter = h * gap / (next[along] - x[along]) * (1.0 - 1e-6);
            if (std::abs(gap) > near && shorter > 0.0 && ++approaches < 200) {
                h = shorter;  // to land just short of it
                continue;
            }
            approaches = 0;
            const int towards = next[along] > x[along] ? 1 : -1;
            const std::array<double, 2> r =
                ratesAcrossCrease(s, crease->inU ? crease->at : x[0], crease->inU ? x[1] : crease->at, x[2], x[3], crease->inU, towards);
            x[along] = crease->at + towards * near;
            x[2] = r[0], x[3] = r[1];
            h = largest;
            continue;
        }
        x = next;
        left -= h;
        h = std::min(largest, 2.0 * h);
        // A geodesic along the surface's edge may run just outside it (rounding, or Newton's
        // difference quotients in geodesicDistanceOn()): up to 1e-6 of the box is allowed (the
        // B-spline's polynomial continues there; callers clamp what they keep), more leaves.
        // A periodic direction has no edge: the geodesic crosses the seam (u runs on past the box).
        const double du = 1e-6 * (u1 - u0), dv = 1e-6 * (v1 - v0);
        const bool inU = s->IsUPeriodic() || (x[0] >= u0 - du && x[0] <= u1 + du), inV = s->IsVPeriodic() || (x[1] >= v0 - dv && x[1] <= v1 + dv);
        if (!inU || !inV) throw OffSurface(ErrorCode::InvalidArgument, "a geodesic leaves the surface");
    }
    return {x[0], x[1]};
}

/// The normal curvature of @p s at @p f along the tangent direction @p t.
double normalCurvature(const Handle(Geom_BSplineSurface)& s, double u, double v, const gp_Vec& t)
{
    gp_Pnt p;
    gp_Vec su, sv, suu, svv, suv;
    s->D2(u, v, p, su, sv, suu, svv, suv);
    const SurfaceFrame f = frameAt(s, u, v);
    const std::array<double, 2> r = parameterRates(f, t);
    const double second = suu.Dot(f.n) * r[0] * r[0] + 2.0 * suv.Dot(f.n) * r[0] * r[1] + svv.Dot(f.n) * r[1] * r[1];
    const gp_Vec along = su * r[0] + sv * r[1];
    return second / along.SquareMagnitude();
}

double geodesicDistanceOn(const Handle(Geom_BSplineSurface)& s, const UV& from, const UV& target, int steps, const gp_Vec* direction, double guess)
{
    const UV to = nearestCopy(s, target, from);  // across a periodic seam, the copy nearest

    const SurfaceFrame f = frameAt(s, from.u, from.v);
    const gp_Vec chord(f.p, s->Value(to.u, to.v));
    if (chord.Magnitude() == 0.0) return 0.0;
    // Unknowns: the direction's angle in the tangent plane (about e1) and the length.
    gp_Vec e1 = f.su.Normalized(), e2 = f.n.Crossed(e1);
    gp_Vec t0 = chord - f.n * chord.Dot(f.n);
    if (direction != nullptr && guess > 0.0) t0 = *direction - f.n * direction->Dot(f.n);
    double angle = std::atan2(t0.Dot(e2), t0.Dot(e1)), length = direction != nullptr && guess > 0.0 ? guess : chord.Magnitude();
    const auto end = [&](double a, double l) { return shootGeodesic(s, from, e1 * std::cos(a) + e2 * std::sin(a), l, steps); };
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


}  // namespace detail
TOWGEOM_END_NAMESPACE
