#include "mesh/parametric_mesher.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <set>

#include "mesh/constraint_keeping_mesher.hpp"
#include "mesh/mesh_cdt.hpp"
#include "mesh/sharp_corners.hpp"
#include "mesh/scaled_space.hpp"
#include "mesh/starting_points.hpp"
#include "mesh/surface_metric.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

using mesh2::CDT;
using mesh2::Criteria;
using mesh2::K;

namespace {

/// Stations along [from, to] at most @p h apart (or, with @p spacingAt, at most spacingAt(x)
/// apart, within [h / 100, h]), plus @p extra ones (kept exactly); stations closer than a third
/// of their spacing to an extra one are dropped.
std::vector<double> stations(double from, double to, double h, const std::vector<double>& extra,
                             const std::function<double(double)>& spacingAt = {})
{
    const double length = to - from;
    std::vector<double> at;  // the evenly or graded spaced stations, both ends exactly
    if (!spacingAt || !(length > 0.0)) {
        const std::size_t n = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(length / h)));
        // The ends exactly (length * n / n need not be length): the rectangle's corners are
        // shared by two of its sides, and a gap there would let the outside into the domain.
        for (std::size_t k = 0; k <= n; ++k)
            at.push_back(k == 0 ? from : k == n ? to : from + length * static_cast<double>(k) / static_cast<double>(n));
    } else {
        // Walked by the local spacing, then shrunk evenly to end on `to`.
        at.push_back(from);
        while (at.back() < to) at.push_back(at.back() + std::clamp(spacingAt(at.back()), h / 100.0, h));
        const double shrink = length / (at.back() - from);
        for (double& x : at) x = from + (x - from) * shrink;
        if (at.size() < 2) at.push_back(to);
        at.back() = to;
    }
    std::vector<double> s(extra);
    for (std::size_t k = 0; k < at.size(); ++k) {
        const double x = at[k];
        // Even stations: a third of h (as always); graded ones: a third of their own spacing.
        const double spacing = !spacingAt || at.size() < 2 ? h : k + 1 < at.size() ? at[k + 1] - x : x - at[k - 1];
        const bool crowded = std::any_of(extra.begin(), extra.end(), [&](double e) { return std::abs(e - x) < spacing / 3.0; });
        if (!crowded || k == 0 || k + 1 == at.size()) s.push_back(x);
    }
    std::sort(s.begin(), s.end());
    s.erase(std::unique(s.begin(), s.end()), s.end());
    return s;
}

/// Rounds of splitting edges between two loop nodes that are no loop chord (Impl::refine()):
/// one usually does; a new node may be joined to loop nodes again only across a neck.
constexpr int kBridgeRounds = 4;

/// Rounds of splitting the tow's ends' edges where faces next to them are still bad
/// (Impl::refine()), and the shortest end edge split, of the mesh size.
constexpr int kEndRounds = 6;
constexpr double kMinEndEdge = 1.0 / 256.0;

/// Loop chords lying along the seam: their ends' x (lower first).
using SeamChords = std::set<std::pair<double, double>>;

