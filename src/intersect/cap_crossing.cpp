#include "intersect/cap_crossing.hpp"

#include <Geom2d_Curve.hxx>
#include <GeomInt_IntSS.hxx>
#include <Geom_Plane.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Standard_Failure.hxx>
#include <gp_Pnt2d.hxx>

#include <algorithm>
#include <cmath>

#include "intersect/cap_cap_segment.hpp"
#include "intersect/intersection_loop_data.hpp"
#include "surface/occt_convert.hpp"
#include "surface/tow_surface_impl.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

double& ownU(PointOn2& p, LoopSide s) { return s == LoopSide::A ? p.ua : p.ub; }
double ownU(const PointOn2& p, LoopSide s) { return s == LoopSide::A ? p.ua : p.ub; }
double& ownV(PointOn2& p, LoopSide s) { return s == LoopSide::A ? p.va : p.vb; }
double& otherU(PointOn2& p, LoopSide s) { return s == LoopSide::A ? p.ub : p.ua; }
double otherU(const PointOn2& p, LoopSide s) { return s == LoopSide::A ? p.ub : p.ua; }
double& otherV(PointOn2& p, LoopSide s) { return s == LoopSide::A ? p.vb : p.va; }

/// The rim's largest distance from the cap's centre.
double rimRadius(const GeomAdaptor_Surface& tube, const CapChart& cap)
{
    double r = 0.0;
    for (std::size_t k = 0; k + 1 < cap.v.size(); k += 4) r = std::max(r, (tube.Value(cap.uRim, cap.v[k]).XYZ() - cap.centre).Modulus());
    return r;
}

/// Does the box @p b (of the other tow) reach the cap's disc (radius @p r about its centre)?
bool reaches(const BoundingBox& b, const CapChart& cap, double r)
{
    const Point3 c = fromOcct(gp_Pnt(cap.centre));
    return c.x + r >= b.min.x && c.x - r <= b.max.x && c.y + r >= b.min.y && c.y - r <= b.max.y && c.z + r >= b.min.z &&
           c.z - r <= b.max.z;
}

/// One line of the section of a cap's plane by the other tow, as OCCT gives it: in space and in
/// the other tow's (u,v).
struct SectionLine {
    Handle(Geom_Curve) curve;
    Handle(Geom2d_Curve) onOther;
    double first = 0.0, last = 1.0;  ///< its parameter range
    /// The parameter of the point @p t, which may run past the last one on a closed line.
    double at(double t) const { return t > last ? t - (last - first) : t; }
};

/// What the points of one cap's section are computed against.
struct CapSection {
    const SurfacePair& closed;  ///< the two closed tows
    const GeomAdaptor_Surface& ownTube;
    const CapChart& cap;
    LoopSide side;  ///< the side of the cap's tow
    ParameterRange other;  ///< the other tow's (u,v) range
    double tolerance = 0.0;
};

/// The point at @p t of @p line with its parameters: its own cap chart's (v next to @p vOwn) and
/// the other tow's (v unwrapped next to @p vOther unless that is NaN). False where the chart has
/// none (the cap's centre).
bool sectionPoint(const CapSection& s, const SectionLine& line, double t, double vOwn, double vOther, PointOn2& x)
{
    const gp_Pnt p = line.curve->Value(line.at(t));
    const gp_Pnt2d q = line.onOther->Value(line.at(t));
    double u = 0.0, v = 0.0;
    if (!capParameters(s.ownTube, s.cap, p, vOwn, u, v)) return false;
    const double period = s.other.vPeriod();
    ownU(x, s.side) = u;
    ownV(x, s.side) = v;
    otherU(x, s.side) = q.X();
    otherV(x, s.side) = std::isnan(vOther) ? q.Y() : q.Y() + period * std::round((vOther - q.Y()) / period);
    x.point = fromOcct(p);
    return true;
}

