#include "intersect/loop_tracing.hpp"

#include "core/segment_distance.hpp"

#include <algorithm>
#include <cmath>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

constexpr int kMaxPieces = 64;      // a loop crosses the seams a few times; more means no progress
constexpr int kMaxDensifyDepth = 12;

struct Domain {
    double uMinA, uMaxA, uMinB, uMaxB;
    double vFirstA, periodA, vFirstB, periodB;
};

Domain domainOf(const SurfacePair& s)
{
    double u0, u1, v0, v1;
    Domain d{};
    s.a->Bounds(u0, u1, v0, v1);
    d.uMinA = u0; d.uMaxA = u1; d.vFirstA = v0; d.periodA = v1 - v0;
    s.b->Bounds(u0, u1, v0, v1);
    d.uMinB = u0; d.uMaxB = u1; d.vFirstB = v0; d.periodB = v1 - v0;
    return d;
}

/// Distance of @p v from the nearest seam (first + k period), in parameter units.
double seamDistance(double v, double first, double period)
{
    const double r = std::remainder(v - first, period);
    return std::abs(r);
}

bool atSeam(double v, double first, double period) { return seamDistance(v, first, period) <= 1e-9 * period; }

bool atTowEnd(const Domain& d, const PointOn2& p)
{
    const double ea = 1e-9 * (d.uMaxA - d.uMinA), eb = 1e-9 * (d.uMaxB - d.uMinB);
    return p.ua <= d.uMinA + ea || p.ua >= d.uMaxA - ea || p.ub <= d.uMinB + eb || p.ub >= d.uMaxB - eb;
}

std::string endReason(const Domain& d, const PointOn2& p)
{
    const double ea = 1e-9 * (d.uMaxA - d.uMinA), eb = 1e-9 * (d.uMaxB - d.uMinB);
    if (p.ua <= d.uMinA + ea || p.ua >= d.uMaxA - ea) return open_reason::kEndOfA;
    if (p.ub <= d.uMinB + eb || p.ub >= d.uMaxB - eb) return open_reason::kEndOfB;
    return open_reason::kWalkStops;
}

/// Shifts the v of every point of @p piece by whole periods so the piece starts next to @p ref.
void alignTo(std::vector<PointOn2>& piece, const PointOn2& ref, const Domain& d) { alignPeriods(piece, ref, d.periodA, d.periodB); }

/// Makes v continuous along @p piece (no jumps of more than half a period).
void unwrap(std::vector<PointOn2>& piece, const Domain& d)
{
    for (std::size_t k = 1; k < piece.size(); ++k) {
        piece[k].va += d.periodA * std::round((piece[k - 1].va - piece[k].va) / d.periodA);
        piece[k].vb += d.periodB * std::round((piece[k - 1].vb - piece[k].vb) / d.periodB);
    }
}

/// A start point just past @p end along the curve (away from @p before), refined.
bool stepPast(const SurfacePair& s, const PointOn2& end, const PointOn2& before, double step, double tol, PointOn2& out)
{
    Vector3 t = intersectionTangent(s, end);
    if (norm(t) == 0.0) return false;
    if (dot(t, end.point - before.point) < 0.0) t = -1.0 * t;
    // Parameter increments on each surface for a 3D step t * step (least squares on dS).
    const auto increment = [&](const Handle(Geom_BSplineSurface)& surf, double u, double v, double& du, double& dv) {
        gp_Pnt p;
        gp_Vec su, sv;
        surf->D1(u, v, p, su, sv);
        const double a = su.Dot(su), b = su.Dot(sv), c = sv.Dot(sv);
        const double r1 = step * (su.X() * t.x + su.Y() * t.y + su.Z() * t.z);
        const double r2 = step * (sv.X() * t.x + sv.Y() * t.y + sv.Z() * t.z);
        const double det = a * c - b * b;
        if (!(det > 0.0)) return false;
        du = (c * r1 - b * r2) / det;
        dv = (a * r2 - b * r1) / det;
        return true;
    };
    PointOn2 g = end;
    double dua, dva, dub, dvb;
    if (!increment(s.a, end.ua, end.va, dua, dva) || !increment(s.b, end.ub, end.vb, dub, dvb)) return false;
    g.ua += dua;
    g.va += dva;
    g.ub += dub;
    g.vb += dvb;
    g.point = end.point + step * t;
    if (!refineNearest(s, g, tol)) return false;
    out = g;
    return true;
}

