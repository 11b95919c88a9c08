#include <GCPnts_AbscissaPoint.hxx>
#include <GCPnts_QuasiUniformDeflection.hxx>
#include <GCPnts_UniformAbscissa.hxx>
#include <GeomAdaptor_Curve.hxx>

#include <cmath>

#include "surface/curve3_impl.hpp"
#include "surface/occt_convert.hpp"
#include "surface/occt_guard.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

using detail::fromOcct;

Curve3::Curve3(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

double Curve3::firstParameter() const { return impl_->curve->FirstParameter(); }
double Curve3::lastParameter() const { return impl_->curve->LastParameter(); }
bool Curve3::closed() const { return impl_->curve->IsClosed(); }
Point3 Curve3::point(double t) const { return fromOcct(impl_->curve->Value(t)); }

Vector3 Curve3::derivative(double t) const
{
    gp_Pnt p;
    gp_Vec d;
    impl_->curve->D1(t, p, d);
    return fromOcct(d);
}

double Curve3::length() const
{
    return detail::guarded(std::string(), "length", [&]() -> double {
        GeomAdaptor_Curve adaptor(impl_->curve);
        return GCPnts_AbscissaPoint::Length(adaptor, 1e-10);
    });
}

namespace {
/// Samples uniform in parameter: the fallback when a sampler returns too few points.
std::vector<Point3> uniformSamples(const Geom_Curve& c, std::size_t count, bool closed)
{
    std::vector<Point3> out;
    const double a = c.FirstParameter(), b = c.LastParameter();
    const std::size_t steps = closed ? count : count - 1;
    for (std::size_t i = 0; i < count; ++i) out.push_back(fromOcct(c.Value(a + (b - a) * i / steps)));
    return out;
}
}  // namespace

std::vector<Point3> Curve3::polyline(double chordalTolerance) const
{
    return detail::guarded(std::string(), "polyline", [&]() -> std::vector<Point3> {
        if (!(chordalTolerance > 0.0)) throw Error(ErrorCode::InvalidArgument, "chordal tolerance must be positive");
        GeomAdaptor_Curve adaptor(impl_->curve);
        GCPnts_QuasiUniformDeflection sampler(adaptor, chordalTolerance);
        std::vector<Point3> out;
        if (sampler.IsDone())
            for (int i = 1; i <= sampler.NbPoints(); ++i) out.push_back(fromOcct(sampler.Value(i)));
        if (closed() && out.size() > 1) out.pop_back();
        if (out.size() < 8) return uniformSamples(*impl_->curve, 8, closed());
        return out;
    });
}

std::vector<Point3> Curve3::polylineBySpacing(double spacing) const
{
    return detail::guarded(std::string(), "polylineBySpacing", [&]() -> std::vector<Point3> {
        if (!(spacing > 0.0)) throw Error(ErrorCode::InvalidArgument, "spacing must be positive");
        GeomAdaptor_Curve adaptor(impl_->curve);
        const double len = GCPnts_AbscissaPoint::Length(adaptor, 1e-10);
        const int count = std::max(2, static_cast<int>(std::ceil(len / spacing)) + 1);
        GCPnts_UniformAbscissa sampler(adaptor, count, 1e-10 * std::max(len, 1e-300));
        std::vector<Point3> out;
        if (sampler.IsDone())
            for (int i = 1; i <= sampler.NbPoints(); ++i) out.push_back(fromOcct(impl_->curve->Value(sampler.Parameter(i))));
        if (closed() && out.size() > 1) out.pop_back();
        if (out.size() < 2) return uniformSamples(*impl_->curve, static_cast<std::size_t>(count), closed());
        return out;
    });
}

TOWGEOM_END_NAMESPACE