/// Refines a point of the section on the cap onto both tows; where the section ends at the
/// other tow's own end, exactly onto its rim (there the curve goes on across both caps,
/// cap_cap_segment.hpp).
bool refineOnCap(const CapSection& s, PointOn2& x)
{
    const double eps = 1e-6 * (s.other.uMax - s.other.uMin);
    const double u = otherU(x, s.side);
    if (u > s.other.uMin + eps && u < s.other.uMax - eps) return refineNearest(s.closed, x, s.tolerance);
    PointCondition c;
    c.kind = s.side == LoopSide::A ? PointCondition::Kind::FixUB : PointCondition::Kind::FixUA;
    c.value = u <= s.other.uMin + eps ? s.other.uMin : s.other.uMax;
    otherU(x, s.side) = c.value;
    if (!refineOnIntersection(s.closed, x, c, s.tolerance)) return false;
    otherU(x, s.side) = c.value;
    return true;
}

/// Where @p line crosses the cap's rim between @p tIn (on the cap) and @p tOut (beyond it):
/// bisection on the line, then Newton with u exactly the rim's. @p near is a point of the
/// section next to it. False if Newton's method fails.
bool rimPoint(const CapSection& s, const SectionLine& line, double tIn, double tOut, const PointOn2& near, PointOn2& at)
{
    const double vOwn = s.side == LoopSide::A ? near.va : near.vb;
    const double vOther = s.side == LoopSide::A ? near.vb : near.va;
    for (int it = 0; it < 60 && std::abs(tOut - tIn) > 1e-13 * (line.last - line.first); ++it) {
        const double mid = 0.5 * (tIn + tOut);
        double u = 0.0, v = 0.0;
        if (!capParameters(s.ownTube, s.cap, line.curve->Value(line.at(mid)), vOwn, u, v)) break;
        (s.cap.contains(u) ? tIn : tOut) = mid;
    }
    PointOn2 x;
    if (!sectionPoint(s, line, 0.5 * (tIn + tOut), vOwn, vOther, x)) return false;
    PointCondition c;
    c.kind = s.side == LoopSide::A ? PointCondition::Kind::FixUA : PointCondition::Kind::FixUB;
    c.value = s.cap.uRim;
    ownU(x, s.side) = c.value;
    if (!refineOnIntersection(s.closed, x, c, s.tolerance)) return false;
    ownU(x, s.side) = c.value;  // exactly on the rim
    at = x;
    return true;
}

/// An end of a section line on the other tow's seam (OCCT splits the lines there): exactly on
/// the seam, so that it meets the next line's end.
void snapToSeam(const CapSection& s, PointOn2& end)
{
    const double period = s.other.vPeriod();
    const double r = (otherV(end, s.side) - s.other.vMin) / period;
    if (std::abs(r - std::round(r)) > 1e-6) return;
    PointOn2 x = end;
    PointCondition c;
    c.kind = s.side == LoopSide::A ? PointCondition::Kind::FixVB : PointCondition::Kind::FixVA;
    c.value = s.other.vMin + period * std::round(r);
    otherV(x, s.side) = c.value;
    if (refineOnIntersection(s.closed, x, c, s.tolerance)) end = x;
}

/// One sample of a section line.
struct SectionSample {
    double t = 0.0;
    bool in = false;       ///< on the cap (within its rim)
    bool refined = false;  ///< x is on both tows
    PointOn2 x;
};

