#include "towgeom/connect_regions.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <utility>

#include "cell/face_crossings.hpp"
#include "cell/mesh_clip.hpp"
#include "core/elapsed.hpp"
#include "core/parallel.hpp"
#include "core/progress_report.hpp"
#include "mesh/mesh_measures.hpp"
#include "mesh/textile_mesh_finish.hpp"
#include "region/connected_region.hpp"
#include "region/mesh_pieces.hpp"
#include "region/mid_surface.hpp"
#include "region/tow_ranks.hpp"
#include "region/winding_loops.hpp"
#include "surface/occt_convert.hpp"
#include "surface/tow_surface_impl.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

using Clock = std::chrono::steady_clock;
using Triangle = std::array<std::size_t, 3>;
using TowPair = std::pair<std::size_t, std::size_t>;
using NodeUV = std::pair<std::size_t, UV>;

using detail::msSince;

Triangle reversed(const Triangle& t) { return {t[0], t[2], t[1]}; }

/// The (u,v) of @p node in a tow's TowMesh::parameters (sorted by node), or null.
const UV* uvOf(const std::vector<NodeUV>& parameters, std::size_t node)
{
    const auto it = std::lower_bound(parameters.begin(), parameters.end(), node,
                                     [](const NodeUV& e, std::size_t n) { return e.first < n; });
    return it != parameters.end() && it->first == node ? &it->second : nullptr;
}

/// @p v moved by whole periods to within half a period of @p near.
double vNear(double v, double near, double period) { return v - period * std::round((v - near) / period); }

Error badInput(const std::string& what, const std::string& context)
{
    return Error(ErrorCode::InvalidArgument, what + " (connectRegions() takes the result of meshTows() on the same tows)", context);
}

/// What the classification reads from meshTows()'s result, in (u,v): every loop's node polygon
/// on both its tows (v unwrapped), every side triangle's centroid (NaN on caps).
/// A cap triangle of a tow with loops across its caps, for classifying it in the cap's plane:
/// its centroid P, the point Q radially beyond it (about the chart's centre) on the tube's end
/// polygon, and the side triangle on that edge: the triangle lies inside a loop where that side
/// triangle does, unless an odd number of the loop's chords on the cap lie between P and Q. So
/// cap and side agree at the rim whatever the loop's (u,v) polygon does near the cap's centre.
struct CapProbe {
    int end = 0;  ///< -1 the first end's cap, +1 the last's; 0 none (not a cap triangle, or no loops)
    double px = 0.0, py = 0.0, qx = 0.0, qy = 0.0;
    std::size_t rimTriangle = SIZE_MAX;  ///< the side triangle on the rim edge through Q
};

struct Parametric {
    std::vector<std::array<std::vector<UV>, 2>> polygon;  ///< per TextileMesh::loops entry, on tow A and B
    std::vector<std::vector<UV>> centroid;                 ///< per tow, per triangle (NaN on caps)
    std::vector<std::vector<CapProbe>> probe;              ///< per tow, per triangle (tows with loops across caps)
    std::vector<bool> capped;                              ///< per tow: closed by its caps
};

/// @p p in the plane of @p cap (about its centre).
std::array<double, 2> inCapPlane(const detail::CapChart& cap, const Point3& p)
{
    const gp_XYZ q = detail::toOcct(p).XYZ() - cap.centre;
    return {q.Dot(cap.e1), q.Dot(cap.e2)};
}

