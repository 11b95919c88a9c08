// A laminate family's fixed-angle curve: the integral curve of the 0° direction field turned by
// theta, the field interpolated between the family's curves in a shared parameter.
#include "towgeom/laminate_family.hpp"

#include <Geom2d_BSplineCurve.hxx>
#include <Standard_Failure.hxx>

#include <array>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/elapsed.hpp"
#include "placement/geodesics.hpp"
#include "placement/nurbs_geometry.hpp"
#include "placement/periodic_surface.hpp"
#include "placement/uv_interpolation.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

using detail::kPi;

/// The cubic B-spline in (u,v) through @p uv at parameters i / (n - 1).
Handle(Geom2d_BSplineCurve) interpolate(const std::vector<UV>& uv)
{
    std::vector<double> t;
    for (std::size_t i = 0; i < uv.size(); ++i) t.push_back(static_cast<double>(i) / static_cast<double>(uv.size() - 1));
    const Handle(Geom2d_BSplineCurve) c = detail::interpolateUV(uv, t);
    if (c.IsNull()) throw Error(ErrorCode::InvalidArgument, "fixedAngleCurve: a curve could not be interpolated (points repeated?)");
    return c;
}

/// The family's map (t, kappa) -> (u,v) and the fixed-angle field in (t, kappa).
struct Field {
    Handle(Geom_BSplineSurface) s;
    std::vector<Handle(Geom2d_BSplineCurve)> curves;
    double cosTheta, sinTheta;

    /// (u,v), d(u,v)/dt and d(u,v)/dkappa at (t, kappa): cubic Hermite in kappa between curves k
    /// and k + 1 with Catmull-Rom slopes (one-sided at the family's ends), so that the field is
    /// C1 across the curves and the fixed-angle curve's curvature has no jumps there.
    std::array<gp_Vec2d, 3> at(double t, double kappa) const
    {
        const std::size_t last = curves.size() - 1;
        const std::size_t k = kappa <= 0.0 ? 0 : std::min(last - 1, static_cast<std::size_t>(std::floor(kappa)));
        const double f = kappa - static_cast<double>(k);
        std::array<gp_Vec2d, 4> p, d;  // curves k - 1 .. k + 2 (clamped), points and t-derivatives
        for (int j = 0; j < 4; ++j) {
            const std::size_t c = std::min(last, static_cast<std::size_t>(std::max<long>(0, static_cast<long>(k) - 1 + j)));
            gp_Pnt2d q;
            curves[c]->D1(t, q, d[j]);
            p[j] = gp_Vec2d(q.X(), q.Y());
        }
        const bool first = k == 0, end = k + 1 == last;
        const auto slope = [&](const std::array<gp_Vec2d, 4>& x, int j) {  // at curve k - 1 + j, j = 1 or 2
            if (j == 1) return first ? x[2] - x[1] : (x[2] - x[0]) * 0.5;
            return end ? x[2] - x[1] : (x[3] - x[1]) * 0.5;
        };
        const double h00 = (2 * f - 3) * f * f + 1, h10 = ((f - 2) * f + 1) * f, h01 = (3 - 2 * f) * f * f, h11 = (f - 1) * f * f;
        const double g00 = 6 * f * f - 6 * f, g10 = (3 * f - 4) * f + 1, g01 = 6 * f - 6 * f * f, g11 = (3 * f - 2) * f;
        const auto blend = [&](const std::array<gp_Vec2d, 4>& x, double a, double b, double c, double e) {
            return x[1] * a + slope(x, 1) * b + x[2] * c + slope(x, 2) * e;
        };
        return {blend(p, h00, h10, h01, h11), blend(d, h00, h10, h01, h11), blend(p, g00, g10, g01, g11)};
    }