double bridgeDistance(const std::vector<PointOn2>& pts, const TraceTolerances& tol);

/// Puts @p end exactly on a tow's end when it lies within the closing distance of it: OCCT's
/// walk stops at a boundary only to its own precision (e.g. 1.4e-9 of the u range short),
/// while the checks downstream (atTowEnd(), the caps) take the end's u as it is.
void snapToTowEnd(const SurfacePair& s, const Domain& d, PointOn2& end, const TraceTolerances& tol)
{
    // Within rounding of an end: exactly on it (a corner where the curve goes on across a cap,
    // recognised downstream by u equal to the end).
    const auto exact = [&] {
        const double ea = 1e-9 * (d.uMaxA - d.uMinA), eb = 1e-9 * (d.uMaxB - d.uMinB);
        if (std::abs(end.ua - d.uMinA) <= ea) end.ua = d.uMinA;
        if (std::abs(end.ua - d.uMaxA) <= ea) end.ua = d.uMaxA;
        if (std::abs(end.ub - d.uMinB) <= eb) end.ub = d.uMinB;
        if (std::abs(end.ub - d.uMaxB) <= eb) end.ub = d.uMaxB;
    };
    if (atTowEnd(d, end)) {
        exact();
        return;
    }
    const auto snapOn = [&](const Handle(Geom_BSplineSurface)& surf, double u, double v, double uMin, double uMax, PointCondition::Kind kind) {
        const double uEnd = u - uMin < uMax - u ? uMin : uMax;
        gp_Pnt p;
        gp_Vec su, sv;
        surf->D1(u, v, p, su, sv);
        if (!(std::abs(uEnd - u) * su.Magnitude() <= tol.closing)) return false;
        PointCondition c;
        c.kind = kind;
        c.value = uEnd;
        PointOn2 x = end;
        if (!refineOnIntersection(s, x, c, tol.point) || distance(x.point, end.point) > 2.0 * tol.closing) return false;
        end = x;
        return true;
    };
    if (!snapOn(s.a, end.ua, end.va, d.uMinA, d.uMaxA, PointCondition::Kind::FixUA))
        snapOn(s.b, end.ub, end.vb, d.uMinB, d.uMaxB, PointCondition::Kind::FixUB);
    exact();
}

/// The first index from @p from on where @p chain comes back to its first point (within a few
/// of its steps) running the same way as it left it and then retraces its start; chain.size() if
/// it does not.
std::size_t returnToStart(const std::vector<PointOn2>& chain, std::size_t from, double bridge)
{
    if (chain.size() < 4) return chain.size();
    const Point3& p0 = chain.front().point;
    // The chain's first steps, over a few bridge lengths.
    std::size_t lead = 1;
    for (double arc = 0.0; lead + 1 < chain.size() && arc < 3.0 * bridge; ++lead) arc += distance(chain[lead].point, chain[lead - 1].point);
    const Vector3 t0 = chain[lead].point - p0;
    for (std::size_t i = std::max<std::size_t>(from, lead + 1); i + 1 < chain.size(); ++i) {
        if (distance(chain[i].point, p0) > bridge) continue;
        if (distance(chain[i + 1].point, p0) < distance(chain[i].point, p0) && distance(chain[i + 1].point, p0) <= bridge) continue;
        // The nearest point of a pass by the start: it must leave the way the chain did.
        std::size_t j = i + 1;
        for (double arc = 0.0; j + 1 < chain.size() && arc < 3.0 * bridge; ++j) arc += distance(chain[j].point, chain[j - 1].point);
        if (dot(chain[j].point - chain[i].point, t0) <= 0.0) continue;
        bool retraces = true;
        for (std::size_t k = i + 1; k <= j && retraces; ++k) {
            double nearest = 1e300;
            for (std::size_t m = 0; m + 1 <= lead + 1 && m + 1 < chain.size(); ++m)
                nearest = std::min(nearest, segmentDistance(chain[k].point, chain[m].point, chain[m + 1].point));
            retraces = nearest <= bridge;
        }
        if (retraces) return i;
    }
    return chain.size();
}

struct Tracer {
    const SurfacePair& s;
    const SurfaceWalker& walker;
    const TraceTolerances& tol;
    Domain d;

