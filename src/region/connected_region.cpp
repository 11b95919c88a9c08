#include "region/connected_region.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cmath>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

/// A loop polygon with its (u,v) box, for repeated point tests.
struct LoopPolygon {
    std::vector<K::Point_2> poly;
    double vLo = 1e300, vHi = -1e300, uLo = 1e300, uHi = -1e300;

    /// Whole periods the loop's closing chord spans: nonzero for a loop that winds around the tow,
    /// whose closing chord ends one period on from its first point (as chordEnds()).
    double wind = 0.0;
    double period = 0.0;

    explicit LoopPolygon(const std::vector<UV>& polygon, double vPeriod = 0.0) : period(vPeriod)
    {
        for (const UV& p : polygon) {
            poly.emplace_back(p.u, p.v);
            vLo = std::min(vLo, p.v);
            vHi = std::max(vHi, p.v);
            uLo = std::min(uLo, p.u);
            uHi = std::max(uHi, p.u);
        }
        if (period > 0.0 && polygon.size() > 1) wind = std::round((polygon.back().v - polygon.front().v) / period);
        if (wind != 0.0) {
            vLo = std::min(vLo, polygon.front().v + wind * period);
            vHi = std::max(vHi, polygon.front().v + wind * period);
        }
    }
    bool winds() const { return wind != 0.0; }
    /// Chord i: from point i to the next, the last to the first (one period on if it winds).
    K::Segment_2 chord(std::size_t i) const
    {
        if (i + 1 < poly.size()) return {poly[i], poly[i + 1]};
        return {poly[i], K::Point_2(poly[0].x(), poly[0].y() + wind * period)};
    }

    bool contains(UV c, double period) const
    {
        if (poly.size() < 3 || !(c.u >= uLo && c.u <= uHi)) return false;  // outside the box (or NaN): no exact test
        // The copy of the point, one period over or not, that can lie in the loop's v range.
        const double shift = period * std::floor((c.v - vLo) / period);
        for (const double v : {c.v - shift, c.v - shift + period}) {
            if (v < vLo || v > vHi) continue;
            if (CGAL::bounded_side_2(poly.begin(), poly.end(), K::Point_2(c.u, v), K()) == CGAL::ON_BOUNDED_SIDE) return true;
        }
        return false;
    }
};

}  // namespace

bool insideLoop(const std::vector<UV>& polygon, UV p, double period) { return LoopPolygon(polygon).contains(p, period); }

bool loopsMeet(const std::vector<UV>& a, const std::vector<UV>& b, double period)
{
    if (a.size() < 3 || b.size() < 3) return false;
    const LoopPolygon pa(a, period), pb0(b, period);
    const double shift0 = std::round((0.5 * (pa.vLo + pa.vHi) - 0.5 * (pb0.vLo + pb0.vHi)) / period);
    for (double k = shift0 - 1.0; k <= shift0 + 1.0; k += 1.0) {
        std::vector<UV> moved = b;
        for (UV& p : moved) p.v += k * period;
        const LoopPolygon pb(moved, period);
        if (pb.uHi < pa.uLo || pa.uHi < pb.uLo || pb.vHi < pa.vLo || pa.vHi < pb.vLo) continue;
        for (std::size_t i = 0; i < pa.poly.size(); ++i) {
            const K::Segment_2 s = pa.chord(i);
            const CGAL::Bbox_2 bs = s.bbox();
            for (std::size_t j = 0; j < pb.poly.size(); ++j) {
                const K::Segment_2 t = pb.chord(j);
                if (CGAL::do_overlap(bs, t.bbox()) && CGAL::do_intersect(s, t)) return true;
            }
        }
        // No crossing: one inside the other, or apart (a loop around the tow bounds no inside).
        if (pa.winds() || pb.winds()) continue;
        if (CGAL::bounded_side_2(pa.poly.begin(), pa.poly.end(), pb.poly.front(), K()) != CGAL::ON_UNBOUNDED_SIDE) return true;
        if (CGAL::bounded_side_2(pb.poly.begin(), pb.poly.end(), pa.poly.front(), K()) != CGAL::ON_UNBOUNDED_SIDE) return true;
    }
    return false;
}

std::vector<LoopCrossing> loopCrossings(const std::vector<UV>& a, const std::vector<std::size_t>& nodesA,
                                        const std::vector<UV>& b, const std::vector<std::size_t>& nodesB, double period)
{
    std::vector<LoopCrossing> out;
    if (a.size() < 3 || b.size() < 3) return out;
    const LoopPolygon pa(a, period), pb0(b, period);
    const double shift0 = std::round((0.5 * (pa.vLo + pa.vHi) - 0.5 * (pb0.vLo + pb0.vHi)) / period);
    const std::size_t na = a.size(), nb = b.size();
    for (double k = shift0 - 1.0; k <= shift0 + 1.0; k += 1.0) {
        std::vector<UV> moved = b;
        for (UV& p : moved) p.v += k * period;
        const LoopPolygon pb(moved, period);
        if (pb.uHi < pa.uLo || pa.uHi < pb.uLo || pb.vHi < pa.vLo || pa.vHi < pb.vLo) continue;
        for (std::size_t i = 0; i < na; ++i) {
            const K::Segment_2 s = pa.chord(i);
            const CGAL::Bbox_2 bs = s.bbox();
            for (std::size_t j = 0; j < nb; ++j) {
                const K::Segment_2 t = pb.chord(j);
                if (!CGAL::do_overlap(bs, t.bbox()) || !CGAL::do_intersect(s, t)) continue;
                const std::size_t a0 = nodesA[i], a1 = nodesA[(i + 1) % na], b0 = nodesB[j], b1 = nodesB[(j + 1) % nb];
                if (a0 == b0 || a0 == b1 || a1 == b0 || a1 == b1) continue;
                // The fractions along both chords (the middle of an overlap if they are parallel).
                const K::Vector_2 d = s.to_vector(), e = t.to_vector(), w = t.source() - s.source();
                const double den = d.x() * e.y() - d.y() * e.x();
                LoopCrossing c{i, j, 0.5, 0.5};
                if (den != 0.0) {
                    c.ta = std::clamp((w.x() * e.y() - w.y() * e.x()) / den, 0.0, 1.0);
                    c.tb = std::clamp((w.x() * d.y() - w.y() * d.x()) / den, 0.0, 1.0);
                }
                out.push_back(c);
            }
        }
    }
    return out;
}

std::vector<std::size_t> trianglesInside(const std::vector<UV>& centroids, const std::vector<UV>& polygon, double period)
{
    const LoopPolygon loop(polygon);
    std::vector<std::size_t> inside;
    for (std::size_t t = 0; t < centroids.size(); ++t)
        if (loop.contains(centroids[t], period)) inside.push_back(t);
    return inside;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
