// YarnPath: a cubic Hermite spline as an OCCT B-spline with triple interior knots.
#include "towgeom/yarn_path.hpp"

#include <GCPnts_AbscissaPoint.hxx>
#include <Geom_BSplineCurve.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>

#include <algorithm>
#include <cmath>

#include "surface/occt_convert.hpp"
#include "surface/occt_guard.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

using detail::fromOcct;
using detail::toOcct;

struct YarnPath::Impl {
    Handle(Geom_BSplineCurve) curve;
    std::size_t points = 0;
};

YarnPath::YarnPath(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

YarnPath YarnPath::hermite(const std::vector<Point3>& p, const std::vector<Vector3>& m)
{
    const std::size_t n = p.size();
    if (n < 2 || m.size() != n)
        throw Error(ErrorCode::InvalidArgument, "a yarn path needs at least 2 points and one tangent per point");
    for (std::size_t i = 0; i < n; ++i) {
        const double all = p[i].x + p[i].y + p[i].z + m[i].x + m[i].y + m[i].z;
        if (!std::isfinite(all)) throw Error(ErrorCode::InvalidArgument, "yarn path point or tangent is not finite");
        if (i > 0 && distance(p[i], p[i - 1]) == 0.0)
            throw Error(ErrorCode::InvalidArgument, "yarn path points " + std::to_string(i - 1) + " and " +
                                                        std::to_string(i) + " coincide");
    }
    // Segment i is the Bezier curve p[i], p[i] + m[i]/3, p[i+1] - m[i+1]/3, p[i+1] on [i, i+1].
    const int segments = static_cast<int>(n) - 1;
    TColgp_Array1OfPnt poles(1, 3 * segments + 1);
    for (int i = 0; i < segments; ++i) {
        poles(3 * i + 1) = toOcct(p[i]);
        poles(3 * i + 2) = toOcct(p[i] + (1.0 / 3.0) * m[i]);
        poles(3 * i + 3) = toOcct(p[i + 1] - (1.0 / 3.0) * m[i + 1]);
    }
    poles(3 * segments + 1) = toOcct(p.back());
    TColStd_Array1OfReal knots(1, segments + 1);
    TColStd_Array1OfInteger mults(1, segments + 1);
    for (int i = 0; i <= segments; ++i) {
        knots(i + 1) = i;
        mults(i + 1) = (i == 0 || i == segments) ? 4 : 3;
    }
    auto impl = std::make_shared<Impl>();
    impl->curve = new Geom_BSplineCurve(poles, knots, mults, 3);
    impl->points = n;
    return YarnPath(impl);
}

YarnPath YarnPath::cardinal(const std::vector<Point3>& p, double tension)
{
    if (!(tension >= 0.0 && tension <= 1.0))
        throw Error(ErrorCode::InvalidArgument, "cardinal spline tension must lie in [0, 1]");
    if (p.size() < 2) throw Error(ErrorCode::InvalidArgument, "a yarn path needs at least 2 points");
    const double scale = 0.5 * (1.0 - tension);
    std::vector<Vector3> m(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (i == 0)
            m[i] = (2.0 * scale) * (p[1] - p[0]);
        else if (i + 1 == p.size())
            m[i] = (2.0 * scale) * (p[i] - p[i - 1]);
        else
            m[i] = scale * (p[i + 1] - p[i - 1]);
    }
    return hermite(p, m);
}

YarnPath YarnPath::catmullRom(const std::vector<Point3>& p) { return cardinal(p, 0.0); }

std::size_t YarnPath::pointCount() const { return impl_->points; }
double YarnPath::lastParameter() const { return static_cast<double>(impl_->points - 1); }

namespace {
double clampT(double t, double last) { return std::clamp(std::isfinite(t) ? t : 0.0, 0.0, last); }
}  // namespace

Point3 YarnPath::point(double t) const { return fromOcct(impl_->curve->Value(clampT(t, lastParameter()))); }

Vector3 YarnPath::derivative(double t) const
{
    gp_Pnt p;
    gp_Vec d;
    impl_->curve->D1(clampT(t, lastParameter()), p, d);
    return fromOcct(d);
}

Vector3 YarnPath::secondDerivative(double t) const
{
    gp_Pnt p;
    gp_Vec d1, d2;
    impl_->curve->D2(clampT(t, lastParameter()), p, d1, d2);
    return fromOcct(d2);
}

double YarnPath::curvature(double t) const
{
    gp_Pnt p;
    gp_Vec d1, d2;
    impl_->curve->D2(clampT(t, lastParameter()), p, d1, d2);
    const double speed = d1.Magnitude();
    if (speed < 1e-300) return 0.0;
    return d1.Crossed(d2).Magnitude() / (speed * speed * speed);
}

double YarnPath::length(double t0, double t1) const
{
    return detail::guarded(std::string(), "length", [&]() -> double {
        GeomAdaptor_Curve adaptor(impl_->curve);
        const double a = clampT(std::min(t0, t1), lastParameter()), b = clampT(std::max(t0, t1), lastParameter());
        return GCPnts_AbscissaPoint::Length(adaptor, a, b, 1e-10);
    });
}

TOWGEOM_END_NAMESPACE
