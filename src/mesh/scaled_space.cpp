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

/// The grid's rows (u, both ends included) and columns around v.
std::vector<double> gridRows(const ParameterRange& r, std::size_t nu)
{
    std::vector<double> u(nu);
    for (std::size_t i = 0; i < nu; ++i)
        u[i] = i + 1 == nu ? r.uMax : r.uMin + (r.uMax - r.uMin) * static_cast<double>(i) / static_cast<double>(nu - 1);
    return u;
}
std::size_t rowCount(const TowSurface& s) { return std::clamp<std::size_t>(kRowsPerSection * s.sectionCount() + 1, 9, 1025); }
std::size_t columnCount(const TowSurface& s) { return std::clamp<std::size_t>(kColumnsPerPoint * s.pointsPerSection(), 16, 512); }

/// The surface's derivatives at the grid's rows @p us and @p nv columns around (row-major),
/// evaluated once for the density and the correction.
std::vector<SurfaceDerivatives> derivativeGrid(const TowSurface& surface, const std::vector<double>& us, std::size_t nv)
{
    const ParameterRange r = surface.parameterRange();
    const double dv = r.vPeriod() / static_cast<double>(nv);
    std::vector<SurfaceDerivatives> grid;
    grid.reserve(us.size() * nv);
    for (double u : us)
        for (std::size_t j = 0; j < nv; ++j) grid.push_back(surface.derivatives(u, r.vMin + static_cast<double>(j) * dv));
    return grid;
}

/// Per row: how fast a conformal x runs along u for a plane 1 around, |S_u| / C (|S_u| the mean
/// speed along u over the row, C the girth across the tow: the integral of |S_u x S_v| / |S_u|
/// over v, the circumference of the section square to the tow, which the shear correction makes
/// a line of constant x). Kept within 1/8 .. 8 of its mean (a section next to nothing around
/// would have no bound); all 1 when the tow has no girth or speed anywhere (a linear plane).
/// @p grid: derivativeGrid() of @p rows rows.
std::vector<double> conformalDensity(const std::vector<SurfaceDerivatives>& grid, std::size_t rows, std::size_t nv, double vPeriod)
{
    const double dv = vPeriod / static_cast<double>(nv);
    std::vector<double> density(rows, 0.0);
    for (std::size_t i = 0; i < rows; ++i) {
        double around = 0.0, speed = 0.0;
        for (std::size_t j = 0; j < nv; ++j) {
            const SurfaceDerivatives& d = grid[i * nv + j];
            const double su = norm(d.du);
            speed += su / static_cast<double>(nv);
            if (su > 0.0) around += norm(cross(d.du, d.dv)) / su * dv;
        }
        density[i] = around > 0.0 ? speed / around : 0.0;
    }
    double mean = 0.0;
    for (double d : density) mean += d / static_cast<double>(density.size());
    if (!(mean > 0.0) || !std::isfinite(mean)) return std::vector<double>(rows, 1.0);
    for (double& d : density) d = std::isfinite(d) ? std::clamp(d, mean / 8.0, 8.0 * mean) : mean;
    return density;
}

/// The integral of @p density over the rows @p us from the first (trapezoids).
std::vector<double> integral(const std::vector<double>& us, const std::vector<double>& density)
{
    std::vector<double> f(us.size(), 0.0);
    for (std::size_t i = 1; i < us.size(); ++i) f[i] = f[i - 1] + 0.5 * (density[i - 1] + density[i]) * (us[i] - us[i - 1]);
    return f;
}

