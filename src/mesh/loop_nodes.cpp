#include "mesh/loop_nodes.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

#include "intersect/intersection_loop_data.hpp"
#include "intersect/intersection_point.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

constexpr double kSeamSnap = 1e-9;  // of the period

UV sideOf(const LoopPoint& p, LoopSide side) { return side == LoopSide::A ? p.onA : p.onB; }

double periodOf(const IntersectionLoop& loop, LoopSide side)
{
    return (side == LoopSide::A ? loop.surfaceA() : loop.surfaceB()).parameterRange().vPeriod();
}

double vMinOf(const IntersectionLoop& loop, LoopSide side)
{
    return (side == LoopSide::A ? loop.surfaceA() : loop.surfaceB()).parameterRange().vMin;
}

UV& sideRef(LoopPoint& p, LoopSide side) { return side == LoopSide::A ? p.onA : p.onB; }

ParameterRange rangeOf(const IntersectionLoop& loop, LoopSide side)
{
    return (side == LoopSide::A ? loop.surfaceA() : loop.surfaceB()).parameterRange();
}

/// Where u lies on tow @p side: -1 on its first cap, +1 on its last, 0 on the tube (its rims
/// included, within 1e-9 of the u range).
int capOf(const IntersectionLoop& loop, LoopSide side, double u)
{
    const ParameterRange r = rangeOf(loop, side);
    const double eps = 1e-9 * (r.uMax - r.uMin);
    return u < r.uMin - eps ? -1 : u > r.uMax + eps ? 1 : 0;
}

/// The point at fraction @p t of the chord [p, q], in 3D and on both tows (v unwrapped).
PointOn2 onChord(const LoopPoint& p, const LoopPoint& q, double t)
{
    const auto lerp = [t](double a, double b) { return a + t * (b - a); };
    return {lerp(p.onA.u, q.onA.u), lerp(p.onA.v, q.onA.v), lerp(p.onB.u, q.onB.u), lerp(p.onB.v, q.onB.v),
            {lerp(p.point.x, q.point.x), lerp(p.point.y, q.point.y), lerp(p.point.z, q.point.z)}, 0.0};
}

/// Whether @p x lies along the chord from @p p to @p q as the curve between them does: its
/// foot on the chord's line within the chord (not beyond an end, where the next chord's crossing
/// may lie), and it no farther from the line than a quarter of the chord's length (loop chords
/// bend far less, kMaxChordBend).
bool alongChord(const LoopPoint& p, const LoopPoint& q, const Point3& x)
{
    const Vector3 d = q.point - p.point;
    const double length2 = dot(d, d);
    if (!(length2 > 0.0)) return distance(x, p.point) == 0.0;
    const double t = dot(x - p.point, d) / length2;
    return t >= 0.0 && t <= 1.0 && distance(x, p.point + t * d) <= 0.25 * std::sqrt(length2);
}

/// How far along the chord from @p p to @p q the foot of @p x lies: 0 at p, 1 at q (beyond
/// them outside [0, 1]).
double fractionAlong(const LoopPoint& p, const LoopPoint& q, const Point3& x)
{
    const Vector3 d = q.point - p.point;
    const double length2 = dot(d, d);
    return length2 > 0.0 ? dot(x - p.point, d) / length2 : 0.0;
}

/// The curve's point between @p p and @p q where tow @p side's v crosses @p seam, by bisection
/// on the chord: the curve's point in the plane normal to the chord at a fraction of it (Newton
/// from the chord's point), its v against the seam's. For a curve nearly tangent to the seam,
/// where Newton on v = seam may find another crossing. False when a point is not found.
bool bisectSeam(const SurfacePair& sp, const LoopPoint& p, const LoopPoint& q, LoopSide side, double seam, double period,
                double tolerance, PointOn2& x)
{
    const double v0 = sideOf(p, side).v;
    double lo = 0.0, hi = 1.0;
    for (int step = 0; step < 60 && hi - lo > 1e-15; ++step) {
        const double t = 0.5 * (lo + hi);
        PointOn2 y = onChord(p, q, t);
        capGuess(sp, onChord(p, q, 0.0), onChord(p, q, 1.0), y);
        const double vGuess = side == LoopSide::A ? y.va : y.vb;
        PointCondition c;
        c.origin = y.point;
        c.normal = q.point - p.point;
        if (!refineOnIntersection(sp, y, c, tolerance)) return false;
        double& v = side == LoopSide::A ? y.va : y.vb;
        if (period > 0.0) v += period * std::round((vGuess - v) / period);
        x = y;
        ((v < seam) == (v0 < seam) ? lo : hi) = t;
    }
    return true;
}

