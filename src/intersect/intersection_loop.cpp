#include "towgeom/intersection_loop.hpp"

#include <GeomAPI_Interpolate.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <TColStd_HArray1OfReal.hxx>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "intersect/intersection_loop_data.hpp"
#include "intersect/loop_tracing.hpp"
#include "surface/curve3_impl.hpp"
#include "surface/occt_convert.hpp"
#include "surface/occt_guard.hpp"
#include "surface/tow_surface_impl.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace detail {

SurfacePair surfacePairOf(const TowSurface& a, const TowSurface& b)
{
    SurfacePair s;
    s.a = a.impl().surface;
    s.b = b.impl().surface;
    s.evalA = new GeomAdaptor_Surface(s.a);
    s.evalB = new GeomAdaptor_Surface(s.b);
    const ParameterRange ra = a.parameterRange(), rb = b.parameterRange();
    s.uMinA = ra.uMin;
    s.uMaxA = ra.uMax;
    s.uMinB = rb.uMin;
    s.uMaxB = rb.uMax;
    return s;
}

SurfacePair closedPairOf(const TowSurface& a, const TowSurface& b)
{
    SurfacePair s = surfacePairOf(a, b);
    s.capsA = &a.impl().caps;
    s.capsB = &b.impl().caps;
    return s;
}

Point3 closedPoint(const TowSurface& t, double u, double v)
{
    const TowCaps& caps = t.impl().caps;
    if (!caps.capAt(u)) return t.point(u, v);
    const GeomAdaptor_Surface tube(t.impl().surface);
    return chartPoint(tube, caps, u, v);
}

std::string crossesCapMessage(const IntersectionLoop& l)
{
    const std::string a = l.surfaceA().name(), b = l.surfaceB().name();
    const std::string which = l.crossesCap(LoopSide::A) ? (l.crossesCap(LoopSide::B) ? "'" + a + "' and '" + b + "'" : "'" + a + "'")
                                                        : "'" + b + "'";
    return "the intersection loop of tows '" + a + "' and '" + b + "' runs across the end cap of tow " + which +
           " (a tow ends inside the other), resolved only with end caps (MeshOptions::caps)";
}

SurfaceDerivatives closedDerivatives(const TowSurface& t, double u, double v)
{
    const TowCaps& caps = t.impl().caps;
    if (!caps.capAt(u)) return t.derivatives(u, v);
    const GeomAdaptor_Surface tube(t.impl().surface);
    gp_Pnt p;
    gp_Vec du, dv;
    chartD1(tube, caps, u, v, p, du, dv);
    return {fromOcct(p), fromOcct(du), fromOcct(dv)};
}

IntersectionLoop makeLoop(std::size_t towA, std::size_t towB, const TowSurface& a, const TowSurface& b,
                          const std::vector<PointOn2>& points, bool closed, const std::string& openReason,
                          double tolerance)
{
    auto d = std::make_shared<IntersectionLoop::Data>(a, b);
    d->towA = towA;
    d->towB = towB;
    d->closed = closed;
    d->openReason = openReason;
    d->tolerance = tolerance;
    d->points.reserve(points.size());
    for (const PointOn2& p : points) {
        d->points.push_back({p.point, {p.ua, p.va}, {p.ub, p.vb}});
        d->maxDistanceA = std::max(d->maxDistanceA, distance(p.point, closedPoint(a, p.ua, p.va)));
        d->maxDistanceB = std::max(d->maxDistanceB, distance(p.point, closedPoint(b, p.ub, p.vb)));
    }
    d->cumulative.assign(1, 0.0);
    const std::size_t n = d->points.size();
    const std::size_t segments = n < 2 ? 0 : closed ? n : n - 1;
    for (std::size_t k = 0; k < segments; ++k)
        d->cumulative.push_back(d->cumulative.back() + distance(d->points[k].point, d->points[(k + 1) % n].point));
    return IntersectionLoop(std::move(d));
}