/// The runs of @p line on the cap: each from rim to rim, or closed (the line lies on the cap
/// whole), or ending where the line does (at the other tow's end or seam).
void runsOnCap(const CapSection& s, const SectionLine& line, double step, std::vector<TracedCurve>& runs)
{
    const int n = std::clamp(static_cast<int>((line.last - line.first) / step), 64, 4000);
    std::vector<SectionSample> samples;
    double vOwn = s.cap.v.front(), vOther = std::nan("");
    for (int k = 0; k <= n; ++k) {
        SectionSample sample;
        sample.t = line.first + (line.last - line.first) * k / n;
        if (!sectionPoint(s, line, sample.t, vOwn, vOther, sample.x)) continue;
        sample.in = s.cap.contains(ownU(sample.x, s.side));
        sample.refined = sample.in && refineOnCap(s, sample.x);
        vOwn = ownV(sample.x, s.side);
        vOther = otherV(sample.x, s.side);
        samples.push_back(sample);
    }
    if (samples.size() < 2) return;
    // The other tow's rim lying in the cap's plane (both tows end in one plane, caps face to
    // face): a contact of the caps, not a curve across them.
    const double eps = 1e-6 * (s.other.uMax - s.other.uMin);
    const auto atOtherEnd = [&](const SectionSample& x) {
        const double u = otherU(x.x, s.side);
        return u <= s.other.uMin + eps || u >= s.other.uMax - eps;
    };
    if (std::all_of(samples.begin(), samples.end(), atOtherEnd)) return;
    const double gap = line.curve->Value(line.first).Distance(line.curve->Value(line.last));
    const bool closedLine = gap <= 1e-5 * s.cap.radius + 10.0 * s.tolerance;
    if (closedLine) samples.pop_back();  // the first again
    const std::size_t m = samples.size();
    const char* const reason = s.side == LoopSide::A ? open_reason::kEndOfB : open_reason::kEndOfA;
    const auto firstOut = std::find_if(samples.begin(), samples.end(), [](const SectionSample& x) { return !x.in; });
    if (firstOut == samples.end()) {
        TracedCurve c;
        for (const SectionSample& x : samples)
            if (x.refined) c.points.push_back(x.x);
        if (c.points.size() < 3) return;
        c.closed = closedLine;
        if (!c.closed) {
            c.openReason = reason;
            snapToSeam(s, c.points.front());
            snapToSeam(s, c.points.back());
        }
        runs.push_back(std::move(c));
        return;
    }
    // From an outside sample on when the line is closed (then once around, its parameter
    // unwrapped past the last); from the line's start when not.
    const std::size_t start = closedLine ? static_cast<std::size_t>(firstOut - samples.begin()) : 0;
    const std::size_t count = closedLine ? m + 1 : m;
    TracedCurve run;
    bool active = false, fromRim = false;
    const auto finish = [&](const char* why) {
        run.openReason = why;
        if (!fromRim && !run.points.empty()) snapToSeam(s, run.points.front());
        if (run.points.size() >= 2) runs.push_back(std::move(run));
        run = TracedCurve{};
        active = false;
    };
    SectionSample previous;
    for (std::size_t i = 0; i < count; ++i) {
        SectionSample sample = samples[(start + i) % m];
        if (start + i >= m) sample.t += line.last - line.first;  // once around
        if (sample.in && !active) {
            PointOn2 r;
            active = true;
            fromRim = i > 0 && rimPoint(s, line, sample.t, previous.t, sample.x, r);
            if (fromRim) run.points.push_back(r);
        }
        if (sample.in && sample.refined) run.points.push_back(sample.x);
        if (!sample.in && active) {
            PointOn2 r;
            const bool rim = rimPoint(s, line, previous.t, sample.t, previous.x, r);
            if (rim) run.points.push_back(r);
            finish(rim ? reason : open_reason::kWalkStops);  // kWalkStops: the rim point not found
        }
        previous = sample;
    }
    if (active) {  // the line ends on the cap
        if (!run.points.empty()) snapToSeam(s, run.points.back());
        finish(reason);
    }
}

/// The pieces of @p other's section by the plane of @p own's cap that lie on the cap: each runs
/// from rim to rim, or is closed (the other tow pierces the cap only), or ends where the section
/// does (at the other tow's end or seam), to be joined later.
std::vector<TracedCurve> capRuns(const SurfacePair& closed, const TowSurface& own, const TowSurface& other, LoopSide side,
                                 const CapChart& cap, const TraceTolerances& tol)
{
    const GeomAdaptor_Surface ownTube(own.impl().surface);
    const double radius = rimRadius(ownTube, cap);
    if (!(radius > 0.0) || !reaches(other.boundingBox(), cap, 1.5 * radius)) return {};
    const double half = 2.0 * radius;
    Handle(Geom_Plane) plane = new Geom_Plane(gp_Pnt(cap.centre), gp_Dir(cap.normal));
    Handle(Geom_RectangularTrimmedSurface) patch = new Geom_RectangularTrimmedSurface(plane, -half, half, -half, half);
    GeomInt_IntSS inter(patch, other.impl().surface, std::max(tol.point, 1e-6 * radius), Standard_True, Standard_False, Standard_True);
    if (!inter.IsDone()) return {};
    const CapSection section{closed, ownTube, cap, side, other.parameterRange(), tol.point};
    std::vector<TracedCurve> runs;
    for (int i = 1; i <= inter.NbLines(); ++i) {
        if (!inter.HasLineOnS2(i)) continue;
        SectionLine line{inter.Line(i), inter.LineOnS2(i)};
        line.first = line.curve->FirstParameter();
        line.last = line.curve->LastParameter();
        if (!(line.last > line.first) || !std::isfinite(line.first) || !std::isfinite(line.last)) continue;
        double length = 0.0;
        for (int k = 1; k <= 32; ++k) {
            const double t0 = line.first + (line.last - line.first) * (k - 1) / 32, t1 = line.first + (line.last - line.first) * k / 32;
            length += line.curve->Value(t1).Distance(line.curve->Value(t0));
        }
        // Samples about 1 % of the cap's radius apart, in the line's parameter.
        const double step = (line.last - line.first) * 0.01 * radius / std::max(length, 1e-300);
        runsOnCap(section, line, step, runs);
    }
    return runs;
}

