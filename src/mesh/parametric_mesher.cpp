#include "mesh/parametric_mesher.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "mesh/constraint_keeping_mesher.hpp"
#include "mesh/surface_metric.hpp"
#include "towgeom/error.hpp"

namespace towgeom::detail {

namespace {

/// What a triangulation vertex is: a loop node (its global index), or not (-1).
struct VertexInfo {
    long node = -1;
    std::size_t own = 0;  ///< the tow's own node number, set by result()
};

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vbi = CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, K>;
using Vb = CGAL::Delaunay_mesh_vertex_base_2<K, Vbi>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

/// CGAL's size-and-shape criteria with the size measured in 3D: an edge is too long when the
/// surface metric makes it longer than h. The shape bound stays in the scaled space, where
/// CGAL's refinement is known to terminate. Loop chords (constrained edges between two loop
/// nodes) are the loop's own sampling, at the loop spacing: they are exempt from the size
/// bound, so the mesher does not split them only for being a little over h.
class Criteria : public CGAL::Delaunay_mesh_size_criteria_2<CDT> {
public:
    using Base = CGAL::Delaunay_mesh_size_criteria_2<CDT>;
    Criteria(double shapeBound, double h, const SurfaceMetric& metric) : Base(shapeBound, h), metric_(&metric) {}

    class Is_bad : public Base::Is_bad {
    public:
        Is_bad(double shapeBound, double h, const SurfaceMetric& metric)
            : Base::Is_bad(shapeBound, h, K()), metric_(&metric)
        {
        }
        using Base::Is_bad::operator();
        CGAL::Mesh_2::Face_badness operator()(const CDT::Face_handle& f, Quality& q) const
        {
            q.second = 0.0;
            for (int k = 0; k < 3; ++k) {
                const CDT::Vertex_handle a = f->vertex(CDT::cw(k)), b = f->vertex(CDT::ccw(k));
                if (f->is_constrained(k) && a->info().node >= 0 && b->info().node >= 0) continue;
                const K::Point_2 &p = a->point(), &r = b->point();
                const double l2 = metric_->squaredLength(0.5 * (p.x() + r.x()), 0.5 * (p.y() + r.y()), r.x() - p.x(), r.y() - p.y());
                q.second = std::max(q.second, l2 / this->squared_size_bound);
            }
            if (q.size() > 1.0) {
                q.first = 1.0;
                return CGAL::Mesh_2::IMPERATIVELY_BAD;
            }
            // The shape, in the scaled space: CGAL's own measure with the size bound off.
            Quality shape;
            const CGAL::Mesh_2::Face_badness badness = Base::Is_bad(this->B, 0.0, K())(f, shape);
            q.first = shape.first;
            return badness;
        }

    private:
        const SurfaceMetric* metric_;
    };
    Is_bad is_bad_object() const { return Is_bad(this->bound(), this->size_bound(), *metric_); }

private:
    const SurfaceMetric* metric_;
};
// Delaunay refinement may split constrained edges; such points are reported (MeshRequests) so
// that both tows of a loop, and both sides of the seam, get them before the final meshing.
using Mesher = CGAL::Delaunay_mesher_2<CDT, Criteria>;

/// Stations along [0, length] at most @p h apart, plus @p extra ones (kept exactly); uniform
/// stations closer than h/3 to an extra one are dropped.
std::vector<double> stations(double length, double h, const std::vector<double>& extra)
{
    const std::size_t n = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(length / h)));
    std::vector<double> s(extra);
    for (std::size_t k = 0; k <= n; ++k) {
        // The ends exactly (length * n / n need not be length): the rectangle's corners are
        // shared by two of its sides, and a gap there would let the outside into the domain.
        const double x = k == n ? length : length * static_cast<double>(k) / static_cast<double>(n);
        const bool crowded = std::any_of(extra.begin(), extra.end(), [&](double e) { return std::abs(e - x) < h / 3.0; });
        if (!crowded || k == 0 || k == n) s.push_back(x);
    }
    std::sort(s.begin(), s.end());
    s.erase(std::unique(s.begin(), s.end()), s.end());
    return s;
}

