#include "region/triple_points.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>

#include "core/segment_distance.hpp"
#include "intersect/intersection_loop_data.hpp"
#include "intersect/intersection_point.hpp"
#include "region/connected_region.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

/// A triple point closer than this fraction of its chord to a node it cannot replace (a seam
/// node, a node of several loops) or to a tow's seam is not made a node: the tiny edge would
/// leave slivers (0.5 degrees at 1e-4 of a period from a seam, 4 degrees at 1e-3). Its loops
/// are left crossing.
constexpr double kClearance = 0.01;
/// How far a triple point may lie from the chord it is put on, relative to the chord: the loop's
/// own chords stay within kMaxChordBend (5 %) of the curve.
constexpr double kOnChord = 0.1;
/// A loop node closer to a new triple node than this fraction of its chord is removed.
constexpr double kMergeFraction = 0.25;

LoopSide sideOf(const IntersectionLoop& l, std::size_t tow) { return l.towA() == tow ? LoopSide::A : LoopSide::B; }
std::size_t otherTow(const IntersectionLoop& l, std::size_t tow) { return l.towA() == tow ? l.towB() : l.towA(); }
UV& sideRef(LoopPoint& p, LoopSide side) { return side == LoopSide::A ? p.onA : p.onB; }
UV onSide(const LoopPoint& p, LoopSide side) { return side == LoopSide::A ? p.onA : p.onB; }

double periodOn(const IntersectionLoop& l, LoopSide side)
{
    return (side == LoopSide::A ? l.surfaceA() : l.surfaceB()).parameterRange().vPeriod();
}


/// A triple point found: the three tows (t, s1, s2) and the point on each.
struct FoundTriple {
    std::array<std::size_t, 3> tows{};
    PointOn3 at;
    double tolerance = 0.0;
};

/// The loop's exact points on tow @p side: a dense polygon for finding crossings.
std::vector<UV> exactPolygon(const IntersectionLoop& l, LoopSide side)
{
    std::vector<UV> uv;
    uv.reserve(l.points().size());
    for (const LoopPoint& p : l.points()) uv.push_back(onSide(p, side));
    return uv;
}

class TripleJoiner {
public:
    TripleJoiner(const std::vector<TowSurface>& tows, const std::vector<IntersectionLoop>& loops, std::vector<SharedLoop>& shared,
                 std::vector<Point3>& nodes)
        : tows_(tows), loops_(loops), shared_(shared), nodes_(nodes)
    {
        std::map<std::size_t, int> loopsThrough;
        for (const SharedLoop& s : shared_)
            for (std::size_t n : std::set<std::size_t>(s.nodes.begin(), s.nodes.end())) ++loopsThrough[n];
        for (const auto& [n, count] : loopsThrough)
            if (count > 1) pinned_.insert(n);
    }

