#include "volume/graded_size.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

constexpr std::uint32_t kNoSource = std::numeric_limits<std::uint32_t>::max();

/// The 13 neighbours (di, dj, dk) of a grid node that come before it in x-fastest order.
std::vector<std::array<int, 3>> earlierNeighbours()
{
    std::vector<std::array<int, 3>> out;
    for (int dk = -1; dk <= 1; ++dk)
        for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di)
                if (dk < 0 || (dk == 0 && (dj < 0 || (dj == 0 && di < 0)))) out.push_back({di, dj, dk});
    return out;
}

}  // namespace

GradedSize::GradedSize(const std::vector<Point3>& nodes, const std::vector<std::array<std::size_t, 3>>& triangles, double slope, double largest,
                       std::size_t gridNodes)
    : slope_(slope), largest_(largest)
{
    // Each node's size: the mean length of the triangle edges at it.
    std::vector<double> sum(nodes.size(), 0.0);
    std::vector<std::uint32_t> count(nodes.size(), 0);
    for (const auto& t : triangles)
        for (std::size_t e = 0; e < 3; ++e) {
            const double l = distance(nodes[t[e]], nodes[t[(e + 1) % 3]]);
            for (std::size_t n : {t[e], t[(e + 1) % 3]}) {
                sum[n] += l;
                ++count[n];
            }
        }
    std::vector<std::uint32_t> used;
    std::vector<double> h(nodes.size(), 0.0);
    Point3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    for (std::size_t n = 0; n < nodes.size(); ++n) {
        if (count[n] == 0) continue;
        used.push_back(static_cast<std::uint32_t>(n));
        h[n] = sum[n] / count[n];
        lo = {std::min(lo.x, nodes[n].x), std::min(lo.y, nodes[n].y), std::min(lo.z, nodes[n].z)};
        hi = {std::max(hi.x, nodes[n].x), std::max(hi.y, nodes[n].y), std::max(hi.z, nodes[n].z)};
    }
    if (used.empty()) {
        largest_ = std::abs(largest_);
        return;
    }
    std::vector<double> sizes;
    for (std::uint32_t n : used) sizes.push_back(h[n]);
    std::nth_element(sizes.begin(), sizes.begin() + static_cast<long>(sizes.size() / 2), sizes.end());
    median_ = sizes[sizes.size() / 2];
    if (largest_ < 0.0) largest_ *= -median_;
    // Never below the surface's own size: a largest size under it caps each node's growth at
    // the node's size instead.
    cap_ = std::max(largest_, *std::max_element(sizes.begin(), sizes.end()));

    // The grid: the surface's median size apart, coarser if that needs more than gridNodes,
    // one spacing beyond the surface on every side.
    const Vector3 extent = hi - lo;
    spacing_ = std::max(median_, 1e-12 * std::max({extent.x, extent.y, extent.z, 1e-300}));
    const auto countFor = [&](double s) {
        return (std::floor(extent.x / s) + 3) * (std::floor(extent.y / s) + 3) * (std::floor(extent.z / s) + 3);
    };
    while (countFor(spacing_) > static_cast<double>(gridNodes)) spacing_ *= 1.25;
    origin_ = lo - Vector3{spacing_, spacing_, spacing_};
    n_ = {static_cast<std::size_t>(std::floor(extent.x / spacing_)) + 3, static_cast<std::size_t>(std::floor(extent.y / spacing_)) + 3,
          static_cast<std::size_t>(std::floor(extent.z / spacing_)) + 3};

    // Each grid node keeps the surface node giving it the least size: first the nodes of the
    // grid cells around each surface node, then two raster sweeps each way.
    std::vector<double> value(n_[0] * n_[1] * n_[2], std::numeric_limits<double>::infinity());
    std::vector<std::uint32_t> source(value.size(), kNoSource);
    const auto offer = [&](std::size_t g, const Point3& x, std::uint32_t s) {
        const double v = std::min(h[s] + slope_ * distance(x, nodes[s]), std::max(largest_, h[s]));
        if (v < value[g]) {
            value[g] = v;
            source[g] = s;
        }
    };
    for (std::uint32_t s : used) {
        const Vector3 r = (1.0 / spacing_) * (nodes[s] - origin_);
        // Clamped: the grid's count and this cell may round differently at the top face.
        const auto cellOf = [&](double x, std::size_t a) { return std::min(static_cast<std::size_t>(std::max(x, 0.0)), n_[a] - 2); };
        const std::size_t i = cellOf(r.x, 0), j = cellOf(r.y, 1), k = cellOf(r.z, 2);
        for (std::size_t c = 0; c < 8; ++c) {
            const std::size_t a = i + (c & 1), b = j + ((c >> 1) & 1), d = k + ((c >> 2) & 1);
            offer(at(a, b, d), gridPoint(a, b, d), s);
        }
    }
    const std::vector<std::array<int, 3>> earlier = earlierNeighbours();
    const auto visit = [&](std::size_t i, std::size_t j, std::size_t k, int sign) {
        const std::size_t g = at(i, j, k);
        const Point3 x = gridPoint(i, j, k);
        for (const auto& d : earlier) {
            const long a = static_cast<long>(i) + sign * d[0], b = static_cast<long>(j) + sign * d[1], c = static_cast<long>(k) + sign * d[2];
            if (a < 0 || b < 0 || c < 0 || a >= static_cast<long>(n_[0]) || b >= static_cast<long>(n_[1]) || c >= static_cast<long>(n_[2]))
                continue;
            const std::uint32_t s = source[at(static_cast<std::size_t>(a), static_cast<std::size_t>(b), static_cast<std::size_t>(c))];
            if (s != kNoSource && s != source[g]) offer(g, x, s);
        }
    };
    for (int round = 0; round < 2; ++round) {
        for (std::size_t k = 0; k < n_[2]; ++k)
            for (std::size_t j = 0; j < n_[1]; ++j)
                for (std::size_t i = 0; i < n_[0]; ++i) visit(i, j, k, 1);
        for (std::size_t k = n_[2]; k-- > 0;)
            for (std::size_t j = n_[1]; j-- > 0;)
                for (std::size_t i = n_[0]; i-- > 0;) visit(i, j, k, -1);
    }
    size_.resize(value.size());
    for (std::size_t g = 0; g < value.size(); ++g) size_[g] = static_cast<float>(std::min(value[g], cap_));
}

