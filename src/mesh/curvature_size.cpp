#include "mesh/curvature_size.hpp"

#include <algorithm>
#include <cmath>

#include "core/elapsed.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {
namespace {

using detail::kPi;

}  // namespace

double largestCurvature(const SurfaceSecondDerivatives& d)
{
    const Vector3 n = cross(d.du, d.dv);
    const double e = dot(d.du, d.du), f = dot(d.du, d.dv), g = dot(d.dv, d.dv), det = e * g - f * f;
    const double area = norm(n);
    if (!(det > 0.0) || !(area > 0.0)) return 0.0;
    const Vector3 unit = (1.0 / area) * n;
    const double l = dot(d.duu, unit), m = dot(d.duv, unit), nn = dot(d.dvv, unit);
    const double mean = (e * nn - 2.0 * f * m + g * l) / (2.0 * det), gauss = (l * nn - m * m) / det;
    return std::abs(mean) + std::sqrt(std::max(0.0, mean * mean - gauss));
}

CurvatureSize::CurvatureSize(const TowSurface& surface, double deviation, double largest, double smallest, double slope)
    : range_(surface.parameterRange())
{
    const double around = kPi * surface.towSize();
    double length = 0.0;  // along the seam's line, sampled (the exact area() costs far more)
    constexpr int kLengthSteps = 256;
    Point3 previous = surface.point(range_.uMin, range_.vMin);
    for (int k = 1; k <= kLengthSteps; ++k) {
        const Point3 p = surface.point(k == kLengthSteps ? range_.uMax : range_.uMin + (range_.uMax - range_.uMin) * k / kLengthSteps, range_.vMin);
        length += distance(previous, p);
        previous = p;
    }
    // Around: two grid steps per smallest size (at most 1024, the curvature then also taken
    // half a step either side); along: half the largest.
    const auto count = [](double x, std::size_t lo, std::size_t hi) {
        return static_cast<std::size_t>(std::clamp(std::ceil(x), static_cast<double>(lo), static_cast<double>(hi)));
    };
    nv_ = count(2.0 * around / smallest, 256, 1024);
    nu_ = count(2.0 * length / largest + 1.0, 8, 2048);
    size_.assign(nu_ * nv_, largest);
    std::vector<Point3> points(nu_ * nv_);
    for (std::size_t i = 0; i < nu_; ++i) {
        const double u = i + 1 == nu_ ? range_.uMax : range_.uMin + (range_.uMax - range_.uMin) * static_cast<double>(i) / static_cast<double>(nu_ - 1);
        for (std::size_t j = 0; j < nv_; ++j) {
            const double v = range_.vMin + range_.vPeriod() * static_cast<double>(j) / static_cast<double>(nv_);
            const SurfaceSecondDerivatives d = surface.secondDerivatives(u, v);
            points[i * nv_ + j] = d.point;
            // The largest of the node's and the half steps' either side: a flat tow's sharp edge
            // is narrower than a step.
            const double half = 0.5 * range_.vPeriod() / static_cast<double>(nv_);
            const double k = std::max({largestCurvature(d), largestCurvature(surface.secondDerivatives(u, v - half)),
                                       largestCurvature(surface.secondDerivatives(u, v + half))});
            if (k > 0.0) node(i, j) = std::clamp(std::sqrt(8.0 * deviation / k), smallest, largest);
        }
    }
    grade(points, slope);
    // The triangle count's factor over the largest size, weighted by the grid cells' areas.
    double weighted = 0.0, total = 0.0;
    for (std::size_t i = 0; i + 1 < nu_; ++i)
        for (std::size_t j = 0; j < nv_; ++j) {
            const std::size_t k = (j + 1) % nv_;
            const double a = norm(cross(points[(i + 1) * nv_ + j] - points[i * nv_ + j], points[i * nv_ + k] - points[i * nv_ + j]));
            const double ratio = largest / node(i, j);
            weighted += a * ratio * ratio;
            total += a;
        }
    density_ = total > 0.0 ? weighted / total : 1.0;
}

void CurvatureSize::grade(const std::vector<Point3>& points, double slope)
{
    // Sweeps until no size exceeds a neighbour's by more than slope x their distance (each sweep
    // relaxes every grid edge both ways; a few suffice, the field being smooth but for the
    // tows' edges).
    const auto relax = [&](std::size_t a, std::size_t b) {
        const double limit = slope * distance(points[a], points[b]);
        double &sa = size_[a], &sb = size_[b];
        bool changed = false;
        if (sa > sb + limit) sa = sb + limit, changed = true;
        if (sb > sa + limit) sb = sa + limit, changed = true;
        return changed;
    };
    for (int sweep = 0; sweep < 64; ++sweep) {
        bool changed = false;
        for (std::size_t i = 0; i < nu_; ++i)
            for (std::size_t j = 0; j < nv_; ++j) {
                if (i + 1 < nu_) changed |= relax(i * nv_ + j, (i + 1) * nv_ + j);
                changed |= relax(i * nv_ + j, i * nv_ + (j + 1) % nv_);
            }
        for (std::size_t i = nu_; i-- > 0;)
            for (std::size_t j = nv_; j-- > 0;) {
                if (i + 1 < nu_) changed |= relax(i * nv_ + j, (i + 1) * nv_ + j);
                changed |= relax(i * nv_ + j, i * nv_ + (j + 1) % nv_);
            }
        if (!changed) break;
    }
}

double CurvatureSize::at(const UV& p) const
{
    const double fu = std::clamp((p.u - range_.uMin) / (range_.uMax - range_.uMin), 0.0, 1.0) * static_cast<double>(nu_ - 1);
    double fv = std::fmod((p.v - range_.vMin) / range_.vPeriod(), 1.0);
    if (fv < 0.0) fv += 1.0;
    fv *= static_cast<double>(nv_);
    const std::size_t i = std::min(static_cast<std::size_t>(fu), nu_ - 2), j = std::min(static_cast<std::size_t>(fv), nv_ - 1);
    const std::size_t k = (j + 1) % nv_;
    const double a = fu - static_cast<double>(i), b = fv - static_cast<double>(j);
    return (1 - a) * ((1 - b) * node(i, j) + b * node(i, k)) + a * ((1 - b) * node(i + 1, j) + b * node(i + 1, k));
}

std::shared_ptr<const CurvatureSize> curvatureSizeFor(const TowSurface& tow, const MeshOptions& mesh, double h)
{
    const double deviation = mesh.chordDeviation > 0.0 ? mesh.chordDeviation : mesh.relativeChordDeviation * tow.towSize();
    if (!(deviation > 0.0)) return nullptr;
    const double smallest = mesh.minEdgeLength > 0.0 ? mesh.minEdgeLength : mesh.relativeMinEdgeLength * tow.towSize();
    return std::make_shared<const CurvatureSize>(tow, deviation, h, std::clamp(smallest, h / 100.0, h));
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