    /// The next piece after the chain's last point, oriented and aligned; empty if none.
    std::vector<PointOn2> continueChain(const std::vector<PointOn2>& chain, std::string& reason) const
    {
        const PointOn2& end = chain.back();
        if (atTowEnd(d, end)) {
            reason = endReason(d, end);
            return {};
        }
        const auto onChain = [&](const std::vector<PointOn2>& piece) {
            // A piece that runs back along the chain: its middle point lies on the chain.
            TracedCurve c;
            c.points = chain;
            return distanceToCurve(c, piece[piece.size() / 2].point) <= tol.closing;
        };
        // The walk gives the line through its start, which may run both ways from the chain's
        // end (e.g. where the curve only touches a seam): split it at the point nearest the end
        // and keep the half that leads away from the chain, starting at the end.
        const auto orient = [&](std::vector<PointOn2> piece) -> std::vector<PointOn2> {
            if (piece.size() < 2) return {};
            std::size_t nearest = 0;
            for (std::size_t k = 1; k < piece.size(); ++k)
                if (distance(piece[k].point, end.point) < distance(piece[nearest].point, end.point)) nearest = k;
            std::vector<PointOn2> ahead(piece.begin() + static_cast<std::ptrdiff_t>(nearest), piece.end());
            std::vector<PointOn2> behind(piece.begin(), piece.begin() + static_cast<std::ptrdiff_t>(nearest) + 1);
            std::reverse(behind.begin(), behind.end());
            for (std::vector<PointOn2>* half : {&ahead, &behind}) {
                if (half->size() < 2) continue;
                alignTo(*half, end, d);
                unwrap(*half, d);
                if (!onChain(*half)) return *half;
            }
            return {};
        };
        // Across a seam: the same point with v on the other side of the period. The walk takes
        // v in [first, first + period]: a chain that reached the seam going up in v goes on from
        // first, one going down from first + period (v is unwrapped along the chain, so the
        // direction, not the value, tells the side).
        const bool seamA = atSeam(end.va, d.vFirstA, d.periodA), seamB = atSeam(end.vb, d.vFirstB, d.periodB);
        if (seamA || seamB) {
            PointOn2 start = end;
            const auto across = [](double v, double before, double first, double period) {
                if (v != before) return v > before ? first : first + period;
                return first;  // the chain lies along the seam: either side (the walk runs along it)
            };
            // The last point before the end that differs from it in v (points along the seam do
            // not tell the side).
            const auto before = [&](double PointOn2::*v, double period) {
                for (std::size_t k = chain.size() - 1; k-- > 0;)
                    if (std::abs(chain[k].*v - end.*v) > 1e-9 * period) return chain[k].*v;
                return end.*v;
            };
            if (seamA) start.va = across(end.va, before(&PointOn2::va, d.periodA), d.vFirstA, d.periodA);
            if (seamB) start.vb = across(end.vb, before(&PointOn2::vb, d.periodB), d.vFirstB, d.periodB);
            std::vector<PointOn2> piece = orient(walker.walk(start));
            if (!piece.empty() && distance(piece.front().point, end.point) <= tol.closing) return piece;
        }
        // Otherwise (or if that gave nothing) restart a little past the end.
        if (chain.size() >= 2) {
            const double step = std::max(10.0 * tol.closing, 0.25 * distance(end.point, chain[chain.size() - 2].point));
            PointOn2 start;
            if (stepPast(s, end, chain[chain.size() - 2], step, tol.point, start)) {
                std::vector<PointOn2> piece = orient(walker.walk(start));
                if (!piece.empty() && distance(piece.front().point, end.point) <= 4.0 * step) return piece;
            }
        }
        reason = endReason(d, end);
        return {};
    }

    /// Extends @p chain forward until it closes or stops; true when closed.
    bool extend(std::vector<PointOn2>& chain, std::string& reason) const
    {
        for (int k = 0; k < kMaxPieces; ++k) {
            snapToTowEnd(s, d, chain.back(), tol);
            std::vector<PointOn2> next = continueChain(chain, reason);
            if (next.empty()) return false;
            const std::size_t before = chain.size();
            chain.insert(chain.end(), next.begin() + 1, next.end());
            if (chain.size() > 2 && distance(chain.back().point, chain.front().point) <= tol.closing) return true;
            // A piece that runs on through the chain's first point (a walk restarted past a
            // singular point, where the closure check at piece ends is skipped) closes it there.
            if (const std::size_t at = returnToStart(chain, before > 0 ? before - 1 : 0, bridgeDistance(chain, tol));
                at < chain.size()) {
                chain.resize(at);
                return true;
            }
            if (chain.size() == before) break;
        }
        reason = open_reason::kDoesNotClose;
        return false;
    }

};