Point3 GradedSize::gridPoint(std::size_t i, std::size_t j, std::size_t k) const
{
    return origin_ + spacing_ * Vector3{static_cast<double>(i), static_cast<double>(j), static_cast<double>(k)};
}

double GradedSize::operator()(const Point3& x) const
{
    if (size_.empty()) return largest_;
    // Outside the grid (beyond the surfaces' bounding box) the size at the nearest grid point,
    // grown by the slope over the distance to it.
    const Vector3 r = (1.0 / spacing_) * (x - origin_);
    double f[3] = {r.x, r.y, r.z};
    std::size_t c[3];
    double outside = 0.0;  // squared, in grid spacings
    for (std::size_t a = 0; a < 3; ++a) {
        const double v = std::clamp(f[a], 0.0, static_cast<double>(n_[a] - 1));
        outside += (f[a] - v) * (f[a] - v);
        c[a] = std::min(static_cast<std::size_t>(v), n_[a] - 2);
        f[a] = v - static_cast<double>(c[a]);
    }
    double out = slope_ * spacing_ * std::sqrt(outside);
    for (std::size_t corner = 0; corner < 8; ++corner) {
        const std::size_t di = corner & 1, dj = (corner >> 1) & 1, dk = (corner >> 2) & 1;
        const double w = (di ? f[0] : 1.0 - f[0]) * (dj ? f[1] : 1.0 - f[1]) * (dk ? f[2] : 1.0 - f[2]);
        out += w * size_[at(c[0] + di, c[1] + dj, c[2] + dk)];
    }
    return std::min(out, cap_);
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