/// After refinement, the faces still bad are those whose circumcentre would encroach on a
/// constraint (the mesher would have split it). Asks for those splits in @p requests: the middle
/// of a loop chord (a node of both tows) or of a seam edge (a node of both sides). An edge of the
/// tow's two ends (x = @p x0 or @p x1) is this tow's alone: its middle goes into @p endSplits,
/// for the mesher to insert itself, unless it is shorter than @p minEndEdge. Faces whose centroid lies beyond
/// [@p keepFrom, @p keepTo] along x are not wanted (beyond a cell's cut): neither counted nor
/// split for. Returns the number of bad faces.
std::size_t requestSplits(const CDT& cdt, const Criteria& criteria, double ly, const ScaledSpace& space, double keepFrom,
                          double keepTo, double x0, double x1, double minEndEdge, const SeamChords& seamChords,
                          MeshRequests& requests, std::vector<K::Point_2>& endSplits)
{
    const Criteria::Is_bad isBad = criteria.is_bad_object();
    std::set<std::pair<long, long>> chords;
    std::set<double> seam;
    const auto encroached = [&](const K::Point_2& p, const CDT::Edge& e) {
        const K::Point_2& a = e.first->vertex(CDT::cw(e.second))->point();
        const K::Point_2& b = e.first->vertex(CDT::ccw(e.second))->point();
        return 4.0 * CGAL::squared_distance(p, CGAL::midpoint(a, b)) <= CGAL::squared_distance(a, b);
    };
    const auto request = [&](const CDT::Edge& e) {
        const CDT::Vertex_handle a = e.first->vertex(CDT::cw(e.second)), b = e.first->vertex(CDT::ccw(e.second));
        const K::Point_2 &pa = a->point(), &pb = b->point();
        const long lo = std::min(a->info().node, b->info().node), hi = std::max(a->info().node, b->info().node);
        const bool onSeam = (pa.y() == 0.0 && pb.y() == 0.0) || (pa.y() == ly && pb.y() == ly);
        // A loop chord along the seam (found by its place, on either side of the seam) is not
        // split: the curve between its nodes dips across the seam, a node there would lie off
        // it, and a seam station would be this tow's only. The faces stay bad.
        if (onSeam && seamChords.count(std::minmax(pa.x(), pb.x()))) return;
        // (No loop chord runs along an end: two rim nodes in a row get a node between them.)
        const bool onEnd = pa.x() == pb.x() && (pa.x() == x0 || pa.x() == x1);
        if (onEnd && std::abs(pb.y() - pa.y()) < minEndEdge) return;  // short enough: the faces stay bad
        if (onEnd) {
            const K::Point_2 middle = CGAL::midpoint(pa, pb);
            if (std::find(endSplits.begin(), endSplits.end(), middle) == endSplits.end()) endSplits.push_back(middle);
        } else if (onSeam) {
            const double x = 0.5 * (pa.x() + pb.x());
            if (seam.insert(x).second) requests.seamU.push_back(space.toUV(x, 0.0).u);
        } else if (lo >= 0) {
            if (chords.emplace(lo, hi).second)
                requests.onLoop.push_back({static_cast<std::size_t>(lo), static_cast<std::size_t>(hi)});
        }
    };
    std::size_t bad = 0;
    std::vector<CDT::Edge> boundary;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
        Criteria::Quality q;
        if (!f->is_in_domain()) continue;
        const double cx = (f->vertex(0)->point().x() + f->vertex(1)->point().x() + f->vertex(2)->point().x()) / 3.0;
        if (cx < keepFrom || cx > keepTo || isBad(f, q) == CGAL::Mesh_2::NOT_BAD) continue;
        ++bad;
        // An angle between two constraints comes from the input (a loop meeting the seam at a
        // shallow angle, a sharp turn of a loop): splitting would not help.
        if (int(f->is_constrained(0)) + int(f->is_constrained(1)) + int(f->is_constrained(2)) >= 2) continue;
        const K::Point_2 c = CGAL::circumcenter(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
        CDT::Locate_type lt;
        int li = 0;
        const CDT::Face_handle at = cdt.locate(c, lt, li, f);
        if (lt == CDT::EDGE && at->is_constrained(li)) {
            request({at, li});
        } else if ((lt == CDT::FACE || lt == CDT::EDGE) && at->is_in_domain()) {
            boundary.clear();
            cdt.get_boundary_of_conflicts(c, std::back_inserter(boundary), at);
            for (const CDT::Edge& e : boundary)
                if (e.first->is_constrained(e.second) && encroached(c, e)) request(e);
        } else {  // outside the domain: the face's own constraints in the way
            // (A face along an end, its circumcentre beyond it, needs that edge split whether or
            // not the circumcentre encroaches on it: a sliver between the end and a loop node.)
            const auto beyondEnd = [&](int k) {
                const K::Point_2 &a = f->vertex(CDT::cw(k))->point(), &b = f->vertex(CDT::ccw(k))->point();
                return a.x() == b.x() && ((a.x() == x0 && c.x() < x0) || (a.x() == x1 && c.x() > x1));
            };
            for (int k = 0; k < 3; ++k)
                if (f->is_constrained(k) && (encroached(c, {f, k}) || beyondEnd(k))) request({f, k});
        }
    }
    return bad;
}

/// The vertex at @p p, or none.
CDT::Vertex_handle vertexAt(const CDT& cdt, const K::Point_2& p)
{
    CDT::Locate_type lt;
    int li = 0;
    const CDT::Face_handle f = cdt.locate(p, lt, li);
    return lt == CDT::VERTEX ? f->vertex(li) : CDT::Vertex_handle();
}

/// The plane's lengths along u and around v (the scale of the parameter space): around, the
/// tow's girth (pi x its size); along, the conformal length, or in a cell the mean length.
struct ParameterScale {
    double alongU = 1.0;
    double aroundV = 1.0;
};

/// With @p conformal, the length along u is that of the conformal plane (ScaledSpace).
ParameterScale parameterScale(const TowSurface& surface, bool conformal)
{
    const ParameterRange r = surface.parameterRange();
    if (conformal) {
        const double around = 3.14159265358979323846 * surface.towSize();
        return {ScaledSpace::conformalLength(surface, around), around};
    }
    constexpr int kSamples = 8;
    const std::size_t along = 4 * surface.sectionCount();
    ParameterScale scale{0.0, 0.0};
    for (int k = 0; k < kSamples; ++k) {
        const double v = r.vMin + r.vPeriod() * k / kSamples;
        Point3 prev = surface.point(r.uMin, v);
        for (std::size_t i = 1; i <= along; ++i) {
            const Point3 p = surface.point(r.uMin + (r.uMax - r.uMin) * static_cast<double>(i) / static_cast<double>(along), v);
            scale.alongU += distance(prev, p) / kSamples;
            prev = p;
        }
    }
    scale.aroundV = 3.14159265358979323846 * surface.towSize();
    return scale;
}

}  // namespace