/// The exact loop point between @p p and @p q where tow @p side's v equals @p seam (@p period:
/// the tow's v period).
LoopPoint seamPoint(const SurfacePair& sp, const LoopPoint& p, const LoopPoint& q, LoopSide side, double seam, double period,
                    double tolerance)
{
    const double v0 = sideOf(p, side).v, v1 = sideOf(q, side).v;
    PointOn2 x = onChord(p, q, (seam - v0) / (v1 - v0));
    capGuess(sp, onChord(p, q, 0.0), onChord(p, q, 1.0), x);
    PointCondition c;
    c.kind = side == LoopSide::A ? PointCondition::Kind::FixVA : PointCondition::Kind::FixVB;
    c.value = seam;
    const PointOn2 guess = x;
    // On failure the interpolated point stays. Newton may also land on another crossing of the
    // seam (a curve nearly tangent to it crosses it several times close together): then the
    // crossing is bracketed on this chord first.
    if (refineOnIntersection(sp, x, c, tolerance) && !alongChord(p, q, x.point)) {
        x = guess;
        PointOn2 near = guess;
        if (bisectSeam(sp, p, q, side, seam, period, tolerance, near)) {
            x = near;
            if (!refineOnIntersection(sp, x, c, tolerance) || !alongChord(p, q, x.point)) x = near;
        }
    }
    LoopPoint r{x.point, {x.ua, x.va}, {x.ub, x.vb}};
    (side == LoopSide::A ? r.onA : r.onB).v = seam;  // exactly, so the mesher sees it on the seam
    return r;
}

/// The largest distance of the curve's mid-arc point from its chord, relative to the chord's
/// length, that a loop chord may have: about 16 chords per turn of the curve. A coarser chord
/// leaves the region polygon so far inside the curve that the secondary's triangles between
/// them still pass through the primary.
constexpr double kMaxChordBend = 0.05;