/// Does @p other's surface cross the plane of @p cap within its disc (radius @p r about the
/// centre, with a margin)? Checked on the tow's input points (the surface interpolates them): a
/// sign change of the distance to the plane between neighbours next to the disc. Cheap; it finds
/// a tow that pierces the cap without touching the tube next to it.
bool pierces(const TowSurface& other, const CapChart& cap, double r)
{
    const BoundingBox box = other.boundingBox();
    if (!reaches(box, cap, 1.5 * r)) return false;
    // The plane must cut the other tow's box.
    bool below = false, above = false;
    for (int k = 0; k < 8; ++k) {
        const gp_XYZ corner((k & 1) ? box.max.x : box.min.x, (k & 2) ? box.max.y : box.min.y, (k & 4) ? box.max.z : box.min.z);
        ((corner - cap.centre).Dot(cap.normal) > 0.0 ? above : below) = true;
    }
    if (!above || !below) return false;
    const std::vector<std::vector<Point3>>& sections = other.sections();
    const auto height = [&](const Point3& p) { return (toOcct(p).XYZ() - cap.centre).Dot(cap.normal); };
    // Where the segment [p, q] crosses the plane, if it does: near the disc?
    const auto crossesNear = [&](const Point3& p, const Point3& q) {
        const double hp = height(p), hq = height(q);
        if ((hp > 0.0) == (hq > 0.0)) return false;
        const double t = hp / (hp - hq);
        const gp_XYZ x = toOcct(p + t * (q - p)).XYZ() - cap.centre;
        // The surface between two input points strays from their chord; a margin covers it.
        return std::hypot(x.Dot(cap.e1), x.Dot(cap.e2)) <= 1.5 * r;
    };
    for (std::size_t i = 0; i < sections.size(); ++i)
        for (std::size_t j = 0; j < sections[i].size(); ++j) {
            const Point3& p = sections[i][j];
            if (crossesNear(p, sections[i][(j + 1) % sections[i].size()])) return true;
            if (i + 1 < sections.size() && j < sections[i + 1].size() && crossesNear(p, sections[i + 1][j])) return true;
        }
    return false;
}

}  // namespace

