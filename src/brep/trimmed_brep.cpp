// The resolved tows as trimmed B-spline solids (OpenCASCADE B-rep): each intersection loop one
// edge with its curves on both surfaces, each tow's surface cut along its loops into faces, the
// primary's face inside a region's loop used by both solids, planar caps at the ends.
#include "towgeom/trimmed_brep.hpp"

#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepLib.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <Geom2dAPI_Interpolate.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_Line.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_Plane.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <TColgp_HArray1OfPnt2d.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <utility>

#include "brep/cell_clip.hpp"
#include "brep/measure.hpp"
#include "brep/rank_fuse.hpp"
#include "brep/trimmed_brep_impl.hpp"
#include "surface/occt_convert.hpp"
#include "surface/tow_surface_impl.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"
#include "towgeom/volume_mesh.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

using detail::areaOf;
using detail::kMeasureEps;

/// A loop on one tow: which loop, and whether the tow's solid keeps the inside as a face of its
/// own surface (an island of a region, or the primary's shared face) or not.
struct LoopOnTow {
    std::size_t loop = 0;
    LoopSide side = LoopSide::A;
};

UV sideOf(const LoopPoint& p, LoopSide side) { return side == LoopSide::A ? p.onA : p.onB; }

LoopSide sideOfTow(const IntersectionLoop& l, std::size_t tow) { return l.towA() == tow ? LoopSide::A : LoopSide::B; }

std::string pairName(const std::vector<TowSurface>& tows, const IntersectionLoop& l)
{
    return "tows '" + tows[l.towA()].name() + "' and '" + tows[l.towB()].name() + "'";
}

/// Twice the signed area of the loop's (u,v) polygon on @p side: positive when it runs
/// counter-clockwise in (u,v).
double signedArea(const IntersectionLoop& l, LoopSide side)
{
    const std::vector<LoopPoint>& p = l.points();
    double a = 0.0;
    for (std::size_t k = 0; k < p.size(); ++k) {
        const UV x = sideOf(p[k], side), y = sideOf(p[(k + 1) % p.size()], side);
        a += x.u * y.v - y.u * x.v;
    }
    return a;
}

/// The v where tow @p t's face puts its seam: the middle of the widest gap (over one period)
/// between the v ranges of the loops on it, so that no loop crosses the seam.
double seamOf(const std::vector<TowSurface>& tows, const std::vector<IntersectionLoop>& loops,
              const std::vector<LoopOnTow>& on, std::size_t t)
{
    const ParameterRange r = tows[t].parameterRange();
    const double period = r.vPeriod();
    if (on.empty()) return r.vMin;
    // Each loop's v range, its start brought into [vMin, vMin + period).
    std::vector<std::pair<double, double>> ranges;
    for (const LoopOnTow& o : on) {
        double lo = 1e300, hi = -1e300;
        for (const LoopPoint& p : loops[o.loop].points()) {
            lo = std::min(lo, sideOf(p, o.side).v);
            hi = std::max(hi, sideOf(p, o.side).v);
        }
        const double shift = period * std::floor((lo - r.vMin) / period);
        ranges.emplace_back(lo - shift, hi - shift);
    }
    std::sort(ranges.begin(), ranges.end());
    // Merge on the circle: sweep, tracking how far the covered run reaches (from the start,
    // ranges that run past vMin + period and wrap over the circle's start count too).
    double bestGap = -1.0, bestSeam = r.vMin;
    double reach = ranges.front().second;
    for (const auto& x : ranges) reach = std::max(reach, x.second - period);
    for (std::size_t k = 1; k <= ranges.size(); ++k) {
        const double next = k < ranges.size() ? ranges[k].first : ranges.front().first + period;
        if (next - reach > bestGap) {
            bestGap = next - reach;
            bestSeam = 0.5 * (reach + next);
        }
        if (k < ranges.size()) reach = std::max(reach, ranges[k].second);
    }
    // A margin for the loops' (u,v) curves, which may bulge a little past their points.
    if (!(bestGap > 1e-3 * period))
        throw Error(ErrorCode::Unsupported, "tow '" + tows[t].name() + "': its loops cover every v around it, so no seam of "
                                            "its face avoids them (the trimmed B-rep needs a seam no loop crosses)");
    for (const auto& x : ranges) {  // no loop crosses the seam, one period on or back
        const double k = std::ceil((x.first - bestSeam) / period);
        if (bestSeam + k * period < x.second)
            throw Error(ErrorCode::Internal, "tow '" + tows[t].name() + "': the seam chosen for its face crosses a loop");
    }
    return bestSeam;
}

/// The (u,v) of @p points on @p side with v moved by whole periods into (seam, seam + period).
std::vector<UV> uvOn(const std::vector<LoopPoint>& points, LoopSide side, double seam, double period)
{
    std::vector<UV> uv;
    uv.reserve(points.size());
    for (const LoopPoint& p : points) uv.push_back(sideOf(p, side));
    double lo = 1e300;
    for (const UV& x : uv) lo = std::min(lo, x.v);
    const double shift = period * std::floor((lo - seam) / period);
    for (UV& x : uv) x.v -= shift;
    return uv;
}