/// The loop at @p spacing, each chord halved (in arc length) until the curve's mid-arc point lies
/// within kMaxChordBend of the chord: loop nodes follow the curve's turns at any spacing.
std::vector<LoopPoint> nodesAlong(const IntersectionLoop& loop, double spacing)
{
    std::vector<LoopPoint> out;
    constexpr int kMaxDepth = 8;
    // The exact point at arc-length fraction s; s beyond 1 (past the first point of a closed
    // loop) one turn on in v.
    const auto pointAt = [&](double s) {
        if (s <= 1.0) return loop.at(s);
        LoopPoint p = loop.at(s - 1.0);
        const LoopPoint first = loop.at(0.0), last = loop.at(1.0);
        p.onA.v += last.onA.v - first.onA.v;
        p.onB.v += last.onB.v - first.onB.v;
        return p;
    };
    const IntersectionLoop::Data& d = loop.data();
    const double total = d.cumulative.empty() ? 0.0 : d.cumulative.back();
    // Whether the curve between arc-length fractions s0 and s1 (nodes p and q) leaves the period
    // cell of a tow's v that both ends lie in: it dips across the seam and back between two
    // nodes (a loop nearly tangent to the seam), where no chord end shows the two crossings.
    const auto dipsAcrossSeam = [&](const LoopPoint& p, const LoopPoint& q, double s0, double s1) {
        if (!(total > 0.0)) return false;
        for (const LoopSide side : {LoopSide::A, LoopSide::B}) {
            const double period = periodOf(loop, side), vMin = vMinOf(loop, side);
            const auto cell = [&](double v) { return std::floor((v - vMin) / period); };
            const double c = cell(sideOf(p, side).v);
            if (cell(sideOf(q, side).v) != c) continue;  // it crosses: a node there (shareLoopNodes)
            // Beyond the cell by more than rounding (a curve along the seam within rounding of it,
            // or an end on it, stays).
            const auto outside = [&](double v) {
                const double r = (v - vMin) / period - c;
                return r < -kSeamSnap || r > 1.0 + kSeamSnap;
            };
            // A turn of the loop, in whole periods (its last point is not its first again).
            const double turn = period * std::round((sideOf(d.points.back(), side).v - sideOf(d.points.front(), side).v) / period);
            // The curve's points strictly between the two fractions (s past 1: one turn on).
            for (int wrap = 0; wrap < 2; ++wrap) {
                const auto from = std::upper_bound(d.cumulative.begin(), d.cumulative.end(), (s0 - wrap) * total);
                for (auto it = from; it != d.cumulative.end() && *it < (s1 - wrap) * total; ++it) {
                    const std::size_t k = static_cast<std::size_t>(it - d.cumulative.begin());
                    if (k < d.points.size() && outside(sideOf(d.points[k], side).v + wrap * turn)) return true;
                }
            }
        }
        return false;
    };
    const auto refine = [&](auto&& self, const LoopPoint& p, const LoopPoint& q, double s0, double s1, int depth) -> void {
        const LoopPoint mid = pointAt(0.5 * (s0 + s1));
        const Point3 chordMid = 0.5 * (p.point + q.point);
        if (depth < kMaxDepth &&
            (distance(mid.point, chordMid) > kMaxChordBend * distance(p.point, q.point) || dipsAcrossSeam(p, q, s0, s1))) {
            self(self, p, mid, s0, 0.5 * (s0 + s1), depth + 1);
            out.push_back(mid);
            self(self, mid, q, 0.5 * (s0 + s1), s1, depth + 1);
        }
    };
    // Where the loop crosses a tow's rim it turns a corner (from the tube onto the cap): those
    // points are nodes, and the loop is resampled between them, so no chord spans a corner.
    std::vector<double> corners;
    if (loop.closed() && (loop.crossesCap(LoopSide::A) || loop.crossesCap(LoopSide::B)) && d.cumulative.back() > 0.0)
        for (std::size_t k = 0; k < d.points.size(); ++k)
            for (const LoopSide side : {LoopSide::A, LoopSide::B}) {
                const double u = sideOf(d.points[k], side).u;
                const int here = capOf(loop, side, u);
                const int before = capOf(loop, side, sideOf(d.points[(k + d.points.size() - 1) % d.points.size()], side).u);
                const int after = capOf(loop, side, sideOf(d.points[(k + 1) % d.points.size()], side).u);
                if (here == 0 && (before != 0) != (after != 0)) {
                    corners.push_back(d.cumulative[k] / d.cumulative.back());
                    break;
                }
            }
    if (corners.empty()) {
        const std::vector<LoopPoint> even = loop.resample(spacing);
        const std::size_t n = loop.closed() ? even.size() : even.size() - 1;  // chords
        for (std::size_t k = 0; k < n; ++k) {
            out.push_back(even[k]);
            const double s0 = static_cast<double>(k) / static_cast<double>(n), s1 = static_cast<double>(k + 1) / static_cast<double>(n);
            // The closing chord's end is the first point one turn on (loop.at(1)).
            refine(refine, even[k], k + 1 < even.size() ? even[k + 1] : loop.at(1.0), s0, s1, 0);
        }
        if (!loop.closed()) out.push_back(even.back());
        return out;
    }
    // Each piece between two corners (the last one ending at the first corner one turn on):
    // evenly at the spacing in arc length, at least one chord; s beyond 1 wraps around.
    const double length = loop.length();
    for (std::size_t c = 0; c < corners.size(); ++c) {
        const double s0 = corners[c], s1 = c + 1 < corners.size() ? corners[c + 1] : corners[0] + 1.0;
        const std::size_t m = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil((s1 - s0) * length / spacing)));
        LoopPoint p = pointAt(s0);
        for (std::size_t k = 0; k < m; ++k) {
            const double a = s0 + (s1 - s0) * static_cast<double>(k) / static_cast<double>(m);
            const double b = s0 + (s1 - s0) * static_cast<double>(k + 1) / static_cast<double>(m);
            const LoopPoint q = pointAt(b);
            out.push_back(p);
            refine(refine, p, q, a, b, 0);
            p = q;
        }
    }
    // v continuous from the first node on (the pieces past the wrap are one turn on already).
    return out;
}

}  // namespace

std::pair<LoopPoint, LoopPoint> chordEnds(const IntersectionLoop& loop, const SharedLoop& shared, std::size_t chord)
{
    const std::size_t n = shared.points.size();
    const LoopPoint& p = shared.points[chord];
    LoopPoint q = shared.points[(chord + 1) % n];
    if (chord + 1 == n) {  // the closing chord
        q.onA.v += periodOf(loop, LoopSide::A) * std::round((p.onA.v - q.onA.v) / periodOf(loop, LoopSide::A));
        q.onB.v += periodOf(loop, LoopSide::B) * std::round((p.onB.v - q.onB.v) / periodOf(loop, LoopSide::B));
    }
    return {p, q};
}

LoopPoint chordPoint(const IntersectionLoop& loop, const SharedLoop& shared, std::size_t chord, double t)
{
    const auto [p, q] = chordEnds(loop, shared, chord);
    const PointOn2 x = onChord(p, q, t);
    return {x.point, {x.ua, x.va}, {x.ub, x.vb}};
}

bool onSeam(const IntersectionLoop& loop, const LoopPoint& p, double within)
{
    for (const LoopSide side : {LoopSide::A, LoopSide::B}) {
        const double r = (sideOf(p, side).v - vMinOf(loop, side)) / periodOf(loop, side);
        if (std::abs(r - std::round(r)) < within) return true;
    }
    return false;
}