/// Segments and points binned by square cells of size h over [0,lx] x [0,ly], for "is anything
/// within h of here" queries.
class NearbyIndex {
public:
    NearbyIndex(double lx, double ly, double h)
        : cell_(h), nx_(static_cast<long>(std::ceil(lx / h)) + 1), ny_(static_cast<long>(std::ceil(ly / h)) + 1),
          segments_(static_cast<std::size_t>(nx_ * ny_)), points_(static_cast<std::size_t>(nx_ * ny_))
    {
    }
    void addSegment(const K::Point_2& a, const K::Point_2& b)
    {
        const auto [i0, j0] = binOf(std::min(a.x(), b.x()), std::min(a.y(), b.y()));
        const auto [i1, j1] = binOf(std::max(a.x(), b.x()), std::max(a.y(), b.y()));
        for (long i = i0; i <= i1; ++i)
            for (long j = j0; j <= j1; ++j) segments_[index(i, j)].emplace_back(a, b);
    }
    void addPoint(const K::Point_2& p)
    {
        const auto [i, j] = binOf(p.x(), p.y());
        points_[index(i, j)].push_back(p);
    }
    /// True if @p p is at least @p segmentGap from every segment, outside every segment's
    /// diametral circle (so it does not encroach on a constraint), and at least @p pointGap from
    /// every point; all gaps at most h.
    bool clear(const K::Point_2& p, double segmentGap, double pointGap) const
    {
        const auto [ci, cj] = binOf(p.x(), p.y());
        for (long i = std::max(0L, ci - 1); i <= std::min(nx_ - 1, ci + 1); ++i)
            for (long j = std::max(0L, cj - 1); j <= std::min(ny_ - 1, cj + 1); ++j) {
                for (const auto& [a, b] : segments_[index(i, j)]) {
                    if (CGAL::squared_distance(p, K::Segment_2(a, b)) < segmentGap * segmentGap) return false;
                    // Inside the diametral circle, with a margin: the mesher would split a, b.
                    if (CGAL::squared_distance(p, CGAL::midpoint(a, b)) < 0.3025 * CGAL::squared_distance(a, b)) return false;
                }
                for (const K::Point_2& q : points_[index(i, j)])
                    if (CGAL::squared_distance(p, q) < pointGap * pointGap) return false;
            }
        return true;
    }

private:
    std::pair<long, long> binOf(double x, double y) const
    {
        return {std::clamp(static_cast<long>(std::floor(x / cell_)), 0L, nx_ - 1),
                std::clamp(static_cast<long>(std::floor(y / cell_)), 0L, ny_ - 1)};
    }
    std::size_t index(long i, long j) const { return static_cast<std::size_t>(i * ny_ + j); }
    double cell_;
    long nx_, ny_;
    std::vector<std::vector<std::pair<K::Point_2, K::Point_2>>> segments_;
    std::vector<std::vector<K::Point_2>> points_;
};

