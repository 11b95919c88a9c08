#include "cell/face_crossings.hpp"

#include <Eigen/Dense>
#include <Geom_BSplineSurface.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <utility>

#include "cell/axis.hpp"
#include "surface/tow_surface_impl.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

/// How far @p p lies beyond face @p f (positive outside the box, on the face 0).
double beyond(const Cell& cell, CellFace f, const Point3& p)
{
    const double x = coord(p, axisOf(f)) - cell.plane(f);
    return isMaxFace(f) ? x : -x;
}

/// A surface's point and first derivatives, v taken modulo its period.
struct Derivatives {
    gp_Pnt p;
    gp_Vec du, dv;
};

/// @p v moved into [vMin, vMax) of @p r by whole periods.
double inPeriod(double v, const ParameterRange& r)
{
    double w = r.vMin + std::fmod(v - r.vMin, r.vPeriod());
    if (w < r.vMin) w += r.vPeriod();
    return w >= r.vMax ? r.vMin : w;
}

Derivatives at(const TowSurface& tow, double u, double v)
{
    Derivatives d;
    tow.impl().surface->D1(u, inPeriod(v, tow.parameterRange()), d.p, d.du, d.dv);
    return d;
}

/// One chord of a loop that crosses a face's plane.
struct ChordCrossing {
    std::size_t chord = 0;
    CellFace face = CellFace::XMin;
    LoopPoint point;  ///< exact, v unwrapped as the chord's
};

/// Cell::periodic: each crossing of a max face paired with the nearest crossing of the same two
/// tows on the opposite face moved by the box's size, and its node (and loop point) put there.
void pairAcrossPeriod(const std::vector<TowSurface>& tows, std::vector<SharedLoop>& shared, const Cell& cell, std::vector<Point3>& nodes,
                      std::vector<FaceCrossing>& crossings)
{
    const auto samePair = [](const FaceCrossing& x, const FaceCrossing& y) {
        return std::minmax(x.towA, x.towB) == std::minmax(y.towA, y.towB);
    };
    const auto refuse = [&](const FaceCrossing& x, const std::string& what) {
        throw Error(ErrorCode::InvalidArgument, "the intersection loop of tows '" + tows[x.towA].name() + "' and '" + tows[x.towB].name() +
                                                    "' crosses the periodic cell's face " + cellFaceName(x.face) + " " + what +
                                                    ": the overlap does not repeat with the cell");
    };
    // Every (max, min) pair of crossings within the tolerance, nearest first: each crossing
    // takes its nearest partner not taken by a nearer pair.
    std::vector<std::tuple<double, std::size_t, std::size_t>> candidates;
    for (std::size_t i = 0; i < crossings.size(); ++i) {
        const FaceCrossing& x = crossings[i];
        if (!isMaxFace(x.face)) continue;
        const int a = axisOf(x.face);
        Point3 shift;
        coord(shift, a) = coord(cell.max, a) - coord(cell.min, a);
        const double within = cell.periodTolerance * std::min(tows[x.towA].towSize(), tows[x.towB].towSize());
        for (std::size_t j = 0; j < crossings.size(); ++j) {
            const FaceCrossing& y = crossings[j];
            if (y.face != static_cast<CellFace>(2 * a) || !samePair(x, y)) continue;
            const double gap = distance(nodes[y.node] + shift, nodes[x.node]);
            if (gap <= within) candidates.emplace_back(gap, i, j);
        }
    }
    std::sort(candidates.begin(), candidates.end());
    std::vector<char> taken(crossings.size(), 0);
    for (const auto& [gap, i, j] : candidates) {
        if (taken[i] || taken[j]) continue;
        taken[i] = taken[j] = 1;
        FaceCrossing& x = crossings[i];
        const int a = axisOf(x.face);
        x.partner = j;
        Point3 p = nodes[crossings[j].node];
        coord(p, a) = coord(cell.max, a);
        nodes[x.node] = p;
        for (SharedLoop& s : shared)
            for (std::size_t k = 0; k < s.nodes.size(); ++k)
                if (s.nodes[k] == x.node) s.points[k].point = p;
    }
    for (std::size_t i = 0; i < crossings.size(); ++i)
        if (!taken[i])
            refuse(crossings[i], std::string("where it does not cross the face ") +
                                     cellFaceName(static_cast<CellFace>(static_cast<int>(crossings[i].face) ^ 1)) +  // the opposite face
                                     " at the same place moved by the cell");
}

}  // namespace

bool inCellBox(const Cell& cell, const Point3& p)
{
    return p.x >= cell.min.x && p.x <= cell.max.x && p.y >= cell.min.y && p.y <= cell.max.y && p.z >= cell.min.z && p.z <= cell.max.z;
}