void closeAcrossCaps(const TowSurface& a, const TowSurface& b, std::vector<TracedCurve>& curves, const TraceTolerances& tol)
{
    const SurfacePair closed = closedPairOf(a, b);
    const TowCaps& capsA = a.impl().caps;
    const TowCaps& capsB = b.impl().caps;
    std::vector<const CapChart*> crossedA, crossedB;  // the caps a curve may cross
    for (const LoopSide side : {LoopSide::A, LoopSide::B}) {
        const TowCaps& caps = side == LoopSide::A ? capsA : capsB;
        for (const CapChart* cap : {&caps.start, &caps.end}) {
            // Caps that an open curve runs into, or that the other tow's surface crosses.
            if (!cap->valid) continue;
            const double eps = 1e-9 * (caps.uMax - caps.uMin);
            const bool reached = std::any_of(curves.begin(), curves.end(), [&](const TracedCurve& c) {
                return !c.closed && !c.points.empty() &&
                       (std::abs(ownU(c.points.front(), side) - cap->uRim) <= eps || std::abs(ownU(c.points.back(), side) - cap->uRim) <= eps);
            });
            if (!reached) {
                const GeomAdaptor_Surface tube((side == LoopSide::A ? a : b).impl().surface);
                if (!pierces(side == LoopSide::A ? b : a, *cap, rimRadius(tube, *cap))) continue;
            }
            (side == LoopSide::A ? crossedA : crossedB).push_back(cap);
            try {
                std::vector<TracedCurve> runs =
                    side == LoopSide::A ? capRuns(closed, a, b, side, *cap, tol) : capRuns(closed, b, a, side, *cap, tol);
                // A cap no curve runs into: only loops wholly on it, clear of its rim (a tow
                // ending on this cap's rim, or touching it there, is no piercing).
                if (!reached) {
                    const double clear = 1e-6 * std::abs(cap->uRim - cap->uPole);
                    runs.erase(std::remove_if(runs.begin(), runs.end(),
                                              [&](const TracedCurve& r) {
                                                  return !r.closed || std::any_of(r.points.begin(), r.points.end(), [&](const PointOn2& p) {
                                                             return std::abs(ownU(p, side) - cap->uRim) <= clear;
                                                         });
                                              }),
                               runs.end());
                }
                for (TracedCurve& r : runs) curves.push_back(std::move(r));
            } catch (const Standard_Failure&) {
                // OCCT could not intersect the cap's plane: the curves into this cap stay open.
            }
        }
    }
    // Where both tows end inside each other, the curve goes on across both caps.
    for (const CapChart* capA : crossedA)
        for (const CapChart* capB : crossedB) {
            const double step = 0.01 * std::min(capA->radius, capB->radius);
            for (TracedCurve& s : capCapSegments(closed, a, *capA, b, *capB, step, tol)) curves.push_back(std::move(s));
        }
    // Join open curves whose ends meet on a rim or a cap.
    const double periodA = a.parameterRange().vPeriod(), periodB = b.parameterRange().vPeriod();
    const double join = 10.0 * tol.closing;
    const auto onCapOrRim = [&](const PointOn2& p) {
        const double ea = 1e-9 * (capsA.uMax - capsA.uMin), eb = 1e-9 * (capsB.uMax - capsB.uMin);
        return p.ua <= capsA.uMin + ea || p.ua >= capsA.uMax - ea || p.ub <= capsB.uMin + eb || p.ub >= capsB.uMax - eb;
    };
    bool joined = true;
    while (joined) {
        joined = false;
        for (std::size_t i = 0; i < curves.size() && !joined; ++i) {
            TracedCurve& c = curves[i];
            if (c.closed || c.points.size() < 2) continue;
            if (!onCapOrRim(c.points.back()) && onCapOrRim(c.points.front())) std::reverse(c.points.begin(), c.points.end());
            if (!onCapOrRim(c.points.back())) continue;
            for (std::size_t j = 0; j < curves.size() && !joined; ++j) {
                TracedCurve& d = curves[j];
                if (j == i || d.closed || d.points.size() < 2) continue;
                if (distance(c.points.back().point, d.points.back().point) < distance(c.points.back().point, d.points.front().point))
                    std::reverse(d.points.begin(), d.points.end());
                if (distance(c.points.back().point, d.points.front().point) > join || !onCapOrRim(d.points.front())) continue;
                std::vector<PointOn2> tail = d.points;
                alignPeriods(tail, c.points.back(), periodA, periodB);
                // Of the two ends that meet, the one exactly on a rim (a corner) stays.
                if (isCorner(closed, tail.front()) && !isCorner(closed, c.points.back())) c.points.back() = tail.front();
                c.points.insert(c.points.end(), tail.begin() + 1, tail.end());
                c.openReason = d.openReason;
                curves.erase(curves.begin() + static_cast<std::ptrdiff_t>(j));
                joined = true;
            }
        }
        // A curve whose two ends met across a cap closes.
        for (TracedCurve& c : curves) {
            if (c.closed || c.points.size() < 3 || !onCapOrRim(c.points.front())) continue;
            if (distance(c.points.front().point, c.points.back().point) <= join) {
                c.points.pop_back();
                c.closed = true;
                c.openReason.clear();
            }
        }
    }
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