    /// (dt/ds, dkappa/ds): unit speed on the surface at theta from the 0° direction, towards
    /// increasing kappa.
    std::array<double, 2> rate(double t, double kappa) const
    {
        const auto [uv, dt, dk] = at(t, kappa);
        const detail::SurfaceFrame f = detail::frameAt(s, uv.X(), uv.Y());
        const gp_Vec xt = f.su * dt.X() + f.sv * dt.Y(), xk = f.su * dk.X() + f.sv * dk.Y();
        if (!(xt.Magnitude() > 0.0)) throw Error(ErrorCode::InvalidArgument, "fixedAngleCurve: a 0° curve has no tangent there");
        const gp_Vec e = xt.Normalized();
        gp_Vec o = f.n.Crossed(e);
        if (o.Dot(xk) < 0.0) o.Reverse();
        const gp_Vec d = e * cosTheta + o * sinTheta;
        // X_t a + X_k b = d, least squares in the tangent plane.
        const double g11 = xt.Dot(xt), g12 = xt.Dot(xk), g22 = xk.Dot(xk), r1 = xt.Dot(d), r2 = xk.Dot(d);
        const double det = g11 * g22 - g12 * g12;
        if (!(det > 1e-14 * g11 * g22)) throw Error(ErrorCode::InvalidArgument, "fixedAngleCurve: neighbouring 0° curves touch there");
        return {(g22 * r1 - g12 * r2) / det, (g11 * r2 - g12 * r1) / det};
    }

    std::array<double, 2> step(const std::array<double, 2>& x, double h) const
    {
        const auto k1 = rate(x[0], x[1]);
        const auto k2 = rate(x[0] + 0.5 * h * k1[0], x[1] + 0.5 * h * k1[1]);
        const auto k3 = rate(x[0] + 0.5 * h * k2[0], x[1] + 0.5 * h * k2[1]);
        const auto k4 = rate(x[0] + h * k3[0], x[1] + h * k3[1]);
        return {x[0] + h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]), x[1] + h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])};
    }
};

}  // namespace