bool segmentMeetsBox(const Point3& p, const Point3& q, const Cell& cell)
{
    double t0 = 0.0, t1 = 1.0;  // slabs
    for (int a = 0; a < 3; ++a) {
        const double from = coord(p, a), d = coord(q, a) - from, lo = coord(cell.min, a), hi = coord(cell.max, a);
        if (d == 0.0) {
            if (from < lo || from > hi) return false;
            continue;
        }
        double s0 = (lo - from) / d, s1 = (hi - from) / d;
        if (s0 > s1) std::swap(s0, s1);
        t0 = std::max(t0, s0);
        t1 = std::min(t1, s1);
        if (t0 > t1) return false;
    }
    return true;
}

bool loopCrossesCellBox(const IntersectionLoop& loop, const Cell& cell)
{
    const std::vector<LoopPoint>& points = loop.points();
    bool meets = false, outside = false;
    for (std::size_t k = 0; k < points.size(); ++k) {
        outside = outside || !inCellBox(cell, points[k].point);
        meets = meets || segmentMeetsBox(points[k].point, points[(k + 1) % points.size()].point, cell);
    }
    return meets && outside;
}

std::vector<FaceCrossing> crossCellFaces(const std::vector<TowSurface>& tows, const std::vector<IntersectionLoop>& loops,
                                         std::vector<SharedLoop>& shared, const std::function<bool(std::size_t)>& across,
                                         const std::function<double(std::size_t)>& closeness, const Cell& cell,
                                         std::vector<Point3>& nodes)
{
    // Nodes of more than one loop (figure-8 touching points, triple points of three tows) stay.
    std::map<std::size_t, int> loopsThrough;
    for (const SharedLoop& s : shared)
        for (std::size_t n : s.nodes) ++loopsThrough[n];
    std::vector<FaceCrossing> out;
    for (std::size_t k = 0; k < shared.size(); ++k) {
        if (!across(k)) continue;
        SharedLoop& s = shared[k];
        const IntersectionLoop& loop = loops[s.loop];
        const TowSurface& ta = tows[loop.towA()];
        const TowSurface& tb = tows[loop.towB()];
        const std::string pair = "the intersection loop of tows '" + ta.name() + "' and '" + tb.name() + "'";
        const auto refuse = [&](const std::string& what) { throw Error(ErrorCode::InvalidArgument, pair + " " + what); };
        const double size = std::min(ta.towSize(), tb.towSize());
        const std::size_t n = s.points.size();
        std::vector<ChordCrossing> found;
        for (std::size_t c = 0; c < n; ++c) {
            const auto [p, q] = chordEnds(loop, s, c);
            const bool pIn = inCellBox(cell, p.point), qIn = inCellBox(cell, q.point);
            if (pIn == qIn) continue;
            int crossed = 0;
            CellFace face = CellFace::XMin;
            for (int f = 0; f < 6; ++f) {
                const CellFace cf = static_cast<CellFace>(f);
                if ((beyond(cell, cf, p.point) > 0.0) != (beyond(cell, cf, q.point) > 0.0)) {
                    ++crossed;
                    face = cf;
                }
            }
            if (crossed != 1)
                refuse(std::string("crosses the cell's box near an edge (between two faces' planes): the cell's faces must cross "
                                   "overlaps away from the box's edges"));
            const double dp = beyond(cell, face, p.point), dq = beyond(cell, face, q.point);
            const LoopPoint start = chordPoint(loop, s, c, dp / (dp - dq));
            // Newton's method on S_A(ua, va) = S_B(ub, vb), x_a(S_A) = plane.
            const int a = axisOf(face);
            const double plane = cell.plane(face);
            Eigen::Vector4d x(start.onA.u, start.onA.v, start.onB.u, start.onB.v);
            bool converged = false;
            Derivatives da, db;
            for (int it = 0; it < 30 && !converged; ++it) {
                da = at(ta, x[0], x[1]);
                db = at(tb, x[2], x[3]);
                Eigen::Vector4d F(da.p.X() - db.p.X(), da.p.Y() - db.p.Y(), da.p.Z() - db.p.Z(), da.p.Coord(a + 1) - plane);
                if (F.norm() < 1e-11 * size) {
                    converged = true;
                    break;
                }
                Eigen::Matrix4d J;
                for (int r = 0; r < 3; ++r) J.row(r) << da.du.Coord(r + 1), da.dv.Coord(r + 1), -db.du.Coord(r + 1), -db.dv.Coord(r + 1);
                J.row(3) << da.du.Coord(a + 1), da.dv.Coord(a + 1), 0.0, 0.0;
                const Eigen::FullPivLU<Eigen::Matrix4d> lu(J);
                if (!lu.isInvertible()) break;
                x += lu.solve(-F);
                // Stay on the tubes (u within their ranges).
                const ParameterRange ra = ta.parameterRange(), rb = tb.parameterRange();
                x[0] = std::clamp(x[0], ra.uMin, ra.uMax);
                x[2] = std::clamp(x[2], rb.uMin, rb.uMax);
            }
            const double chordLength = distance(p.point, q.point);
            Point3 meet{0.5 * (da.p.X() + db.p.X()), 0.5 * (da.p.Y() + db.p.Y()), 0.5 * (da.p.Z() + db.p.Z())};
            if (!converged || distance(meet, start.point) > 2.0 * chordLength + 1e-9 * size)
                refuse(std::string("crosses the cell's face ") + cellFaceName(face) +
                       " but the point where it does (on both tows and the face) was not found: the tows may be tangent there");
            coord(meet, a) = plane;
            for (int b = 0; b < 3; ++b)
                if (b != a && !(coord(meet, b) > coord(cell.min, b) && coord(meet, b) < coord(cell.max, b)))
                    refuse(std::string("crosses the plane of the cell's face ") + cellFaceName(face) +
                           " outside the face: the cell's faces must cross overlaps away from the box's edges");
            found.push_back({c, face, {meet, {x[0], x[1]}, {x[2], x[3]}}});
        }
        if (found.empty()) continue;
        // The loop rebuilt with the crossings in it; its inside nodes too close to one dropped.
        std::vector<LoopPoint> points;
        std::vector<std::size_t> ids;
        std::vector<char> crossing;
        std::size_t next = 0;
        for (std::size_t c = 0; c < n; ++c) {
            points.push_back(s.points[c]);
            ids.push_back(s.nodes[c]);
            crossing.push_back(0);
            for (; next < found.size() && found[next].chord == c; ++next) {
                // (On the closing chord its v is unwrapped as the last point's, which it follows.)
                const LoopPoint& p = found[next].point;
                points.push_back(p);
                ids.push_back(nodes.size());
                nodes.push_back(p.point);
                crossing.push_back(1);
                FaceCrossing fc;
                fc.face = found[next].face;
                fc.towA = loop.towA();
                fc.towB = loop.towB();
                fc.node = ids.back();
                fc.onA = {p.onA.u, inPeriod(p.onA.v, ta.parameterRange())};
                fc.onB = {p.onB.u, inPeriod(p.onB.v, tb.parameterRange())};
                out.push_back(fc);
            }
        }
        const std::size_t m = points.size();
        std::vector<char> drop(m, 0);
        const double near = closeness(k);
        for (std::size_t i = 0; i < m; ++i) {
            if (!crossing[i]) continue;
            for (const std::size_t step : {m - 1, std::size_t(1)}) {  // back, forward
                const std::size_t j = (i + step) % m;
                if (crossing[j] || !inCellBox(cell, points[j].point) || loopsThrough[ids[j]] > 1 || onSeam(loop, points[j], 1e-9)) continue;
                // The last node inside between two crossings stays (the loop keeps 3 nodes at least).
                std::size_t beyond = (j + step) % m;
                while (drop[beyond]) beyond = (beyond + step) % m;
                if (crossing[beyond]) continue;
                if (distance(points[i].point, points[j].point) < near) drop[j] = 1;
            }
        }
        s.points.clear();
        s.nodes.clear();
        for (std::size_t i = 0; i < m; ++i)
            if (!drop[i]) {
                s.points.push_back(points[i]);
                s.nodes.push_back(ids[i]);
            }
    }
    if (cell.periodic) pairAcrossPeriod(tows, shared, cell, nodes, out);
    return out;
}