/// Exact points of a loop per point it has, for its edge's curves: cubic interpolation through
/// the loop's own points (spaced for the chordal tolerance) strays up to ~5e-6 of the tow size
/// from the surfaces, and the STEP file's volumes off by 3e-6; through twice as many, 16 times
/// less (within 1e-6). Each point is a pole of the curves, and OCCT's integrals over a trimmed
/// face slow down with them: four times as many took six times as long. (Approximated curves with
/// fewer poles are not periodic, and OCCT's STEP reader heals their faces into pieces.)
constexpr double kEdgeDensity = 2.0;

/// The edge of closed loop @p l: a periodic B-spline through its exact points (kEdgeDensity per
/// point of the loop) with chord-length parameters, and on each tow a periodic B-spline through
/// their (u,v) at the same parameters, v in that tow's seam period; made same-parameter by OCCT.
TopoDS_Edge loopEdge(const IntersectionLoop& l, const Handle(Geom_BSplineSurface)& sa, double seamA, double periodA,
                     const Handle(Geom_BSplineSurface)& sb, double seamB, double periodB, double tolerance)
{
    const std::vector<LoopPoint> p = l.resample(l.length() / (kEdgeDensity * static_cast<double>(l.points().size())));
    const int n = static_cast<int>(p.size());
    Handle(TColgp_HArray1OfPnt) pts = new TColgp_HArray1OfPnt(1, n);
    Handle(TColStd_HArray1OfReal) params = new TColStd_HArray1OfReal(1, n + 1);
    double s = 0.0;
    for (int k = 0; k < n; ++k) {
        pts->SetValue(k + 1, detail::toOcct(p[static_cast<std::size_t>(k)].point));
        params->SetValue(k + 1, s);
        s += distance(p[static_cast<std::size_t>(k)].point, p[static_cast<std::size_t>((k + 1) % n)].point);
    }
    params->SetValue(n + 1, s);
    const double close = 1e-3 * s / n;  // OCCT refuses points closer than this
    GeomAPI_Interpolate curve(pts, params, Standard_True, close);
    curve.Perform();
    if (!curve.IsDone()) throw Error(ErrorCode::Internal, "OpenCASCADE could not interpolate the loop's points");
    const auto pcurve = [&](LoopSide side, double seam, double period) {
        const std::vector<UV> uv = uvOn(p, side, seam, period);
        Handle(TColgp_HArray1OfPnt2d) q = new TColgp_HArray1OfPnt2d(1, n);
        for (int k = 0; k < n; ++k) q->SetValue(k + 1, gp_Pnt2d(uv[static_cast<std::size_t>(k)].u, uv[static_cast<std::size_t>(k)].v));
        Geom2dAPI_Interpolate c(q, params, Standard_True, 1e-12);
        c.Perform();
        if (!c.IsDone()) throw Error(ErrorCode::Internal, "OpenCASCADE could not interpolate the loop's (u,v) points");
        return c.Curve();
    };
    BRep_Builder b;
    TopoDS_Vertex v;
    b.MakeVertex(v, pts->Value(1), tolerance);
    TopoDS_Edge e;
    b.MakeEdge(e, curve.Curve(), tolerance);
    b.Add(e, v.Oriented(TopAbs_FORWARD));
    b.Add(e, v.Oriented(TopAbs_REVERSED));
    b.Range(e, 0.0, s);
    b.UpdateEdge(e, pcurve(LoopSide::A, seamA, periodA), sa, TopLoc_Location(), tolerance);
    b.UpdateEdge(e, pcurve(LoopSide::B, seamB, periodB), sb, TopLoc_Location(), tolerance);
    b.Range(e, sa, TopLoc_Location(), 0.0, s);
    b.Range(e, sb, TopLoc_Location(), 0.0, s);
    e.Closed(Standard_True);
    // The builder marks a new edge same-parameter: unmark it, so that OCCT checks the curves
    // against each other and sets the tolerance they need.
    b.SameParameter(e, Standard_False);
    b.SameRange(e, Standard_False);
    BRepLib::SameParameter(e, tolerance);
    return e;
}

/// A one-edge wire of @p e that runs counter-clockwise (@p ccw) or clockwise in (u,v) of the
/// surface on @p side of the loop.
TopoDS_Wire wireOf(const TopoDS_Edge& e, const IntersectionLoop& l, LoopSide side, bool ccw)
{
    const bool forward = (signedArea(l, side) > 0.0) == ccw;
    BRep_Builder b;
    TopoDS_Wire w;
    b.MakeWire(w);
    b.Add(w, e.Oriented(forward ? TopAbs_FORWARD : TopAbs_REVERSED));
    w.Closed(Standard_True);
    return w;
}

/// The face of @p s inside the loop wire @p outer (counter-clockwise) with the holes @p holes.
TopoDS_Face insideFace(const Handle(Geom_BSplineSurface)& s, const TopoDS_Wire& outer, const std::vector<TopoDS_Wire>& holes,
                       double tolerance)
{
    BRep_Builder b;
    TopoDS_Face face;
    b.MakeFace(face, s, tolerance);
    b.Add(face, outer);
    for (const TopoDS_Wire& h : holes) b.Add(face, h);
    b.NaturalRestriction(face, Standard_False);
    return face;
}