/// The faces of a closed tow that u lies on: kStartCap, kTube, kEndCap; a rim point (u exactly
/// a tube's end) is on both the tube and its cap. Only the tube without @p caps.
constexpr unsigned kStartCap = 1, kTube = 2, kEndCap = 4;
unsigned facesAt(const TowCaps* caps, double u)
{
    if (!caps) return kTube;
    if (u < caps->uMin) return kStartCap;
    if (u > caps->uMax) return kEndCap;
    return kTube | (u == caps->uMin ? kStartCap : 0u) | (u == caps->uMax ? kEndCap : 0u);
}

}  // namespace

bool isCorner(const SurfacePair& s, const PointOn2& p)
{
    const auto two = [](unsigned f) { return (f & (f - 1)) != 0; };
    return two(facesAt(s.capsA, p.ua)) || two(facesAt(s.capsB, p.ub));
}

namespace {

/// Is @p m on a face that @p a and @p b share, on both tows (where they share one)? A point
/// refined between two points of one face must not slip onto another branch of the curve
/// across a rim (next to a corner the plane normal to the curve cuts both branches).
bool onSharedFaces(const SurfacePair& s, const PointOn2& a, const PointOn2& b, const PointOn2& m)
{
    const auto ok = [](unsigned fa, unsigned fb, unsigned fm) { return (fa & fb) == 0 || (fa & fb & fm) != 0; };
    return ok(facesAt(s.capsA, a.ua), facesAt(s.capsA, b.ua), facesAt(s.capsA, m.ua)) &&
           ok(facesAt(s.capsB, a.ub), facesAt(s.capsB, b.ub), facesAt(s.capsB, m.ub));
}

void refineAll(const SurfacePair& s, std::vector<PointOn2>& pts, double tolerance)
{
    for (PointOn2& p : pts) {
        if (isCorner(s, p)) continue;  // exactly on a rim already
        PointOn2 q = p;
        if (refineNearest(s, q, tolerance)) p = q;
    }
}

/// The curve's point next to the guess @p m between @p a and @p b, on their shared faces:
/// refineNearest(), else with one of the guess's parameters held (its u or v on either tow).
bool refineBetween(const SurfacePair& s, const PointOn2& a, const PointOn2& b, PointOn2& m, double tolerance)
{
    PointOn2 x = m;
    if (refineNearest(s, x, tolerance) && onSharedFaces(s, a, b, x)) {
        m = x;
        return true;
    }
    using Kind = PointCondition::Kind;
    for (const Kind kind : {Kind::FixUA, Kind::FixUB, Kind::FixVA, Kind::FixVB}) {
        PointCondition c;
        c.kind = kind;
        c.value = kind == Kind::FixUA ? m.ua : kind == Kind::FixUB ? m.ub : kind == Kind::FixVA ? m.va : m.vb;
        x = m;
        if (refineOnIntersection(s, x, c, tolerance) && onSharedFaces(s, a, b, x) && distance(x.point, m.point) <= distance(a.point, b.point)) {
            m = x;
            return true;
        }
    }
    return false;
}

/// Appends the points after @p a up to @p b, with refined midpoints inserted wherever the
/// chord strays more than the chordal tolerance from the curve.
void densify(const SurfacePair& s, const TraceTolerances& tol, std::vector<PointOn2>& out, const PointOn2& a,
             const PointOn2& b, int depth)
{
    if (depth < kMaxDensifyDepth) {
        PointOn2 m;
        m.ua = 0.5 * (a.ua + b.ua);
        m.va = 0.5 * (a.va + b.va);
        m.ub = 0.5 * (a.ub + b.ub);
        m.vb = 0.5 * (a.vb + b.vb);
        m.point = 0.5 * (a.point + b.point);
        // On a cap a straight chord is a curve in (u,v): chords there turn at most 1/64 of a
        // period about its centre, so that (u,v) polygons of the loop follow it.
        const double turn = capGuess(s, a, b, m);
        if (refineBetween(s, a, b, m, tol.point) && (distance(m.point, 0.5 * (a.point + b.point)) > tol.chordal || turn > 1.0 / 64.0)) {
            densify(s, tol, out, a, m, depth + 1);
            densify(s, tol, out, m, b, depth + 1);
            return;
        }
    }
    out.push_back(b);
}

/// Keeps the first and last points, every corner (isCorner()) and, greedily, as few others as
/// possible such that every dropped point lies within @p within of the chord that replaces it.
std::vector<PointOn2> decimate(const SurfacePair& s, const std::vector<PointOn2>& pts, double within)
{
    if (pts.size() < 3) return pts;
    std::vector<PointOn2> kept{pts.front()};
    std::size_t i = 0;
    while (i + 1 < pts.size()) {
        std::size_t j = i + 1;
        while (j + 1 < pts.size() && !isCorner(s, pts[j])) {
            bool ok = true;
            for (std::size_t k = i + 1; k <= j && ok; ++k)
                ok = segmentDistance(pts[k].point, pts[i].point, pts[j + 1].point) <= within;
            if (!ok) break;
            ++j;
        }
        kept.push_back(pts[j]);
        i = j;
    }
    return kept;
}

/// decimate() for a closed loop: split at the point farthest from the first so that each half
/// keeps its ends, and the loop at least three points.
std::vector<PointOn2> decimateClosed(const SurfacePair& s, const std::vector<PointOn2>& pts, double within)
{
    if (pts.size() < 4) return pts;
    std::size_t far = 1;
    for (std::size_t k = 2; k < pts.size(); ++k)
        if (distance(pts[k].point, pts[0].point) > distance(pts[far].point, pts[0].point)) far = k;
    std::vector<PointOn2> first(pts.begin(), pts.begin() + static_cast<std::ptrdiff_t>(far) + 1);
    std::vector<PointOn2> second(pts.begin() + static_cast<std::ptrdiff_t>(far), pts.end());
    second.push_back(pts.front());
    std::vector<PointOn2> kept = decimate(s, first, within);
    const std::vector<PointOn2> rest = decimate(s, second, within);
    kept.insert(kept.end(), rest.begin() + 1, rest.end() - 1);  // both ends are already kept
    if (kept.size() < 3) {  // a straight back-and-forth cannot happen on a loop; keep a triangle
        kept = {pts[0], pts[far / 2 > 0 ? far / 2 : 1], pts[far]};
    }
    return kept;
}

/// How far apart two curve ends may be and still be joined: a few of the curve's own steps.
double bridgeDistance(const std::vector<PointOn2>& pts, const TraceTolerances& tol)
{
    double step = 0.0;
    for (std::size_t k = 1; k < pts.size(); ++k) step = std::max(step, distance(pts[k].point, pts[k - 1].point));
    return std::max(10.0 * tol.closing, 3.0 * step);
}

}  // namespace