/// The apexes, on both sides, of the triangle on the chord [a, b] that is equilateral in 3D (by the
/// surface metric at the chord's middle), or isosceles with sides @p longest if the chord is
/// nearly that long already (a triangle on a loop chord that is too big is refined, and its
/// circumcentre, close to the chord, would make the mesher split the chord).
std::array<K::Point_2, 2> apexes(const K::Point_2& a, const K::Point_2& b, const SurfaceMetric& metric, double longest)
{
    const K::Point_2 m = CGAL::midpoint(a, b);
    const SurfaceMetric::Form f = metric.at(m.x(), m.y());
    // The metric's Cholesky factor W (x -> w = W x makes it Euclidean): W = [[p, q], [0, r]].
    const double p = std::sqrt(f.e), q = f.f / p, r = std::sqrt(std::max(f.g - q * q, 1e-300));
    const double dx = b.x() - a.x(), dy = b.y() - a.y();
    const double wx = p * dx + q * dy, wy = r * dy, half = 0.5 * std::hypot(wx, wy);
    const double side = std::max(std::min(2.0 * half, longest), 1.01 * half);
    // The unit normal (-wy, wx) / 2 half, back from w to (x, y).
    const double uy = wx / (2.0 * half) / r, ux = (-wy / (2.0 * half) - q * uy) / p;
    const auto sideLength = [&](const K::Point_2& x) {
        const auto edge = [&](const K::Point_2& e) {
            return std::sqrt(metric.squaredLength(0.5 * (e.x() + x.x()), 0.5 * (e.y() + x.y()), x.x() - e.x(), x.y() - e.y()));
        };
        return std::max(edge(a), edge(b));
    };
    std::array<K::Point_2, 2> out;
    for (int k = 0; k < 2; ++k) {
        const double sign = k == 0 ? 1.0 : -1.0;
        double height = std::sqrt(side * side - half * half);
        // The metric at the middle of the chord is not the metric at the middle of the sides:
        // shorten the height until the longer side is what was asked for (where the surface's
        // speed changes fast, as at the tips of a lenticular section).
        for (int iteration = 0; iteration < 4; ++iteration) {
            const double s = sideLength(m + sign * height * K::Vector_2(ux, uy));
            if (s <= longest) break;
            const double want = std::max(longest * longest - half * half, 0.0), have = std::max(s * s - half * half, 1e-300);
            height *= std::max(std::sqrt(want / have), 0.3);
        }
        out[static_cast<std::size_t>(k)] = m + sign * height * K::Vector_2(ux, uy);
    }
    return out;
}

/// Points that make the Delaunay triangles of [0,lx] x [0,ly] already of size h and good shape
/// before refinement, so that CGAL refines little and seldom has to split a constraint (each
/// split on a loop is a node both tows need: another meshing round):
/// - along every loop chord, the apex of the equilateral triangle on it, on both sides;
/// - a hexagonal lattice of spacing h, kept 0.7 h away from the constraints and 0.6 h from the
///   apexes.
/// Points that would encroach on a constrained edge, or crowd one another, are left out.
void insertStartingPoints(CDT& cdt, const std::vector<std::vector<K::Point_2>>& chords, const SurfaceMetric& metric,
                          double lx, double ly, double h)
{
    NearbyIndex near(lx, ly, h);
    for (auto e = cdt.constrained_edges_begin(); e != cdt.constrained_edges_end(); ++e)
        near.addSegment(e->first->vertex(CDT::cw(e->second))->point(), e->first->vertex(CDT::ccw(e->second))->point());
    const auto inside = [&](const K::Point_2& p, double margin) {
        return p.x() > margin && p.x() < lx - margin && p.y() > margin && p.y() < ly - margin;
    };
    std::vector<K::Point_2> points;
    for (const std::vector<K::Point_2>& loop : chords)
        for (std::size_t k = 0; k + 1 < loop.size(); ++k)
            for (const K::Point_2& p : apexes(loop[k], loop[k + 1], metric, 0.97 * h)) {
                // Gaps relative to the apex's own triangle: it is as far from its chord as it is.
                const double height = std::sqrt(CGAL::squared_distance(p, K::Segment_2(loop[k], loop[k + 1])));
                const double side = std::sqrt(CGAL::squared_distance(p, loop[k]));
                if (inside(p, 0.5 * height) && near.clear(p, 0.7 * height, 0.7 * side)) {
                    near.addPoint(p);
                    points.push_back(p);
                }
            }
    const double dy = h * std::sqrt(3.0) / 2.0;
    for (long j = 1; static_cast<double>(j) * dy < ly; ++j)
        for (double x = (j % 2 ? 0.5 * h : h); x < lx; x += h) {
            const K::Point_2 p(x, static_cast<double>(j) * dy);
            if (near.clear(p, 0.7 * h, 0.6 * h)) points.push_back(p);
        }
    cdt.insert(points.begin(), points.end());
}