/// The tube's face over [uMin, uMax] x [seam, seam + period] with its natural boundary: the
/// rims at uMin and uMax (closed edges, returned in @p rims) and the seam at v = seam, one edge
/// with its two curves on the face (OpenCASCADE's MakeFace closes a periodic face this way only
/// at the surface's own first v).
TopoDS_Face tubeFace(const Handle(Geom_BSplineSurface)& s, const ParameterRange& r, double seam, double tolerance,
                     TopoDS_Edge (&rims)[2])
{
    const double v0 = seam, v1 = seam + r.vPeriod();
    BRep_Builder b;
    TopoDS_Face face;
    b.MakeFace(face, s, tolerance);
    TopoDS_Vertex at[2];
    b.MakeVertex(at[0], s->Value(r.uMin, v0), tolerance);
    b.MakeVertex(at[1], s->Value(r.uMax, v0), tolerance);
    const double us[2] = {r.uMin, r.uMax};
    for (int k = 0; k < 2; ++k) {
        TopoDS_Edge& e = rims[k];
        // The rim's curve starts at the seam (a periodic curve's own origin elsewhere would make
        // the caps' curves on their planes start there too).
        Handle(Geom_BSplineCurve) rim = Handle(Geom_BSplineCurve)::DownCast(s->UIso(us[k]));
        if (rim.IsNull()) throw Error(ErrorCode::Internal, "an iso-u curve of a tow's surface is not a B-spline");
        rim->SetOrigin(v0, 1e-12 * r.vPeriod());
        rim->SetNotPeriodic();
        b.MakeEdge(e, rim, tolerance);
        b.UpdateEdge(e, new Geom2d_Line(gp_Pnt2d(us[k], 0.0), gp_Dir2d(0.0, 1.0)), face, tolerance);
        b.Add(e, at[k].Oriented(TopAbs_FORWARD));
        b.Add(e, at[k].Oriented(TopAbs_REVERSED));
        b.Range(e, v0, v1);
        e.Closed(Standard_True);
    }
    TopoDS_Edge seamEdge;
    b.MakeEdge(seamEdge, s->VIso(v0), tolerance);
    b.UpdateEdge(seamEdge, new Geom2d_Line(gp_Pnt2d(0.0, v0), gp_Dir2d(1.0, 0.0)),
                 new Geom2d_Line(gp_Pnt2d(0.0, v1), gp_Dir2d(1.0, 0.0)), face, tolerance);
    b.Add(seamEdge, at[0].Oriented(TopAbs_FORWARD));
    b.Add(seamEdge, at[1].Oriented(TopAbs_REVERSED));
    b.Range(seamEdge, r.uMin, r.uMax);
    TopoDS_Wire w;
    b.MakeWire(w);
    b.Add(w, rims[0].Oriented(TopAbs_REVERSED));
    b.Add(w, seamEdge.Oriented(TopAbs_FORWARD));
    b.Add(w, rims[1].Oriented(TopAbs_FORWARD));
    b.Add(w, seamEdge.Oriented(TopAbs_REVERSED));
    w.Closed(Standard_True);
    b.Add(face, w);
    return face;
}

/// The outward direction at the tube's end @p u (the mean of -+dS/du around it).
gp_Vec outwardAtEnd(const Handle(Geom_BSplineSurface)& s, double u, double vMin, double period, bool atStart)
{
    gp_Vec sum(0.0, 0.0, 0.0);
    for (int k = 0; k < 16; ++k) {
        gp_Pnt p;
        gp_Vec du, dv;
        s->D1(u, vMin + period * k / 16.0, p, du, dv);
        sum += du;
    }
    return atStart ? -sum : sum;
}

/// The planar cap closing the tube at its rim @p rim (iso-u curve of @p s at @p u, v over
/// [v0, v0 + period]), its normal @p outward: the plane through the rim's centroid with its
/// Newell normal; the rim's tolerance raised to its largest distance from that plane.
TopoDS_Face capFace(const Handle(Geom_BSplineSurface)& s, double u, double v0, double period, TopoDS_Edge& rim,
                    const gp_Vec& outward, double size, const std::string& tow, const char* end)
{
    constexpr int kSamples = 256;
    std::vector<gp_Pnt> p;
    gp_XYZ centre(0.0, 0.0, 0.0), newell(0.0, 0.0, 0.0);
    for (int k = 0; k < kSamples; ++k) {
        p.push_back(s->Value(u, v0 + period * k / kSamples));
        centre += p.back().XYZ();
    }
    centre /= kSamples;
    for (int k = 0; k < kSamples; ++k) newell += (p[k].XYZ() - centre).Crossed(p[(k + 1) % kSamples].XYZ() - centre);
    if (!(newell.Modulus() > 0.0)) throw Error(ErrorCode::Internal, "the " + std::string(end) + " section of tow '" + tow + "' encloses no area");
    const gp_Dir along(newell);  // the rim runs counter-clockwise about it
    const bool rimForward = gp_Vec(along).Dot(outward) > 0.0;
    const gp_Dir normal = rimForward ? along : along.Reversed();
    double deviation = 0.0;
    for (const gp_Pnt& q : p) deviation = std::max(deviation, std::abs((q.XYZ() - centre).Dot(normal.XYZ())));
    if (deviation > 1e-3 * size)
        throw Error(ErrorCode::Unsupported, "tow '" + tow + "': its " + end + " section is not planar (its points lie up to " +
                                                std::to_string(deviation) + " off their plane): the trimmed B-rep closes tows with "
                                                "planar caps only");
    BRep_Builder b;
    if (deviation > BRep_Tool::Tolerance(rim)) b.UpdateEdge(rim, 1.01 * deviation);
    for (TopExp_Explorer x(rim, TopAbs_VERTEX); x.More(); x.Next())
        b.UpdateVertex(TopoDS::Vertex(x.Current()), std::max(BRep_Tool::Tolerance(TopoDS::Vertex(x.Current())), BRep_Tool::Tolerance(rim)));
    TopoDS_Face face;
    b.MakeFace(face, new Geom_Plane(gp_Pnt(centre), normal), BRep_Tool::Tolerance(rim));
    TopoDS_Wire w;
    b.MakeWire(w);
    b.Add(w, rim.Oriented(rimForward ? TopAbs_FORWARD : TopAbs_REVERSED));
    w.Closed(Standard_True);
    b.Add(face, w);
    BRepLib::BuildPCurveForEdgeOnPlane(rim, face);
    return face;
}

