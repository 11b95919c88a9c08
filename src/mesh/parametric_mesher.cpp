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

#include "towgeom/error.hpp"

namespace towgeom::detail {

namespace {

/// What a triangulation vertex is: a loop node (its global index), or not (-1).
struct VertexInfo {
    long node = -1;
};

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vbi = CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, K>;
using Vb = CGAL::Delaunay_mesh_vertex_base_2<K, Vbi>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<CDT>;
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

/// Inserts the points of a hexagonal lattice of spacing @p h over [0,lx] x [0,ly] that lie at
/// least 0.7 h from every constrained edge already in @p cdt.
void insertLattice(CDT& cdt, double lx, double ly, double h)
{
    // Constrained edges binned by cells of size h.
    const double cell = h;
    const long nx = static_cast<long>(std::ceil(lx / cell)) + 1, ny = static_cast<long>(std::ceil(ly / cell)) + 1;
    std::vector<std::vector<std::pair<K::Point_2, K::Point_2>>> bins(static_cast<std::size_t>(nx * ny));
    const auto binOf = [&](double x, double y) {
        const long i = std::clamp(static_cast<long>(std::floor(x / cell)), 0L, nx - 1);
        const long j = std::clamp(static_cast<long>(std::floor(y / cell)), 0L, ny - 1);
        return std::pair<long, long>(i, j);
    };
    for (auto e = cdt.constrained_edges_begin(); e != cdt.constrained_edges_end(); ++e) {
        const K::Point_2 a = e->first->vertex(CDT::cw(e->second))->point();
        const K::Point_2 b = e->first->vertex(CDT::ccw(e->second))->point();
        const auto [i0, j0] = binOf(std::min(a.x(), b.x()), std::min(a.y(), b.y()));
        const auto [i1, j1] = binOf(std::max(a.x(), b.x()), std::max(a.y(), b.y()));
        for (long i = i0; i <= i1; ++i)
            for (long j = j0; j <= j1; ++j) bins[static_cast<std::size_t>(i * ny + j)].emplace_back(a, b);
    }
    const double keep2 = (0.7 * h) * (0.7 * h);
    const auto clear = [&](const K::Point_2& p) {
        const auto [ci, cj] = binOf(p.x(), p.y());
        for (long i = std::max(0L, ci - 1); i <= std::min(nx - 1, ci + 1); ++i)
            for (long j = std::max(0L, cj - 1); j <= std::min(ny - 1, cj + 1); ++j)
                for (const auto& [a, b] : bins[static_cast<std::size_t>(i * ny + j)])
                    if (CGAL::squared_distance(p, K::Segment_2(a, b)) < keep2) return false;
        return true;
    };
    std::vector<K::Point_2> points;
    const double dy = h * std::sqrt(3.0) / 2.0;
    for (long j = 1; j * dy < ly; ++j)
        for (double x = (j % 2 ? 0.5 * h : h); x < lx; x += h) {
            const K::Point_2 p(x, static_cast<double>(j) * dy);
            if (clear(p)) points.push_back(p);
        }
    cdt.insert(points.begin(), points.end());
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

ParametricMesh meshTow(const TowSurface& surface, const std::vector<LoopConstraint>& constraints,
                       const std::vector<double>& seamU, const MeshSizes& sizes, std::vector<Point3>& newNodes,
                       std::size_t firstNewNode, MeshRequests& requests)
{
    const ParameterRange r = surface.parameterRange();
    const ParameterScale scale = parameterScale(surface);
    const double su = scale.alongU / (r.uMax - r.uMin), sv = scale.aroundV / r.vPeriod();
    const auto toXY = [&](const UV& p) { return K::Point_2((p.u - r.uMin) * su, (p.v - r.vMin) * sv); };
    const double lx = scale.alongU, ly = scale.aroundV, h = sizes.edgeLength;

    // Seam stations: uniform along u plus every loop node on the seam, the same on both edges.
    std::vector<double> seamX;
    for (double u : seamU) seamX.push_back((u - r.uMin) * su);
    for (const LoopConstraint& c : constraints)
        for (std::size_t k = 0; k < c.uv.size(); ++k)
            if (c.uv[k].v == r.vMin || c.uv[k].v == r.vMax) seamX.push_back(toXY(c.uv[k]).x());
    // Seam stations at half the size: edges that short are seldom encroached, so the mesher
    // rarely splits them (a split must be copied to the other side and meshed again).
    const std::vector<double> xs = stations(lx, 0.5 * h, seamX);
    const std::vector<double> ys = stations(ly, h, {});

    CDT cdt;
    const auto polyline = [&](const std::vector<K::Point_2>& pts) {
        for (std::size_t k = 0; k + 1 < pts.size(); ++k) cdt.insert_constraint(pts[k], pts[k + 1]);
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
    for (const LoopConstraint& c : constraints) {
        std::vector<CDT::Vertex_handle> vs;
        for (std::size_t k = 0; k < c.uv.size(); ++k) {
            CDT::Vertex_handle v = cdt.insert(toXY(c.uv[k]));
            v->info().node = static_cast<long>(c.nodes[k]);
            vs.push_back(v);
        }
        for (std::size_t k = 0; k + 1 < vs.size(); ++k) cdt.insert_constraint(vs[k], vs[k + 1]);
        if (c.closed && vs.size() > 2) cdt.insert_constraint(vs.back(), vs.front());
    }

    // A hexagonal lattice of spacing h away from the constraints: Delaunay triangles of it are
    // already of the size and shape asked for, so refinement only has work near constraints.
    insertLattice(cdt, lx, ly, h);

    // CGAL's shape bound is the squared sine of the smallest angle (0.125: 20.7 degrees); size
    // bound h; both in the scaled space.
    const double angle = std::clamp(sizes.minAngle, 1.0, 30.0) * 3.14159265358979323846 / 180.0;
    Mesher mesher(cdt, Criteria(std::sin(angle) * std::sin(angle), h));
    mesher.refine_mesh();

    // Points the mesher put on a constraint (Delaunay refinement splits encroached constrained
    // edges): on a loop they must become loop nodes of both tows, on the seam a node of both
    // sides. Report them; the caller adds them and meshes again.
    const auto onBoundary = [&](const K::Point_2& p) { return p.x() == 0.0 || p.x() == lx || p.y() == 0.0 || p.y() == ly; };
    std::set<double> bottomX, topX;
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
        if (v->point().y() == 0.0) bottomX.insert(v->point().x());
        if (v->point().y() == ly) topX.insert(v->point().x());
    }
    for (double x : bottomX)
        if (!topX.count(x)) requests.seamU.push_back(r.uMin + x / su);
    for (double x : topX)
        if (!bottomX.count(x)) requests.seamU.push_back(r.uMin + x / su);
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
        if (v->info().node >= 0 || onBoundary(v->point())) continue;
        bool constrained = false;
        auto e = cdt.incident_edges(v), done = e;
        do {
            constrained = constrained || cdt.is_constrained(*e);
        } while (++e != done);
        if (!constrained) continue;
        // The loop chord it lies on: the nearest one.
        double best = 1e300;
        MeshRequests::OnLoop at{};
        for (const LoopConstraint& c : constraints) {
            const std::size_t n = c.uv.size(), segments = c.closed ? n : n - 1;
            for (std::size_t k = 0; k < segments; ++k) {
                const K::Point_2 a = toXY(c.uv[k]), b = toXY(c.uv[(k + 1) % n]);
                const double l2 = CGAL::squared_distance(a, b);
                const double t = l2 > 0.0 ? std::clamp(((v->point() - a) * (b - a)) / l2, 0.0, 1.0) : 0.0;
                const double d = CGAL::squared_distance(v->point(), a + t * (b - a));
                if (d < best) {
                    best = d;
                    at = {c.nodes[k], c.nodes[(k + 1) % n], t};
                }
            }
        }
        requests.onLoop.push_back(at);
    }

    // Nodes: loop nodes are global already; v = vMax reuses the node at v = vMin.
    ParametricMesh out;
    std::map<CDT::Vertex_handle, std::size_t> node;
    std::map<double, std::size_t> seamNode;  // x on the v = vMin edge -> node
    const auto uvOf = [&](const K::Point_2& p) { return UV{r.uMin + p.x() / su, r.vMin + p.y() / sv}; };
    std::vector<CDT::Vertex_handle> later;
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
        if (v->info().node >= 0) {
            node[v] = static_cast<std::size_t>(v->info().node);
            if (v->point().y() == 0.0) seamNode[v->point().x()] = node[v];
            continue;
        }
        if (v->point().y() == ly) {
            later.push_back(v);
            continue;
        }
        const UV uv = uvOf(v->point());
        node[v] = firstNewNode + newNodes.size();
        newNodes.push_back(surface.point(uv.u, uv.v));
        if (v->point().y() == 0.0) seamNode[v->point().x()] = node[v];
    }
    if (!requests.empty()) return out;  // not final: the caller meshes again
    if (cdt.number_of_faces() == 0 || std::none_of(cdt.finite_faces_begin(), cdt.finite_faces_end(), [](const auto& f) { return f.is_in_domain(); }))
        throw Error(ErrorCode::Internal, "the parameter rectangle was not meshed", "tow '" + surface.name() + "'");
    for (CDT::Vertex_handle v : later) node[v] = seamNode.at(v->point().x());
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
        if (!f->is_in_domain()) continue;
        out.triangles.push_back({node.at(f->vertex(0)), node.at(f->vertex(1)), node.at(f->vertex(2))});
        const UV a = uvOf(f->vertex(0)->point()), b = uvOf(f->vertex(1)->point()), c = uvOf(f->vertex(2)->point());
        out.centroids.push_back({(a.u + b.u + c.u) / 3.0, (a.v + b.v + c.v) / 3.0});
    }
    return out;
}

}  // namespace towgeom::detail