namespace {

/// @p loop on the surfaces @p a and @p b, its points mapped by @p move and its lengths
/// multiplied by @p lengthScale (the (u,v) are the same in both frames).
template <class Move>
IntersectionLoop movedLoop(const IntersectionLoop& loop, const TowSurface& a, const TowSurface& b, Move move, double lengthScale)
{
    const IntersectionLoop::Data& f = loop.data();
    auto d = std::make_shared<IntersectionLoop::Data>(a, b);
    d->towA = f.towA;
    d->towB = f.towB;
    d->closed = f.closed;
    d->openReason = f.openReason;
    d->tolerance = f.tolerance * lengthScale;
    d->maxDistanceA = f.maxDistanceA * lengthScale;
    d->maxDistanceB = f.maxDistanceB * lengthScale;
    d->points = f.points;
    for (LoopPoint& p : d->points) p.point = move(p.point);
    d->cumulative = f.cumulative;
    for (double& c : d->cumulative) c *= lengthScale;
    if (f.areas->done)  // the areas already computed, scaled: not integrated again
        std::call_once(d->areas->once, [&] {
            d->areas->a = f.areas->a * lengthScale * lengthScale;
            d->areas->b = f.areas->b * lengthScale * lengthScale;
            d->areas->done = true;
        });
    return IntersectionLoop(std::move(d));
}

}  // namespace

IntersectionLoop loopToUser(const IntersectionLoop& loop, const TowSurface& a, const TowSurface& b, const Frame& frame)
{
    return movedLoop(loop, a, b, [&](const Point3& p) { return frame.toUser(p); }, frame.lengthToUser(1.0));
}

IntersectionLoop loopToFrame(const IntersectionLoop& loop, const TowSurface& a, const TowSurface& b, const Frame& frame)
{
    return movedLoop(loop, a, b, [&](const Point3& p) { return frame.toFrame(p); }, frame.lengthToFrame(1.0));
}

}  // namespace detail

namespace {

UV sideOf(const LoopPoint& p, LoopSide side) { return side == LoopSide::A ? p.onA : p.onB; }

/// The loop's points with the closing point appended (one turn on) for closed loops.
std::vector<LoopPoint> walkOrder(const IntersectionLoop::Data& d)
{
    std::vector<LoopPoint> pts = d.points;
    if (d.closed && !pts.empty()) {
        LoopPoint first = pts.front();
        const LoopPoint& last = pts.back();
        const double pa = d.a.parameterRange().vPeriod(), pb = d.b.parameterRange().vPeriod();
        first.onA.v += pa * std::round((last.onA.v - first.onA.v) / pa);
        first.onB.v += pb * std::round((last.onB.v - first.onB.v) / pb);
        pts.push_back(first);
    }
    return pts;
}

detail::PointOn2 toPointOn2(const LoopPoint& p) { return {p.onA.u, p.onA.v, p.onB.u, p.onB.v, p.point, 0.0}; }

LoopPoint toLoopPoint(const detail::PointOn2& p) { return {p.point, {p.ua, p.va}, {p.ub, p.vb}}; }

LoopPoint mix(const LoopPoint& a, const LoopPoint& b, double t)
{
    const auto lerp = [t](double x, double y) { return x + t * (y - x); };
    return {{lerp(a.point.x, b.point.x), lerp(a.point.y, b.point.y), lerp(a.point.z, b.point.z)},
            {lerp(a.onA.u, b.onA.u), lerp(a.onA.v, b.onA.v)},
            {lerp(a.onB.u, b.onB.u), lerp(a.onB.v, b.onB.v)}};
}

/// The exact curve point where the curve crosses the plane normal to the chord [p, q] at
/// fraction @p t along it; the point on the chord if Newton's method fails.
LoopPoint exactOnChord(const detail::SurfacePair& sp, const LoopPoint& p, const LoopPoint& q, double t, double tolerance)
{
    const LoopPoint guess = mix(p, q, t);
    detail::PointOn2 x = toPointOn2(guess);
    detail::capGuess(sp, toPointOn2(p), toPointOn2(q), x);
    detail::PointCondition c;
    c.kind = detail::PointCondition::Kind::Plane;
    c.origin = guess.point;
    c.normal = q.point - p.point;
    const double n = norm(c.normal);
    if (!(n > 0.0)) return guess;
    c.normal = (1.0 / n) * c.normal;
    return detail::refineOnIntersection(sp, x, c, tolerance) ? toLoopPoint(x) : guess;
}

/// The exact curve point at arc-length fraction @p s of the loop walked as @p pts.
LoopPoint pointAt(const IntersectionLoop::Data& d, const std::vector<LoopPoint>& pts, double s)
{
    if (pts.size() < 2) return pts.front();
    const double target = s * d.cumulative.back();
    const std::size_t k =
        std::min<std::size_t>(std::upper_bound(d.cumulative.begin(), d.cumulative.end(), target) - d.cumulative.begin(),
                              d.cumulative.size() - 1) - 1;
    const double len = d.cumulative[k + 1] - d.cumulative[k];
    const double t = len > 0.0 ? std::clamp((target - d.cumulative[k]) / len, 0.0, 1.0) : 0.0;
    if (t == 0.0) return pts[k];
    if (t == 1.0) return pts[k + 1];
    const detail::SurfacePair sp = detail::closedPairOf(d.a, d.b);
    return detail::guarded("", "IntersectionLoop::at", [&] { return exactOnChord(sp, pts[k], pts[k + 1], t, d.tolerance); });
}

}  // namespace