FixedAngleCurve fixedAngleCurve(const NurbsSurface& surface, const std::vector<CurveOnSurface>& family, double thetaDegrees,
                                const FixedAngleOptions& options)
{
    if (family.size() < 2) throw Error(ErrorCode::InvalidArgument, "fixedAngleCurve: at least two 0° curves");
    for (std::size_t k = 0; k < family.size(); ++k) {
        const std::vector<UV>& uv = family[k].uv;
        if (uv.size() < 4 || uv.size() != family.front().uv.size())
            throw Error(ErrorCode::InvalidArgument, "fixedAngleCurve: 0° curves of the same number of points, at least 4");
        for (std::size_t i = 0; i < uv.size(); ++i) {
            if (!std::isfinite(uv[i].u) || !std::isfinite(uv[i].v))
                throw Error(ErrorCode::InvalidArgument, "fixedAngleCurve: 0° curve " + std::to_string(k) + ": point " + std::to_string(i) + " is not finite");
            if (i > 0 && uv[i].u == uv[i - 1].u && uv[i].v == uv[i - 1].v)
                throw Error(ErrorCode::InvalidArgument, "fixedAngleCurve: 0° curve " + std::to_string(k) + ": points " + std::to_string(i - 1) + " and " +
                                                            std::to_string(i) + " coincide");
        }
    }
    if (!(thetaDegrees > 0.0 && thetaDegrees < 180.0)) throw Error(ErrorCode::InvalidArgument, "fixedAngleCurve: an angle in (0, 180) degrees");
    if (!(options.start >= 0.0 && options.start <= 1.0)) throw Error(ErrorCode::InvalidArgument, "fixedAngleCurve: a start in [0, 1]");
    if (!(options.step >= 0.0) || !std::isfinite(options.step)) throw Error(ErrorCode::InvalidArgument, "fixedAngleCurve: a step of 0 or more");
    FixedAngleCurve out;
    try {
        Field field;
        field.s = detail::toolSurface(surface);
        for (const CurveOnSurface& c : family) field.curves.push_back(interpolate(c.uv));
        field.cosTheta = std::cos(thetaDegrees * kPi / 180.0);
        field.sinTheta = std::sin(thetaDegrees * kPi / 180.0);
        const double lastCurve = static_cast<double>(family.size() - 1);
        const auto point = [&](const std::array<double, 2>& x) {
            const gp_Vec2d uv = field.at(x[0], x[1])[0];
            return UV{uv.X(), uv.Y()};
        };
        // At least four steps across each gap between curves (each crossing's angle is measured
        // from three points of the curve).
        double nearest = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k + 1 < family.size(); ++k) {
            const UV a = point({options.start, static_cast<double>(k)}), b = point({options.start, static_cast<double>(k + 1)});
            nearest = std::min(nearest, field.s->Value(a.u, a.v).Distance(field.s->Value(b.u, b.v)));
        }
        const double h = options.step > 0.0 && options.step <= nearest / 4.0 ? options.step : nearest / 20.0;
        if (!(h > 0.0)) throw Error(ErrorCode::InvalidArgument, "fixedAngleCurve: the 0° curves coincide at the start");
        std::array<double, 2> x{options.start, 0.0};
        std::vector<UV> uv{point(x)};
        std::vector<std::size_t> crossingAt{0};
        std::vector<double> crossingT{options.start};  // the 0° curve's parameter there
        const std::size_t maxSteps = 1000000;
        for (std::size_t n = 0; x[1] < lastCurve; ++n) {
            if (n == maxSteps) throw Error(ErrorCode::InvalidArgument, "fixedAngleCurve: the curve does not reach the last 0° curve");
            std::array<double, 2> y = field.step(x, h);
            const double target = std::floor(x[1]) + 1.0;
            if (y[1] >= target - 1e-12) {
                // Land on the 0° curve: the step's length by secant iterations.
                double a = 0.0, fa = x[1] - target, b = h, fb = y[1] - target;
                for (int it = 0; it < 30 && std::abs(fb) > 1e-13; ++it) {
                    const double c = b - fb * (b - a) / (fb - fa);
                    a = b, fa = fb, b = c;
                    y = field.step(x, b);
                    fb = y[1] - target;
                }
                y[1] = target;
                // A landing just past the last point replaces it (no near-repeated points).
                if (b < 0.5 * h && uv.size() > 1 && crossingAt.back() != uv.size() - 1) uv.pop_back();
                crossingAt.push_back(uv.size());
                crossingT.push_back(y[0]);
            }
            if (!(y[0] >= 0.0 && y[0] <= 1.0)) throw Error(ErrorCode::InvalidArgument, "fixedAngleCurve: the curve leaves the 0° curves' ends");
            x = y;
            const UV p = point(x);
            if (!detail::insideParameters(field.s, p.u, p.v)) throw Error(ErrorCode::InvalidArgument, "fixedAngleCurve: the curve leaves the surface");
            uv.push_back(p);
        }
        out.curve = curveOnSurface(surface, uv);
        // Each crossing's angle: the curve's tangent from its points (the quadratic through three
        // of them by chord length, second-order accurate at the ends too) against the 0° curve's
        // tangent there.
        const std::vector<Point3>& p = out.curve.points;
        if (p.size() < 3) throw Error(ErrorCode::InvalidArgument, "fixedAngleCurve: the curve has fewer than 3 points");
        for (std::size_t k = 0; k < crossingAt.size(); ++k) {
            const std::size_t i = crossingAt[k], first = std::min(i > 0 ? i - 1 : 0, p.size() - 3);
            const double t1 = distance(p[first], p[first + 1]), t2 = t1 + distance(p[first + 1], p[first + 2]), t = i == first ? 0.0 : i == first + 1 ? t1 : t2;
            const Vector3 own = ((2 * t - t1 - t2) / (t1 * t2)) * p[first] + ((2 * t - t2) / (t1 * (t1 - t2))) * p[first + 1] +
                                ((2 * t - t1) / (t2 * (t2 - t1))) * p[first + 2];
            gp_Pnt2d c;
            gp_Vec2d dZero;
            field.curves[k]->D1(crossingT[k], c, dZero);
            const detail::SurfaceFrame f = detail::frameAt(field.s, uv[i].u, uv[i].v);
            const gp_Vec a(own.x, own.y, own.z), b = f.su * dZero.X() + f.sv * dZero.Y();
            out.crossings.push_back({k, uv[i], a.Angle(b) * 180.0 / kPi});
        }
    } catch (const Standard_Failure& e) {
        throw Error(ErrorCode::Internal, std::string("fixedAngleCurve: OpenCASCADE failed: ") + e.GetMessageString());
    }
    return out;
}

TOWGEOM_END_NAMESPACE