/// The largest tolerance of @p shape's edges and vertices.
double maxToleranceOf(const TopoDS_Shape& shape)
{
    double m = 0.0;
    for (TopExp_Explorer x(shape, TopAbs_EDGE); x.More(); x.Next()) m = std::max(m, BRep_Tool::Tolerance(TopoDS::Edge(x.Current())));
    for (TopExp_Explorer x(shape, TopAbs_VERTEX); x.More(); x.Next())
        m = std::max(m, BRep_Tool::Tolerance(TopoDS::Vertex(x.Current())));
    return m;
}

/// @throws towgeom::Error (InvalidArgument) when @p r is not of @p tows, (Unsupported) when it
/// was not made by the connect method.
void checkInput(const std::vector<TowSurface>& tows, const ResolveResult& r)
{
    if (r.tows.size() != tows.size() || r.mesh.tows.size() != tows.size())
        throw Error(ErrorCode::InvalidArgument, "trimmedBrep: the resolve result is of " + std::to_string(r.tows.size()) +
                                                    " tows, not of the " + std::to_string(tows.size()) + " given");
    for (std::size_t t = 0; t < tows.size(); ++t)
        if (r.mesh.tows[t].name != tows[t].name())
            throw Error(ErrorCode::InvalidArgument, "trimmedBrep: tow " + std::to_string(t) + " of the resolve result is '" +
                                                        r.mesh.tows[t].name + "', not '" + tows[t].name() + "'");
    if (r.method != ResolutionMethod::Connect)
        throw Error(ErrorCode::Unsupported, "the trimmed B-rep is built for the connect method only (the symmetric method's "
                                            "mid-surfaces and the shrunk tows are not B-spline faces of the input tows)");
}

/// @throws towgeom::Error (Unsupported) for what the loops alone do not build (fuseByRank()
/// does): triple points, loops that wind around a tow or run across a cap; (Internal) for an
/// open loop bounding a region.
void checkLoopsTrim(const std::vector<TowSurface>& tows, const ResolveResult& r)
{
    if (!r.mesh.triplePoints.empty())
        throw Error(ErrorCode::Unsupported, "the trimmed B-rep is not built where three tows meet (" +
                                                std::to_string(r.mesh.triplePoints.size()) + " triple points)");
    const auto check = [&](std::size_t k) {
        if (k >= r.intersections.loops.size())
            throw Error(ErrorCode::InvalidArgument, "trimmedBrep: a region names loop " + std::to_string(k) + " of " +
                                                        std::to_string(r.intersections.loops.size()));
        const IntersectionLoop& l = r.intersections.loops[k];
        const std::string what = "the loop of " + pairName(tows, l);
        if (!l.closed()) throw Error(ErrorCode::Internal, what + " bounds a region but is open");
        if (l.windsAround(LoopSide::A) || l.windsAround(LoopSide::B))
            throw Error(ErrorCode::Unsupported, what + " winds around a tow (one passes through or ends inside the other): "
                                                       "not built as a trimmed B-rep yet");
        if (l.crossesCap(LoopSide::A) || l.crossesCap(LoopSide::B))
            throw Error(ErrorCode::Unsupported, what + " runs across an end cap: not built as a trimmed B-rep yet");
    };
    for (const ConnectedRegion& g : r.mesh.regions) {
        if (g.surface != SharedSurface::Primary) throw Error(ErrorCode::Internal, "a connect region off the primary's surface");
        check(g.loop);
        const IntersectionLoop& l = r.intersections.loops[g.loop];
        if (std::minmax(g.primary, g.secondary) != std::minmax(l.towA(), l.towB()))
            throw Error(ErrorCode::InvalidArgument, "trimmedBrep: a region's tows are not those of its loop");
        for (std::size_t h : g.holes) check(h);
    }
}