/// dx/dv that squares the plane at every grid point (x running @p dxdu[i] per unit u at row i),
/// integrated around each row (trapezoids), without the drift over the whole turn and centred on
/// zero: the correction c(row, column). @p grid: derivativeGrid() of dxdu.size() rows.
std::vector<double> squaringOffsets(const std::vector<SurfaceDerivatives>& grid, const std::vector<double>& dxdu, std::size_t nv, double vPeriod)
{
    const double dv = vPeriod / static_cast<double>(nv);
    std::vector<double> c(dxdu.size() * nv, 0.0), slope(nv + 1);
    for (std::size_t i = 0; i < dxdu.size(); ++i) {
        for (std::size_t j = 0; j < nv; ++j) {
            const SurfaceDerivatives& d = grid[i * nv + j];
            const double uu = dot(d.du, d.du);
            slope[j] = uu > 0.0 ? dxdu[i] * dot(d.du, d.dv) / uu : 0.0;
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

double ScaledSpace::conformalLength(const TowSurface& surface, double ly)
{
    // Conformal between the grid's first and last cells, which take their share of the length
    // at the mean rate (x is linear in u there): lx = ly (F(u[nu-2]) - F(u[1])) + 2 lx / (nu - 1).
    const std::size_t nu = rowCount(surface);
    const std::vector<double> us = gridRows(surface.parameterRange(), nu);
    const std::size_t nv = columnCount(surface);
    const std::vector<double> f = integral(us, conformalDensity(derivativeGrid(surface, us, nv), nu, nv, surface.parameterRange().vPeriod()));
    return ly * (f[nu - 2] - f[1]) * static_cast<double>(nu - 1) / static_cast<double>(nu - 3);
}

ScaledSpace::ScaledSpace(const TowSurface& surface, double su, double sv, bool unshear)
    : range_(surface.parameterRange()), su_(su), sv_(sv)
{
    if (!unshear) return;
    nu_ = rowCount(surface);
    nv_ = columnCount(surface);
    u_ = gridRows(range_, nu_);
    const double lx = (range_.uMax - range_.uMin) * su;
    // The base: x conformal along u between the grid's first and last cells (x runs as fast as
    // the tow is long there, for its girth there), linear in u, (u - uMin) su, in those two
    // cells. None in the last cell at each end: there x is (u - uMin) su to the last bit, as
    // without the correction (a loop across a cap, with nodes on the rim and thin triangles next
    // to it, failed in the region stage with the correction blended down to the rim itself).
    const std::vector<SurfaceDerivatives> grid = derivativeGrid(surface, u_, nv_);
    const std::vector<double> density = conformalDensity(grid, nu_, nv_, range_.vPeriod()), f = integral(u_, density);
    std::vector<double> base(nu_), dxdu(nu_, su);
    const double from = (u_[1] - range_.uMin) * su, to = (u_[nu_ - 2] - range_.uMin) * su;
    const double stretch = (to - from) / (f[nu_ - 2] - f[1]);
    double bent = 0.0;  // how far the base is from linear
    for (std::size_t i = 0; i < nu_; ++i) {
        base[i] = i == 0 ? 0.0 : i + 1 == nu_ ? lx : i == 1 ? from : i + 2 == nu_ ? to : from + (f[i] - f[1]) * stretch;
        if (i > 0 && i + 1 < nu_) dxdu[i] = density[i] * stretch;
        bent = std::max(bent, std::abs(base[i] - (u_[i] - range_.uMin) * su));
    }
    const std::vector<double> c = squaringOffsets(grid, dxdu, nv_, range_.vPeriod());
    double largest = 0.0;
    for (double e : c) largest = std::max(largest, std::abs(e));
    if (!(largest > 1e-9 * lx) && !(bent > 1e-9 * lx)) return;  // square and conformal already
    // The correction's blend: none in the last cell at each end, then a ramp to the full
    // correction as steep as lets it take at most half of the base's rise along u, by the
    // correction's largest value in the rows (where the shear is small next to an end, the
    // ramp is short).
    std::vector<double> rowLargest(nu_, 0.0);
    for (std::size_t i = 0; i < nu_; ++i)
        for (std::size_t j = 0; j < nv_; ++j) rowLargest[i] = std::max(rowLargest[i], std::abs(c[i * nv_ + j]));
    std::vector<double> weight(nu_, 0.0), back(nu_, 0.0);
    const auto ramp = [&](std::size_t from, std::size_t to) {  // weight at row to, from that at row from
        const double largest = std::max({rowLargest[from], rowLargest[to], 1e-300});
        return std::min(1.0, 0.5 * std::abs(base[to] - base[from]) / largest);
    };
    for (std::size_t i = 2; i + 2 < nu_; ++i) weight[i] = std::min(1.0, weight[i - 1] + ramp(i - 1, i));
    for (std::size_t i = nu_ - 3; i >= 2; --i) back[i] = std::min(1.0, back[i + 1] + ramp(i + 1, i));
    for (std::size_t i = 0; i < nu_; ++i) weight[i] = std::min(weight[i], back[i]);
    // Where sections turn fast the correction's own slope along u may make x fall: a smaller
    // share of it, or none (the base alone rises).
    for (const double share : {1.0, 0.5, 0.25, 0.0}) {
        x_.assign(nu_ * nv_, 0.0);
        for (std::size_t i = 0; i < nu_; ++i)
            for (std::size_t j = 0; j < nv_; ++j) x_[i * nv_ + j] = base[i] + share * weight[i] * c[i * nv_ + j];
        bool rising = true;
        for (std::size_t i = 0; i + 1 < nu_ && rising; ++i)
            for (std::size_t j = 0; j < nv_ && rising; ++j) rising = at(i + 1, j) - at(i, j) >= 0.25 * (base[i + 1] - base[i]);
        // Every row but those of the end cells is off (u - uMin) su.
        shifted_.assign(nu_, false);
        for (std::size_t i = 2; i + 2 < nu_; ++i) shifted_[i] = true;
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