SharedLoop shareLoopNodes(const IntersectionLoop& loop, std::size_t loopIndex, double spacing,
                          std::vector<Point3>& globalNodes)
{
    const std::vector<LoopPoint> base = nodesAlong(loop, spacing);
    const SurfacePair sp = closedPairOf(loop.surfaceA(), loop.surfaceB());
    SharedLoop shared;
    shared.loop = loopIndex;
    const std::size_t n = base.size();
    // Seam crossings of either tow on each chord. One close to a chord end replaces that end (a
    // node a hair's breadth from another would be a tiny feature the mesher refines forever);
    // the others are inserted.
    std::vector<LoopPoint> points = base;
    std::vector<char> snapped(n, 0);
    // A node on a tow's rim is a corner of the loop (from the tube onto a cap): it stays, a seam
    // crossing next to it is a node of its own.
    const auto atRimOfEither = [&](const LoopPoint& p) {
        for (const LoopSide side : {LoopSide::A, LoopSide::B}) {
            const ParameterRange r = rangeOf(loop, side);
            const double eps = 1e-9 * (r.uMax - r.uMin);
            const double u = sideOf(p, side).u;
            if (std::abs(u - r.uMin) <= eps || std::abs(u - r.uMax) <= eps) return true;
        }
        return false;
    };
    std::vector<std::vector<LoopPoint>> inserted(n);
    for (std::size_t k = 0; k < n; ++k) {
        const LoopPoint& p = base[k];
        LoopPoint q = base[(k + 1) % n];
        if (k + 1 == n) {  // the closing chord: the first point one turn on, if the loop winds
            q.onA.v += periodOf(loop, LoopSide::A) * std::round((p.onA.v - q.onA.v) / periodOf(loop, LoopSide::A));
            q.onB.v += periodOf(loop, LoopSide::B) * std::round((p.onB.v - q.onB.v) / periodOf(loop, LoopSide::B));
        }
        struct Crossing {
            double t;
            LoopPoint point;
            LoopSide side;  // the tow whose seam it is on (exactly)
        };
        std::vector<Crossing> found;
        for (const LoopSide side : {LoopSide::A, LoopSide::B}) {
            const double period = periodOf(loop, side), vMin = vMinOf(loop, side);
            const double v0 = sideOf(p, side).v, v1 = sideOf(q, side).v;
            const double lo = std::min(v0, v1), hi = std::max(v0, v1);
            for (double seam = vMin + period * std::ceil((lo - vMin) / period); seam < hi; seam += period) {
                if (seam <= lo) continue;
                found.push_back({(seam - v0) / (v1 - v0), seamPoint(sp, p, q, side, seam, period, loop.tolerance()), side});
            }
        }
        // Where the chord crosses a tow's rim (one end on its cap, the other on its tube): the
        // exact point on the rim, u exactly the tube's end there.
        for (const LoopSide side : {LoopSide::A, LoopSide::B}) {
            const double u0 = sideOf(p, side).u, u1 = sideOf(q, side).u;
            const int c0 = capOf(loop, side, u0), c1 = capOf(loop, side, u1);
            if (c0 == c1) continue;
            const ParameterRange r = rangeOf(loop, side);
            const double rim = (c0 != 0 ? c0 : c1) < 0 ? r.uMin : r.uMax;
            const double t = std::clamp((rim - u0) / (u1 - u0), 0.0, 1.0);
            PointOn2 x = onChord(p, q, t);
            (side == LoopSide::A ? x.ua : x.ub) = rim;
            PointCondition c;
            c.kind = side == LoopSide::A ? PointCondition::Kind::FixUA : PointCondition::Kind::FixUB;
            c.value = rim;
            refineOnIntersection(sp, x, c, loop.tolerance());  // on failure the interpolated point stays
            LoopPoint at{x.point, {x.ua, x.va}, {x.ub, x.vb}};
            sideRef(at, side).u = rim;
            found.push_back({t, at, side});
        }
        // In their order along the curve, by where each exact point lies along the chord (not by
        // the linear guess of each tow's v or u, which is far off where the curve is nearly
        // tangent to a seam: two crossings close together would swap).
        for (Crossing& c : found) c.t = fractionAlong(p, q, c.point.point);
        std::sort(found.begin(), found.end(), [](const Crossing& a, const Crossing& b) { return a.t < b.t; });
        // Both tows' seams crossed at one point (a loop through where the seams meet): one node,
        // exactly on both seams.
        const double same = 10.0 * loop.tolerance();
        std::vector<std::pair<double, LoopPoint>> crossings;
        for (std::size_t i = 0; i < found.size(); ++i) {
            LoopPoint c = found[i].point;
            while (i + 1 < found.size() && found[i + 1].side != found[i].side && distance(found[i + 1].point.point, c.point) <= same) {
                const LoopSide other = found[i + 1].side;
                (other == LoopSide::A ? c.onA : c.onB).v = sideOf(found[i + 1].point, other).v;
                ++i;
            }
            crossings.emplace_back(found[i].t, c);
        }
        constexpr double kSnap = 0.25;
        // A crossing at a node already put on the other tow's seam: that node, on both seams.
        const auto onBoth = [&](const LoopPoint& c, std::size_t end, bool closing) {
            if (!snapped[end] || distance(c.point, points[end].point) > same) return false;
            for (const LoopSide side : {LoopSide::A, LoopSide::B}) {
                const double period = periodOf(loop, side);
                const double r = (sideOf(c, side).v - vMinOf(loop, side)) / period;
                if (std::abs(r - std::round(r)) > kSeamSnap) continue;  // not on this seam
                double v = sideOf(c, side).v;
                if (closing) v -= side == LoopSide::A ? q.onA.v - base[0].onA.v : q.onB.v - base[0].onB.v;
                (side == LoopSide::A ? points[end].onA : points[end].onB).v = v;
            }
            return true;
        };
        for (std::size_t i = 0; i < crossings.size(); ++i) {
            const auto& [t, c] = crossings[i];
            // A crossing at a rim node (a corner on the seam): that node, put on the seam.
            for (const std::size_t end : {k, (k + 1) % n})
                if (atRimOfEither(base[end]) && distance(c.point, base[end].point) <= same) snapped[end] = 1;
            if (onBoth(c, k, false) || onBoth(c, (k + 1) % n, k + 1 == n)) continue;
            // Only the chord's first crossing may replace its first node, and only its last the
            // next node: the others are inserted between them, in order.
            if (t < kSnap && i == 0 && !snapped[k] && !atRimOfEither(base[k])) {
                points[k] = c;
                snapped[k] = 1;
            } else if (t > 1.0 - kSnap && i + 1 == crossings.size() && !snapped[(k + 1) % n] && !atRimOfEither(base[(k + 1) % n])) {
                LoopPoint r = c;  // back to the first point's own turn on the closing chord
                if (k + 1 == n) {
                    r.onA.v -= q.onA.v - base[0].onA.v;
                    r.onB.v -= q.onB.v - base[0].onB.v;
                }
                points[(k + 1) % n] = r;
                snapped[(k + 1) % n] = 1;
            } else {
                inserted[k].push_back(c);
            }
        }
    }
    for (std::size_t k = 0; k < n; ++k) {
        shared.points.push_back(points[k]);
        shared.points.insert(shared.points.end(), inserted[k].begin(), inserted[k].end());
    }
    // Nodes within rounding of a rim are on it; two rim nodes in a row get the curve's point
    // between them, so that every piece between rims (on the tube or on a cap) has a node of
    // its own that says which it is.
    for (const LoopSide side : {LoopSide::A, LoopSide::B}) {
        const ParameterRange r = rangeOf(loop, side);
        const double eps = 1e-9 * (r.uMax - r.uMin);
        for (LoopPoint& q : shared.points) {
            UV& uv = sideRef(q, side);
            if (std::abs(uv.u - r.uMin) <= eps) uv.u = r.uMin;
            if (std::abs(uv.u - r.uMax) <= eps) uv.u = r.uMax;
        }
        const auto atRim = [&](const LoopPoint& q) { return sideOf(q, side).u == r.uMin || sideOf(q, side).u == r.uMax; };
        for (std::size_t k = 0; k < shared.points.size() && shared.points.size() > 1; ++k) {
            const std::size_t m = shared.points.size();
            LoopPoint a = shared.points[k], b = shared.points[(k + 1) % m];
            if (!atRim(a) || !atRim(b) || sideOf(a, side).u != sideOf(b, side).u) continue;
            if (k + 1 == m) {
                b.onA.v += periodOf(loop, LoopSide::A) * std::round((a.onA.v - b.onA.v) / periodOf(loop, LoopSide::A));
                b.onB.v += periodOf(loop, LoopSide::B) * std::round((a.onB.v - b.onB.v) / periodOf(loop, LoopSide::B));
            }
            PointOn2 x = onChord(a, b, 0.5);
            capGuess(sp, onChord(a, b, 0.0), onChord(a, b, 1.0), x);
            if (!refineNearest(sp, x, loop.tolerance()))
                throw Error(ErrorCode::Internal, "the curve between two nodes on a tow's rim could not be found (a loop grazing the rim)",
                            "tows '" + loop.surfaceA().name() + "' and '" + loop.surfaceB().name() + "'");
            shared.points.insert(shared.points.begin() + static_cast<std::ptrdiff_t>(k) + 1, LoopPoint{x.point, {x.ua, x.va}, {x.ub, x.vb}});
            ++k;
        }
    }
    // A first point that lies exactly on a seam is a seam node as it is.
    for (const LoopPoint& p : shared.points) {
        shared.nodes.push_back(globalNodes.size());
        globalNodes.push_back(p.point);
    }
    return shared;
}

