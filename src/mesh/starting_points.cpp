#include "mesh/starting_points.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail::mesh2 {

namespace {

/// Segments and points binned by square cells of size h over [0,lx] x [0,ly], for "is anything
/// within h of here" queries.
class NearbyIndex {
public:
    /// Bins of size @p h over [x0, x1] x [0, ly] (points beyond go to the nearest bin).
    NearbyIndex(double x0, double x1, double ly, double h)
        : x0_(x0), cell_(h), nx_(static_cast<long>(std::ceil((x1 - x0) / h)) + 1), ny_(static_cast<long>(std::ceil(ly / h)) + 1),
          segments_(static_cast<std::size_t>(nx_ * ny_)), points_(static_cast<std::size_t>(nx_ * ny_))
    {
    }
    void addSegment(const K::Point_2& a, const K::Point_2& b)
    {
        const auto [i0, j0] = binOf(std::min(a.x(), b.x()), std::min(a.y(), b.y()));
        const auto [i1, j1] = binOf(std::max(a.x(), b.x()), std::max(a.y(), b.y()));
        for (long i = i0; i <= i1; ++i)
            for (long j = j0; j <= j1; ++j) segments_[index(i, j)].emplace_back(a, b);
    }
    void addPoint(const K::Point_2& p)
    {
        const auto [i, j] = binOf(p.x(), p.y());
        points_[index(i, j)].push_back(p);
    }
    /// True if @p p is at least @p segmentGap from every segment, outside every segment's
    /// diametral circle (so it does not encroach on a constraint), and at least @p pointGap from
    /// every point; all gaps at most h.
    bool clear(const K::Point_2& p, double segmentGap, double pointGap) const
    {
        const auto [ci, cj] = binOf(p.x(), p.y());
        for (long i = std::max(0L, ci - 1); i <= std::min(nx_ - 1, ci + 1); ++i)
            for (long j = std::max(0L, cj - 1); j <= std::min(ny_ - 1, cj + 1); ++j) {
                for (const auto& [a, b] : segments_[index(i, j)]) {
                    if (CGAL::squared_distance(p, K::Segment_2(a, b)) < segmentGap * segmentGap) return false;
                    // Inside the diametral circle, with a margin: the mesher would split a, b.
                    if (CGAL::squared_distance(p, CGAL::midpoint(a, b)) < 0.3025 * CGAL::squared_distance(a, b)) return false;
                }
                for (const K::Point_2& q : points_[index(i, j)])
                    if (CGAL::squared_distance(p, q) < pointGap * pointGap) return false;
            }
        return true;
    }

private:
    std::pair<long, long> binOf(double x, double y) const
    {
        return {std::clamp(static_cast<long>(std::floor((x - x0_) / cell_)), 0L, nx_ - 1),
                std::clamp(static_cast<long>(std::floor(y / cell_)), 0L, ny_ - 1)};
    }
    std::size_t index(long i, long j) const { return static_cast<std::size_t>(i * ny_ + j); }
    double x0_, cell_;
    long nx_, ny_;
    std::vector<std::vector<std::pair<K::Point_2, K::Point_2>>> segments_;
    std::vector<std::vector<K::Point_2>> points_;
};

/// The apexes, on both sides, of the triangle on the chord [a, b] that is equilateral in 3D (by the
/// surface metric at the chord's middle), or isosceles with sides @p longest if the chord is
/// nearly that long already (a triangle on a loop chord that is too big is refined, and its
/// circumcentre, close to the chord, would make the mesher split the chord). None for a chord
/// longer than 1.7 x @p longest.
std::vector<K::Point_2> apexes(const K::Point_2& a, const K::Point_2& b, const SurfaceMetric& metric, double longest)
{
    const K::Point_2 m = CGAL::midpoint(a, b);
    const SurfaceMetric::Form f = metric.at(m.x(), m.y());
    // The metric's Cholesky factor W (x -> w = W x makes it Euclidean): W = [[p, q], [0, r]].
    const double p = std::sqrt(f.e), q = f.f / p, r = std::sqrt(std::max(f.g - q * q, 1e-300));
    const double dx = b.x() - a.x(), dy = b.y() - a.y();
    const double wx = p * dx + q * dy, wy = r * dy, half = 0.5 * std::hypot(wx, wy);
    // A chord much longer than h (a loop spacing over h) has no good triangle of size h on it:
    // refinement decides there.
    if (half == 0.0 || half > 0.85 * longest) return {};
    const double side = std::max(std::min(2.0 * half, longest), 1.01 * half);
    // The unit normal (-wy, wx) / 2 half, back from w to (x, y).
    const double uy = wx / (2.0 * half) / r, ux = (-wy / (2.0 * half) - q * uy) / p;
    const auto sideLength = [&](const K::Point_2& x) {
        const auto edge = [&](const K::Point_2& e) {
            return std::sqrt(metric.squaredLength(0.5 * (e.x() + x.x()), 0.5 * (e.y() + x.y()), x.x() - e.x(), x.y() - e.y()));
        };
        return std::max(edge(a), edge(b));
    };
    std::vector<K::Point_2> out(2);
    for (int k = 0; k < 2; ++k) {
        const double sign = k == 0 ? 1.0 : -1.0;
        double height = std::sqrt(side * side - half * half);
        // The metric at the middle of the chord is not the metric at the middle of the sides:
        // shorten the height until the longer side is what was asked for (where the surface's
        // speed changes fast, as at the tips of a lenticular section).
        for (int iteration = 0; iteration < 4; ++iteration) {
            const double s = sideLength(m + sign * height * K::Vector_2(ux, uy));
            if (s <= longest) break;
            const double want = std::max(longest * longest - half * half, 0.0), have = std::max(s * s - half * half, 1e-300);
            height *= std::max(std::sqrt(want / have), 0.3);
        }
        out[static_cast<std::size_t>(k)] = m + sign * height * K::Vector_2(ux, uy);
    }
    return out;
}

}  // namespace