/// After refinement, the faces still bad are those whose circumcentre would encroach on a
/// constraint (the mesher would have split it). Asks for those splits in @p requests: the middle
/// of a loop chord (a node of both tows) or of a seam edge (a node of both sides); the stations
/// of the tow's two ends are fixed. Returns the number of bad faces.
std::size_t requestSplits(const CDT& cdt, const Criteria& criteria, double ly, double uMin, double su,
                          MeshRequests& requests)
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
        if ((pa.y() == 0.0 && pb.y() == 0.0) || (pa.y() == ly && pb.y() == ly)) {
            const double x = 0.5 * (pa.x() + pb.x());
            if (seam.insert(x).second) requests.seamU.push_back(uMin + x / su);
        } else if (a->info().node >= 0 && b->info().node >= 0) {
            const long lo = std::min(a->info().node, b->info().node), hi = std::max(a->info().node, b->info().node);
            if (chords.emplace(lo, hi).second)
                requests.onLoop.push_back({static_cast<std::size_t>(lo), static_cast<std::size_t>(hi), 0.5});
        }
    };
    std::size_t bad = 0;
    std::vector<CDT::Edge> boundary;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
        Criteria::Quality q;
        if (!f->is_in_domain() || isBad(f, q) == CGAL::Mesh_2::NOT_BAD) continue;
        ++bad;
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
            for (int k = 0; k < 3; ++k)
                if (f->is_constrained(k) && encroached(c, {f, k})) request({f, k});
        }
    }
    return bad;
}

}  // namespace