struct ParametricMesher::Impl {
    const TowSurface& surface;
    MeshSizes sizes;
    ParameterRange range;
    ParameterScale scale;
    double su, sv;  // scaled length per unit u, v
    double keep0, keep1;  // the wanted part of the scaled rectangle along u: everything, or sizes.uSpan
    double x0, x1;        // the meshed part: [0, alongU], or sizes.uSpan widened by h (within it)
    /// The plane meshed in: squared where the sections are oblique, except in a cell (its cuts
    /// and kept span are along u).
    ScaledSpace space;
    /// refineAround()'s spots in the scaled space, by x; the largest radius. (Before criteria:
    /// localSize() reads them when criteria is made.)
    struct ScaledSpot {
        double x, y, radius, size;
    };
    std::vector<ScaledSpot> spots;
    double spotReach = 0.0;
    SurfaceMetric metric;
    Criteria criteria;
    CDT cdt;
    std::multimap<std::size_t, CDT::Vertex_handle> loopVertex;  // a seam node has two
    std::set<std::pair<long, long>> loopsOfNode;  // (loop node, a loop it is on: LoopConstraint::loop)
    /// Whether loop node @p node lies on loop @p loop.
    bool onLoop(long node, long loop) const { return loopsOfNode.count({node, loop}) > 0; }
    /// The loops loop node @p node lies on, as a range of loopsOfNode.
    auto loopsOf(long node) const
    {
        return std::make_pair(loopsOfNode.lower_bound({node, std::numeric_limits<long>::min()}),
                              loopsOfNode.upper_bound({node, std::numeric_limits<long>::max()}));
    }
    /// Whether loop nodes @p a and @p b lie on one loop.
    bool oneLoop(long a, long b) const
    {
        for (auto [it, end] = loopsOf(a); it != end; ++it)
            if (onLoop(b, it->second)) return true;
        return false;
    }
    SeamChords seamChords;  // the x of the loop chords along the seam (lower first)
    /// Stations the ends' edges were split at (y, at x0 and at x1), kept when meshed again.
    std::array<std::vector<double>, 2> endStations;
    std::size_t badFaces = 0;