IntersectionLoop::IntersectionLoop(std::shared_ptr<const Data> data) : data_(std::move(data)) {}

std::size_t IntersectionLoop::towA() const { return data_->towA; }
std::size_t IntersectionLoop::towB() const { return data_->towB; }
const TowSurface& IntersectionLoop::surfaceA() const { return data_->a; }
const TowSurface& IntersectionLoop::surfaceB() const { return data_->b; }
bool IntersectionLoop::closed() const { return data_->closed; }
const std::string& IntersectionLoop::openReason() const { return data_->openReason; }

IntersectionLoop::OpenKind IntersectionLoop::openKind() const
{
    OpenKind kind = OpenKind::None;
    if (!data_->closed && !detail::openKindOf(data_->openReason, kind))
        throw Error(ErrorCode::Internal, "an open curve with an unknown reason: " + data_->openReason);
    return kind;
}
const std::vector<LoopPoint>& IntersectionLoop::points() const { return data_->points; }

bool IntersectionLoop::crossesCap(LoopSide side) const
{
    const ParameterRange r = (side == LoopSide::A ? data_->a : data_->b).parameterRange();
    const double eps = 1e-9 * (r.uMax - r.uMin);
    return std::any_of(data_->points.begin(), data_->points.end(), [&](const LoopPoint& p) {
        const double u = sideOf(p, side).u;
        return u < r.uMin - eps || u > r.uMax + eps;
    });
}
double IntersectionLoop::length() const { return data_->cumulative.back(); }
double IntersectionLoop::tolerance() const { return data_->tolerance; }

double IntersectionLoop::maxDistance(LoopSide side) const
{
    return side == LoopSide::A ? data_->maxDistanceA : data_->maxDistanceB;
}

std::vector<UV> IntersectionLoop::uvCurve(LoopSide side) const
{
    std::vector<UV> uv;
    uv.reserve(data_->points.size());
    for (const LoopPoint& p : data_->points) uv.push_back(sideOf(p, side));
    return uv;
}