namespace {
constexpr std::size_t kRun = 32;
std::size_t segmentCount(const TracedCurve& c)
{
    return c.points.empty() ? 0 : (c.closed ? c.points.size() : c.points.size() - 1);
}
}  // namespace

CurveProximity::CurveProximity(const TracedCurve& curve) : curve_(&curve)
{
    const auto& q = curve.points;
    const std::size_t segments = segmentCount(curve);
    for (std::size_t k = 0; k < segments; k += kRun) {
        BoundingBox& box = runs_.emplace_back();
        for (std::size_t j = k; j <= std::min(k + kRun, segments); ++j) box.add(q[j % q.size()].point);
    }
}

bool CurveProximity::within(const Point3& p, double d) const
{
    const auto& q = curve_->points;
    if (q.empty()) return false;
    if (distance(p, q.front().point) <= d) return true;
    const std::size_t segments = segmentCount(*curve_);
    for (std::size_t r = 0; r < runs_.size(); ++r) {
        const BoundingBox& b = runs_[r];
        if (p.x < b.min.x - d || p.x > b.max.x + d || p.y < b.min.y - d || p.y > b.max.y + d || p.z < b.min.z - d ||
            p.z > b.max.z + d)
            continue;
        for (std::size_t k = r * kRun; k < std::min((r + 1) * kRun, segments); ++k)
            if (segmentDistance(p, q[k].point, q[(k + 1) % q.size()].point) <= d) return true;
    }
    return false;
}

