#include "region/winding_loops.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "intersect/intersection_loop_data.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

UV onTow(const LoopPoint& p, const IntersectionLoop& l, std::size_t tow) { return l.towA() == tow ? p.onA : p.onB; }

/// +1 when going along @p t (increasing u) at @p l's points leaves o (the side before the loop is
/// inside o), -1 when it enters o, 0 when the points do not agree.
int exitsAlongU(const std::vector<TowSurface>& tows, std::size_t t, std::size_t o, const IntersectionLoop& l)
{
    const std::vector<LoopPoint>& pts = l.points();
    // The unit tangent along t against o's normal, summed over the loop: a loop folding back
    // in v has points of both signs, its crossing is the side that dominates.
    const std::size_t step = std::max<std::size_t>(1, pts.size() / 32);
    double sum = 0.0, total = 0.0;
    for (std::size_t k = 0; k < pts.size(); k += step) {
        const UV a = onTow(pts[k], l, t), b = onTow(pts[k], l, o);
        // On the closed tows (a loop may run across a cap): going along t is outward on its
        // first cap, inward on its last.
        const Vector3 du = closedDerivatives(tows[t], a.u, a.v).du;
        const SurfaceDerivatives db = closedDerivatives(tows[o], b.u, b.v);
        const Vector3 n = cross(db.du, db.dv);
        if (!(norm(du) > 0.0) || !(norm(n) > 0.0)) continue;
        const double s = dot(du, n) / (norm(du) * norm(n));
        sum += s;
        total += std::abs(s);
    }
    if (!(total > 0.0) || std::abs(sum) < 0.5 * total) return 0;  // no clear side
    return sum > 0.0 ? 1 : -1;
}

double meanU(const IntersectionLoop& l, std::size_t t)
{
    double sum = 0.0;
    for (const LoopPoint& p : l.points()) sum += onTow(p, l, t).u;
    return l.points().empty() ? 0.0 : sum / static_cast<double>(l.points().size());
}

}  // namespace

std::optional<WindingBands> windingBands(const std::vector<TowSurface>& tows, std::size_t t, std::size_t o,
                                         const std::vector<IntersectionLoop>& loops, std::vector<std::size_t> winding)
{
    if (winding.empty()) return std::nullopt;
    std::sort(winding.begin(), winding.end(), [&](std::size_t a, std::size_t b) { return meanU(loops[a], t) < meanU(loops[b], t); });
    WindingBands bands;
    bands.loops = winding;
    // Before the first loop: inside o when crossing it along t leaves o; then alternately.
    bool inside = false;
    for (std::size_t k = 0; k < winding.size(); ++k) {
        const int exits = exitsAlongU(tows, t, o, loops[winding[k]]);
        if (exits == 0) return std::nullopt;
        if (k == 0) {
            bands.startInside = exits > 0;
            inside = bands.startInside;
        } else if ((exits > 0) != inside) {
            return std::nullopt;
        }
        inside = !inside;
    }
    return bands;
}

WindingPolygon::WindingPolygon(std::vector<UV> polygon) : uv(std::move(polygon))
{
    uLo = 1e300;
    uHi = -1e300;
    for (const UV& p : uv) {
        uLo = std::min(uLo, p.u);
        uHi = std::max(uHi, p.u);
    }
}

std::size_t loopsBefore(const std::vector<WindingPolygon>& polygons, UV p, double uMin, double period)
{
    std::size_t before = 0;
    for (const WindingPolygon& w : polygons) {
        if (p.u <= w.uLo) continue;  // every crossing at u >= uLo: none before p
        if (p.u > w.uHi) {           // every crossing before p: once around, an odd number
            ++before;
            continue;
        }
        const std::vector<UV>& poly = w.uv;
        std::size_t crossings = 0;
        const std::size_t n = poly.size();
        // A winding loop's closing chord ends one period on from its first point.
        const double wind = n > 0 ? period * std::round((poly[n - 1].v - poly[0].v) / period) : 0.0;
        for (std::size_t k = 0; k < n; ++k) {
            const UV a = poly[k];
            UV b = poly[(k + 1) % n];
            if (k + 1 == n) b.v += wind;
            const double lo = std::min(a.v, b.v), hi = std::max(a.v, b.v);
            if (!(hi > lo)) continue;
            // Every copy p.v + m period in [lo, hi): the chord crosses that v-line there.
            for (double v = p.v + period * std::ceil((lo - p.v) / period); v < hi; v += period) {
                const double f = (v - a.v) / (b.v - a.v);
                const double u = a.u + f * (b.u - a.u);
                if (u >= uMin && u < p.u) ++crossings;
            }
        }
        before += crossings % 2;
    }
    return before;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
