#include "intersect/cap_cap_segment.hpp"

#include <GeomAPI_IntCS.hxx>
#include <Geom_Curve.hxx>
#include <Geom_Plane.hxx>
#include <Standard_Failure.hxx>

#include <algorithm>
#include <cmath>

#include "surface/occt_convert.hpp"
#include "surface/tow_surface_impl.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

/// A point of the planes' common line: its place along the line, and where it lies on a rim
/// (0: inside both caps' interiors, 1: on capA's rim at v = rimV, 2: on capB's rim).
struct LinePoint {
    double t = 0.0;
    int rim = 0;
    double rimV = 0.0;
};

/// Where the rim of @p cap (the iso-line u = uRim of @p tube) crosses @p plane: each crossing's
/// place along the line (origin @p o, unit direction @p d) and the rim's v there.
void rimCrossings(const Handle(Geom_BSplineSurface)& tube, const CapChart& cap, const Handle(Geom_Plane)& plane, const gp_XYZ& o,
                  const gp_XYZ& d, int rim, std::vector<LinePoint>& out)
{
    const Handle(Geom_Curve) iso = tube->UIso(cap.uRim);
    GeomAPI_IntCS inter(iso, plane);
    if (!inter.IsDone()) return;
    for (int i = 1; i <= inter.NbPoints(); ++i) {
        double u = 0.0, v = 0.0, w = 0.0;
        inter.Parameters(i, u, v, w);
        out.push_back({(inter.Point(i).XYZ() - o).Dot(d), rim, w});
    }
}

/// Is @p p (on the cap's plane) strictly inside its rim?
bool insideCap(const GeomAdaptor_Surface& tube, const CapChart& cap, const gp_XYZ& p)
{
    double u = 0.0, v = 0.0;
    return capParameters(tube, cap, gp_Pnt(p), cap.v.front(), u, v) && cap.contains(u);
}

}  // namespace

std::vector<TracedCurve> capCapSegments(const SurfacePair& closed, const TowSurface& a, const CapChart& capA, const TowSurface& b,
                                        const CapChart& capB, double step, const TraceTolerances& tol)
{
    if (!capA.valid || !capB.valid || !(step > 0.0)) return {};
    gp_XYZ d = capA.normal.Crossed(capB.normal);
    const double sine = d.Modulus();
    if (sine < 1e-6) return {};  // parallel planes: caps face to face touch or miss
    // The line's point nearest the origin of the planes' equations n.x = h.
    const double ha = capA.normal.Dot(capA.centre), hb = capB.normal.Dot(capB.centre);
    const gp_XYZ o = (ha * capB.normal.Crossed(d) + hb * d.Crossed(capA.normal)) / (sine * sine);
    d /= sine;
    const GeomAdaptor_Surface tubeA(a.impl().surface), tubeB(b.impl().surface);
    std::vector<LinePoint> crossings;
    try {
        rimCrossings(a.impl().surface, capA, new Geom_Plane(gp_Pnt(capB.centre), gp_Dir(capB.normal)), o, d, 1, crossings);
        rimCrossings(b.impl().surface, capB, new Geom_Plane(gp_Pnt(capA.centre), gp_Dir(capA.normal)), o, d, 2, crossings);
    } catch (const Standard_Failure&) {
        return {};
    }
    std::sort(crossings.begin(), crossings.end(), [](const LinePoint& x, const LinePoint& y) { return x.t < y.t; });
    std::vector<TracedCurve> segments;
    for (std::size_t k = 0; k + 1 < crossings.size(); ++k) {
        const LinePoint& from = crossings[k];
        const LinePoint& to = crossings[k + 1];
        const double length = to.t - from.t;
        if (!(length > tol.closing)) continue;
        const gp_XYZ mid = o + 0.5 * (from.t + to.t) * d;
        if (!insideCap(tubeA, capA, mid) || !insideCap(tubeB, capB, mid)) continue;
        const int n = std::max(2, static_cast<int>(std::ceil(length / step)));
        TracedCurve segment;
        segment.openReason = open_reason::kEndOfA;
        double vA = from.rim == 1 ? from.rimV : capA.v.front(), vB = from.rim == 2 ? from.rimV : capB.v.front();
        bool complete = true;
        for (int i = 0; i <= n && complete; ++i) {
            const LinePoint& end = i == 0 ? from : to;
            const bool atEnd = i == 0 || i == n;
            const gp_XYZ p = o + (from.t + length * i / n) * d;
            PointOn2 x;
            x.point = fromOcct(gp_Pnt(p));
            complete = capParameters(tubeA, capA, gp_Pnt(p), vA, x.ua, x.va) && capParameters(tubeB, capB, gp_Pnt(p), vB, x.ub, x.vb);
            if (!complete) break;
            PointCondition c;
            if (atEnd && end.rim != 0) {
                // Exactly on the rim it starts or ends at: there it meets a curve on the tube.
                c.kind = end.rim == 1 ? PointCondition::Kind::FixUA : PointCondition::Kind::FixUB;
                c.value = end.rim == 1 ? capA.uRim : capB.uRim;
                (end.rim == 1 ? x.ua : x.ub) = c.value;
                complete = refineOnIntersection(closed, x, c, tol.point);
                (end.rim == 1 ? x.ua : x.ub) = c.value;
            } else {
                complete = refineNearest(closed, x, tol.point);
            }
            vA = x.va;
            vB = x.vb;
            if (complete) segment.points.push_back(x);
        }
        if (complete) segments.push_back(std::move(segment));
    }
    return segments;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