    /// The triple points where the exact curves of shared loops @p i and @p j (of different
    /// pairs) cross on tow @p t, each refined once (points found from another tow again are
    /// not repeated). A crossing that cannot be refined is left: the node polygons still cross
    /// there, which the caller finds.
    void find(std::size_t t, std::size_t i, std::size_t j, std::vector<FoundTriple>& found) const
    {
        const IntersectionLoop& li = loop(i);
        const IntersectionLoop& lj = loop(j);
        const std::size_t s1 = otherTow(li, t), s2 = otherTow(lj, t);
        const std::vector<LoopPoint>& pi = li.points();
        const std::vector<LoopPoint>& pj = lj.points();
        std::vector<std::size_t> ni(pi.size()), nj(pj.size());  // distinct "nodes": no chord is left out
        for (std::size_t k = 0; k < ni.size(); ++k) ni[k] = k;
        for (std::size_t k = 0; k < nj.size(); ++k) nj[k] = pi.size() + k;
        const double tolerance = std::min(li.tolerance(), lj.tolerance());
        const double same = 100.0 * tolerance;  // Newton's points for one triple point agree to rounding
        for (const LoopCrossing& c : loopCrossings(exactPolygon(li, sideOf(li, t)), ni, exactPolygon(lj, sideOf(lj, t)), nj,
                                                   tows_[t].parameterRange().vPeriod())) {
            // Chord ends, the second's v next to the first's (the closing chord of a loop around a
            // tow ends one period on).
            const auto next = [](const IntersectionLoop& l, const std::vector<LoopPoint>& pts, std::size_t k) {
                LoopPoint q = pts[(k + 1) % pts.size()];
                for (const LoopSide side : {LoopSide::A, LoopSide::B}) {
                    const double period = periodOn(l, side);
                    sideRef(q, side).v += period * std::round((onSide(pts[k], side).v - onSide(q, side).v) / period);
                }
                return q;
            };
            const LoopPoint& a0 = pi[c.chordA];
            const LoopPoint a1 = next(li, pi, c.chordA);
            const LoopPoint& b0 = pj[c.chordB];
            const LoopPoint b1 = next(lj, pj, c.chordB);
            const auto lerp = [](UV p, UV q, double f) { return UV{p.u + f * (q.u - p.u), p.v + f * (q.v - p.v)}; };
            const UV onT = lerp(onSide(a0, sideOf(li, t)), onSide(a1, sideOf(li, t)), c.ta);
            const UV onS1 = lerp(onSide(a0, sideOf(li, s1)), onSide(a1, sideOf(li, s1)), c.ta);
            const UV onS2 = lerp(onSide(b0, sideOf(lj, s2)), onSide(b1, sideOf(lj, s2)), c.tb);
            FoundTriple x{{t, s1, s2}, {}, tolerance};
            x.at.uv = {onT.u, onT.v, onS1.u, onS1.v, onS2.u, onS2.v};
            if (!refineTriplePoint(surfacePairOf(tows_[t], tows_[s1]), surfacePairOf(tows_[t], tows_[s2]), x.at, tolerance)) continue;
            const bool known = std::any_of(found.begin(), found.end(), [&](const FoundTriple& f) {
                return std::is_permutation(f.tows.begin(), f.tows.end(), x.tows.begin()) && distance(f.at.point, x.at.point) <= same;
            });
            if (!known) found.push_back(x);
        }
    }