    Impl(const TowSurface& s, const MeshSizes& z)
        : surface(s), sizes(z), range(s.parameterRange()), scale(parameterScale(s, !z.uSpan)),
          su(scale.alongU / (range.uMax - range.uMin)), sv(scale.aroundV / range.vPeriod()),
          keep0(z.uSpan ? ((*z.uSpan)[0] - range.uMin) * su : -std::numeric_limits<double>::infinity()),
          keep1(z.uSpan ? ((*z.uSpan)[1] - range.uMin) * su : std::numeric_limits<double>::infinity()),
          x0(z.uSpan ? std::max(0.0, keep0 - z.edgeLength) : 0.0), x1(z.uSpan ? std::min(scale.alongU, keep1 + z.edgeLength) : scale.alongU),
          space(s, su, sv, !z.uSpan), metric(s, space, scale.alongU, scale.aroundV, z.edgeLength),
          criteria(shapeBound(z.minAngle), z.edgeLength, metric, localSize())
    {
    }
    /// The smallest size of the spots around (x, y) (across the seam too), or +infinity.
    double spotSize(double x, double y) const
    {
        const double period = range.vPeriod() * sv;
        double h = std::numeric_limits<double>::infinity();
        auto it = std::lower_bound(spots.begin(), spots.end(), x - spotReach, [](const ScaledSpot& s, double v) { return s.x < v; });
        for (; it != spots.end() && it->x <= x + spotReach; ++it) {
            double dy = std::abs(y - it->y);
            dy = std::min(dy, period - dy);
            if ((x - it->x) * (x - it->x) + dy * dy <= it->radius * it->radius) h = std::min(h, it->size);
        }
        return h;
    }
    /// sizes.sizeAt and the spots in the scaled space, or none.
    Criteria::LocalSize localSize() const
    {
        if (!sizes.sizeAt && spots.empty()) return {};
        return [this](double x, double y) {
            const double near = spotSize(x, y);
            if (!sizes.sizeAt) return near;
            const UV at = toUV({x, y});
            const double h = sizes.sizeAt(at);
            if (!(h > 0.0) || !std::isfinite(h))
                throw Error(ErrorCode::InvalidArgument, "the mesh size function gives " + std::to_string(h) + " at (u, v) = (" +
                                                            std::to_string(at.u) + ", " + std::to_string(at.v) + ")",
                            "tow '" + surface.name() + "'");
            return std::min(h, near);
        };
    }
    static double shapeBound(double minAngle)
    {
        const double a = std::clamp(minAngle, 1.0, 30.0) * 3.14159265358979323846 / 180.0;
        return std::sin(a) * std::sin(a);  // CGAL's bound: the squared sine of the smallest angle
    }
    K::Point_2 toXY(const UV& p) const
    {
        double x = 0.0, y = 0.0;
        space.toXY(p.u, p.v, x, y);
        return {x, y};
    }
    UV toUV(const K::Point_2& p) const { return space.toUV(p.x(), p.y()); }
    CDT::Vertex_handle insertLoopNode(const K::Point_2& p, std::size_t node)
    {
        // A node of two loops (a triple point, a figure-8's touching point) is one vertex, though
        // its two loops may give its (u,v) a rounding apart. A seam node has one on each side.
        if (p.y() != 0.0 && p.y() != scale.aroundV)
            for (auto [it, end] = loopVertex.equal_range(node); it != end; ++it)
                if (it->second->point().y() != 0.0 && it->second->point().y() != scale.aroundV) return it->second;
        const CDT::Vertex_handle v = cdt.insert(p);
        if (v->info().node >= 0 && static_cast<std::size_t>(v->info().node) != node)
            throw Error(ErrorCode::Internal,
                        "two intersection-loop nodes (" + std::to_string(v->info().node) + ", " + std::to_string(node) +
                            ") fall on the same point (u, v) = (" + std::to_string(toUV(p).u) + ", " + std::to_string(toUV(p).v) +
                            ") of the surface: intersection loops meet there (three tows "
                            "interpenetrate at one point, or a loop touches itself), which resolve does not handle",
                        "tow '" + surface.name() + "'");
        v->info().node = static_cast<long>(node);
        loopVertex.emplace(node, v);
        return v;
    }
    /// Puts a node of this tow's own at the middle of every edge that joins two nodes of one
    /// loop without being its chord (across a narrow neck of the loop, where its two sides come
    /// close): the other tow may join the same two nodes on the other side of the loop, and
    /// after the swap one tow's mesh would hold that edge four times. Returns whether it did.
    bool splitLoopBridges()
    {
        // The third side of a corner (a loop's turn, or where it meets the seam or a tow's end),
        // or an edge from a node where two loops meet (a figure-8's touching point, a triple
        // point): the triangle is the corner's, splitting would not end.
        const auto corner = [&](CDT::Face_handle h) {
            return !cdt.is_infinite(h) && int(h->is_constrained(0)) + int(h->is_constrained(1)) + int(h->is_constrained(2)) >= 2;
        };
        const auto meeting = [&](CDT::Vertex_handle v) {
            const auto [first, end] = loopsOf(v->info().node);
            return std::distance(first, end) > 1;
        };
        std::vector<K::Point_2> middles;
        for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
            const CDT::Face_handle f = e->first, g = f->neighbor(e->second);
            if (f->is_constrained(e->second) || !(f->is_in_domain() || (!cdt.is_infinite(g) && g->is_in_domain()))) continue;
            const CDT::Vertex_handle a = f->vertex(CDT::cw(e->second)), b = f->vertex(CDT::ccw(e->second));
            if (a->info().node < 0 || b->info().node < 0 || !oneLoop(a->info().node, b->info().node)) continue;
            if (corner(f) || corner(g) || meeting(a) || meeting(b)) continue;
            middles.push_back(CGAL::midpoint(a->point(), b->point()));
        }
        std::size_t inserted = 0;
        for (const K::Point_2& p : middles) {
            // A rounded middle that falls on a vertex or a constraint (a loop chord: it would
            // get a node of this tow only) is left out.
            CDT::Locate_type lt;
            int li = 0;
            const CDT::Face_handle at = cdt.locate(p, lt, li);
            if (lt == CDT::VERTEX || (lt == CDT::EDGE && at->is_constrained(li))) continue;
            cdt.insert(p, at);
            ++inserted;
        }
        return inserted > 0;
    }
    /// Whether a vertex lies on the seam (either side) strictly between x = @p a and @p b.
    bool seamVertexBetween(double a, double b) const
    {
        const auto [lo, hi] = std::minmax(a, b);
        for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
            const K::Point_2& q = v->point();
            if ((q.y() == 0.0 || q.y() == scale.aroundV) && q.x() > lo && q.x() < hi) return true;
        }
        return false;
    }
    /// Refines (with splitLoopBridges()), then asks for the splits that the faces still bad need.
    /// Once refineAround() has given spots (the tow's mesh crossed another's), the ends' edges
    /// are split here too where faces next to them need it (they are this tow's alone), and kept
    /// for a new mesh. (Not before: each split means refining the whole tow again.)
    void refine(MeshRequests& requests)
    {
        for (int round = 0;; ++round) {
            refineKeepingConstraints(cdt, criteria);
            for (int bridge = 0; bridge < kBridgeRounds && splitLoopBridges(); ++bridge) refineKeepingConstraints(cdt, criteria);
            MeshRequests asked;
            std::vector<K::Point_2> endSplits;
            badFaces = requestSplits(cdt, criteria, scale.aroundV, space, keep0, keep1, x0, x1, kMinEndEdge * sizes.edgeLength,
                                     seamChords, asked, endSplits);
            if (endSplits.empty() || spots.empty() || round == kEndRounds) {
                requests.seamU.insert(requests.seamU.end(), asked.seamU.begin(), asked.seamU.end());
                requests.onLoop.insert(requests.onLoop.end(), asked.onLoop.begin(), asked.onLoop.end());
                return;
            }
            for (const K::Point_2& p : endSplits) {
                cdt.insert(p);  // a point on a constrained edge splits it
                (p.x() == x0 ? endStations[0] : endStations[1]).push_back(p.y());
            }
        }
    }
    /// A loop chord along the seam (its two nodes on one side of it, @p va and @p vb): the curve
    /// between them dips across the seam, and the new node lies off it, on the seam's one side or
    /// the other. It goes on that side, joined to the chord's ends there by two new constraints;
    /// the chord stays as the seam's edge (a thin triangle of the domain between them), no loop
    /// chord now, with a seam station at the node's x when it lies between the chord's ends.
    /// NotAlongSeam when the chord is not along the seam or the node lies on it (split as any
    /// chord); Failed when the chord's ends have no vertices on that side (the tow is meshed
    /// again from the start).
    enum class SeamSplit { NotAlongSeam, Done, Failed };
    SeamSplit splitAlongSeam(const ChordSplit& s, CDT::Vertex_handle va, CDT::Vertex_handle vb)
    {
        const double ly = scale.aroundV, period = range.vPeriod() * sv;
        const double ya = va->point().y(), yb = vb->point().y();
        if (ya != yb || (ya != 0.0 && ya != ly)) return SeamSplit::NotAlongSeam;
        const K::Point_2 at = toXY(s.at);
        double y = at.y() - period * std::floor(at.y() / period);  // in [0, period)
        if (y < 1e-9 * period || y > period - 1e-9 * period) return SeamSplit::NotAlongSeam;  // on the seam: split along it
        const double side = y < 0.5 * period ? 0.0 : ly;
        const CDT::Vertex_handle a = vertexAt(cdt, K::Point_2(va->point().x(), side)), b = vertexAt(cdt, K::Point_2(vb->point().x(), side));
        if (a == CDT::Vertex_handle() || b == CDT::Vertex_handle()) return SeamSplit::Failed;
        const CDT::Vertex_handle vm = insertLoopNode(K::Point_2(at.x(), y), s.node);
        cdt.insert_constraint(a, vm);
        cdt.insert_constraint(vm, b);
        // The seam's edge between the chord's ends is no loop chord now (the loop runs through
        // the new node): requestSplits() may ask for seam stations in it (kept as a loop chord,
        // its faces across the seam sagged through the other tow's faces: seed 145, 13 crossing
        // triangle pairs that refinement made worse), and it gets a station of this tow's own at
        // the new node's x, on both sides, so that those faces follow the surface next to the
        // loop. (The station is not kept for a full re-mesh, which puts uniform stations there.)
        const auto [lo, hi] = std::minmax(va->point().x(), vb->point().x());
        seamChords.erase({lo, hi});
        if (at.x() > lo && at.x() < hi) {
            cdt.insert(K::Point_2(at.x(), 0.0));
            cdt.insert(K::Point_2(at.x(), ly));
        }
        return SeamSplit::Done;
    }
};

