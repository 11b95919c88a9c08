#include "mesh/scaled_space.hpp"

#include <algorithm>
#include <cmath>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

/// The correction's grid: rows per section span along u, columns per input point around v.
constexpr std::size_t kRowsPerSection = 4;
constexpr std::size_t kColumnsPerPoint = 2;

/// dx/dv that squares the plane at every grid point, integrated around each row (trapezoids),
/// without the drift over the whole turn and centred on zero: the correction c(row, column).
std::vector<double> squaringOffsets(const TowSurface& surface, double su, const std::vector<double>& us, std::size_t nv)
{
    const ParameterRange r = surface.parameterRange();
    const double dv = r.vPeriod() / static_cast<double>(nv);
    std::vector<double> c(us.size() * nv, 0.0), slope(nv + 1);
    for (std::size_t i = 0; i < us.size(); ++i) {
        for (std::size_t j = 0; j < nv; ++j) {
            const SurfaceDerivatives d = surface.derivatives(us[i], r.vMin + static_cast<double>(j) * dv);
            const double uu = dot(d.du, d.du);
            slope[j] = uu > 0.0 ? su * dot(d.du, d.dv) / uu : 0.0;
        }
        slope[nv] = slope[0];
        double* row = &c[i * nv];
        double sum = 0.0;
        for (std::size_t j = 1; j < nv; ++j) row[j] = row[j - 1] + 0.5 * (slope[j - 1] + slope[j]) * dv;
        const double turn = row[nv - 1] + 0.5 * (slope[nv - 1] + slope[nv]) * dv;  // the twist's drift
        for (std::size_t j = 0; j < nv; ++j) {
            row[j] -= turn * static_cast<double>(j) / static_cast<double>(nv);
            sum += row[j];
        }
        for (std::size_t j = 0; j < nv; ++j) row[j] -= sum / static_cast<double>(nv);
    }
    return c;
}

}  // namespace

ScaledSpace::ScaledSpace(const TowSurface& surface, double su, double sv, bool unshear)
    : range_(surface.parameterRange()), su_(su), sv_(sv)
{
    if (!unshear) return;
    nu_ = std::clamp<std::size_t>(kRowsPerSection * surface.sectionCount() + 1, 9, 1025);
    nv_ = std::clamp<std::size_t>(kColumnsPerPoint * surface.pointsPerSection(), 16, 512);
    u_.resize(nu_);
    for (std::size_t i = 0; i < nu_; ++i)
        u_[i] = i + 1 == nu_ ? range_.uMax
                             : range_.uMin + (range_.uMax - range_.uMin) * static_cast<double>(i) / static_cast<double>(nu_ - 1);
    const std::vector<double> c = squaringOffsets(surface, su, u_, nv_);
    const double lx = (range_.uMax - range_.uMin) * su;
    double largest = 0.0;
    for (double e : c) largest = std::max(largest, std::abs(e));
    if (!(largest > 1e-9 * lx)) return;  // square already
    // The blend: none in the grid's last cell at each end, then a ramp to the full correction
    // over 2 x its largest value, where it cannot make x fall along u (the ramp's slope adds at
    // most half of su). None in the last cell: there x is (u - uMin) su to the last bit, as
    // without the correction (a loop across a cap, with nodes on the rim and thin triangles next
    // to it, failed in the region stage with the correction blended down to the rim itself).
    const double blend = 2.0 * largest, margin = lx / static_cast<double>(nu_ - 1);
    std::vector<double> base(nu_), weight(nu_);
    for (std::size_t i = 0; i < nu_; ++i) {
        base[i] = i + 1 == nu_ ? lx : (u_[i] - range_.uMin) * su;
        // (Rows 1 and nu - 2 lie at the margin: none there, whatever the rounding.)
        weight[i] = i <= 1 || i + 2 >= nu_ ? 0.0 : std::clamp((std::min(base[i], lx - base[i]) - margin) / blend, 0.0, 1.0);
    }
    // Where sections turn fast the correction's own slope along u may make x fall: a smaller
    // share of it, or none.
    for (const double share : {1.0, 0.5, 0.25}) {
        x_.assign(nu_ * nv_, 0.0);
        for (std::size_t i = 0; i < nu_; ++i)
            for (std::size_t j = 0; j < nv_; ++j) x_[i * nv_ + j] = base[i] + share * weight[i] * c[i * nv_ + j];
        bool rising = true;
        for (std::size_t i = 0; i + 1 < nu_ && rising; ++i)
            for (std::size_t j = 0; j < nv_ && rising; ++j) rising = at(i + 1, j) - at(i, j) >= 0.25 * (base[i + 1] - base[i]);
        shifted_.assign(nu_, false);
        for (std::size_t i = 0; i < nu_; ++i) shifted_[i] = weight[i] > 0.0;
        if (rising) return;
    }
    x_.clear();
}

