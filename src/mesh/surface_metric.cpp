#include "mesh/surface_metric.hpp"

#include <algorithm>
#include <cmath>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

SurfaceMetric::SurfaceMetric(const TowSurface& surface, const ScaledSpace& space, double lx, double ly, double spacing)
{
    constexpr std::size_t kMaxSide = 1024;
    const auto count = [&](double length) {
        return std::clamp<std::size_t>(static_cast<std::size_t>(std::ceil(length / spacing)) + 1, 2, kMaxSide);
    };
    nx_ = count(lx);
    ny_ = count(ly);
    cellX_ = lx / static_cast<double>(nx_ - 1);
    cellY_ = ly / static_cast<double>(ny_ - 1);
    const ParameterRange r = surface.parameterRange();
    forms_.resize(nx_ * ny_);
    for (std::size_t i = 0; i < nx_; ++i)
        for (std::size_t j = 0; j < ny_; ++j) {
            // The ends exactly: u beyond uMax is outside the surface.
            const UV p = space.toUV(static_cast<double>(i) * cellX_, static_cast<double>(j) * cellY_);
            const double u = i + 1 == nx_ ? r.uMax : std::clamp(p.u, r.uMin, r.uMax);
            const double v = j + 1 == ny_ ? r.vMax : p.v;
            const SurfaceDerivatives d = surface.derivatives(u, v);
            // S_x = S_u du/dx, S_y = S_u du/dy + S_v dv/dy, from x(u, v) and y = (v - vMin) sv.
            const ScaledSpace::Slopes s = space.slopes(u, v);
            const Vector3 sx = (1.0 / s.xu) * d.du, sy = (-s.xv / (s.xu * space.sv())) * d.du + (1.0 / space.sv()) * d.dv;
            forms_[i * ny_ + j] = {dot(sx, sx), dot(sx, sy), dot(sy, sy)};
        }
}

SurfaceMetric::Form SurfaceMetric::at(double x, double y) const
{
    const double fx = std::clamp(x / cellX_, 0.0, static_cast<double>(nx_ - 1));
    const double fy = std::clamp(y / cellY_, 0.0, static_cast<double>(ny_ - 1));
    const std::size_t i = std::min(static_cast<std::size_t>(fx), nx_ - 2), j = std::min(static_cast<std::size_t>(fy), ny_ - 2);
    const double a = fx - static_cast<double>(i), b = fy - static_cast<double>(j);
    const Form& f00 = forms_[i * ny_ + j];
    const Form& f01 = forms_[i * ny_ + j + 1];
    const Form& f10 = forms_[(i + 1) * ny_ + j];
    const Form& f11 = forms_[(i + 1) * ny_ + j + 1];
    const auto mix = [&](double Form::*c) {
        return (1 - a) * ((1 - b) * f00.*c + b * f01.*c) + a * ((1 - b) * f10.*c + b * f11.*c);
    };
    return {mix(&Form::e), mix(&Form::f), mix(&Form::g)};
}

double SurfaceMetric::squaredLength(double x, double y, double dx, double dy) const
{
    const Form m = at(x, y);
    return m.e * dx * dx + 2.0 * m.f * dx * dy + m.g * dy * dy;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
