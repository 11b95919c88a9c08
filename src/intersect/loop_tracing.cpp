#include "intersect/loop_tracing.hpp"

#include <algorithm>
#include <cmath>

namespace towgeom::detail {

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
    if (p.ua <= d.uMinA + ea || p.ua >= d.uMaxA - ea) return "the curve reaches an end of the first tow";
    if (p.ub <= d.uMinB + eb || p.ub >= d.uMaxB - eb) return "the curve reaches an end of the second tow";
    return "the surface-surface walk stops here and cannot be continued (tangent surfaces?)";
}

/// Shifts the v of every point of @p piece by whole periods so the piece starts next to @p ref.
void alignTo(std::vector<PointOn2>& piece, const PointOn2& ref, const Domain& d)
{
    if (piece.empty()) return;
    const double sa = d.periodA * std::round((ref.va - piece.front().va) / d.periodA);
    const double sb = d.periodB * std::round((ref.vb - piece.front().vb) / d.periodB);
    for (PointOn2& p : piece) {
        p.va += sa;
        p.vb += sb;
    }
}

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
        const auto orient = [&](std::vector<PointOn2> piece) -> std::vector<PointOn2> {
            if (piece.size() < 2) return {};
            if (distance(piece.back().point, end.point) < distance(piece.front().point, end.point))
                std::reverse(piece.begin(), piece.end());
            alignTo(piece, end, d);
            unwrap(piece, d);
            if (onChain(piece)) return {};
            return piece;
        };
        // Across a seam: the same point with v on the other side of the period.
        const bool seamA = atSeam(end.va, d.vFirstA, d.periodA), seamB = atSeam(end.vb, d.vFirstB, d.periodB);
        if (seamA || seamB) {
            PointOn2 start = end;
            const auto flip = [](double v, double first, double period) {
                const double w = v - period * std::floor((v - first) / period + 0.5);  // nearest seam value
                return std::abs(w - first) < 0.5 * period ? first + period : first;
            };
            if (seamA) start.va = flip(end.va, d.vFirstA, d.periodA);
            if (seamB) start.vb = flip(end.vb, d.vFirstB, d.periodB);
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
            std::vector<PointOn2> next = continueChain(chain, reason);
            if (next.empty()) return false;
            const std::size_t before = chain.size();
            chain.insert(chain.end(), next.begin() + 1, next.end());
            if (chain.size() > 2 && distance(chain.back().point, chain.front().point) <= tol.closing) return true;
            if (chain.size() == before) break;
        }
        reason = "the curve does not close after many pieces";
        return false;
    }

    void refineAll(std::vector<PointOn2>& pts) const
    {
        for (PointOn2& p : pts) {
            PointOn2 q = p;
            if (refineNearest(s, q, tol.point)) p = q;
        }
    }

    void densify(std::vector<PointOn2>& out, const PointOn2& a, const PointOn2& b, int depth) const
    {
        if (depth < kMaxDensifyDepth) {
            PointOn2 m;
            m.ua = 0.5 * (a.ua + b.ua);
            m.va = 0.5 * (a.va + b.va);
            m.ub = 0.5 * (a.ub + b.ub);
            m.vb = 0.5 * (a.vb + b.vb);
            m.point = 0.5 * (a.point + b.point);
            if (refineNearest(s, m, tol.point) && distance(m.point, 0.5 * (a.point + b.point)) > tol.chordal) {
                densify(out, a, m, depth + 1);
                densify(out, m, b, depth + 1);
                return;
            }
        }
        out.push_back(b);
    }
};

/// The distance from @p p to the segment [a, b].
double segmentDistance(const Point3& p, const Point3& a, const Point3& b)
{
    const Vector3 ab = b - a;
    const double l2 = dot(ab, ab);
    const double t = l2 > 0.0 ? std::clamp(dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
    return distance(p, a + t * ab);
}

/// Keeps the first and last points and, greedily, as few others as possible such that every
/// dropped point lies within @p within of the chord that replaces it.
std::vector<PointOn2> decimate(const std::vector<PointOn2>& pts, double within)
{
    if (pts.size() < 3) return pts;
    std::vector<PointOn2> kept{pts.front()};
    std::size_t i = 0;
    while (i + 1 < pts.size()) {
        std::size_t j = i + 1;
        while (j + 1 < pts.size()) {
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

}  // namespace

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

TracedCurve traceCurve(const SurfacePair& surfaces, const SurfaceWalker& walker, const PointOn2& seed,
                       const TraceTolerances& tolerances)
{
    Tracer tr{surfaces, walker, tolerances, domainOf(surfaces)};
    TracedCurve curve;
    std::vector<PointOn2> chain = walker.walk(seed);
    if (chain.size() < 2) return curve;
    alignTo(chain, seed, tr.d);
    unwrap(chain, tr.d);
    bool closed = distance(chain.back().point, chain.front().point) <= tolerances.closing && chain.size() > 2;
    std::string reason;
    if (!closed) closed = tr.extend(chain, reason);
    if (!closed) {
        std::string backReason;
        std::reverse(chain.begin(), chain.end());
        closed = tr.extend(chain, backReason);
        std::reverse(chain.begin(), chain.end());
        if (closed) reason.clear();
    }
    if (closed) chain.pop_back();  // the closing point repeats the first

    tr.refineAll(chain);
    // Drop points that coincide with their predecessor (piece junctions).
    std::vector<PointOn2> clean;
    for (const PointOn2& p : chain)
        if (clean.empty() || distance(clean.back().point, p.point) > 1e-3 * tolerances.closing) clean.push_back(p);
    if (closed && clean.size() > 1 && distance(clean.back().point, clean.front().point) <= 1e-3 * tolerances.closing)
        clean.pop_back();
    // The walk's points are much denser than needed: keep only those the chordal tolerance
    // asks for, then densify where a chord strays from the curve.
    clean = decimate(clean, 0.5 * tolerances.chordal);
    // Densify to the chordal tolerance.
    std::vector<PointOn2> dense;
    if (!clean.empty()) dense.push_back(clean.front());
    const std::size_t segments = closed ? clean.size() : clean.size() - 1;
    for (std::size_t k = 0; k < segments && !clean.empty(); ++k) {
        PointOn2 b = clean[(k + 1) % clean.size()];
        if (k + 1 == clean.size()) {  // the closing segment: b is the first point, one turn on
            b.va += tr.d.periodA * std::round((clean[k].va - b.va) / tr.d.periodA);
            b.vb += tr.d.periodB * std::round((clean[k].vb - b.vb) / tr.d.periodB);
        }
        tr.densify(dense, clean[k], b, 0);
    }
    if (closed && dense.size() > 1) dense.pop_back();  // the closing segment ended on the first point
    curve.points = std::move(dense);
    curve.closed = closed;
    curve.openReason = closed ? std::string() : reason;
    return curve;
}

}  // namespace towgeom::detail