bool splitChord(const IntersectionLoop& loop, SharedLoop& shared, std::size_t a, std::size_t b, double t,
                std::vector<Point3>& globalNodes)
{
    const std::size_t n = shared.nodes.size();
    std::size_t i = n;
    for (std::size_t k = 0; k < n && i == n; ++k) {
        if (shared.nodes[k] == a && shared.nodes[(k + 1) % n] == b) i = k;
        if (shared.nodes[k] == b && shared.nodes[(k + 1) % n] == a) {
            i = k;
            t = 1.0 - t;
        }
    }
    if (i == n) return false;
    const auto ends = chordEnds(loop, shared, i);
    const LoopPoint &p = ends.first, &q = ends.second;  // (named: lambdas below use them)
    const SurfacePair sp = closedPairOf(loop.surfaceA(), loop.surfaceB());
    // The exact loop point where the curve crosses the plane normal to the chord at fraction f.
    const auto pointAt = [&](double f) {
        PointOn2 x = onChord(p, q, f);
        capGuess(sp, onChord(p, q, 0.0), onChord(p, q, 1.0), x);
        PointCondition c;
        c.kind = PointCondition::Kind::Plane;
        c.origin = x.point;
        c.normal = q.point - p.point;
        refineOnIntersection(sp, x, c, loop.tolerance());
        return LoopPoint{x.point, {x.ua, x.va}, {x.ub, x.vb}};
    };
    // The new node must lie in the chord's period cell on both tows: the chord does not cross a
    // seam (seam crossings are nodes), but the curve may dip across one between two nodes (a loop
    // nearly tangent to a seam); such a node would fall outside the tow's rectangle.
    const auto cellOf = [&](LoopSide side) {
        const double period = periodOf(loop, side), vMin = vMinOf(loop, side);
        return vMin + period * std::floor((0.5 * (sideOf(p, side).v + sideOf(q, side).v) - vMin) / period);
    };
    const auto onSeamOf = [&](const LoopPoint& e, LoopSide side) {  // (within rounding, as constraintsOn())
        const double period = periodOf(loop, side), r = (sideOf(e, side).v - cellOf(side)) / period;
        return std::abs(r) <= kSeamSnap || std::abs(r - 1.0) <= kSeamSnap;
    };
    const auto inCells = [&](const LoopPoint& at) {
        for (const LoopSide side : {LoopSide::A, LoopSide::B}) {
            const double cell = cellOf(side), v = sideOf(at, side).v;
            if (v < cell || v > cell + periodOf(loop, side)) return false;
        }
        return true;
    };
    LoopPoint m = pointAt(t);
    // The curve may dip across a seam between the two nodes (nearly tangent to it, crossing it
    // twice where the nodes saw no crossing): the new node is then where it crosses between the
    // middle and an end off the seam (p's side first), on the seam, as the nodes' own crossings
    // are. A chord with both ends on the seam stays, and so does one whose crossing lies a hair
    // from an end (it would be that end's point in the mesher's plane).
    for (const LoopSide side : {LoopSide::A, LoopSide::B}) {
        const double cell = cellOf(side), period = periodOf(loop, side), v = sideOf(m, side).v;
        if (v >= cell && v <= cell + period) continue;
        const double seam = v < cell ? cell : cell + period;
        if (!onSeamOf(p, side))
            m = seamPoint(sp, p, m, side, seam, period, loop.tolerance());
        else if (!onSeamOf(q, side))
            m = seamPoint(sp, m, q, side, seam, period, loop.tolerance());
        const double hair = 1e-6 * distance(p.point, q.point);
        if (distance(m.point, p.point) <= hair || distance(m.point, q.point) <= hair) return false;
        break;
    }
    if (!inCells(m)) return false;
    // Nor may it lie across a tow's rim from the chord (a loop grazing the rim dips onto the cap
    // and back between two nodes on the tube): a piece of the loop on the tube would get a node
    // on the cap. The part of the tow the chord is on is that of an end not on the rim.
    for (const LoopSide side : {LoopSide::A, LoopSide::B}) {
        const ParameterRange r = rangeOf(loop, side);
        const auto onRim = [&](double u) { return u == r.uMin || u == r.uMax; };
        const double u0 = sideOf(p, side).u, u1 = sideOf(q, side).u, um = sideOf(m, side).u;
        if (!onRim(u0) && capOf(loop, side, um) != capOf(loop, side, u0)) return false;
        if (!onRim(u1) && capOf(loop, side, um) != capOf(loop, side, u1)) return false;
    }
    shared.points.insert(shared.points.begin() + static_cast<std::ptrdiff_t>(i) + 1, m);
    shared.nodes.insert(shared.nodes.begin() + static_cast<std::ptrdiff_t>(i) + 1, globalNodes.size());
    globalNodes.push_back(m.point);
    return true;
}

