#include "volume/facet_folds.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

std::optional<FacetFold> sharpestFold(const std::vector<Point3>& nodes, const std::vector<const std::vector<std::size_t>*>& surfaces,
                                      double tolerance)
{
    // Nodes on two or more surfaces; only edges between two of them can be where surfaces meet.
    constexpr std::size_t kNone = static_cast<std::size_t>(-1);
    std::vector<std::size_t> firstSurface(nodes.size(), kNone);
    std::vector<char> shared(nodes.size(), 0);
    for (std::size_t s = 0; s < surfaces.size(); ++s)
        for (std::size_t n : *surfaces[s]) {
            std::size_t& first = firstSurface[n - 1];
            if (first == kNone) first = s;
            else if (first != s) shared[n - 1] = 1;
        }
    struct Wing {
        std::size_t a, b, opposite, surface;  // edge a < b, the triangle's third node
    };
    std::vector<Wing> wings;
    for (std::size_t s = 0; s < surfaces.size(); ++s) {
        const std::vector<std::size_t>& t = *surfaces[s];
        for (std::size_t k = 0; k + 2 < t.size(); k += 3)
            for (std::size_t e = 0; e < 3; ++e) {
                const std::size_t a = t[k + e] - 1, b = t[k + (e + 1) % 3] - 1, o = t[k + (e + 2) % 3] - 1;
                if (shared[a] && shared[b]) wings.push_back({std::min(a, b), std::max(a, b), o, s});
            }
    }
    std::sort(wings.begin(), wings.end(), [](const Wing& p, const Wing& q) { return std::tie(p.a, p.b) < std::tie(q.a, q.b); });
    std::optional<FacetFold> sharpest;
    for (std::size_t i = 0; i < wings.size();) {
        std::size_t j = i + 1;
        while (j < wings.size() && wings[j].a == wings[i].a && wings[j].b == wings[i].b) ++j;
        const Point3 &a = nodes[wings[i].a], &b = nodes[wings[i].b];
        const Vector3 axis = b - a;
        const double length2 = dot(axis, axis);
        // Each triangle's direction away from the edge, perpendicular to it.
        const auto away = [&](const Wing& w) {
            const Vector3 d = nodes[w.opposite] - a;
            return d - (dot(d, axis) / length2) * axis;
        };
        for (std::size_t p = i; p < j && length2 > 0.0; ++p)
            for (std::size_t q = p + 1; q < j; ++q) {
                const Vector3 u = away(wings[p]), v = away(wings[q]);
                if (!(dot(u, u) > 0.0) || !(dot(v, v) > 0.0)) continue;  // a triangle of no area: no direction to compare
                const double angle = std::atan2(norm(cross(u, v)), dot(u, v));
                if (angle < tolerance && (!sharpest || angle < sharpest->angle))
                    sharpest = FacetFold{wings[p].surface, wings[q].surface, 0.5 * (a + b), angle};
            }
        i = j;
    }
    return sharpest;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