void insertStartingPoints(CDT& cdt, const std::vector<std::vector<K::Point_2>>& chords, const SurfaceMetric& metric,
                          double x0, double x1, double ly, double h)
{
    NearbyIndex near(x0, x1, ly, h);
    for (auto e = cdt.constrained_edges_begin(); e != cdt.constrained_edges_end(); ++e)
        near.addSegment(e->first->vertex(CDT::cw(e->second))->point(), e->first->vertex(CDT::ccw(e->second))->point());
    const auto inside = [&](const K::Point_2& p, double margin) {
        return p.x() > x0 + margin && p.x() < x1 - margin && p.y() > margin && p.y() < ly - margin;
    };
    std::vector<K::Point_2> points;
    for (const std::vector<K::Point_2>& loop : chords)
        for (std::size_t k = 0; k + 1 < loop.size(); ++k)
            for (const K::Point_2& p : apexes(loop[k], loop[k + 1], metric, 0.97 * h)) {
                // Gaps relative to the apex's own triangle: it is as far from its chord as it is.
                const double height = std::sqrt(CGAL::squared_distance(p, K::Segment_2(loop[k], loop[k + 1])));
                const double side = std::sqrt(CGAL::squared_distance(p, loop[k]));
                if (inside(p, 0.5 * height) && near.clear(p, 0.7 * height, 0.7 * side)) {
                    near.addPoint(p);
                    points.push_back(p);
                }
            }
    const double dy = h * std::sqrt(3.0) / 2.0;
    for (long j = 1; static_cast<double>(j) * dy < ly; ++j)
        for (double x = x0 + (j % 2 ? 0.5 * h : h); x < x1; x += h) {
            const K::Point_2 p(x, static_cast<double>(j) * dy);
            if (near.clear(p, 0.7 * h, 0.6 * h)) points.push_back(p);
        }
    cdt.insert(points.begin(), points.end());
}

}  // namespace detail::mesh2
TOWGEOM_END_NAMESPACE