/// Whether two loops' (u,v) polygons on one tow (already in the same seam period) cross or one
/// lies inside the other.
bool overlapInUv(const std::vector<UV>& a, const std::vector<UV>& b)
{
    const auto box = [](const std::vector<UV>& p) {
        std::array<double, 4> x{1e300, -1e300, 1e300, -1e300};
        for (const UV& q : p) x = {std::min(x[0], q.u), std::max(x[1], q.u), std::min(x[2], q.v), std::max(x[3], q.v)};
        return x;
    };
    const auto ba = box(a), bb = box(b);
    if (ba[1] < bb[0] || bb[1] < ba[0] || ba[3] < bb[2] || bb[3] < ba[2]) return false;
    const auto inside = [](const UV& q, const std::vector<UV>& p) {
        bool in = false;
        for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++)
            if ((p[i].v > q.v) != (p[j].v > q.v) && q.u < (p[j].u - p[i].u) * (q.v - p[i].v) / (p[j].v - p[i].v) + p[i].u) in = !in;
        return in;
    };
    if (inside(a.front(), b) || inside(b.front(), a)) return true;
    const auto orient = [](const UV& p, const UV& q, const UV& s) { return (q.u - p.u) * (s.v - p.v) - (q.v - p.v) * (s.u - p.u); };
    for (std::size_t i = 0; i < a.size(); ++i) {
        const UV &p = a[i], &q = a[(i + 1) % a.size()];
        for (std::size_t j = 0; j < b.size(); ++j) {
            const UV &s = b[j], &t = b[(j + 1) % b.size()];
            if ((orient(p, q, s) > 0.0) != (orient(p, q, t) > 0.0) && (orient(s, t, p) > 0.0) != (orient(s, t, q) > 0.0)) return true;
        }
    }
    return false;
}

}  // namespace

TrimmedBrep::TrimmedBrep(std::shared_ptr<const Impl> impl, std::vector<BrepSolid> solids, std::size_t sharedFaces, BrepSolid matrix,
                         std::string matrixNote, std::string fusedBecause)
    : impl_(std::move(impl)),
      solids_(std::move(solids)),
      sharedFaces_(sharedFaces),
      matrix_(std::move(matrix)),
      matrixNote_(std::move(matrixNote)),
      fusedBecause_(std::move(fusedBecause))
{
}

namespace {

/// The matrix of a cell: the box minus the tows' clipped solids (@p impl's), added to the compound
/// as MATRIX; volume the box's less the tows' (@p tows), area the box's faces less the tows'
/// faces on them plus the tows' faces no other tow shares and not on the box (@p clipped). Not built
/// (faces 0, @p note why) while tows of @p r still overlap. The tows' tolerances and validity
/// are read again (the boolean may raise tolerances on their own edges).
BrepSolid buildMatrix(TrimmedBrep::Impl& impl, const ResolveResult& r, const std::vector<TowSurface>& names,
                      std::vector<BrepSolid>& tows, const detail::ClippedTows& clipped, BRep_Builder& b, std::string& note)
{
    BrepSolid m;
    m.name = "MATRIX";
    const Cell& cell = r.mesh.cell->box;
    const std::vector<UnresolvedPairEntry> overlapping = overlappingPairs(r);
    if (!overlapping.empty()) {
        const UnresolvedPairEntry& p = overlapping.front();
        std::set<std::pair<std::size_t, std::size_t>> pairs;  // distinct pairs (one may have several reasons)
        for (const UnresolvedPairEntry& e : overlapping) pairs.insert({e.towA, e.towB});
        note = "tows '" + names[p.towA].name() + "' and '" + names[p.towB].name() + "' still overlap [" + p.code + "]" +
               (pairs.size() > 1 ? " (and " + std::to_string(pairs.size() - 1) + " other pair" + (pairs.size() > 2 ? "s" : "") + ")"
                                 : std::string()) +
               ": the box less the tows would not be the matrix";
        return m;
    }
    const std::size_t towSolids = impl.solids.size();  // the tows inside the cell, in order
    const detail::MatrixCut cut = detail::cutMatrix(impl.solids, cell, clipped.onBox);
    std::size_t k = 0;
    for (BrepSolid& t : tows)
        if (t.faces > 0 && k < towSolids) {
            t.maxTolerance = maxToleranceOf(impl.solids[k]);
            t.valid = BRepCheck_Analyzer(impl.solids[k++]).IsValid();
        }
    if (!cut.failure.empty()) {
        note = cut.failure;
        return m;
    }
    const double dx = cell.max.x - cell.min.x, dy = cell.max.y - cell.min.y, dz = cell.max.z - cell.min.z;
    m.volume = cell.volume();
    for (const BrepSolid& t : tows) m.volume -= t.volume;
    m.area = 2.0 * (dx * dy + dy * dz + dz * dx) - clipped.onBoxAreas + clipped.freeAreas;
    m.faces = cut.faces;
    m.sharedFaces = cut.sharedFaces;
    m.cellFaces = cut.cellFaces;
    m.valid = true;  // cutMatrix() checked every piece
    for (const TopoDS_Solid& piece : cut.pieces) {
        b.Add(impl.compound, piece);
        impl.solids.push_back(piece);
        impl.names.push_back(m.name);
        m.maxTolerance = std::max(m.maxTolerance, maxToleranceOf(piece));
    }
    return m;
}

}  // namespace