bool joinTouchingLoops(SharedLoop& a, const IntersectionLoop& la, SharedLoop& b, const IntersectionLoop& lb, double within,
                       std::vector<Point3>& globalNodes)
{
    // The closest pair of exact points of the two curves.
    const std::vector<LoopPoint>& pa = la.points();
    const std::vector<LoopPoint>& pb = lb.points();
    double best = within;
    std::size_t ia = pa.size();
    for (std::size_t i = 0; i < pa.size(); ++i)
        for (const LoopPoint& q : pb) {
            const double d = distance(pa[i].point, q.point);
            if (d < best) {
                best = d;
                ia = i;
            }
        }
    if (ia == pa.size()) return false;
    const LoopPoint touch = pa[ia];
    // Each loop's node nearest to the touching point; not a seam node (those are the seam's too).
    const auto nearest = [&](const SharedLoop& s, const IntersectionLoop& l) {
        std::size_t k = s.points.size();
        double d = 1e300;
        for (std::size_t i = 0; i < s.points.size(); ++i) {
            const double di = distance(s.points[i].point, touch.point);
            if (di < d) {
                d = di;
                k = i;
            }
        }
        return onSeam(l, s.points[k], kSeamSnap) ? s.points.size() : k;
    };
    const std::size_t ka = nearest(a, la), kb = nearest(b, lb);
    if (ka == a.points.size() || kb == b.points.size()) return false;
    // The same point in each loop's own unwrapping of v.
    const auto placed = [&](const LoopPoint& old, const IntersectionLoop& l) {
        LoopPoint p = touch;
        p.onA.v += periodOf(l, LoopSide::A) * std::round((old.onA.v - p.onA.v) / periodOf(l, LoopSide::A));
        p.onB.v += periodOf(l, LoopSide::B) * std::round((old.onB.v - p.onB.v) / periodOf(l, LoopSide::B));
        return p;
    };
    a.points[ka] = placed(a.points[ka], la);
    b.points[kb] = placed(b.points[kb], lb);
    globalNodes[a.nodes[ka]] = touch.point;
    b.nodes[kb] = a.nodes[ka];
    return true;
}