ParameterScale parameterScale(const TowSurface& surface)
{
    const ParameterRange r = surface.parameterRange();
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

struct ParametricMesher::Impl {
    const TowSurface& surface;
    MeshSizes sizes;
    ParameterRange range;
    ParameterScale scale;
    double su, sv;  // scaled length per unit u, v
    SurfaceMetric metric;
    Criteria criteria;
    CDT cdt;
    std::multimap<std::size_t, CDT::Vertex_handle> loopVertex;  // a seam node has two
    std::size_t badFaces = 0;

    Impl(const TowSurface& s, const MeshSizes& z)
        : surface(s), sizes(z), range(s.parameterRange()), scale(parameterScale(s)),
          su(scale.alongU / (range.uMax - range.uMin)), sv(scale.aroundV / range.vPeriod()),
          metric(s, su, sv, scale.alongU, scale.aroundV, z.edgeLength),
          criteria(shapeBound(z.minAngle), z.edgeLength, metric)
    {
    }
    static double shapeBound(double minAngle)
    {
        const double a = std::clamp(minAngle, 1.0, 30.0) * 3.14159265358979323846 / 180.0;
        return std::sin(a) * std::sin(a);  // CGAL's bound: the squared sine of the smallest angle
    }
    K::Point_2 toXY(const UV& p) const { return {(p.u - range.uMin) * su, (p.v - range.vMin) * sv}; }
    UV toUV(const K::Point_2& p) const { return {range.uMin + p.x() / su, range.vMin + p.y() / sv}; }
    CDT::Vertex_handle insertLoopNode(const K::Point_2& p, std::size_t node)
    {
        const CDT::Vertex_handle v = cdt.insert(p);
        v->info().node = static_cast<long>(node);
        loopVertex.emplace(node, v);
        return v;
    }
    /// Refines, then asks for the splits that the faces still bad need.
    void refine(MeshRequests& requests)
    {
        refineKeepingConstraints(cdt, criteria);
        badFaces = requestSplits(cdt, criteria, scale.aroundV, range.uMin, su, requests);
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
    const double lx = m.scale.alongU, ly = m.scale.aroundV, h = m.sizes.edgeLength;
    m.cdt.clear();
    m.loopVertex.clear();

    // Seam stations: uniform along u plus every loop node on the seam, the same on both sides.
    // All four sides get stations h/2 apart: edges that short are seldom encroached, nor too
    // long in 3D where the surface is longer than its mean.
    std::vector<double> seamX;
    for (double u : seamU) seamX.push_back((u - m.range.uMin) * m.su);
    for (const LoopConstraint& c : constraints)
        for (std::size_t k = 0; k < c.uv.size(); ++k)
            if (c.uv[k].v == m.range.vMin || c.uv[k].v == m.range.vMax) seamX.push_back(m.toXY(c.uv[k]).x());
    const std::vector<double> xs = stations(lx, 0.5 * h, seamX);
    const std::vector<double> ys = stations(ly, 0.5 * h, {});
    const auto polyline = [&](const std::vector<K::Point_2>& pts) {
        for (std::size_t k = 0; k + 1 < pts.size(); ++k) m.cdt.insert_constraint(pts[k], pts[k + 1]);
    };
    std::vector<K::Point_2> bottom, top, left, right;
    for (double x : xs) {
        bottom.emplace_back(x, 0.0);
        top.emplace_back(x, ly);
    }
    for (double y : ys) {
        left.emplace_back(0.0, y);
        right.emplace_back(lx, y);
    }
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
    insertStartingPoints(m.cdt, chords, m.metric, lx, ly, h);
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
        // The new node's v, by whole periods, next to the chord's (a chord may end on the seam).
        K::Point_2 p = m.toXY(s.at);
        const double middle = 0.5 * (va->point().y() + vb->point().y());
        p = K::Point_2(p.x(), p.y() + period * std::round((middle - p.y()) / period));
        m.cdt.remove_constrained_edge(f, i);
        const CDT::Vertex_handle vm = m.insertLoopNode(p, s.node);
        m.cdt.insert_constraint(va, vm);
        m.cdt.insert_constraint(vm, vb);
    }
    // New seam stations on both sides: a point on a constrained edge splits it.
    for (double u : seamU) {
        const double x = (u - m.range.uMin) * m.su;
        m.cdt.insert(K::Point_2(x, 0.0));
        m.cdt.insert(K::Point_2(x, m.scale.aroundV));
    }
    m.refine(requests);
    return true;
}

std::size_t ParametricMesher::badFaces() const { return impl_->badFaces; }

ParametricMesh ParametricMesher::result(std::size_t firstNewNode)
{
    Impl& m = *impl_;
    const double ly = m.scale.aroundV;
    // Loop nodes are global already; the tow's own nodes are numbered from firstNewNode in
    // order; a node at v = vMax is the node at v = vMin.
    ParametricMesh out;
    std::map<double, std::size_t> seamNode;  // x on the v = vMin side -> node
    const auto nodeOf = [](CDT::Vertex_handle v) {
        return v->info().node >= 0 ? static_cast<std::size_t>(v->info().node) : v->info().own;
    };
    for (auto v = m.cdt.finite_vertices_begin(); v != m.cdt.finite_vertices_end(); ++v) {
        if (v->info().node < 0 && v->point().y() != ly) {
            v->info().own = firstNewNode + out.newNodes.size();
            out.newNodes.push_back(m.toUV(v->point()));
        }
        if (v->point().y() == 0.0) seamNode[v->point().x()] = nodeOf(v);
    }
    for (auto v = m.cdt.finite_vertices_begin(); v != m.cdt.finite_vertices_end(); ++v) {
        if (v->info().node >= 0 || v->point().y() != ly) continue;
        const auto at = seamNode.find(v->point().x());
        if (at == seamNode.end())
            throw Error(ErrorCode::Internal, "the two sides of the seam have different nodes", "tow '" + m.surface.name() + "'");
        v->info().own = at->second;
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
    return out;
}

}  // namespace towgeom::detail