namespace {

/// The tows trimmed by their loops (each loop one edge; see trimmedBrep()).
/// @throws towgeom::Error (Unsupported) for what the loops alone do not build.
TrimmedBrep loopTrimmed(const std::vector<TowSurface>& tows, const ResolveResult& r, const BrepOptions& o, double tolerance)
{
    checkLoopsTrim(tows, r);
    const std::vector<IntersectionLoop>& loops = r.intersections.loops;

    // The loops on each tow, its seam, and per tow the loops whose inside is not part of its own
    // main face.
    std::vector<std::vector<LoopOnTow>> on(tows.size());
    for (const ConnectedRegion& g : r.mesh.regions)
        for (std::size_t k : [&] { std::vector<std::size_t> all{g.loop}; all.insert(all.end(), g.holes.begin(), g.holes.end()); return all; }())
            for (std::size_t t : {g.primary, g.secondary}) on[t].push_back({k, sideOfTow(loops[k], t)});
    std::vector<double> seam(tows.size());
    for (std::size_t t = 0; t < tows.size(); ++t) seam[t] = seamOf(tows, loops, on[t], t);
    // Loops on one tow must not meet or nest, but for a region's islands inside its loop: loops
    // of two pairs that do are a third tow's overlap; a region inside another's island (loops
    // nested three deep) is not built either.
    const auto holeOf = [&](std::size_t hole, std::size_t loop) {
        return std::any_of(r.mesh.regions.begin(), r.mesh.regions.end(), [&](const ConnectedRegion& g) {
            return g.loop == loop && std::find(g.holes.begin(), g.holes.end(), hole) != g.holes.end();
        });
    };
    for (std::size_t t = 0; t < tows.size(); ++t) {
        const double period = tows[t].parameterRange().vPeriod();
        for (std::size_t i = 0; i < on[t].size(); ++i)
            for (std::size_t j = i + 1; j < on[t].size(); ++j) {
                const std::size_t li = on[t][i].loop, lj = on[t][j].loop;
                if (holeOf(li, lj) || holeOf(lj, li)) continue;
                const IntersectionLoop &a = loops[li], &b = loops[lj];
                if (!overlapInUv(uvOn(a.points(), on[t][i].side, seam[t], period), uvOn(b.points(), on[t][j].side, seam[t], period)))
                    continue;
                if (a.towA() == b.towA() && a.towB() == b.towB())
                    throw Error(ErrorCode::Unsupported, "on tow '" + tows[t].name() + "' loops of " + pairName(tows, a) +
                                                            " lie inside one another more than two deep (a region inside "
                                                            "another's island): not built as a trimmed B-rep yet");
                throw Error(ErrorCode::Unsupported, "on tow '" + tows[t].name() + "' the loops of " + pairName(tows, a) + " and of " +
                                                        pairName(tows, b) + " overlap (three tows overlap there): not built as a "
                                                        "trimmed B-rep yet");
            }
    }

    auto impl = std::make_shared<TrimmedBrep::Impl>();
    std::vector<BrepSolid> solids(tows.size());
    BrepSolid matrix;  // with a cell: the box minus the tows
    std::string matrixNote;  // why it is not built
    std::size_t sharedCount = 0;
    try {
        // 1. One edge per loop.
        std::map<std::size_t, TopoDS_Edge> edges;
        for (std::size_t t = 0; t < tows.size(); ++t)
            for (const LoopOnTow& x : on[t]) {
                if (edges.count(x.loop)) continue;
                const IntersectionLoop& l = loops[x.loop];
                const TowSurface &a = tows[l.towA()], &b = tows[l.towB()];
                edges[x.loop] = loopEdge(l, a.impl().surface, seam[l.towA()], a.parameterRange().vPeriod(), b.impl().surface,
                                         seam[l.towB()], b.parameterRange().vPeriod(), tolerance);
            }
        const auto wire = [&](std::size_t loop, std::size_t tow, bool ccw) {
            return wireOf(edges.at(loop), loops[loop], sideOfTow(loops[loop], tow), ccw);
        };
        // 2. Faces inside loops: per region the shared face on the primary, the islands on both.
        std::vector<std::vector<TopoDS_Face>> faces(tows.size());  // oriented as in each tow's shell
        std::vector<std::size_t> loopCount(tows.size(), 0);
        std::vector<detail::SharedFace> sharedFaces;  // per region, its face and the two tows sharing it
        for (const ConnectedRegion& g : r.mesh.regions) {
            const Handle(Geom_BSplineSurface)& sp = tows[g.primary].impl().surface;
            std::vector<TopoDS_Wire> holes;
            for (std::size_t h : g.holes) holes.push_back(wire(h, g.primary, false));
            const TopoDS_Face face = insideFace(sp, wire(g.loop, g.primary, true), holes, tolerance);
            faces[g.primary].push_back(face);
            faces[g.secondary].push_back(TopoDS::Face(face.Reversed()));
            sharedFaces.push_back({g.primary, g.secondary, face});
            ++sharedCount;
            for (std::size_t h : g.holes)
                for (std::size_t t : {g.primary, g.secondary})
                    faces[t].push_back(insideFace(tows[t].impl().surface, wire(h, t, true), {}, tolerance));
        }
        // 3. Each tow's own surface outside its loops, and its caps; the solid.
        std::vector<TopoDS_Solid> built(tows.size());
        BRep_Builder b;
        b.MakeCompound(impl->compound);
        for (std::size_t t = 0; t < tows.size(); ++t) {
            const TowSurface& tow = tows[t];
            const Handle(Geom_BSplineSurface)& s = tow.impl().surface;
            const ParameterRange pr = tow.parameterRange();
            TopoDS_Edge rims[2];
            TopoDS_Face face = tubeFace(s, pr, seam[t], tolerance, rims);
            // The solid's volume and area: the whole tow closed by its caps (its exact volume and
            // area, TowSurface's own integrals), less the disc of its surface inside each outer
            // loop on it, plus the faces inside loops (shared faces, islands). The discs (reversed)
            // and those faces close up around what changed: BRepGProp integrates them in one
            // call, about one point (a face's volume alone is taken about a point of its own), on
            // small faces (over the tube's face with the loops as holes it takes seconds per tow).
            TopoDS_Compound change;
            b.MakeCompound(change);
            double area = tow.area();
            for (const LoopOnTow& x : on[t]) {
                const bool outer = std::any_of(r.mesh.regions.begin(), r.mesh.regions.end(),
                                               [&](const ConnectedRegion& g) { return g.loop == x.loop; });
                if (!outer) continue;  // islands lie inside an outer loop
                b.Add(face, wire(x.loop, t, false));
                const TopoDS_Face disc = insideFace(s, wire(x.loop, t, true), {}, tolerance);
                b.Add(change, disc.Reversed());
                area -= areaOf(disc);
            }
            b.NaturalRestriction(face, Standard_False);
            loopCount[t] = on[t].size();
            for (const TopoDS_Face& f : faces[t]) {  // shared faces and islands
                b.Add(change, f);
                area += areaOf(f);
            }
            GProp_GProps changed;
            BRepGProp::VolumeProperties(change, changed, kMeasureEps);
            faces[t].push_back(face);
            for (int k = 0; k < 2; ++k) {
                const double u = k == 0 ? pr.uMin : pr.uMax;
                faces[t].push_back(capFace(s, u, seam[t], pr.vPeriod(), rims[k], outwardAtEnd(s, u, pr.vMin, pr.vPeriod(), k == 0),
                                           tow.towSize(), tow.name(), k == 0 ? "first" : "last"));
                area += areaOf(faces[t].back());
            }
            TopoDS_Shell shell;
            b.MakeShell(shell);
            for (const TopoDS_Face& f : faces[t]) b.Add(shell, f);
            shell.Closed(BRep_Tool::IsClosed(shell));
            TopoDS_Solid solid;
            b.MakeSolid(solid);
            b.Add(solid, shell);
            BrepSolid& out = solids[t];
            out.name = tow.name();
            out.volume = tow.volume() + changed.Mass();
            out.area = area;
            out.faces = faces[t].size();
            out.loops = loopCount[t];
            built[t] = solid;
        }
        // 4. With a cell, each solid clipped to the box: the tows sharing a face the box cuts
        // (or nearly touches) together, the others alone.
        detail::ClippedTows clipped;
        if (r.mesh.cell) {
            clipped = detail::clipTowsToCell(tows, r, sharedFaces, built, solids, o.matrix);
            sharedCount = clipped.sharedFaces;
        }
        for (std::size_t t = 0; t < tows.size(); ++t) {
            if (built[t].IsNull()) continue;  // wholly outside the cell: no solid
            b.Add(impl->compound, built[t]);
            impl->solids.push_back(built[t]);
            impl->names.push_back(tows[t].name());
            BrepSolid& out = solids[t];
            if (!r.mesh.cell)
                out.sharedFaces = static_cast<std::size_t>(std::count_if(sharedFaces.begin(), sharedFaces.end(), [&](const detail::SharedFace& f) {
                    return f.towA == t || f.towB == t;
                }));
            out.valid = BRepCheck_Analyzer(built[t]).IsValid();
            out.maxTolerance = maxToleranceOf(built[t]);
        }
        if (r.mesh.cell && o.matrix) matrix = buildMatrix(*impl, r, tows, solids, clipped, b, matrixNote);
    } catch (const Standard_Failure& e) {
        throw Error(ErrorCode::Internal, std::string("OpenCASCADE failed building the trimmed B-rep: ") + e.GetMessageString());
    }
    return TrimmedBrep(std::move(impl), std::move(solids), sharedCount, std::move(matrix), std::move(matrixNote));
}

/// Tow @p t's whole solid: its B-spline face with its natural boundary (seam at vMin) and its two
/// planar caps; @p area the area of its boundary.
TopoDS_Solid wholeSolid(const TowSurface& tow, double tolerance, double& area)
{
    const Handle(Geom_BSplineSurface)& s = tow.impl().surface;
    const ParameterRange pr = tow.parameterRange();
    TopoDS_Edge rims[2];
    BRep_Builder b;
    TopoDS_Shell shell;
    b.MakeShell(shell);
    b.Add(shell, tubeFace(s, pr, pr.vMin, tolerance, rims));
    area = tow.area();
    for (int k = 0; k < 2; ++k) {
        const double u = k == 0 ? pr.uMin : pr.uMax;
        const TopoDS_Face cap = capFace(s, u, pr.vMin, pr.vPeriod(), rims[k], outwardAtEnd(s, u, pr.vMin, pr.vPeriod(), k == 0),
                                        tow.towSize(), tow.name(), k == 0 ? "first" : "last");
        b.Add(shell, cap);
        area += areaOf(cap);
    }
    shell.Closed(BRep_Tool::IsClosed(shell));
    TopoDS_Solid solid;
    b.MakeSolid(solid);
    b.Add(solid, shell);
    return solid;
}

/// The tows by the rank rule on their whole solids (fuseByRank()): what the loops alone do not
/// build (three tows at a point, loops across caps or around a tow, a tow cut apart).
/// @throws towgeom::Error (Unsupported) naming a pair that still overlaps (the mesh leaves it
///         overlapping: the solids would not agree with it).
TrimmedBrep rankFused(const std::vector<TowSurface>& tows, const ResolveResult& r, const BrepOptions& o, double tolerance,
                      std::string because)
{
    // The whole solids first: an end section that is not planar is refused for what it is.
    std::vector<TopoDS_Solid> whole(tows.size());
    std::vector<double> area(tows.size());
    std::vector<std::string> names;
    for (std::size_t t = 0; t < tows.size(); ++t) {
        whole[t] = wholeSolid(tows[t], tolerance, area[t]);
        names.push_back(tows[t].name());
    }
    const std::string why = " (the general fuse builds the solids only when every pair and loop is resolved; the loop path "
                            "refused: " + because + ")";
    const std::vector<UnresolvedPairEntry> overlapping = overlappingPairs(r);
    if (!overlapping.empty())
        throw Error(ErrorCode::Unsupported, "tows '" + tows[overlapping.front().towA].name() + "' and '" +
                                                tows[overlapping.front().towB].name() + "' still overlap [" + overlapping.front().code +
                                                "]" + why);
    for (const SkippedLoop& k : r.skippedLoops)
        if (k.reason != SkippedLoop::Reason::OutsideCell)
            throw Error(ErrorCode::Unsupported, "a loop the mesh leaves unresolved (" + k.message + ")" + why);
    // Of a pair with a region, its primary ranks above; otherwise the rank the regions were made
    // by (ResolveResult::ranks; input order without them).
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> primary;
    for (const ConnectedRegion& g : r.mesh.regions) primary[std::minmax(g.primary, g.secondary)] = g.primary;
    const bool ranked = r.ranks.size() == tows.size();
    const auto above = [&](std::size_t a, std::size_t b) {
        if (a == b) return false;
        const auto it = primary.find(std::minmax(a, b));
        if (it != primary.end()) return it->second == a;
        return ranked ? r.ranks[a] < r.ranks[b] : a < b;
    };
    std::optional<Cell> box;
    if (r.mesh.cell) box = r.mesh.cell->box;
    const detail::RankFusion fused = detail::fuseByRank(whole, area, above, box, names);

    auto impl = std::make_shared<TrimmedBrep::Impl>();
    BRep_Builder b;
    b.MakeCompound(impl->compound);
    const auto fill = [&](BrepSolid& out, const detail::FusedSolid& f, const std::string& name) {
        out.name = name;
        out.faces = f.faces;
        out.sharedFaces = f.sharedFaces;
        out.cellFaces = f.cellFaces;
        out.valid = !f.solids.empty();
        for (const TopoDS_Solid& s : f.solids) {
            out.valid = out.valid && BRepCheck_Analyzer(s).IsValid();
            out.maxTolerance = std::max(out.maxTolerance, maxToleranceOf(s));
            b.Add(impl->compound, s);
            impl->solids.push_back(s);
            impl->names.push_back(name);
        }
    };
    std::vector<BrepSolid> solids(tows.size());
    double onBoxAreas = 0.0, freeAreas = 0.0;
    for (std::size_t t = 0; t < tows.size(); ++t) {
        const detail::FusedSolid& f = fused.tows[t];
        fill(solids[t], f, tows[t].name());
        if (f.solids.empty()) continue;  // nothing kept (outside the cell, or inside tows above it)
        solids[t].volume = tows[t].volume() - f.lostVolume;
        solids[t].area = f.area;
        for (const ConnectedRegion& g : r.mesh.regions)
            if (g.primary == t || g.secondary == t) solids[t].loops += 1 + g.holes.size();
        onBoxAreas += f.onBoxArea;
        freeAreas += f.freeArea;
    }
    BrepSolid matrix;
    if (box && o.matrix) {
        fill(matrix, fused.matrix, "MATRIX");
        const Cell& c = *box;
        const double dx = c.max.x - c.min.x, dy = c.max.y - c.min.y, dz = c.max.z - c.min.z;
        matrix.volume = c.volume();
        for (const BrepSolid& t : solids) matrix.volume -= t.volume;
        matrix.area = 2.0 * (dx * dy + dy * dz + dz * dx) - onBoxAreas + freeAreas;
    }
    return TrimmedBrep(std::move(impl), std::move(solids), fused.sharedFaces, std::move(matrix), {}, std::move(because));
}

}  // namespace

TrimmedBrep trimmedBrep(const std::vector<TowSurface>& tows, const ResolveResult& r, const BrepOptions& o)
{
    if (!(o.tolerance >= 0.0) || !std::isfinite(o.tolerance) || !(o.relativeTolerance > 0.0) || !std::isfinite(o.relativeTolerance))
        throw Error(ErrorCode::InvalidArgument, "trimmedBrep: the tolerances must be finite, tolerance >= 0 and relativeTolerance > 0");
    checkInput(tows, r);
    double smallest = 1e300;
    for (const TowSurface& t : tows) smallest = std::min(smallest, t.towSize());
    const double tolerance = o.tolerance > 0.0 ? o.tolerance : o.relativeTolerance * smallest;
    std::string because;
    try {
        return loopTrimmed(tows, r, o, tolerance);
    } catch (const Error& e) {
        if (e.code() != ErrorCode::Unsupported) throw;
        because = e.what();
    }
    return rankFused(tows, r, o, tolerance, std::move(because));
}

TOWGEOM_END_NAMESPACE