std::vector<LoopConstraint> clipLoopPieces(const std::vector<LoopConstraint>& pieces, const Cell& cell, const std::vector<Point3>& nodes)
{
    std::vector<LoopConstraint> out;
    for (const LoopConstraint& piece : pieces) {
        const std::size_t n = piece.nodes.size();
        std::vector<char> in(n);
        for (std::size_t k = 0; k < n; ++k) in[k] = inCellBox(cell, nodes[piece.nodes[k]]) ? 1 : 0;
        if (std::all_of(in.begin(), in.end(), [](char c) { return c != 0; })) {
            out.push_back(piece);
            continue;
        }
        // A closed piece is walked from a node outside, once around.
        std::size_t first = 0;
        if (piece.closed)
            while (in[first]) ++first;
        const std::size_t count = piece.closed ? n + 1 : n;
        LoopConstraint run;
        run.loop = piece.loop;
        const auto flush = [&] {
            if (run.nodes.size() >= 2) out.push_back(run);
            run = {};
            run.loop = piece.loop;
        };
        for (std::size_t i = 0; i < count; ++i) {
            const std::size_t k = (first + i) % n;
            if (!in[k]) {
                flush();
                continue;
            }
            run.uv.push_back(piece.uv[k]);
            run.nodes.push_back(piece.nodes[k]);
        }
        flush();
    }
    return out;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