std::vector<UV> loopPolygon(const SharedLoop& shared, LoopSide side)
{
    std::vector<UV> uv;
    uv.reserve(shared.points.size());
    for (const LoopPoint& p : shared.points) uv.push_back(sideOf(p, side));
    return uv;
}

namespace {

/// Shifts each piece into the tow's rectangle by the period cell of its first chord's midpoint.
void shiftIntoRectangle(std::vector<LoopConstraint>& pieces, double vMin, double period, const std::string& towName)
{
    for (LoopConstraint& c : pieces) {
        if (c.uv.size() < 2) continue;
        const double mid = 0.5 * (c.uv[0].v + c.uv[1].v);
        const double shift = period * std::floor((mid - vMin) / period);
        for (UV& q : c.uv) {
            q.v -= shift;
            // Beyond the rectangle by more than rounding: a chord crossing the seam with no node
            // there (shareLoopNodes() missed a crossing), which no mesh can follow. Clamping it
            // would fold the tow's mesh inside the loop.
            if (q.v < vMin - kSeamSnap * period || q.v > vMin + (1.0 + kSeamSnap) * period)
                throw Error(ErrorCode::Internal, "an intersection loop crosses the seam of the tow's surface where no node of it lies",
                            "tow '" + towName + "'");
            q.v = std::clamp(q.v, vMin, vMin + period);
        }
    }
    pieces.erase(std::remove_if(pieces.begin(), pieces.end(), [](const LoopConstraint& c) { return c.uv.size() < 2; }),
                 pieces.end());
}

/// The loop on tow @p side walked once from node @p start, cut at every node @p cut says; v
/// continuous across the closing chord (one period on for a loop that winds around the tow).
std::vector<LoopConstraint> cutAt(const std::vector<UV>& uv, const std::vector<std::size_t>& nodes, std::size_t start, double period,
                                  const std::function<bool(const UV&)>& cut)
{
    const std::size_t n = uv.size();
    const double offset = period * std::round((uv[n - 1].v - uv[0].v) / period);
    std::vector<LoopConstraint> pieces;
    LoopConstraint current;
    for (std::size_t step = 0; step <= n; ++step) {
        const std::size_t k = (start + step) % n;
        UV p = uv[k];
        if (start + step >= n) p.v += offset;  // past the closing chord
        current.uv.push_back(p);
        current.nodes.push_back(nodes[k]);
        if (step > 0 && cut(uv[k])) {
            pieces.push_back(std::move(current));
            current = LoopConstraint{};
            current.uv.push_back(p);
            current.nodes.push_back(nodes[k]);
        }
    }
    return pieces;
}

}  // namespace