void alignPeriods(std::vector<PointOn2>& piece, const PointOn2& ref, double periodA, double periodB)
{
    if (piece.empty()) return;
    const double sa = periodA * std::round((ref.va - piece.front().va) / periodA);
    const double sb = periodB * std::round((ref.vb - piece.front().vb) / periodB);
    for (PointOn2& p : piece) {
        p.va += sa;
        p.vb += sb;
    }
}

double distanceToCurve(const TracedCurve& curve, const Point3& p)
{
    const auto& q = curve.points;
    if (q.empty()) return 1e300;
    double best = distance(p, q.front().point);
    const std::size_t segments = curve.closed ? q.size() : q.size() - 1;
    for (std::size_t k = 0; k < segments; ++k)
        best = std::min(best, segmentDistance(p, q[k].point, q[(k + 1) % q.size()].point));
    return best;
}

void joinOpenCurves(const SurfacePair& surfaces, std::vector<TracedCurve>& curves, const TraceTolerances& tolerances)
{
    const Domain d = domainOf(surfaces);
    bool joined = true;
    while (joined) {
        joined = false;
        for (std::size_t i = 0; i < curves.size() && !joined; ++i)
            for (std::size_t j = 0; j < curves.size() && !joined; ++j) {
                TracedCurve& a = curves[i];
                TracedCurve& b = curves[j];
                if (a.closed || b.closed || i == j || a.points.empty() || b.points.empty()) continue;
                const double bridge = std::max(bridgeDistance(a.points, tolerances), bridgeDistance(b.points, tolerances));
                // a's end meets b's start (after reversing b if need be), away from tow ends.
                if (distance(a.points.back().point, b.points.back().point) <
                    distance(a.points.back().point, b.points.front().point))
                    std::reverse(b.points.begin(), b.points.end());
                if (atTowEnd(d, a.points.back()) || distance(a.points.back().point, b.points.front().point) > bridge)
                    continue;
                std::vector<PointOn2> tail = b.points;
                alignTo(tail, a.points.back(), d);
                a.points.insert(a.points.end(), tail.begin(), tail.end());
                curves.erase(curves.begin() + static_cast<std::ptrdiff_t>(j));
                TracedCurve& c = curves[i < j ? i : i - 1];
                if (!atTowEnd(d, c.points.front()) && !atTowEnd(d, c.points.back()) &&
                    distance(c.points.front().point, c.points.back().point) <= bridge) {
                    c.closed = true;
                    c.openReason.clear();
                }
                joined = true;
            }
    }
}

void dropDuplicateCurves(std::vector<TracedCurve>& curves, const TraceTolerances& tolerances)
{
    const double within = 2.0 * tolerances.chordal + tolerances.closing;
    const auto runsAlong = [&](const TracedCurve& c, const CurveProximity& other) {
        return std::all_of(c.points.begin(), c.points.end(), [&](const PointOn2& p) { return other.within(p.point, within); });
    };
    std::vector<char> dropped(curves.size(), 0);
    std::vector<CurveProximity> proximity;
    proximity.reserve(curves.size());
    for (const TracedCurve& c : curves) proximity.emplace_back(c);
    // Of two that run along each other, the closed one, else the one with more points.
    const auto better = [&](std::size_t i, std::size_t j) {
        if (curves[i].closed != curves[j].closed) return curves[i].closed;
        return curves[i].points.size() >= curves[j].points.size();
    };
    for (std::size_t i = 0; i < curves.size(); ++i)
        for (std::size_t j = i + 1; j < curves.size() && !dropped[i]; ++j) {
            if (dropped[j]) continue;
            const bool jAlongI = runsAlong(curves[j], proximity[i]), iAlongJ = runsAlong(curves[i], proximity[j]);
            if (jAlongI && iAlongJ) (better(i, j) ? dropped[j] : dropped[i]) = 1;
            else if (jAlongI) dropped[j] = 1;  // j is part of i
            else if (iAlongJ) dropped[i] = 1;  // i is part of j
        }
    std::size_t kept = 0;
    for (std::size_t k = 0; k < curves.size(); ++k)
        if (!dropped[k]) {
            if (kept != k) curves[kept] = std::move(curves[k]);
            ++kept;
        }
    curves.resize(kept);
}

bool openKindOf(const std::string& reason, IntersectionLoop::OpenKind& kind)
{
    using K = IntersectionLoop::OpenKind;
    const std::pair<const char*, K> known[] = {{open_reason::kEndOfA, K::ReachesEndOfA},
                                               {open_reason::kEndOfB, K::ReachesEndOfB},
                                               {open_reason::kWalkStops, K::WalkStops},
                                               {open_reason::kDoesNotClose, K::DoesNotClose}};
    for (const auto& [text, k] : known)
        if (reason == text) {
            kind = k;
            return true;
        }
    return false;
}