void ScaledSpace::column(double v, std::size_t& j, std::size_t& j1, double& b) const
{
    j = 0;
    b = 0.0;
    if (v != range_.vMin && v != range_.vMax) {  // the seam exactly: column 0, on both sides
        double t = (v - range_.vMin) / range_.vPeriod();
        t -= std::floor(t);
        const double f = t * static_cast<double>(nv_);
        j = std::min(static_cast<std::size_t>(f), nv_ - 1);
        b = f - static_cast<double>(j);
    }
    j1 = (j + 1) % nv_;
}

ScaledSpace::Cell ScaledSpace::cellAt(double u, double v) const
{
    Cell c;
    const double f = std::clamp((u - range_.uMin) / (range_.uMax - range_.uMin) * static_cast<double>(nu_ - 1), 0.0,
                                static_cast<double>(nu_ - 1));
    c.i = std::min(static_cast<std::size_t>(f), nu_ - 2);
    c.a = f - static_cast<double>(c.i);
    column(v, c.j, c.j1, c.b);
    return c;
}

void ScaledSpace::toXY(double u, double v, double& x, double& y) const
{
    y = (v - range_.vMin) * sv_;
    if (!corrected() || u <= range_.uMin || u >= range_.uMax) {
        x = (u - range_.uMin) * su_;  // the ends exactly as without the correction
        return;
    }
    const Cell c = cellAt(u, v);
    if (!shifted_[c.i] && !shifted_[c.i + 1]) {
        x = (u - range_.uMin) * su_;  // no correction in this cell: exactly as without
        return;
    }
    const double lo = (1.0 - c.b) * at(c.i, c.j) + c.b * at(c.i, c.j1);
    const double hi = (1.0 - c.b) * at(c.i + 1, c.j) + c.b * at(c.i + 1, c.j1);
    x = (1.0 - c.a) * lo + c.a * hi;
}

UV ScaledSpace::toUV(double x, double y) const
{
    const double v = range_.vMin + y / sv_;
    if (!corrected()) return {range_.uMin + x / su_, v};
    std::size_t j = 0, j1 = 0;
    double b = 0.0;
    column(v, j, j1, b);
    const auto row = [&](std::size_t i) { return b == 0.0 ? at(i, j) : (1.0 - b) * at(i, j) + b * at(i, j1); };
    // At and beyond the ends exactly as without the correction (it is none there).
    if (x <= 0.0 || x >= row(nu_ - 1)) return {range_.uMin + x / su_, v};
    std::size_t lo = 0, hi = nu_ - 1;  // row(lo) <= x < row(hi): x rises along u
    while (hi - lo > 1) {
        const std::size_t mid = (lo + hi) / 2;
        (row(mid) <= x ? lo : hi) = mid;
    }
    if (!shifted_[lo] && !shifted_[hi]) return {range_.uMin + x / su_, v};
    const double xl = row(lo), xh = row(hi);
    return {u_[lo] + (x - xl) / (xh - xl) * (u_[hi] - u_[lo]), v};
}

ScaledSpace::Slopes ScaledSpace::slopes(double u, double v) const
{
    if (!corrected()) return {su_, 0.0};
    const Cell c = cellAt(u, v);
    const double du = u_[c.i + 1] - u_[c.i], dv = range_.vPeriod() / static_cast<double>(nv_);
    Slopes s;
    s.xu = ((1.0 - c.b) * (at(c.i + 1, c.j) - at(c.i, c.j)) + c.b * (at(c.i + 1, c.j1) - at(c.i, c.j1))) / du;
    s.xv = ((1.0 - c.a) * (at(c.i, c.j1) - at(c.i, c.j)) + c.a * (at(c.i + 1, c.j1) - at(c.i + 1, c.j))) / dv;
    return s;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