std::vector<LoopConstraint> constraintsOn(const SharedLoop& shared, const IntersectionLoop& loop, LoopSide side)
{
    const double period = periodOf(loop, side), vMin = vMinOf(loop, side);
    const auto ofThisLoop = [&](std::vector<LoopConstraint> pieces) {
        for (LoopConstraint& piece : pieces) piece.loop = static_cast<long>(shared.loop);
        return pieces;
    };
    std::vector<UV> uv = loopPolygon(shared, side);
    const std::size_t n = uv.size();
    // A node a hair's breadth from the seam (a loop touching it) is put on it: it would otherwise
    // make a sliver with the seam's edge. On the seam it is a node of both sides.
    for (UV& p : uv) {
        const double r = (p.v - vMin) / period;
        if (std::abs(r - std::round(r)) < kSeamSnap) p.v = vMin + period * std::round(r);
    }
    const auto onSeam = [&](double v) {
        const double r = (v - vMin) / period;
        return r == std::round(r);
    };
    const ParameterRange range = rangeOf(loop, side);
    const auto atRim = [&](const UV& p) { return p.u == range.uMin || p.u == range.uMax; };
    // A loop across a cap: only its pieces on the tube, from rim (or seam) to rim (or seam).
    if (loop.crossesCap(side)) {
        std::size_t start = n;
        for (std::size_t k = 0; k < n && start == n; ++k)
            if (atRim(uv[k])) start = k;
        if (start == n) return {};  // wholly on a cap
        std::vector<LoopConstraint> pieces =
            cutAt(uv, shared.nodes, start, period, [&](const UV& p) { return atRim(p) || onSeam(p.v); });
        pieces.erase(std::remove_if(pieces.begin(), pieces.end(),
                                    [&](const LoopConstraint& c) {
                                        return std::any_of(c.uv.begin(), c.uv.end(), [&](const UV& p) { return capOf(loop, side, p.u) != 0; });
                                    }),
                     pieces.end());
        shiftIntoRectangle(pieces, vMin, period, (side == LoopSide::A ? loop.surfaceA() : loop.surfaceB()).name());
        return ofThisLoop(std::move(pieces));
    }
    // Start at a seam node if there is one, so every piece runs from seam to seam.
    std::size_t start = n;
    for (std::size_t k = 0; k < n && start == n; ++k)
        if (onSeam(uv[k].v)) start = k;
    if (start == n) {  // no seam crossing: one closed constraint, shifted into the rectangle
        LoopConstraint c;
        c.closed = true;
        double shift = period * std::floor((uv[0].v - vMin) / period);
        for (std::size_t k = 0; k < n; ++k) {
            c.uv.push_back({uv[k].u, uv[k].v - shift});
            c.nodes.push_back(shared.nodes[k]);
        }
        return ofThisLoop({c});
    }
    // The loop walked once from that seam node back to it, cut at every seam node.
    std::vector<LoopConstraint> pieces = cutAt(uv, shared.nodes, start, period, [&](const UV& p) { return onSeam(p.v); });
    shiftIntoRectangle(pieces, vMin, period, (side == LoopSide::A ? loop.surfaceA() : loop.surfaceB()).name());
    return ofThisLoop(std::move(pieces));
}

std::vector<CapConstraint> capConstraintsOn(const SharedLoop& shared, const IntersectionLoop& loop, LoopSide side)
{
    if (!loop.crossesCap(side)) return {};
    const std::vector<UV> uv = loopPolygon(shared, side);
    const std::size_t n = uv.size();
    const ParameterRange range = rangeOf(loop, side);
    const auto atRim = [&](const UV& p) { return p.u == range.uMin || p.u == range.uMax; };
    std::size_t start = n;
    for (std::size_t k = 0; k < n && start == n; ++k)
        if (atRim(uv[k])) start = k;
    if (start == n) return {{capOf(loop, side, uv[0].u), shared.nodes, true}};  // wholly on a cap
    std::vector<CapConstraint> out;
    for (const LoopConstraint& c : cutAt(uv, shared.nodes, start, periodOf(loop, side), atRim)) {
        int end = 0;
        for (const UV& p : c.uv)
            if (capOf(loop, side, p.u) != 0) end = capOf(loop, side, p.u);
        if (end != 0) out.push_back({end, c.nodes, false});
    }
    return out;
}

std::vector<std::vector<CapConstraint>> capConstraintsOfTows(const std::vector<SharedLoop>& shared, const std::vector<IntersectionLoop>& loops,
                                                             std::size_t towCount)
{
    std::vector<std::vector<CapConstraint>> out(towCount);
    for (const SharedLoop& s : shared) {
        const IntersectionLoop& l = loops[s.loop];
        for (const LoopSide side : {LoopSide::A, LoopSide::B})
            for (CapConstraint& c : capConstraintsOn(s, l, side)) out[side == LoopSide::A ? l.towA() : l.towB()].push_back(std::move(c));
    }
    return out;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