    /// Inserts @p x as one node into the loops of its three pairs (each the pair's loop with a
    /// chord nearest to it). False (nothing changed) when a pair has no loop there, or the point
    /// lies on a seam.
    bool insert(const FoundTriple& x)
    {
        const std::size_t t = x.tows[0], s1 = x.tows[1], s2 = x.tows[2];
        const auto uvOn = [&](std::size_t tow) {
            const std::size_t o = tow == t ? 0 : tow == s1 ? 2 : 4;
            return UV{x.at.uv[o], x.at.uv[o + 1]};
        };
        std::array<std::pair<std::size_t, std::size_t>, 3> where{};  // (shared loop, chord) per pair
        const std::array<std::pair<std::size_t, std::size_t>, 3> pairs{{std::minmax(t, s1), std::minmax(t, s2), std::minmax(s1, s2)}};
        for (std::size_t p = 0; p < 3; ++p) {
            std::size_t k = shared_.size(), chord = 0;
            double best = 1e300;
            for (std::size_t m = 0; m < shared_.size(); ++m) {
                const IntersectionLoop& lm = loop(m);
                if (std::make_pair(lm.towA(), lm.towB()) != pairs[p]) continue;
                for (std::size_t q = 0; q < shared_[m].points.size(); ++q) {
                    const auto [a, b] = chordEnds(lm, shared_[m], q);
                    const double d = segmentDistance(x.at.point, a.point, b.point);
                    if (d < best && d <= kOnChord * distance(a.point, b.point) + 10.0 * x.tolerance) {
                        best = d;
                        k = m;
                        chord = q;
                    }
                }
            }
            if (k == shared_.size()) return false;
            const IntersectionLoop& l = loop(k);
            const auto [a, b] = chordEnds(l, shared_[k], chord);
            const double length = distance(a.point, b.point);
            // Along the chord, in the chord's period cell on both tows (as splitChord()), and clear
            // of chord ends that must stay.
            const Vector3 ab = b.point - a.point;
            const double along = dot(x.at.point - a.point, ab) / dot(ab, ab);
            if (!(along > -0.25 && along < 1.25)) return false;  // a near end is removed by insertNode()
            const LoopPoint here{x.at.point, uvOn(l.towA()), uvOn(l.towB())};
            for (const LoopSide side : {LoopSide::A, LoopSide::B}) {
                const double period = periodOn(l, side);
                const double vMin = (side == LoopSide::A ? l.surfaceA() : l.surfaceB()).parameterRange().vMin;
                const double v0 = onSide(a, side).v, v1 = onSide(b, side).v;
                const double cell = vMin + period * std::floor((0.5 * (v0 + v1) - vMin) / period);
                double v = onSide(here, side).v;
                v += period * std::round((0.5 * (v0 + v1) - v) / period);
                if (v <= cell || v >= cell + period) return false;
            }
            for (const LoopPoint* end : {&a, &b}) {
                const std::size_t n = end == &a ? shared_[k].nodes[chord] : shared_[k].nodes[(chord + 1) % shared_[k].nodes.size()];
                if ((pinned_.count(n) || onSeam(l, *end, 1e-9)) && distance(end->point, x.at.point) < kClearance * length) return false;
            }
            // Clear of each of the three tows' seams.
            for (const std::size_t tow : x.tows) {
                const UV uv = uvOn(tow);
                if (distance(tows_[tow].point(uv.u, tows_[tow].parameterRange().vMin), x.at.point) < kClearance * length) return false;
            }
            where[p] = {k, chord};
        }
        const std::size_t node = nodes_.size();
        nodes_.push_back(x.at.point);
        pinned_.insert(node);
        for (const auto& [k, chord] : where) {
            const IntersectionLoop& l = loop(k);
            insertNode(k, chord, LoopPoint{x.at.point, uvOn(l.towA()), uvOn(l.towB())}, node);
        }
        return true;
    }

private:
    const IntersectionLoop& loop(std::size_t k) const { return loops_[shared_[k].loop]; }

    /// Puts @p p (node @p node) into shared loop @p k after point @p chord, v next to the
    /// chord's; removes neighbours closer than kMergeFraction of the chord.
    void insertNode(std::size_t k, std::size_t chord, LoopPoint p, std::size_t node)
    {
        SharedLoop& s = shared_[k];
        const IntersectionLoop& l = loop(k);
        const auto [a, b] = chordEnds(l, s, chord);
        for (const LoopSide side : {LoopSide::A, LoopSide::B}) {
            const double period = periodOn(l, side);
            const double middle = 0.5 * (onSide(a, side).v + onSide(b, side).v);
            sideRef(p, side).v += period * std::round((middle - sideRef(p, side).v) / period);
        }
        const double length = distance(a.point, b.point);
        s.points.insert(s.points.begin() + static_cast<std::ptrdiff_t>(chord) + 1, p);
        s.nodes.insert(s.nodes.begin() + static_cast<std::ptrdiff_t>(chord) + 1, node);
        const std::size_t n = s.points.size(), at = chord + 1;
        std::vector<std::size_t> drop;
        for (const std::size_t q : {(at + 1) % n, (at + n - 1) % n})
            if (distance(s.points[q].point, p.point) < kMergeFraction * length && !pinned_.count(s.nodes[q]) &&
                !onSeam(l, s.points[q], 1e-9) && n - drop.size() > 4)
                drop.push_back(q);
        std::sort(drop.rbegin(), drop.rend());
        for (const std::size_t q : drop) {
            s.points.erase(s.points.begin() + static_cast<std::ptrdiff_t>(q));
            s.nodes.erase(s.nodes.begin() + static_cast<std::ptrdiff_t>(q));
        }
    }