ParametricMesher::ParametricMesher(const TowSurface& surface, const MeshSizes& sizes)
    : impl_(std::make_unique<Impl>(surface, sizes))
{
}
ParametricMesher::~ParametricMesher() = default;
ParametricMesher::ParametricMesher(ParametricMesher&&) noexcept = default;

void ParametricMesher::mesh(const std::vector<LoopConstraint>& constraints, const std::vector<double>& seamU,
                            MeshRequests& requests)
{
    Impl& m = *impl_;
    const double ly = m.scale.aroundV, h = m.sizes.edgeLength;
    m.cdt.clear();
    m.loopVertex.clear();
    m.loopsOfNode.clear();
    for (const LoopConstraint& c : constraints)
        if (c.loop >= 0)
            for (std::size_t n : c.nodes) m.loopsOfNode.emplace(static_cast<long>(n), c.loop);
    m.seamChords.clear();

    // Seam stations: uniform along u plus every loop node on the seam, the same on both sides.
    // All four sides get stations h/2 apart in the plane: edges that short are seldom
    // encroached, nor too long in 3D where the surface is longer than its mean (along the seam,
    // h/2 times the tow's girth there over its mean; longer seam edges are split in rounds).
    std::vector<double> seamX, loopSeamX;  // all stations asked for; the loop nodes among them
    for (double u : seamU) seamX.push_back(m.toXY({u, m.range.vMin}).x());
    for (const LoopConstraint& c : constraints)
        for (std::size_t k = 0; k < c.uv.size(); ++k)
            if (c.uv[k].v == m.range.vMin || c.uv[k].v == m.range.vMax) loopSeamX.push_back(m.toXY(c.uv[k]).x());
    seamX.insert(seamX.end(), loopSeamX.begin(), loopSeamX.end());
    // A loop chord along the seam (both its nodes on it) is one edge of the seam: no station
    // between its nodes, which the other tow's mesh would not have on that chord (not one asked
    // for before the chord was split onto the seam either).
    for (const LoopConstraint& c : constraints)
        for (std::size_t k = 0; k + 1 < c.uv.size(); ++k)
            for (const double side : {m.range.vMin, m.range.vMax})
                if (c.uv[k].v == side && c.uv[k + 1].v == side)
                    m.seamChords.insert(std::minmax(m.toXY(c.uv[k]).x(), m.toXY(c.uv[k + 1]).x()));
    // Where a size function grades the mesh, the stations follow it: half the local size apart.
    const Criteria::LocalSize local = m.sizes.sizeAt ? m.localSize() : Criteria::LocalSize{};  // not for spots alone
    const auto spacingAlong = [&](bool alongX, double fixed) -> std::function<double(double)> {
        if (!local) return {};
        return [&local, alongX, fixed](double t) { return 0.5 * (alongX ? local(t, fixed) : local(fixed, t)); };
    };
    std::vector<double> xs = stations(m.x0, m.x1, 0.5 * h, seamX, spacingAlong(true, 0.0));
    xs.erase(std::remove_if(xs.begin(), xs.end(),
                            [&](double x) {
                                return std::find(loopSeamX.begin(), loopSeamX.end(), x) == loopSeamX.end() &&
                                       std::any_of(m.seamChords.begin(), m.seamChords.end(),
                                                   [&](const std::pair<double, double>& c) { return x > c.first && x < c.second; });
                            }),
             xs.end());
    // Loop nodes on the tow's ends (a loop across an end cap) are stations of those ends, so
    // that no station lies a hair's breadth from one.
    std::vector<double> startY, endY;
    for (const LoopConstraint& c : constraints)
        for (const UV& p : c.uv) {
            if (p.u == m.range.uMin) startY.push_back(m.toXY(p).y());
            if (p.u == m.range.uMax) endY.push_back(m.toXY(p).y());
        }
    std::vector<double> ys = stations(0.0, ly, 0.5 * h, startY, spacingAlong(false, m.x0)),
                        ysEnd = stations(0.0, ly, 0.5 * h, endY, spacingAlong(false, m.x1));
    for (int end = 0; end < 2; ++end) {  // and where refinement split them before
        std::vector<double>& y = end == 0 ? ys : ysEnd;
        y.insert(y.end(), m.endStations[end].begin(), m.endStations[end].end());
        std::sort(y.begin(), y.end());
        y.erase(std::unique(y.begin(), y.end()), y.end());
    }
    const auto polyline = [&](const std::vector<K::Point_2>& pts) {
        for (std::size_t k = 0; k + 1 < pts.size(); ++k) m.cdt.insert_constraint(pts[k], pts[k + 1]);
    };
    std::vector<K::Point_2> bottom, top, left, right;
    for (double x : xs) {
        bottom.emplace_back(x, 0.0);
        top.emplace_back(x, ly);
    }
    for (double y : ys) left.emplace_back(xs.front(), y);
    for (double y : ysEnd) right.emplace_back(xs.back(), y);
    polyline(bottom);
    polyline(top);
    polyline(left);
    polyline(right);
    std::vector<std::vector<K::Point_2>> chords;  // each loop piece in the scaled space, closed ones closed
    for (const LoopConstraint& c : constraints) {
        std::vector<CDT::Vertex_handle> vs;
        std::vector<K::Point_2>& piece = chords.emplace_back();
        for (std::size_t k = 0; k < c.uv.size(); ++k) {
            piece.push_back(m.toXY(c.uv[k]));
            vs.push_back(m.insertLoopNode(piece.back(), c.nodes[k]));
        }
        for (std::size_t k = 0; k + 1 < vs.size(); ++k) m.cdt.insert_constraint(vs[k], vs[k + 1]);
        if (c.closed && vs.size() > 2) {
            m.cdt.insert_constraint(vs.back(), vs.front());
            piece.push_back(piece.front());
        }
    }
    insertStartingPoints(m.cdt, chords, m.metric, xs.front(), xs.back(), ly, h);
    m.refine(requests);
}