/// True when the segments [a, b] and [c, d] cross (in the plane).
bool segmentsCross(const std::array<double, 2>& a, const std::array<double, 2>& b, const std::array<double, 2>& c,
                   const std::array<double, 2>& d)
{
    const auto orient = [](const std::array<double, 2>& p, const std::array<double, 2>& q, const std::array<double, 2>& r) {
        const double x = (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
        return x > 0.0 ? 1 : x < 0.0 ? -1 : 0;
    };
    return orient(a, b, c) * orient(a, b, d) < 0 && orient(c, d, a) * orient(c, d, b) < 0;
}

/// True when @p p lies on a face's plane of @p cell (exactly: the cell's nodes are put there).
bool onCellFace(const CellMesh& cell, const Point3& p)
{
    const Cell& b = cell.box;
    return p.x == b.min.x || p.x == b.max.x || p.y == b.min.y || p.y == b.max.y || p.z == b.min.z || p.z == b.max.z;
}

/// The points of @p loop outside the box of @p cell between its consecutive meshed nodes @p from
/// and @p to when both lie on the box's faces (where the loop leaves the cell and comes back), in
/// loop order; none otherwise. Each node is placed on the loop's chord nearest to it (not at its
/// nearest point: a straight loop's points may be few and far, two of them equally near).
std::vector<LoopPoint> outsideStretch(const IntersectionLoop& loop, const CellMesh& cell, const std::vector<Point3>& nodes,
                                      std::size_t from, std::size_t to)
{
    if (from >= nodes.size() || to >= nodes.size() || !onCellFace(cell, nodes[from]) || !onCellFace(cell, nodes[to])) return {};
    const std::vector<LoopPoint>& points = loop.points();
    const std::size_t n = points.size();
    // The chord (k, k + 1) nearest to p and how far along it p lies (0 to 1); of two equally
    // near (p nearest to the point they share), the one p projects into.
    const auto onChord = [&](const Point3& p) {
        std::size_t best = 0;
        double gap = std::numeric_limits<double>::infinity(), along = 0.0;
        bool into = false;
        for (std::size_t k = 0; k < n; ++k) {
            const Point3 &a = points[k].point, &b = points[(k + 1) % n].point;
            const double l2 = dot(b - a, b - a), t = l2 > 0.0 ? dot(p - a, b - a) / l2 : 0.0;
            const double d = distance(p, a + std::clamp(t, 0.0, 1.0) * (b - a));
            const bool in = t >= 0.0 && t <= 1.0;
            const double tie = 1e-12 * std::sqrt(l2);  // rounding at the shared point
            if (d < gap - tie || (d <= gap + tie && (in != into ? in : d < gap))) {
                gap = d;
                best = k;
                along = std::clamp(t, 0.0, 1.0);
                into = in;
            }
        }
        return std::make_pair(best, along);
    };
    const auto [first, along] = onChord(nodes[from]);
    const auto [last, alongLast] = onChord(nodes[to]);
    std::vector<LoopPoint> out;
    if (first == last && along <= alongLast) return out;  // both on one chord, in loop order: nothing between
    for (std::size_t k = (first + 1) % n;; k = (k + 1) % n) {
        if (!detail::inCellBox(cell.box, points[k].point)) out.push_back(points[k]);
        if (k == last) break;
    }
    return out;
}

/// Checks that @p meshed is meshTows()'s result for @p tows (sizes, names, node indices, the
/// loops' and side triangles' nodes with (u,v) on their tows) and reads it in (u,v).
Parametric readParametric(const std::vector<TowSurface>& tows, const ResolveResult& meshed)
{
    const TextileMesh& mesh = meshed.mesh;
    const std::vector<IntersectionLoop>& loops = meshed.intersections.loops;
    if (mesh.tows.size() != tows.size())
        throw badInput("the meshes are of " + std::to_string(mesh.tows.size()) + " tows, not " + std::to_string(tows.size()), "");
    if (!mesh.regions.empty()) throw badInput("the meshes are connected already (TextileMesh::regions is not empty)", "");
    const std::size_t n = mesh.nodes.size();
    Parametric p;
    p.centroid.resize(tows.size());
    p.probe.resize(tows.size());
    p.capped.assign(tows.size(), false);
    for (std::size_t t = 0; t < tows.size(); ++t) {
        const TowMesh& m = mesh.tows[t];
        const std::string where = "tow '" + tows[t].name() + "'";
        if (m.name != tows[t].name()) throw badInput("the mesh of tow " + std::to_string(t) + " is named '" + m.name + "'", where);
        const std::size_t k = m.triangles.size();
        if (m.region.size() != k || m.face.size() != k || m.fibreDirection.size() != k)
            throw badInput("region, face and fibreDirection must have one entry per triangle", where);
        for (std::size_t i = 0; i < m.parameters.size(); ++i)
            if (m.parameters[i].first >= n || (i > 0 && m.parameters[i - 1].first >= m.parameters[i].first) ||
                !std::isfinite(m.parameters[i].second.u) || !std::isfinite(m.parameters[i].second.v))
                throw badInput("parameters must list nodes in increasing order, each once, with finite (u,v)", where);
    }
    for (const TriplePoint& t : mesh.triplePoints)
        if (t.node >= n) throw badInput("a triple point's node is out of range", "");
    std::vector<char> listed(loops.size(), 0);
    for (std::size_t k = 0; k < mesh.loops.size(); ++k) {
        const MeshedLoop& ml = mesh.loops[k];
        const std::string where = "loop " + std::to_string(ml.loop);
        if (ml.loop < loops.size() && listed[ml.loop]++) throw badInput("the loop is listed twice", where);
        if (ml.loop >= loops.size() || !loops[ml.loop].closed()) throw badInput("not a closed loop of the intersection report", where);
        if (ml.nodes.size() < 3) throw badInput("a loop needs at least 3 nodes", where);
        const IntersectionLoop& l = loops[ml.loop];
        if (l.towA() >= tows.size() || l.towB() >= tows.size()) throw badInput("the loop's tows are not among the tows", where);
        std::array<std::vector<UV>, 2>& both = p.polygon.emplace_back();
        for (const LoopSide side : {LoopSide::A, LoopSide::B}) {
            const std::size_t t = side == LoopSide::A ? l.towA() : l.towB();
            const double period = tows[t].parameterRange().vPeriod();
            std::vector<UV>& out = both[side == LoopSide::A ? 0 : 1];
            for (std::size_t i = 0; i < ml.nodes.size(); ++i) {
                const std::size_t node = ml.nodes[i];
                const UV* uv = node < n ? uvOf(mesh.tows[t].parameters, node) : nullptr;
                if (!uv) throw badInput("a loop node has no (u,v) on tow '" + tows[t].name() + "'", where);
                // v unwrapped along the loop: a loop around the tow ends one period on.
                out.push_back({uv->u, out.empty() ? uv->v : vNear(uv->v, out.back().v, period)});
                // Where a loop leaves the cell (its nodes outside are not in the meshes), its
                // polygon follows the loop's own points outside: a straight chord in (u,v) between
                // the two nodes on the face would cut across the tow's kept part where its cut is
                // curved.
                if (mesh.cell)
                    for (const LoopPoint& q : outsideStretch(l, *mesh.cell, mesh.nodes, node, ml.nodes[(i + 1) % ml.nodes.size()])) {
                        const UV& w = side == LoopSide::A ? q.onA : q.onB;
                        out.push_back({w.u, vNear(w.v, out.back().v, period)});
                    }
            }
        }
    }
    // Every side triangle's (u,v) centroid, v unwrapped from its first node's; the tow's (u,v)
    // looked up by node in a table filled per tow.
    std::vector<const UV*> at(n, nullptr);
    for (std::size_t t = 0; t < tows.size(); ++t) {
        const TowMesh& m = mesh.tows[t];
        const std::string where = "tow '" + tows[t].name() + "'";
        const std::size_t k = m.triangles.size();
        const double period = tows[t].parameterRange().vPeriod();
        for (const NodeUV& e : m.parameters) at[e.first] = &e.second;
        p.centroid[t].assign(k, UV{std::nan(""), std::nan("")});
        // Cap triangles of a tow with loops across its caps get a probe (CapProbe).
        const bool capLoops = std::any_of(mesh.loops.begin(), mesh.loops.end(), [&](const MeshedLoop& ml) {
            const IntersectionLoop& l = loops[ml.loop];
            return (l.towA() == t && l.crossesCap(LoopSide::A)) || (l.towB() == t && l.crossesCap(LoopSide::B));
        });
        const GeomAdaptor_Surface tube(tows[t].impl().surface);
        const detail::TowCaps& caps = tows[t].impl().caps;
        const ParameterRange range = tows[t].parameterRange();
        if (capLoops) p.probe[t].assign(k, CapProbe{});
        for (std::size_t i = 0; i < k; ++i) {
            const Triangle& tri = m.triangles[i];
            if (tri[0] >= n || tri[1] >= n || tri[2] >= n) throw badInput("a triangle's node is out of range", where);
            if (m.face[i] != TowFace::Side) {
                p.capped[t] = true;
                // (A cap on a cell's face is not the tow's own cap: loops across its own caps end
                // outside the cell there.)
                if (!capLoops || (m.face[i] == TowFace::Start ? m.cutAt[0] : m.cutAt[1])) continue;
                const detail::CapChart& cap = m.face[i] == TowFace::Start ? caps.start : caps.end;
                double u = 0.0, v = 0.0;
                const Point3 c = (1.0 / 3.0) * (mesh.nodes[tri[0]] + mesh.nodes[tri[1]] + mesh.nodes[tri[2]]);
                if (!detail::capParameters(tube, cap, detail::toOcct(c), range.vMin, u, v)) continue;
                CapProbe& q = p.probe[t][i];
                q.end = m.face[i] == TowFace::Start ? -1 : 1;
                const std::array<double, 2> pc = inCapPlane(cap, c);
                q.px = pc[0];
                q.py = pc[1];
                continue;
            }
            const UV *a = at[tri[0]], *b = at[tri[1]], *c = at[tri[2]];
            if (!a || !b || !c) throw badInput("a side triangle's node has no (u,v) on the tow", where);
            const double vb = vNear(b->v, a->v, period), vc = vNear(c->v, a->v, period);
            p.centroid[t][i] = {(a->u + b->u + c->u) / 3.0, (a->v + vb + vc) / 3.0};
        }
        // Each cap probe's Q and rim triangle: the side triangles' edges on the tube's ends,
        // found by the polar angle about the cap's centre.
        if (capLoops) {
            struct RimEdge {
                std::array<double, 2> a, b;
                std::size_t triangle;
            };
            std::array<std::vector<RimEdge>, 2> rims;  // first end, last end
            for (std::size_t i = 0; i < k; ++i) {
                if (m.face[i] != TowFace::Side) continue;
                const Triangle& tri = m.triangles[i];
                for (int e = 0; e < 3; ++e) {
                    const UV *a = at[tri[static_cast<std::size_t>(e)]], *b = at[tri[static_cast<std::size_t>((e + 1) % 3)]];
                    for (const int end : {0, 1}) {
                        const double u = end == 0 ? range.uMin : range.uMax;
                        if (!a || !b || a->u != u || b->u != u) continue;
                        const detail::CapChart& cap = end == 0 ? caps.start : caps.end;
                        rims[static_cast<std::size_t>(end)].push_back(
                            {inCapPlane(cap, mesh.nodes[tri[static_cast<std::size_t>(e)]]), inCapPlane(cap, mesh.nodes[tri[static_cast<std::size_t>((e + 1) % 3)]]), i});
                    }
                }
            }
            for (CapProbe& q : p.probe[t]) {
                if (q.end == 0) continue;
                // The rim edge the ray from the centre through P crosses first beyond P, and where.
                const double dx = q.px, dy = q.py;
                double nearest = 1e300;
                for (const RimEdge& r : rims[q.end < 0 ? 0 : 1]) {
                    const double ex = r.b[0] - r.a[0], ey = r.b[1] - r.a[1];
                    const double den = dx * ey - dy * ex;
                    if (den == 0.0) continue;
                    const double s = (r.a[0] * ey - r.a[1] * ex) / den;  // along the ray (P at 1)
                    const double w = (r.a[0] * dy - r.a[1] * dx) / den;  // along the edge
                    if (s >= 1.0 && s < nearest && w >= -1e-9 && w <= 1.0 + 1e-9) {
                        nearest = s;
                        // Q: the edge's midpoint (P lies in the triangle of the centre and this
                        // edge, so [P, Q] stays on the cap), never a rim node shared by two edges.
                        q.qx = 0.5 * (r.a[0] + r.b[0]);
                        q.qy = 0.5 * (r.a[1] + r.b[1]);
                        q.rimTriangle = r.triangle;
                    }
                }
            }
        }
        for (const NodeUV& e : m.parameters) at[e.first] = nullptr;
    }
    return p;
}

/// A tow whose mesh after the swap is not closed, or has a triangle no region takes.
struct TowFailure {
    std::size_t tow = 0;
    std::string message;
};

/// The bands of a tow cut by the loops of one pair that wind around it: the other tow, its bands
/// and their loops' node polygons on this tow, in band order.
struct TowBands {
    std::size_t other = 0;
    detail::WindingBands bands;
    std::vector<std::size_t> loops;                // indices into TextileMesh::loops, in band order
    std::vector<detail::WindingPolygon> polygons;  // each loop's node polygon on the tow
};

/// A region's move to the mid-surface: its nodes off the loops and where they go, or why the
/// region keeps the primary's surface (the rank rule decides there).
struct MidSurfaceMove {
    std::vector<std::size_t> nodes;
    std::vector<Point3> positions;
    std::string note;  ///< empty when the region moves
};

/// The MidSurfaceMove of region @p r (triangles still numbered in the primary's input mesh), with
/// the secondary's triangles inside its loop @p secondaryInside; @p crowded when a third tow
/// overlaps it. Every loop of @p in counts, the inactive ones too (their nodes stay in both
/// their tows' meshes).
MidSurfaceMove midSurfaceMove(const std::vector<TowSurface>& tows, const std::vector<IntersectionLoop>& loops, const TextileMesh& in,
                              const ConnectedRegion& r, const std::vector<Triangle>& secondaryInside, bool crowded)
{
    MidSurfaceMove m;
    const std::string pair = "tows '" + tows[r.primary].name() + "' and '" + tows[r.secondary].name() + "'";
    if (crowded) {
        m.note = "a third tow overlaps the region of " + pair + " (loop " + std::to_string(r.loop) + "): the rank rule decides there";
        return m;
    }
    // A region cut by a face of the cell: its nodes on the face must stay there (the face's caps
    // are split by the primary's surface).
    if (in.cell)
        for (const std::size_t n : r.nodes)
            if (onCellFace(*in.cell, in.nodes[n])) {
                m.note = "the region of " + pair + " (loop " + std::to_string(r.loop) + ") reaches a face of the cell: the rank rule decides there";
                return m;
            }
    // Its own loops (the loop and its holes) must not wind around a tow or cross a cap, and no
    // other loop may have a node in it.
    std::set<std::size_t> own(r.holes.begin(), r.holes.end());
    own.insert(r.loop);
    for (std::size_t l : own)
        for (const LoopSide side : {LoopSide::A, LoopSide::B})
            if (loops[l].windsAround(side) || loops[l].crossesCap(side)) {
                m.note = "loop " + std::to_string(l) + " of " + pair + " goes around a tow or across an end cap: the rank rule decides there";
                return m;
            }
    std::set<std::size_t> onOwnLoop, onOtherLoop;
    for (const MeshedLoop& ml : in.loops) (own.count(ml.loop) ? onOwnLoop : onOtherLoop).insert(ml.nodes.begin(), ml.nodes.end());
    for (const TriplePoint& p : in.triplePoints) onOtherLoop.insert(p.node);
    std::set<std::size_t> regionNodes;
    for (std::size_t k : r.triangles) {
        const Triangle& t = in.tows[r.primary].triangles[k];
        regionNodes.insert(t.begin(), t.end());
    }
    for (std::size_t n : regionNodes) {
        if (onOwnLoop.count(n)) continue;
        if (onOtherLoop.count(n)) {
            m.note = "another loop runs through the region of " + pair + " (loop " + std::to_string(r.loop) + "): the rank rule decides there";
            return m;
        }
        m.nodes.push_back(n);
    }
    detail::MidSurfaceRegion region;
    region.primary = &tows[r.primary];
    region.secondary = &tows[r.secondary];
    region.primaryParameters = &in.tows[r.primary].parameters;
    region.secondaryParameters = &in.tows[r.secondary].parameters;
    region.secondaryTriangles = secondaryInside;
    region.movable = m.nodes;
    std::string why;
    if (!detail::midSurfacePositions(region, in.nodes, m.positions, why))
        m.note = "no mid-surface for the region of " + pair + " (loop " + std::to_string(r.loop) + "): " + why + "; the rank rule decides there";
    return m;
}

/// One classification and swap with the loops of @p meshed flagged in @p active; @p out gets the
/// mesh, the regions and the tows' figures. Returns the tows that failed (then @p out is not
/// complete).
std::vector<TowFailure> connect(const std::vector<TowSurface>& tows, const ResolveResult& meshed, const Parametric& uv,
                                const std::vector<char>& active, const ResolveOptions& options, ResolveResult& out)
{
    const std::size_t threads = detail::workerCount(options.threads);
    const std::vector<IntersectionLoop>& loops = meshed.intersections.loops;
    const TextileMesh& in = meshed.mesh;
    const std::vector<Point3>& N = in.nodes;
    std::vector<TowFailure> failures;
    // The active loops ("shared" below): indices into in.loops.
    std::vector<std::size_t> shared;
    for (std::size_t k = 0; k < in.loops.size(); ++k)
        if (active[k]) shared.push_back(k);
    const auto loopOf = [&](std::size_t s) -> const IntersectionLoop& { return loops[in.loops[shared[s]].loop]; };
    const auto polygonOf = [&](std::size_t s, LoopSide side) -> const std::vector<UV>& {
        return uv.polygon[shared[s]][side == LoopSide::A ? 0 : 1];
    };
    const std::vector<std::size_t> rank = detail::towRanks(tows, options.primaryPatterns);
    const auto period = [&](std::size_t t) { return tows[t].parameterRange().vPeriod(); };
    const auto pairOf = [&](std::size_t s) { return TowPair{loopOf(s).towA(), loopOf(s).towB()}; };
    // The nesting depth of each loop among its pair's loops; the loops directly inside one of
    // even depth are the holes of its region.
    std::vector<std::size_t> depth(shared.size(), 0);
    std::vector<std::vector<std::size_t>> inside(shared.size());  // the pair's loops inside each loop
    for (std::size_t a = 0; a < shared.size(); ++a)
        for (std::size_t b = 0; b < shared.size(); ++b) {
            if (a == b || pairOf(a) != pairOf(b)) continue;
            // On a tow around which neither loop winds (a loop around a tow bounds no inside there).
            const IntersectionLoop& la = loopOf(a);
            const IntersectionLoop& lb = loopOf(b);
            const bool onA = !la.windsAround(LoopSide::A) && !lb.windsAround(LoopSide::A);
            if (!onA && (la.windsAround(LoopSide::B) || lb.windsAround(LoopSide::B))) continue;
            const LoopSide side = onA ? LoopSide::A : LoopSide::B;
            if (detail::insideLoop(polygonOf(a, side), polygonOf(b, side).front(), period(onA ? pairOf(a).first : pairOf(a).second))) {
                ++depth[b];
                inside[a].push_back(b);
            }
        }
    // Each active loop's chords on the caps of its tows, in the caps' planes: per (loop, side),
    // the chords on the first and on the last cap.
    using Chord = std::array<std::array<double, 2>, 2>;
    std::vector<std::array<std::array<std::vector<Chord>, 2>, 2>> capChords(shared.size());
    for (std::size_t k = 0; k < shared.size(); ++k)
        for (const LoopSide side : {LoopSide::A, LoopSide::B}) {
            const IntersectionLoop& l = loopOf(k);
            if (!l.crossesCap(side)) continue;
            const std::size_t t = side == LoopSide::A ? l.towA() : l.towB();
            const detail::TowCaps& caps = tows[t].impl().caps;
            const std::vector<UV>& poly = polygonOf(k, side);
            const std::vector<std::size_t>& nodes = in.loops[shared[k]].nodes;
            // A loop clipped by a cell (its polygon holds its points outside too) runs across
            // caps only outside the box, on cut ends, whose caps have no probe.
            if (poly.size() != nodes.size()) continue;
            for (std::size_t i = 0; i < nodes.size(); ++i) {
                const std::size_t j = (i + 1) % nodes.size();
                const int end = poly[i].u < caps.uMin || poly[j].u < caps.uMin ? 0 : poly[i].u > caps.uMax || poly[j].u > caps.uMax ? 1 : -1;
                if (end < 0) continue;
                const detail::CapChart& cap = end == 0 ? caps.start : caps.end;
                capChords[k][side == LoopSide::A ? 0 : 1][static_cast<std::size_t>(end)].push_back({inCapPlane(cap, N[nodes[i]]), inCapPlane(cap, N[nodes[j]])});
            }
        }
    // The number of loop @p k's chords on the cap of probe @p q that the segment from @p from
    // to @p to crosses.
    const auto crossings = [&](std::size_t k, LoopSide side, const CapProbe& q, const std::array<double, 2>& from,
                               const std::array<double, 2>& to) {
        std::size_t c = 0;
        for (const Chord& ch : capChords[k][side == LoopSide::A ? 0 : 1][q.end < 0 ? 0 : 1])
            if (segmentsCross(from, to, ch[0], ch[1])) ++c;
        return c;
    };
    // Per tow, (triangle, loop) for every loop whose inside holds the triangle, by triangle.
    std::vector<std::vector<std::pair<std::size_t, std::size_t>>> hits(tows.size());
    detail::parallelFor(tows.size(), threads, [&](std::size_t t) {
        detail::throwIfCancelled(options.monitor);
        for (std::size_t k = 0; k < shared.size(); ++k)
            for (const LoopSide side : {LoopSide::A, LoopSide::B}) {
                const IntersectionLoop& l = loopOf(k);
                if ((side == LoopSide::A ? l.towA() : l.towB()) != t || l.windsAround(side)) continue;  // bands: below
                for (std::size_t tri : detail::trianglesInside(uv.centroid[t], polygonOf(k, side), period(t)))
                    hits[t].emplace_back(tri, k);
            }
        // Each loop's inside by the pieces its chords cut the mesh into (MeshPieces): a triangle
        // thin along a chord may fail its own test. Again with the cap triangles below.
        // Only triangles with a test vote: side triangles, then also the cap triangles probed
        // for a loop across that cap.
        const detail::MeshPieces pieces(in.tows[t].triangles);
        std::vector<bool> onSide(in.tows[t].triangles.size()), probed;
        for (std::size_t i = 0; i < onSide.size(); ++i) onSide[i] = !std::isnan(uv.centroid[t][i].u);
        probed = onSide;
        for (std::size_t i = 0; i < uv.probe[t].size(); ++i)
            if (uv.probe[t][i].end != 0 && uv.probe[t][i].rimTriangle != SIZE_MAX) probed[i] = true;
        const auto byPieces = [&](std::vector<std::pair<std::size_t, std::size_t>>& h, bool withCaps) {
            std::map<std::size_t, std::vector<std::size_t>> byLoop;
            for (const auto& [tri, k] : h) byLoop[k].push_back(tri);
            h.clear();
            for (auto& [k, tris] : byLoop) {
                std::sort(tris.begin(), tris.end());
                const IntersectionLoop& l = loopOf(k);
                const bool caps = withCaps && l.crossesCap(l.towA() == t ? LoopSide::A : LoopSide::B);
                for (std::size_t tri : pieces.inside(in.loops[shared[k]].nodes, tris, caps ? probed : onSide)) h.emplace_back(tri, k);
            }
            std::sort(h.begin(), h.end());
        };
        byPieces(hits[t], false);
        // Cap triangles (CapProbe): inside a loop where the side triangle at the rim beyond them
        // is, unless an odd number of the loop's chords on the cap lie between.
        if (uv.probe[t].empty()) return;
        std::vector<std::pair<std::size_t, std::size_t>> capHits;
        for (std::size_t k = 0; k < shared.size(); ++k)
            for (const LoopSide side : {LoopSide::A, LoopSide::B}) {
                const IntersectionLoop& l = loopOf(k);
                if ((side == LoopSide::A ? l.towA() : l.towB()) != t || l.windsAround(side) || !l.crossesCap(side)) continue;
                for (std::size_t tri = 0; tri < uv.probe[t].size(); ++tri) {
                    const CapProbe& q = uv.probe[t][tri];
                    if (q.end == 0 || q.rimTriangle == SIZE_MAX) continue;  // (then the swap's check names the pair)
                    const bool rimInside = std::binary_search(hits[t].begin(), hits[t].end(), std::make_pair(q.rimTriangle, k));
                    if (rimInside != (crossings(k, side, q, {q.px, q.py}, {q.qx, q.qy}) % 2 == 1)) capHits.emplace_back(tri, k);
                }
            }
        hits[t].insert(hits[t].end(), capHits.begin(), capHits.end());
        byPieces(hits[t], true);
    });
    // On a cell's face, a cap triangle of two tows' caps lies inside both (a loop of theirs
    // crosses the face): the lower-ranked tow gives way there, inside the pair's loop with the
    // node nearest to it.
    if (in.cell) {
        std::map<Triangle, std::vector<std::pair<std::size_t, std::size_t>>> onFace;  // sorted nodes -> (tow, triangle)
        for (std::size_t t = 0; t < tows.size(); ++t) {
            const TowMesh& m = in.tows[t];
            for (std::size_t k = 0; k < m.triangles.size(); ++k) {
                if (!((m.face[k] == TowFace::Start && m.cutAt[0]) || (m.face[k] == TowFace::End && m.cutAt[1]))) continue;
                Triangle key = m.triangles[k];
                std::sort(key.begin(), key.end());
                onFace[key].emplace_back(t, k);
            }
        }
        for (const auto& [key, list] : onFace) {
            if (list.size() < 2) continue;
            const Point3 centre = (1.0 / 3.0) * (N[key[0]] + N[key[1]] + N[key[2]]);
            for (const auto& [t, tri] : list)
                for (const auto& on : list) {
                    const std::size_t o = on.first;
                    if (o == t || rank[o] > rank[t]) continue;
                    std::size_t best = shared.size();
                    double nearest = std::numeric_limits<double>::infinity();
                    for (std::size_t k = 0; k < shared.size(); ++k) {
                        if (pairOf(k) != TowPair(std::min(t, o), std::max(t, o))) continue;
                        for (const std::size_t n : in.loops[shared[k]].nodes)
                            if (const double d = distance(N[n], centre); d < nearest) {
                                nearest = d;
                                best = k;
                            }
                    }
                    if (best < shared.size()) hits[t].emplace_back(tri, best);
                }
        }
        for (auto& h : hits) std::sort(h.begin(), h.end());
    }
    // One region per loop of even depth, primary the higher-ranked tow of its pair.
    std::vector<long> regionOf(shared.size(), -1);
    std::vector<ConnectedRegion> regions;
    std::vector<std::vector<Triangle>> lens;  // per region: both tows' surfaces inside the loop
    std::vector<std::vector<Triangle>> secondaryInside;  // per region: the secondary's surface inside the loop
    std::vector<char> crowded;  // per region: a triangle of it lies inside a third tow too
    for (std::size_t k = 0; k < shared.size(); ++k) {
        if (depth[k] % 2 == 1) continue;  // a hole of the region around it
        const auto [a, b] = pairOf(k);
        ConnectedRegion r;
        r.primary = rank[a] < rank[b] ? a : b;
        r.secondary = rank[a] < rank[b] ? b : a;
        r.loop = in.loops[shared[k]].loop;
        for (std::size_t h : inside[k])
            if (depth[h] == depth[k] + 1) r.holes.push_back(in.loops[shared[h]].loop);
        r.loopNodes = in.loops[shared[k]].nodes;
        regionOf[k] = static_cast<long>(regions.size());
        regions.push_back(std::move(r));
        lens.emplace_back();
        secondaryInside.emplace_back();
        crowded.push_back(0);
    }
    // Loops that wind around a tow (it passes through the other tow, or ends inside it) cut it
    // into bands alternately inside and outside the other.
    std::vector<std::vector<TowBands>> bandsOn(tows.size());
    std::set<TowPair> bandPairs;
    {
        std::map<TowPair, std::vector<std::size_t>> winding;  // (t, o) -> its loops winding around t, by index in shared
        for (std::size_t k = 0; k < shared.size(); ++k) {
            const IntersectionLoop& l = loopOf(k);
            if (l.windsAround(LoopSide::A) && l.windsAround(LoopSide::B)) continue;
            if (l.windsAround(LoopSide::A)) winding[{l.towA(), l.towB()}].push_back(k);
            if (l.windsAround(LoopSide::B)) winding[{l.towB(), l.towA()}].push_back(k);
        }
        for (const auto& [to, list] : winding) {
            std::vector<std::size_t> reportLoops;
            for (std::size_t k : list) reportLoops.push_back(in.loops[shared[k]].loop);
            std::optional<detail::WindingBands> b = detail::windingBands(tows, to.first, to.second, loops, reportLoops);
            if (!b) {
                failures.push_back({to.first, "its loops with tow '" + tows[to.second].name() +
                                                  "' go around it but do not cut it into bands alternately inside and outside"});
                continue;
            }
            TowBands tb{to.second, std::move(*b), {}, {}};
            for (const std::size_t l : tb.bands.loops) {
                const std::size_t k = *std::find_if(list.begin(), list.end(), [&](std::size_t s) { return in.loops[shared[s]].loop == l; });
                tb.loops.push_back(k);
                tb.polygons.emplace_back(polygonOf(k, loops[l].towA() == to.first ? LoopSide::A : LoopSide::B));
            }
            bandPairs.insert(std::minmax(to.first, to.second));
            bandsOn[to.first].push_back(std::move(tb));
        }
    }
    if (!failures.empty()) return failures;
    std::map<TowPair, std::size_t> windingRegionLoop;  // pair -> its first loop around a tow
    for (std::size_t k = 0; k < shared.size(); ++k) {
        const IntersectionLoop& l = loopOf(k);
        if ((l.windsAround(LoopSide::A) || l.windsAround(LoopSide::B)) && regionOf[k] >= 0) windingRegionLoop.try_emplace(pairOf(k), k);
    }
    std::vector<std::vector<char>> removed(tows.size());
    std::vector<std::vector<long>> region(tows.size());
    // Per tow, the triangles of lower-ranked tows' surfaces it gets: (triangle, region, fibre
    // direction of the surface it lies on).
    std::vector<std::vector<std::tuple<Triangle, long, Vector3>>> inserted(tows.size());
    std::vector<char> failed(tows.size(), 0);
    for (std::size_t t = 0; t < tows.size(); ++t) {
        const TowMesh& mesh = in.tows[t];
        removed[t].assign(mesh.triangles.size(), 0);
        region[t].assign(mesh.triangles.size(), -1);
        const auto& h = hits[t];
        const double uMin = tows[t].parameterRange().uMin;
        std::size_t next = 0;  // into hits, sorted by triangle
        for (std::size_t tri = 0; tri < mesh.triangles.size(); ++tri) {
            const std::size_t first = next;
            while (next < h.size() && h[next].first == tri) ++next;
            if (first == next && bandsOn[t].empty()) {  // inside no loop: skip ahead
                tri = next < h.size() ? h[next].first - 1 : mesh.triangles.size();
                continue;
            }
            // The tows it lies inside, each with its pair's deepest loop around it.
            std::map<std::size_t, std::pair<std::size_t, std::size_t>> within;  // tow -> (loops around it, deepest)
            for (std::size_t q = first; q < next; ++q) {
                const std::size_t k = h[q].second;
                const auto [a, b] = pairOf(k);
                auto& [count, deepest] = within.try_emplace(a == t ? b : a, 0, k).first->second;
                ++count;
                if (depth[k] > depth[deepest]) deepest = k;
            }
            // Bands: inside the other tow when an odd number of its winding loops lie between the
            // tow's start and the triangle, unless the start is inside; caps in the end bands.
            for (const TowBands& b : bandsOn[t]) {
                const std::size_t n = b.loops.size();
                std::size_t passed = 0;
                const CapProbe* q = uv.probe[t].empty() ? nullptr : &uv.probe[t][tri];
                if (mesh.face[tri] == TowFace::Side) {
                    passed = detail::loopsBefore(b.polygons, uv.centroid[t][tri], std::min(uMin, tows[t].impl().caps.uLow()), period(t));
                } else if (q && q->end != 0) {
                    // On a cap with loops across it: from the cap's centre (before every loop on
                    // the first cap, after every loop on the last), each loop's chords crossed.
                    for (const std::size_t k : b.loops) {
                        const LoopSide side = loopOf(k).towA() == t ? LoopSide::A : LoopSide::B;
                        passed += ((q->end > 0 ? 1 : 0) + crossings(k, side, *q, {0.0, 0.0}, {q->px, q->py})) % 2;
                    }
                } else if (mesh.face[tri] == TowFace::End) {
                    passed = n;
                }
                if (b.bands.startInside == (passed % 2 == 1)) continue;  // outside o there
                const std::size_t bounding = b.loops[passed > 0 ? std::min(passed, n) - 1 : 0];
                auto [it, added] = within.try_emplace(b.other, 1, bounding);
                if (!added) {
                    ++it->second.first;
                    if (it->second.first % 2 == 1 && regionOf[it->second.second] < 0) it->second.second = bounding;
                }
            }
            // Inside by parity but its deepest loop is a hole (a loop nested in a loop around a
            // tow, whose nesting was taken on the other tow): the pair's band region.
            for (auto& [o, c] : within)
                if (c.first % 2 == 1 && regionOf[c.second] < 0)
                    if (const auto w = windingRegionLoop.find(std::minmax(t, o)); w != windingRegionLoop.end()) c.second = w->second;
            std::size_t top = tows.size();  // the highest-ranked tow it lies inside
            std::size_t insideTows = 0;
            for (const auto& [o, c] : within)
                if (c.first % 2 == 1) {
                    ++insideTows;
                    if (top == tows.size() || rank[o] < rank[top]) top = o;
                }
            // Inside two other tows or more: every region of those pairs has a third tow in it.
            if (insideTows > 1)
                for (const auto& [o, c] : within)
                    if (c.first % 2 == 1 && regionOf[c.second] >= 0) crowded[static_cast<std::size_t>(regionOf[c.second])] = 1;
            for (const auto& [o, c] : within)
                if (c.first % 2 == 1 && regionOf[c.second] >= 0) lens[static_cast<std::size_t>(regionOf[c.second])].push_back(mesh.triangles[tri]);
            if (top == tows.size()) continue;
            if (rank[top] < rank[t]) {
                removed[t][tri] = 1;
                if (const long id = regionOf[within[top].second]; id >= 0) secondaryInside[static_cast<std::size_t>(id)].push_back(mesh.triangles[tri]);
            } else {
                const long id = regionOf[within[top].second];
                if (id < 0) {
                    if (!failed[t]) failures.push_back({t, "a triangle inside an odd number of loops has no region"});
                    failed[t] = 1;
                    continue;
                }
                const Triangle& triangle = mesh.triangles[tri];
                region[t][tri] = id;
                ConnectedRegion& r = regions[static_cast<std::size_t>(id)];
                r.triangles.push_back(tri);
                r.area += detail::triangleArea(N, triangle);
                inserted[top].emplace_back(reversed(triangle), id, mesh.fibreDirection[tri]);
            }
        }
    }
    if (!failures.empty()) return failures;
    // A tow through another (or ending inside it): its loops bound one overlap together, whose
    // volume goes to the pair's first region that kept triangles.
    for (const TowPair& pair : bandPairs) {
        std::vector<Triangle> all;
        long keep = -1;
        for (std::size_t k = 0; k < shared.size(); ++k) {
            if (pairOf(k) != pair || regionOf[k] < 0) continue;
            const std::size_t g = static_cast<std::size_t>(regionOf[k]);
            all.insert(all.end(), lens[g].begin(), lens[g].end());
            lens[g].clear();
            if (keep < 0 && !regions[g].triangles.empty()) keep = regionOf[k];
        }
        if (keep >= 0) lens[static_cast<std::size_t>(keep)] = std::move(all);
    }
    // Regions that kept triangles (a loop's surface may lie wholly inside a higher-ranked tow),
    // renumbered in loop order.
    out.tows.assign(tows.size(), TowResolution{});
    std::vector<long> renumbered(regions.size(), -1);
    std::vector<std::size_t> kept;  // the regions kept, by their old number
    for (std::size_t g = 0; g < regions.size(); ++g) {
        ConnectedRegion& r = regions[g];
        if (r.triangles.empty()) continue;
        std::set<std::size_t> regionNodes;
        for (std::size_t k : r.triangles) {
            const Triangle& tri = in.tows[r.primary].triangles[k];
            regionNodes.insert(tri.begin(), tri.end());
        }
        r.nodes.assign(regionNodes.begin(), regionNodes.end());
        // The loop's nodes around this region: where a higher-ranked tow covers part of the
        // loop, its nodes there belong to no triangle of the region.
        std::vector<std::size_t> around;
        for (std::size_t n : r.loopNodes)
            if (regionNodes.count(n)) around.push_back(n);
        r.loopNodes = std::move(around);
        // Both tows' surfaces inside the loop bound the two tows' overlap there, facing out of
        // it: its volume.
        r.volumeRemoved = std::abs(detail::signedVolume(N, lens[g]));
        out.tows[r.primary].primaryAnywhere = true;
        out.tows[r.secondary].secondaryAnywhere = true;
        renumbered[g] = static_cast<long>(out.mesh.regions.size());
        kept.push_back(g);
        out.mesh.regions.push_back(std::move(r));
    }
    for (auto& ids : region)
        for (long& id : ids)
            if (id >= 0) id = renumbered[static_cast<std::size_t>(id)];
    for (auto& list : inserted)
        for (auto& entry : list) std::get<1>(entry) = renumbered[static_cast<std::size_t>(std::get<1>(entry))];
    // The symmetric method: each region's nodes off the loops moved to the mid-surface.
    std::vector<Point3> nodes = N;
    std::vector<char> moved(N.size(), 0);
    if (options.method == ResolutionMethod::Symmetric) {
        std::vector<MidSurfaceMove> moves(out.mesh.regions.size());
        detail::parallelFor(out.mesh.regions.size(), threads, [&](std::size_t g) {
            moves[g] = midSurfaceMove(tows, loops, in, out.mesh.regions[g], secondaryInside[kept[g]], crowded[kept[g]] != 0);
        });
        for (std::size_t g = 0; g < moves.size(); ++g) {
            ConnectedRegion& r = out.mesh.regions[g];
            r.note = moves[g].note;
            if (!r.note.empty()) continue;
            r.surface = SharedSurface::Middle;
            for (std::size_t i = 0; i < moves[g].nodes.size(); ++i) {
                nodes[moves[g].nodes[i]] = moves[g].positions[i];
                moved[moves[g].nodes[i]] = 1;
            }
            r.area = 0.0;
            for (std::size_t k : r.triangles) r.area += detail::triangleArea(nodes, in.tows[r.primary].triangles[k]);
        }
    }
    out.mesh.tows.resize(tows.size());
    std::vector<std::vector<std::size_t>> placeOf(tows.size());  // input triangle -> its place in the tow's mesh
    detail::parallelFor(tows.size(), threads, [&](std::size_t t) {
        const TowMesh& mesh = in.tows[t];
        TowMesh& m = out.mesh.tows[t];
        m.name = mesh.name;
        m.cutAt = mesh.cutAt;
        placeOf[t].assign(mesh.triangles.size(), SIZE_MAX);
        for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
            if (removed[t][k]) continue;
            placeOf[t][k] = m.triangles.size();
            m.triangles.push_back(mesh.triangles[k]);
            m.region.push_back(region[t][k]);
            m.face.push_back(mesh.face[k]);
            m.fibreDirection.push_back(mesh.fibreDirection[k]);
        }
        for (const auto& [tri, id, direction] : inserted[t]) {  // another tow's surface (or cap): this tow's side
            m.triangles.push_back(tri);
            m.region.push_back(id);
            m.face.push_back(TowFace::Side);
            m.fibreDirection.push_back(direction);
        }
        // Its nodes on its own surface, with their (u,v).
        std::vector<std::size_t> used;
        used.reserve(3 * m.triangles.size());
        for (const Triangle& tri : m.triangles) used.insert(used.end(), tri.begin(), tri.end());
        std::sort(used.begin(), used.end());
        used.erase(std::unique(used.begin(), used.end()), used.end());
        auto at = mesh.parameters.begin();
        for (std::size_t n : used) {
            while (at != mesh.parameters.end() && at->first < n) ++at;
            if (at != mesh.parameters.end() && at->first == n && !moved[n]) m.parameters.push_back(*at);
        }
    });
    // A region's triangles by their place in the primary's final mesh (it keeps them all).
    for (ConnectedRegion& r : out.mesh.regions)
        for (std::size_t& k : r.triangles) k = placeOf[r.primary][k];
    // Every tow must still be closed (a tube open at its two ends without caps), oriented and
    // 2-manifold; anything else is a defect, never written out.
    std::vector<std::size_t> badEdges(tows.size(), 0);
    detail::parallelFor(tows.size(), threads, [&](std::size_t t) {
        TowResolution& r = out.tows[t];
        const auto& triangles = out.mesh.tows[t].triangles;
        // Its own mesh's volume: closed by its caps, or open at its two ends (closed by fans);
        // either way checked with the mesh after the swap below.
        r.volumeBefore = uv.capped[t] ? detail::signedVolume(N, in.tows[t].triangles) : detail::closedVolume(N, in.tows[t].triangles);
        const detail::SurfaceFigures f = detail::surfaceFigures(nodes, triangles);
        r.volumeAfter = f.volume;
        r.area = f.area;
        r.boundaryLoops = f.boundaryLoops;
        badEdges[t] = f.badEdges;
        r.pieces = detail::connectedPieces(triangles);
        if (t < meshed.tows.size()) {
            r.meshSize = meshed.tows[t].meshSize;
            r.fold = meshed.tows[t].fold;
        }
    });
    for (std::size_t t = 0; t < tows.size(); ++t)
        if (badEdges[t] != 0 || out.tows[t].boundaryLoops != (uv.capped[t] || meshed.mesh.tows[t].triangles.empty() ? 0u : 2u))
            failures.push_back({t, detail::notClosedMessage(uv.capped[t], badEdges[t], out.tows[t].boundaryLoops)});
    if (!failures.empty()) return failures;
    // The loops resolved, and the triple points where three of them cross.
    for (std::size_t k : shared) out.mesh.loops.push_back(in.loops[k]);
    out.mesh.triplePoints = in.triplePoints;
    out.mesh.sharpCorners = in.sharpCorners;
    out.mesh.cell = in.cell;
    detail::keepResolvedTriplePoints(out.mesh, loops);
    out.mesh.nodes = std::move(nodes);
    return failures;
}

}  // namespace