    const std::vector<TowSurface>& tows_;
    const std::vector<IntersectionLoop>& loops_;
    std::vector<SharedLoop>& shared_;
    std::vector<Point3>& nodes_;
    std::set<std::size_t> pinned_;  // nodes of several loops: never removed
};

/// The shared loops on tow @p t.
std::vector<std::size_t> loopsOn(const std::vector<IntersectionLoop>& loops, const std::vector<SharedLoop>& shared, std::size_t t)
{
    std::vector<std::size_t> on;
    for (std::size_t k = 0; k < shared.size(); ++k) {
        const IntersectionLoop& l = loops[shared[k].loop];
        if (l.towA() == t || l.towB() == t) on.push_back(k);
    }
    return on;
}

bool samePair(const IntersectionLoop& a, const IntersectionLoop& b) { return a.towA() == b.towA() && a.towB() == b.towB(); }

bool acrossCap(const IntersectionLoop& l) { return l.crossesCap(LoopSide::A) || l.crossesCap(LoopSide::B); }

}  // namespace

TripleJoin joinAtTriplePoints(const std::vector<TowSurface>& tows, const std::vector<IntersectionLoop>& loops,
                              std::vector<SharedLoop>& shared, std::vector<Point3>& nodes)
{
    TripleJoiner joiner(tows, loops, shared, nodes);
    // Every triple point, found where the exact curves cross on any of its three tows (a crossing
    // the node polygons miss on one tow, two close crossings in one chord, shows on another).
    std::vector<FoundTriple> found;
    for (std::size_t t = 0; t < tows.size(); ++t) {
        const std::vector<std::size_t> on = loopsOn(loops, shared, t);
        for (std::size_t a = 0; a < on.size(); ++a)
            for (std::size_t b = a + 1; b < on.size(); ++b)
                if (!samePair(loops[shared[on[a]].loop], loops[shared[on[b]].loop]) && !acrossCap(loops[shared[on[a]].loop]) &&
                    !acrossCap(loops[shared[on[b]].loop]))  // triple points on caps are not looked for
                    joiner.find(t, on[a], on[b], found);
    }
    TripleJoin out;
    std::set<std::size_t> tripleNodes;
    for (const FoundTriple& x : found)
        if (joiner.insert(x)) {
            tripleNodes.insert(nodes.size() - 1);
            std::array<std::size_t, 3> three = x.tows;
            std::sort(three.begin(), three.end());
            out.points.push_back({nodes.size() - 1, three});
        }
    // Two triple nodes next to each other on a loop get the curve's point between them: between
    // two close triple points the loops of the three pairs are three different arcs, which a
    // single chord each would make one edge (a region of no area).
    for (SharedLoop& s : shared)
        for (std::size_t q = 0; q < s.nodes.size(); ++q) {
            const std::size_t a = s.nodes[q], b = s.nodes[(q + 1) % s.nodes.size()];
            if (tripleNodes.count(a) && tripleNodes.count(b) && splitChord(loops[s.loop], s, a, b, 0.5, nodes)) ++q;
        }
    // The node polygons that still cross (a triple point not found or not inserted).
    for (std::size_t t = 0; t < tows.size(); ++t) {
        const std::vector<std::size_t> on = loopsOn(loops, shared, t);
        const double period = tows[t].parameterRange().vPeriod();
        for (std::size_t a = 0; a < on.size(); ++a)
            for (std::size_t b = a + 1; b < on.size(); ++b) {
                const std::size_t i = on[a], j = on[b];
                const IntersectionLoop& li = loops[shared[i].loop];
                const IntersectionLoop& lj = loops[shared[j].loop];
                if (samePair(li, lj)) continue;
                if (!loopCrossings(loopPolygon(shared[i], sideOf(li, t)), shared[i].nodes, loopPolygon(shared[j], sideOf(lj, t)),
                                   shared[j].nodes, period)
                         .empty())
                    out.crossing.push_back({t, i, j});
            }
    }
    return out;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