bool ParametricMesher::split(const std::vector<ChordSplit>& splits, const std::vector<double>& seamU,
                             MeshRequests& requests)
{
    Impl& m = *impl_;
    const double period = m.range.vPeriod() * m.sv;
    for (const ChordSplit& s : splits) {
        // The chord's constrained edge (of a seam node's two vertices, the one on this chord).
        CDT::Vertex_handle va, vb;
        CDT::Face_handle f;
        int i = 0;
        const auto as = m.loopVertex.equal_range(s.a), bs = m.loopVertex.equal_range(s.b);
        for (auto x = as.first; x != as.second && va == CDT::Vertex_handle(); ++x)
            for (auto y = bs.first; y != bs.second; ++y)
                if (m.cdt.is_edge(x->second, y->second, f, i) && f->is_constrained(i)) {
                    va = x->second;
                    vb = y->second;
                    break;
                }
        if (va == CDT::Vertex_handle()) return false;
        // The new node is on the chord's loop(s).
        std::vector<long> loops;
        for (auto [it, end] = m.loopsOf(static_cast<long>(s.a)); it != end; ++it)
            if (m.onLoop(static_cast<long>(s.b), it->second)) loops.push_back(it->second);
        for (long l : loops) m.loopsOfNode.emplace(static_cast<long>(s.node), l);
        const Impl::SeamSplit along = m.splitAlongSeam(s, va, vb);
        if (along == Impl::SeamSplit::Failed) return false;
        if (along == Impl::SeamSplit::Done) continue;
        // The new node's v, by whole periods, next to the chord's (a chord may end on the seam).
        // A node a hair's breadth from the seam goes on it, on both sides (as constraintsOn()).
        K::Point_2 p = m.toXY(s.at);
        const double middle = 0.5 * (va->point().y() + vb->point().y());
        double y = p.y() + period * std::round((middle - p.y()) / period);
        if (std::abs(y) < 1e-9 * period) y = 0.0;
        if (std::abs(y - m.scale.aroundV) < 1e-9 * period) y = m.scale.aroundV;
        p = K::Point_2(p.x(), y);
        // A node on the seam next to one there makes that half a chord along the seam, one edge:
        // seam vertices between them (stations made before) are dropped by meshing again.
        if (y == 0.0 || y == m.scale.aroundV)
            for (const CDT::Vertex_handle e : {va, vb})
                if (e->point().y() == y && m.seamVertexBetween(e->point().x(), p.x())) return false;
        m.cdt.remove_constrained_edge(f, i);
        const CDT::Vertex_handle vm = m.insertLoopNode(p, s.node);
        if (y == 0.0 || y == m.scale.aroundV) m.cdt.insert(K::Point_2(p.x(), y == 0.0 ? m.scale.aroundV : 0.0));
        m.cdt.insert_constraint(va, vm);
        m.cdt.insert_constraint(vm, vb);
        // A node on the seam next to one there: that half runs along the seam.
        if (y == 0.0 || y == m.scale.aroundV)
            for (const CDT::Vertex_handle e : {va, vb})
                if (e->point().y() == y) m.seamChords.insert(std::minmax(e->point().x(), p.x()));
        // A chord along the seam split on it: its two halves are along the seam.
        if (m.seamChords.erase(std::minmax(va->point().x(), vb->point().x())) > 0) {
            m.seamChords.insert(std::minmax(va->point().x(), p.x()));
            m.seamChords.insert(std::minmax(p.x(), vb->point().x()));
        }
    }
    // New seam stations on both sides: a point on a constrained edge splits it. None inside a
    // loop chord along the seam (asked for before a split above made it one).
    for (double u : seamU) {
        const double x = m.toXY({u, m.range.vMin}).x();
        if (std::any_of(m.seamChords.begin(), m.seamChords.end(), [&](const std::pair<double, double>& c) { return x > c.first && x < c.second; }))
            continue;
        m.cdt.insert(K::Point_2(x, 0.0));
        m.cdt.insert(K::Point_2(x, m.scale.aroundV));
    }
    m.refine(requests);
    return true;
}