ResolveResult connectRegions(const std::vector<TowSurface>& tows, ResolveResult meshed, const ResolveOptions& options)
{
    if (options.method == ResolutionMethod::Shrink)
        throw Error(ErrorCode::InvalidArgument, "the shrink method changes the tows before they are meshed: use resolveTextile() or shrinkTows()");
    if (options.cell && options.cell->cutsMeshes()) {  // the cell clips the resolved meshes
        ResolveOptions uncut = options;
        uncut.cell.reset();
        return detail::clipResultToCell(tows, connectRegions(tows, std::move(meshed), uncut), options);
    }
    const Clock::time_point t0 = Clock::now();
    const Parametric uv = readParametric(tows, meshed);
    detail::sayStage(options, "connecting " + std::to_string(meshed.mesh.loops.size()) + " regions");
    // A tow that is not closed after the swap costs the tow pairs with loops on it: their loops
    // are left out of the regions (their nodes stay in the meshes) and the rest is connected again.
    std::vector<char> active(meshed.mesh.loops.size(), 1);
    std::vector<UnresolvedPair> unresolved;
    for (;;) {
        ResolveResult out;
        const std::vector<TowFailure> failures = connect(tows, meshed, uv, active, options, out);
        if (failures.empty()) {
            detail::keepUsedNodes(out.mesh);
            out.quality = detail::meshQuality(out.mesh, detail::surfaceAngleBound(options.mesh.minAngle));
            out.quality.facesOverBounds = meshed.quality.facesOverBounds;
            out.intersections = std::move(meshed.intersections);
            out.skippedLoops = std::move(meshed.skippedLoops);
            out.unresolved = std::move(meshed.unresolved);
            out.unresolved.insert(out.unresolved.end(), unresolved.begin(), unresolved.end());
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"  // ResolveResult::skipped, until 0.3
            out.skipped = std::move(meshed.skipped);
#pragma GCC diagnostic pop
            out.meshRounds = meshed.meshRounds;
            out.crossingTrianglePairs = meshed.crossingTrianglePairs;
            out.method = options.method;
            out.ranks = detail::towRanks(tows, options.primaryPatterns);
            out.timings = meshed.timings;
            out.timings.regions = msSince(t0);
            return out;
        }
        // Each failed tow's pairs, all taken before any loop is switched off: a pair between
        // two failed tows is left out once, and belongs to both.
        std::vector<std::set<TowPair>> pairsOf(failures.size());
        for (std::size_t i = 0; i < failures.size(); ++i)
            for (std::size_t k = 0; k < active.size(); ++k) {
                const IntersectionLoop& l = meshed.intersections.loops[meshed.mesh.loops[k].loop];
                if (active[k] && (l.towA() == failures[i].tow || l.towB() == failures[i].tow)) pairsOf[i].emplace(l.towA(), l.towB());
            }
        std::set<TowPair> leftOut;
        for (std::size_t i = 0; i < failures.size(); ++i) {
            const TowFailure& f = failures[i];
            if (pairsOf[i].empty()) throw Error(ErrorCode::Internal, f.message, "tow '" + tows[f.tow].name() + "'");
            for (const TowPair& p : pairsOf[i])
                if (leftOut.insert(p).second)
                    unresolved.push_back({p.first, p.second, UnresolvedPair::Reason::RegionFailed,
                                          "tow '" + tows[f.tow].name() + "' could not be connected with the loops of tows '" +
                                              tows[p.first].name() + "' and '" + tows[p.second].name() + "': " + f.message});
        }
        for (std::size_t k = 0; k < active.size(); ++k) {
            const IntersectionLoop& l = meshed.intersections.loops[meshed.mesh.loops[k].loop];
            if (leftOut.count({l.towA(), l.towB()})) active[k] = 0;
        }
        const std::size_t left = leftOut.size();
        detail::sayStage(options, "connecting again without the " + std::to_string(left) + " tow pair(s) on " +
                                      std::to_string(failures.size()) + " tow(s) whose regions failed");
    }
}

TOWGEOM_END_NAMESPACE