bool IntersectionLoop::windsAround(LoopSide side) const
{
    if (!data_->closed || data_->points.empty()) return false;
    const std::vector<LoopPoint> pts = walkOrder(*data_);
    const double period = (side == LoopSide::A ? data_->a : data_->b).parameterRange().vPeriod();
    return std::abs(sideOf(pts.back(), side).v - sideOf(pts.front(), side).v) > 0.5 * period;
}

namespace {

/// The area on tow @p side enclosed by the closed loop @p pts (walk order, the first point
/// repeated one turn on) whose chords' exact midpoints are @p mids.
double areaOnSide(const TowSurface& s, const std::vector<LoopPoint>& pts, const std::vector<LoopPoint>& mids, LoopSide side)
{
    double u0 = 1e300;
    for (const LoopPoint& p : pts) u0 = std::min(u0, sideOf(p, side).u);
    // Green: area = | closed integral of F dv |, F(u, v) = integral from u0 to u of |S_u x S_v|(s, v) ds.
    static const double gx[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
                                 0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
    static const double gw[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
                                 0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
    GeomAdaptor_Surface surface(s.impl().surface);  // cached per span: fast for nearby points
    const detail::TowCaps& caps = s.impl().caps;
    // Gauss on [lo, hi]: the integrand is smooth on the tube and on each cap, kinked at the rims.
    const auto gaussOn = [&](double lo, double hi, double v) {
        const double h = 0.5 * (hi - lo);
        if (h == 0.0) return 0.0;
        double sum = 0.0;
        for (int k = 0; k < 8; ++k) {
            gp_Pnt p;
            gp_Vec du, dv;
            detail::chartD1(surface, caps, lo + h * (1.0 + gx[k]), v, p, du, dv);
            sum += gw[k] * du.Crossed(dv).Magnitude();
        }
        return h * sum;
    };
    const auto F = [&](double u, double v) {
        // From u0 to u, split at the tube's ends.
        const double lo = std::min(u0, u), hi = std::max(u0, u);
        double sum = 0.0;
        const double cuts[4] = {lo, std::clamp(caps.uMin, lo, hi), std::clamp(caps.uMax, lo, hi), hi};
        for (int k = 0; k < 3; ++k) sum += gaussOn(cuts[k], cuts[k + 1], v);
        return u >= u0 ? sum : -sum;
    };
    // Each chord is replaced by the parabola in (u, v) through its ends and the exact curve
    // point in its middle, so the polygon's chord error does not enter the area; Simpson's rule
    // on it (exact for cubics; the chords are short) shares F at the points between chords.
    std::vector<double> atPoint(pts.size());
    for (std::size_t k = 0; k < pts.size(); ++k) {
        const UV p = sideOf(pts[k], side);
        atPoint[k] = F(p.u, p.v);
    }
    double area = 0.0;
    for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
        const UV a = sideOf(pts[k], side), b = sideOf(pts[k + 1], side);
        const UV m = sideOf(mids[k], side);
        // dv/dt of the parabola at t = 0, 1/2, 1.
        const double dv0 = -3.0 * a.v + 4.0 * m.v - b.v, dvm = b.v - a.v, dv1 = a.v - 4.0 * m.v + 3.0 * b.v;
        area += (atPoint[k] * dv0 + 4.0 * F(m.u, m.v) * dvm + atPoint[k + 1] * dv1) / 6.0;
    }
    return std::abs(area);
}

}  // namespace

double IntersectionLoop::enclosedArea(LoopSide side) const
{
    const Data& d = *data_;
    // Both tows' areas at once (the chords' exact midpoints serve both), once per loop.
    std::call_once(d.areas->once, [&] {
        constexpr double nan = std::numeric_limits<double>::quiet_NaN();
        const bool aWinds = windsAround(LoopSide::A), bWinds = windsAround(LoopSide::B);
        if (!d.closed || d.points.size() < 3 || (aWinds && bWinds)) {
            d.areas->a = d.areas->b = nan;
            return;
        }
        const std::vector<LoopPoint> pts = walkOrder(d);
        const detail::SurfacePair sp = detail::closedPairOf(d.a, d.b);
        std::vector<LoopPoint> mids;
        mids.reserve(pts.size());
        for (std::size_t k = 0; k + 1 < pts.size(); ++k) mids.push_back(exactOnChord(sp, pts[k], pts[k + 1], 0.5, d.tolerance));
        d.areas->a = aWinds ? nan : areaOnSide(d.a, pts, mids, LoopSide::A);
        d.areas->b = bWinds ? nan : areaOnSide(d.b, pts, mids, LoopSide::B);
        d.areas->done = true;
    });
    return side == LoopSide::A ? d.areas->a : d.areas->b;
}

LoopPoint IntersectionLoop::at(double s) const
{
    if (!(s >= 0.0 && s <= 1.0)) throw Error(ErrorCode::InvalidArgument, "IntersectionLoop::at: s must lie in [0, 1]");
    return pointAt(*data_, walkOrder(*data_), s);
}

std::vector<LoopPoint> IntersectionLoop::resample(double spacing) const
{
    if (!(spacing > 0.0) || !std::isfinite(spacing))
        throw Error(ErrorCode::InvalidArgument, "IntersectionLoop::resample: spacing must be positive and finite");
    constexpr double kMaxPoints = 1e7;
    const double L = length();
    if (L / spacing > kMaxPoints) {
        std::ostringstream m;
        m << "IntersectionLoop::resample: spacing " << spacing << " would give more than 1e7 points on a curve of length "
          << L;
        throw Error(ErrorCode::InvalidArgument, m.str());
    }
    std::size_t n = static_cast<std::size_t>(std::ceil(L / spacing));
    if (data_->closed) n = std::max<std::size_t>(n, 3);
    n = std::max<std::size_t>(n, 1);
    const std::vector<LoopPoint> pts = walkOrder(*data_);
    std::vector<LoopPoint> out;
    const std::size_t count = data_->closed ? n : n + 1;
    out.reserve(count);
    for (std::size_t k = 0; k < count; ++k)
        out.push_back(pointAt(*data_, pts, static_cast<double>(k) / static_cast<double>(n)));
    return out;
}

std::vector<std::vector<UV>> IntersectionLoop::clippedUvCurves(LoopSide side) const
{
    const Data& d = *data_;
    const ParameterRange r = (side == LoopSide::A ? d.a : d.b).parameterRange();
    const double period = r.vPeriod();
    const std::vector<LoopPoint> pts = d.closed ? walkOrder(d) : d.points;
    if (pts.size() < 2) return {uvCurve(side)};
    const detail::SurfacePair sp = detail::closedPairOf(d.a, d.b);

    // 1. Every chord that crosses a seam value gets the exact curve point on the seam.
    std::vector<UV> uv{sideOf(pts.front(), side)};
    for (std::size_t k = 1; k < pts.size(); ++k) {
        const double v0 = sideOf(pts[k - 1], side).v, v1 = sideOf(pts[k], side).v;
        const double lo = std::min(v0, v1), hi = std::max(v0, v1);
        const double firstSeam = r.vMin + period * std::floor((lo - r.vMin) / period + 1.0);
        for (double seam = firstSeam; seam < hi; seam += period) {
            if (seam <= lo) continue;
            const double t = (seam - v0) / (v1 - v0);
            detail::PointOn2 x = toPointOn2(mix(pts[k - 1], pts[k], t));
            detail::capGuess(sp, toPointOn2(pts[k - 1]), toPointOn2(pts[k]), x);
            detail::PointCondition c;
            c.kind = side == LoopSide::A ? detail::PointCondition::Kind::FixVA : detail::PointCondition::Kind::FixVB;
            c.value = seam;
            UV onSeam = sideOf(mix(pts[k - 1], pts[k], t), side);
            if (detail::refineOnIntersection(sp, x, c, d.tolerance)) onSeam = sideOf(toLoopPoint(x), side);
            onSeam.v = seam;
            uv.push_back(onSeam);
        }
        uv.push_back(sideOf(pts[k], side));
    }
    // 2. Now every chord lies in one period cell: split where the cell changes.
    const auto cellOf = [&](const UV& a, const UV& b) { return std::floor((0.5 * (a.v + b.v) - r.vMin) / period); };
    std::vector<std::vector<UV>> pieces;
    std::vector<double> cells;
    const double tiny = 1e-12 * period;
    for (std::size_t k = 1; k < uv.size(); ++k) {
        // Chords of (almost) no length, e.g. from a first point within rounding of the seam to
        // the seam point inserted after it, would make pieces of their own.
        if (std::abs(uv[k].u - uv[k - 1].u) <= tiny && std::abs(uv[k].v - uv[k - 1].v) <= tiny) continue;
        const double c = cellOf(uv[k - 1], uv[k]);
        if (pieces.empty() || c != cells.back()) {
            pieces.push_back({uv[k - 1]});
            cells.push_back(c);
        }
        pieces.back().push_back(uv[k]);
    }
    // 3. A closed loop that starts inside a piece: its last piece continues into its first (one
    //    period cell further on for a loop that winds around the tow).
    const double winding = std::round((uv.back().v - uv.front().v) / period);
    if (d.closed && pieces.size() > 1 && cells.back() == cells.front() + winding) {
        for (auto it = pieces.front().begin() + 1; it != pieces.front().end(); ++it)
            pieces.back().push_back({it->u, it->v + winding * period});
        pieces.front() = std::move(pieces.back());
        cells.front() = cells.back();
        pieces.pop_back();
        cells.pop_back();
    }
    // 4. Shift each piece into the rectangle (seam points land exactly on vMin or vMax).
    for (std::size_t p = 0; p < pieces.size(); ++p)
        for (UV& q : pieces[p]) q.v = std::clamp(q.v - period * cells[p], r.vMin, r.vMax);
    return pieces;
}

Curve3 IntersectionLoop::curve() const
{
    const Data& d = *data_;
    if (d.points.size() < 3) throw Error(ErrorCode::InvalidArgument, "IntersectionLoop::curve: too few points");
    return detail::guarded("", "IntersectionLoop::curve", [&]() -> Curve3 {
        const int n = static_cast<int>(d.points.size());
        Handle(TColgp_HArray1OfPnt) pts = new TColgp_HArray1OfPnt(1, n);
        // Periodic interpolation takes one parameter more: the period's end.
        const int np = d.closed ? n + 1 : n;
        Handle(TColStd_HArray1OfReal) par = new TColStd_HArray1OfReal(1, np);
        // Interpolated in a frame where the loop is about unit size (OCCT's confusion distance
        // is absolute), then moved back; the parameter stays the arc length in the frame.
        BoundingBox box;
        for (const LoopPoint& p : d.points) box.add(p.point);
        const detail::Frame frame = detail::Frame::around(box, box.diagonal());
        for (int k = 0; k < n; ++k) pts->SetValue(k + 1, detail::toOcct(frame.toFrame(d.points[k].point)));
        for (int k = 0; k < np; ++k) par->SetValue(k + 1, frame.lengthToFrame(d.cumulative[k]));
        GeomAPI_Interpolate interp(pts, par, d.closed ? Standard_True : Standard_False, Precision::Confusion());
        interp.Perform();
        if (!interp.IsDone()) throw Error(ErrorCode::Internal, "IntersectionLoop::curve: interpolation failed");
        Handle(Geom_BSplineCurve) c = interp.Curve();
        c->Transform(frame.trsf().Inverted());
        auto impl = std::make_shared<Curve3::Impl>();
        impl->curve = c;
        return Curve3(impl);
    });
}

TOWGEOM_END_NAMESPACE