void ParametricMesher::refineAround(const std::vector<SizeSpot>& spots, MeshRequests& requests)
{
    Impl& m = *impl_;
    for (const SizeSpot& s : spots) {
        const K::Point_2 p = m.toXY(s.at);
        m.spots.push_back({p.x(), p.y(), s.radius, s.size});
        m.spotReach = std::max(m.spotReach, s.radius);
    }
    std::sort(m.spots.begin(), m.spots.end(), [](const Impl::ScaledSpot& a, const Impl::ScaledSpot& b) { return a.x < b.x; });
    m.criteria = Criteria(Impl::shapeBound(m.sizes.minAngle), m.sizes.edgeLength, m.metric, m.localSize());
    m.refine(requests);
}

std::size_t ParametricMesher::badFaces() const { return impl_->badFaces; }

ParametricMesh ParametricMesher::result(std::size_t firstNewNode)
{
    Impl& m = *impl_;
    const double ly = m.scale.aroundV;
    // Loop nodes are global already; the tow's own nodes are numbered from firstNewNode in
    // order. The seam's two sides are one row of nodes: a vertex at v = vMax is the vertex at
    // v = vMin (the same loop node if either is one: a loop may touch the seam at a node).
    ParametricMesh out;
    const auto nodeOf = [](CDT::Vertex_handle v) {
        return v->info().node >= 0 ? static_cast<std::size_t>(v->info().node) : v->info().own;
    };
    const auto seamError = [&](double x) {
        return Error(ErrorCode::Internal, "the two sides of the seam have different nodes at u = " + std::to_string(m.toUV({x, 0.0}).u),
                     "tow '" + m.surface.name() + "'");
    };
    std::map<double, std::pair<CDT::Vertex_handle, CDT::Vertex_handle>> seam;  // x -> (v = vMin, v = vMax)
    for (auto v = m.cdt.finite_vertices_begin(); v != m.cdt.finite_vertices_end(); ++v) {
        if (v->point().y() == 0.0) {
            seam[v->point().x()].first = v;
        } else if (v->point().y() == ly) {
            seam[v->point().x()].second = v;
        } else if (v->info().node < 0) {
            v->info().own = firstNewNode + out.newNodes.size();
            out.newNodes.push_back(m.toUV(v->point()));
        }
    }
    for (auto& [x, pair] : seam) {
        const auto [bottom, top] = pair;
        if (bottom == CDT::Vertex_handle() || top == CDT::Vertex_handle()) throw seamError(x);
        const long a = bottom->info().node, b = top->info().node;
        if (a >= 0 && b >= 0 && a != b) throw seamError(x);
        std::size_t node = 0;
        if (a >= 0 || b >= 0) {
            node = static_cast<std::size_t>(std::max(a, b));
        } else {
            node = firstNewNode + out.newNodes.size();
            out.newNodes.push_back(m.toUV(bottom->point()));
        }
        bottom->info().own = top->info().own = node;
    }
    out.triangles.reserve(m.cdt.number_of_faces());
    out.centroids.reserve(m.cdt.number_of_faces());
    for (auto f = m.cdt.finite_faces_begin(); f != m.cdt.finite_faces_end(); ++f) {
        if (!f->is_in_domain()) continue;
        out.triangles.push_back({nodeOf(f->vertex(0)), nodeOf(f->vertex(1)), nodeOf(f->vertex(2))});
        const K::Point_2 c = CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
        out.centroids.push_back(m.toUV(c));
    }
    if (out.triangles.empty())
        throw Error(ErrorCode::Internal, "the parameter rectangle was not meshed", "tow '" + m.surface.name() + "'");
    out.badFaces = m.badFaces;
    // The corners' angles on the surface: the metric's at the apex (the first fundamental form).
    const auto angleAt = [&](CDT::Face_handle f, int i) {
        const K::Point_2& p = f->vertex(i)->point();
        const K::Vector_2 a = f->vertex(CDT::ccw(i))->point() - p, b = f->vertex(CDT::cw(i))->point() - p;
        const SurfaceMetric::Form g = m.metric.at(p.x(), p.y());
        const auto dot = [&](const K::Vector_2& x, const K::Vector_2& y) {
            return g.e * x.x() * y.x() + g.f * (x.x() * y.y() + x.y() * y.x()) + g.g * x.y() * y.y();
        };
        const double ab = dot(a, b), cross = std::sqrt(std::max(0.0, dot(a, a) * dot(b, b) - ab * ab));
        return std::atan2(cross, ab) * 180.0 / 3.14159265358979323846;
    };
    const auto distanceFrom = [&](CDT::Vertex_handle v, const K::Point_2& p) {
        const K::Point_2& a = v->point();
        return std::sqrt(m.metric.squaredLength(a.x(), a.y(), p.x() - a.x(), p.y() - a.y()));
    };
    for (const CornerWedge& w : sharpWedges(m.cdt, angleAt, distanceFrom, surfaceAngleBound(m.sizes.minAngle), m.sizes.edgeLength)) {
        SharpCorner c{nodeOf(w.vertex), 0, TowFace::Side, w.angle, {}};
        for (CDT::Face_handle f : w.faces) c.triangles.push_back({nodeOf(f->vertex(0)), nodeOf(f->vertex(1)), nodeOf(f->vertex(2))});
        out.sharpCorners.push_back(std::move(c));
    }
    return out;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