TracedCurve traceCurve(const SurfacePair& surfaces, const SurfaceWalker& walker, const PointOn2& seed,
                       const TraceTolerances& tolerances)
{
    Tracer tr{surfaces, walker, tolerances, domainOf(surfaces)};
    TracedCurve curve;
    std::vector<PointOn2> chain = walker.walk(seed);
    if (chain.size() < 2) return curve;
    alignTo(chain, seed, tr.d);
    unwrap(chain, tr.d);
    // OCCT's march may pass its start where the surfaces are tangent (a figure-8's singular
    // point) and go round again: the curve closes at its first return.
    bool closed = false;
    if (const std::size_t at = returnToStart(chain, 1, bridgeDistance(chain, tolerances)); at < chain.size()) {
        chain.resize(at);
        closed = true;
    }
    closed = closed || (distance(chain.back().point, chain.front().point) <= tolerances.closing && chain.size() > 2);
    std::string reason;
    if (!closed) closed = tr.extend(chain, reason);
    if (!closed) {
        std::string backReason;
        std::reverse(chain.begin(), chain.end());
        closed = tr.extend(chain, backReason);
        std::reverse(chain.begin(), chain.end());
        if (closed) reason.clear();
    }
    if (!closed && !atTowEnd(tr.d, chain.front()) && !atTowEnd(tr.d, chain.back()) &&
        distance(chain.front().point, chain.back().point) <= bridgeDistance(chain, tolerances)) {
        // Neither end could be continued, yet they are a few walk steps apart and neither is at
        // a tow's end (the curve grazes a seam there): the gap is one more chord of the loop.
        closed = true;
        reason.clear();
    }
    if (closed && chain.size() > 2 && distance(chain.back().point, chain.front().point) <= tolerances.closing)
        chain.pop_back();  // the closing point repeats the first
    curve.points = std::move(chain);
    curve.closed = closed;
    curve.openReason = closed ? std::string() : reason;
    return curve;
}

void consolidateCurve(const SurfacePair& surfaces, TracedCurve& curve, const TraceTolerances& tolerances)
{
    const Domain d = domainOf(surfaces);
    const bool closed = curve.closed;
    std::vector<PointOn2> chain = std::move(curve.points);
    // The walk's points (on both surfaces within the point tolerance, far below the chordal
    // one) are much denser than needed: keep only those the chordal tolerance asks for, refine
    // those onto both surfaces, then densify where a chord strays from the curve.
    const auto coincide = [&](const PointOn2& p, const PointOn2& q) { return distance(p.point, q.point) <= 1e-3 * tolerances.closing; };
    if (closed && chain.size() > 1 && distance(chain.back().point, chain.front().point) <= tolerances.point) chain.pop_back();
    chain = closed ? decimateClosed(surfaces, chain, 0.5 * tolerances.chordal) : decimate(surfaces, chain, 0.5 * tolerances.chordal);
    refineAll(surfaces, chain, tolerances.point);
    // Drop points that coincide with their predecessor (piece junctions).
    std::vector<PointOn2> clean;
    for (const PointOn2& p : chain)
        if (clean.empty() || !coincide(clean.back(), p)) clean.push_back(p);
    if (closed && clean.size() > 1 && coincide(clean.back(), clean.front())) clean.pop_back();
    std::vector<PointOn2> dense;
    if (!clean.empty()) dense.push_back(clean.front());
    const std::size_t segments = clean.empty() ? 0 : closed ? clean.size() : clean.size() - 1;
    for (std::size_t k = 0; k < segments; ++k) {
        PointOn2 b = clean[(k + 1) % clean.size()];
        if (k + 1 == clean.size()) {  // the closing segment: b is the first point, one turn on
            b.va += d.periodA * std::round((clean[k].va - b.va) / d.periodA);
            b.vb += d.periodB * std::round((clean[k].vb - b.vb) / d.periodB);
        }
        densify(surfaces, tolerances, dense, clean[k], b, 0);
    }
    if (closed && dense.size() > 1) dense.pop_back();  // the closing segment ended on the first point
    curve.points = std::move(dense);
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
