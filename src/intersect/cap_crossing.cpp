#include "intersect/cap_crossing.hpp"

#include <Geom2d_Curve.hxx>
#include <GeomInt_IntSS.hxx>
#include <Geom_Plane.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Standard_Failure.hxx>
#include <gp_Pnt2d.hxx>

#include <algorithm>
#include <cmath>

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

/// The point where the chord from @p in (on the cap) to @p out (past its rim) crosses the rim,
/// refined onto both tows. False if Newton's method fails.
bool rimCrossing(const SurfacePair& closed, LoopSide side, const CapChart& cap, const PointOn2& in, const PointOn2& out,
                 double tolerance, PointOn2& at)
{
    const double a = ownU(in, side), b = ownU(out, side);
    const double t = b != a ? std::clamp((cap.uRim - a) / (b - a), 0.0, 1.0) : 0.5;
    PointOn2 x;
    x.ua = in.ua + t * (out.ua - in.ua);
    x.va = in.va + t * (out.va - in.va);
    x.ub = in.ub + t * (out.ub - in.ub);
    x.vb = in.vb + t * (out.vb - in.vb);
    ownU(x, side) = cap.uRim;
    x.point = in.point + t * (out.point - in.point);
    PointCondition c;
    c.kind = side == LoopSide::A ? PointCondition::Kind::FixUA : PointCondition::Kind::FixUB;
    c.value = cap.uRim;
    if (!refineOnIntersection(closed, x, c, tolerance)) return false;
    ownU(x, side) = cap.uRim;  // exactly on the rim
    at = x;
    return true;
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
    const double otherPeriod = other.parameterRange().vPeriod();
    const double otherMin = other.parameterRange().uMin, otherMax = other.parameterRange().uMax;
    const double otherEps = 1e-6 * (otherMax - otherMin);
    std::vector<TracedCurve> runs;
    for (int i = 1; i <= inter.NbLines(); ++i) {
        if (!inter.HasLineOnS2(i)) continue;
        const Handle(Geom_Curve)& curve = inter.Line(i);
        const Handle(Geom2d_Curve)& onOther = inter.LineOnS2(i);
        const double f = curve->FirstParameter(), l = curve->LastParameter();
        if (!(l > f) || !std::isfinite(f) || !std::isfinite(l)) continue;
        double length = 0.0;
        for (int k = 1; k <= 32; ++k) length += curve->Value(f + (l - f) * k / 32).Distance(curve->Value(f + (l - f) * (k - 1) / 32));
        const int n = std::clamp(static_cast<int>(length / (0.01 * radius)), 64, 4000);
        std::vector<PointOn2> pts;
        std::vector<char> in;
        double vOwn = cap.v.front(), vOther = std::nan("");
        for (int k = 0; k <= n; ++k) {
            const double t = f + (l - f) * k / n;
            const gp_Pnt p = curve->Value(t);
            const gp_Pnt2d q = onOther->Value(t);
            PointOn2 x;
            double u = 0.0, v = 0.0;
            if (!capParameters(ownTube, cap, p, vOwn, u, v)) continue;
            ownU(x, side) = u;
            ownV(x, side) = v;
            otherU(x, side) = q.X();
            otherV(x, side) = std::isnan(vOther) ? q.Y() : q.Y() + otherPeriod * std::round((vOther - q.Y()) / otherPeriod);
            x.point = fromOcct(p);
            // The section reaches the other tow's own end on this cap (both tows end there, cap
            // against cap): this line is not followed, the curves into it stay open.
            if ((q.X() <= otherMin + otherEps || q.X() >= otherMax - otherEps) && cap.contains(u)) {
                pts.clear();
                break;
            }
            if (!refineNearest(closed, x, tol.point)) continue;
            vOwn = ownV(x, side);
            vOther = otherV(x, side);
            pts.push_back(x);
            in.push_back(cap.contains(ownU(x, side)) ? 1 : 0);
        }
        if (pts.size() < 3) continue;
        // A section line that ends at the other tow's seam (OCCT splits it there): its end
        // exactly on the seam, so that it meets the next line's start.
        const ParameterRange otherRange = other.parameterRange();
        for (PointOn2* end : {&pts.front(), &pts.back()}) {
            const double r = (otherV(*end, side) - otherRange.vMin) / otherPeriod;
            if (std::abs(r - std::round(r)) > 1e-6) continue;
            PointOn2 x = *end;
            PointCondition c;
            c.kind = side == LoopSide::A ? PointCondition::Kind::FixVB : PointCondition::Kind::FixVA;
            c.value = otherRange.vMin + otherPeriod * std::round(r);
            otherV(x, side) = c.value;
            if (refineOnIntersection(closed, x, c, tol.point)) *end = x;
        }
        const double step = length / n;
        const bool closedLine = distance(pts.front().point, pts.back().point) <= 2.0 * step;
        if (closedLine && distance(pts.front().point, pts.back().point) <= 1e-3 * step) {
            pts.pop_back();
            in.pop_back();
        }
        const std::size_t m = pts.size();
        if (std::all_of(in.begin(), in.end(), [](char c) { return c != 0; })) {
            TracedCurve c;
            c.points = pts;
            c.closed = closedLine;
            c.openReason = c.closed ? "" : side == LoopSide::A ? open_reason::kEndOfB : open_reason::kEndOfA;
            runs.push_back(std::move(c));
            continue;
        }
        // Runs of points on the cap, from an outside point on (cyclically when the line closes).
        std::size_t first = 0;
        if (closedLine)
            while (in[first]) ++first;
        const std::size_t count = closedLine ? m : m - first;
        TracedCurve run;
        for (std::size_t s = 0; s <= count; ++s) {
            const bool past = s == count;
            const std::size_t k = (first + s) % m;
            const bool inside = !past && in[k];
            const std::size_t prev = (k + m - 1) % m;
            const bool hasPrev = closedLine || first + s > 0;
            if (inside && run.points.empty()) {
                PointOn2 r;
                if (hasPrev && !in[prev] && rimCrossing(closed, side, cap, pts[k], pts[prev], tol.point, r)) run.points.push_back(r);
                run.points.push_back(pts[k]);
            } else if (inside) {
                run.points.push_back(pts[k]);
            } else if (!run.points.empty()) {
                PointOn2 r;
                run.openReason = side == LoopSide::A ? open_reason::kEndOfB : open_reason::kEndOfA;
                if (!past || closedLine) {
                    if (rimCrossing(closed, side, cap, pts[prev], pts[k], tol.point, r))
                        run.points.push_back(r);
                    else
                        run.openReason = open_reason::kWalkStops;  // the rim point not found
                }
                if (run.points.size() >= 2) runs.push_back(std::move(run));
                run = TracedCurve{};
            }
        }
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
