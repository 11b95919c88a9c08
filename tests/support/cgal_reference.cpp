#include "cgal_reference.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/intersection.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <set>
#include <utility>
#include <vector>

namespace towgeom::testing {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

Mesh toCgal(const TriangleMesh& m)
{
    Mesh out;
    std::vector<Mesh::Vertex_index> ids;
    for (const Point3& p : m.vertices) ids.push_back(out.add_vertex(Kernel::Point_3(p.x, p.y, p.z)));
    for (const auto& t : m.triangles) out.add_face(ids[t[0]], ids[t[1]], ids[t[2]]);
    return out;
}

Mesh closedCgal(const TriangleMesh& m, const char* what)
{
    Mesh c = toCgal(m);
    if (c.number_of_faces() != m.triangles.size())
        throw std::runtime_error(std::string(what) + ": not a manifold triangle mesh (faces refused)");
    if (!CGAL::is_closed(c)) throw std::runtime_error(std::string(what) + ": mesh not closed");
    if (!PMP::does_bound_a_volume(c)) throw std::runtime_error(std::string(what) + ": mesh does not bound a volume");
    PMP::orient_to_bound_a_volume(c);
    return c;
}
}  // namespace

IntersectionPolylines surfaceIntersection(const TriangleMesh& a, const TriangleMesh& b)
{
    Mesh ma = toCgal(a), mb = toCgal(b);
    std::vector<std::vector<Kernel::Point_3>> polylines;
    CGAL::Polygon_mesh_processing::surface_intersection(ma, mb, std::back_inserter(polylines));
    IntersectionPolylines r;
    for (const auto& p : polylines) (p.size() > 2 && p.front() == p.back() ? r.closed : r.open) += 1;
    return r;
}

std::vector<std::vector<Point3>> surfaceIntersectionCurves(const TriangleMesh& a, const TriangleMesh& b)
{
    Mesh ma = toCgal(a), mb = toCgal(b);
    std::vector<std::vector<Kernel::Point_3>> polylines;
    CGAL::Polygon_mesh_processing::surface_intersection(ma, mb, std::back_inserter(polylines));
    std::vector<std::vector<Point3>> out;
    for (const auto& p : polylines) {
        out.emplace_back();
        for (const auto& q : p) out.back().push_back({q.x(), q.y(), q.z()});
    }
    return out;
}

TriangleCrossings crossingTrianglePairs(const std::vector<Point3>& nodes,
                                        const std::vector<std::array<std::size_t, 3>>& a,
                                        const std::vector<std::array<std::size_t, 3>>& b)
{
    using Tri = std::array<std::size_t, 3>;
    using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;
    const auto point = [&](std::size_t n) { return Kernel::Point_3(nodes[n].x, nodes[n].y, nodes[n].z); };
    const auto boxes = [&](const std::vector<Tri>& ts) {
        std::vector<Box> out;
        out.reserve(ts.size());
        for (std::size_t k = 0; k < ts.size(); ++k) {
            const Tri& t = ts[k];
            out.emplace_back(point(t[0]).bbox() + point(t[1]).bbox() + point(t[2]).bbox(), k);
        }
        return out;
    };
    std::vector<Box> ba = boxes(a), bb = boxes(b);
    TriangleCrossings r;
    const auto test = [&](const Box& x, const Box& y) {
        ++r.boxPairs;
        const Tri& s = a[x.info()];
        const Tri& t = b[y.info()];
        // Which corners are shared: si[k] = index in t of s[k], or -1.
        int si[3], shared = 0;
        for (int k = 0; k < 3; ++k) {
            si[k] = -1;
            for (int l = 0; l < 3; ++l)
                if (s[k] == t[l]) si[k] = l;
            if (si[k] >= 0) ++shared;
        }
        const Kernel::Triangle_3 ts(point(s[0]), point(s[1]), point(s[2])), tt(point(t[0]), point(t[1]), point(t[2]));
        bool crosses = false;
        if (shared == 3) {
            ++r.identical;
            return;
        }
        if (shared == 0) {
            crosses = CGAL::do_intersect(ts, tt);
        } else if (shared == 2) {
            ++r.sharing;
            int ks = 0, kt = 0;  // the corners not shared
            while (si[ks] >= 0) ++ks;
            const std::size_t p = s[(ks + 1) % 3], q = s[(ks + 2) % 3];  // the shared edge
            while (t[kt] == p || t[kt] == q) ++kt;
            const Kernel::Point_3 P = point(p), Q = point(q), S = point(s[ks]), T = point(t[kt]);
            crosses = CGAL::coplanar(P, Q, S, T) && CGAL::coplanar_orientation(P, Q, S, T) == CGAL::POSITIVE;
        } else {
            ++r.sharing;
            int ks = 0, kt = 0;  // the shared corner in s and in t
            while (si[ks] < 0) ++ks;
            kt = si[ks];
            const Kernel::Segment_3 oppS(point(s[(ks + 1) % 3]), point(s[(ks + 2) % 3]));
            const Kernel::Segment_3 oppT(point(t[(kt + 1) % 3]), point(t[(kt + 2) % 3]));
            crosses = CGAL::do_intersect(oppS, tt) || CGAL::do_intersect(oppT, ts);
        }
        if (crosses) {
            if (r.first.size() < 100) r.first.emplace_back(x.info(), y.info());
            ++r.crossing;
            if (shared > 0) ++r.crossingSharing;
        }
    };
    CGAL::box_intersection_d(ba.begin(), ba.end(), bb.begin(), bb.end(), test);
    return r;
}

double minimumDistance(const TriangleMesh& a, const TriangleMesh& b, double within)
{
    using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;
    const auto point = [](const TriangleMesh& m, std::size_t n) {
        return Kernel::Point_3(m.vertices[n].x, m.vertices[n].y, m.vertices[n].z);
    };
    const auto triangle = [&](const TriangleMesh& m, std::size_t k) {
        const auto& t = m.triangles[k];
        return Kernel::Triangle_3(point(m, t[0]), point(m, t[1]), point(m, t[2]));
    };
    const auto boundingBox = [&](const TriangleMesh& m) {
        CGAL::Bbox_3 box;
        for (std::size_t n = 0; n < m.vertices.size(); ++n) box += point(m, n).bbox();
        return box;
    };
    // Each triangle's box grown by within; only those reaching the other mesh's box so grown
    // (no other triangle can come within reach).
    const auto boxes = [&](const TriangleMesh& m, const CGAL::Bbox_3& other) {
        const CGAL::Bbox_3 reach(other.xmin() - 2.0 * within, other.ymin() - 2.0 * within, other.zmin() - 2.0 * within,
                                 other.xmax() + 2.0 * within, other.ymax() + 2.0 * within, other.zmax() + 2.0 * within);
        std::vector<Box> out;
        for (std::size_t k = 0; k < m.triangles.size(); ++k) {
            const CGAL::Bbox_3 box = triangle(m, k).bbox();
            if (!CGAL::do_overlap(box, reach)) continue;
            out.emplace_back(CGAL::Bbox_3(box.xmin() - within, box.ymin() - within, box.zmin() - within, box.xmax() + within,
                                          box.ymax() + within, box.zmax() + within),
                             k);
        }
        return out;
    };
    std::vector<Box> ba = boxes(a, boundingBox(b)), bb = boxes(b, boundingBox(a));
    // The candidate pairs, nearest boxes first: a pair whose triangles' boxes lie further apart
    // than the least distance found cannot be nearer (nor intersect), so the rest is skipped.
    std::vector<std::pair<double, std::pair<std::size_t, std::size_t>>> pairs;
    CGAL::box_intersection_d(ba.begin(), ba.end(), bb.begin(), bb.end(), [&](const Box& x, const Box& y) {
        const CGAL::Bbox_3 p = triangle(a, x.info()).bbox(), q = triangle(b, y.info()).bbox();
        double gap = 0.0;
        for (int k = 0; k < 3; ++k) {
            const double g = std::max({0.0, p.min(k) - q.max(k), q.min(k) - p.max(k)});
            gap += g * g;
        }
        pairs.push_back({gap, {x.info(), y.info()}});
    });
    std::sort(pairs.begin(), pairs.end());
    double least = std::numeric_limits<double>::infinity();
    for (const auto& [gap, pair] : pairs) {
        if (gap >= least) break;
        const Kernel::Triangle_3 s = triangle(a, pair.first), t = triangle(b, pair.second);
        if (CGAL::do_intersect(s, t)) return 0.0;
        for (int i = 0; i < 3; ++i) {
            least = std::min(least, CGAL::squared_distance(s.vertex(i), t));
            least = std::min(least, CGAL::squared_distance(t.vertex(i), s));
            for (int j = 0; j < 3; ++j)
                least = std::min(least, CGAL::squared_distance(Kernel::Segment_3(s.vertex(i), s.vertex((i + 1) % 3)),
                                                               Kernel::Segment_3(t.vertex(j), t.vertex((j + 1) % 3))));
        }
    }
    return std::sqrt(least);
}

double closedMeshVolume(const TriangleMesh& m) { return PMP::volume(closedCgal(m, "volume")); }

double intersectionVolume(const TriangleMesh& a, const TriangleMesh& b)
{
    Mesh ma = closedCgal(a, "first mesh"), mb = closedCgal(b, "second mesh"), out;
    if (!PMP::corefine_and_compute_intersection(ma, mb, out))
        throw std::runtime_error("corefine_and_compute_intersection failed");
    return PMP::volume(out);
}

double differenceVolume(const TriangleMesh& a, const std::vector<TriangleMesh>& minus)
{
    Mesh rest = closedCgal(a, "first mesh");
    for (const TriangleMesh& m : minus) {
        Mesh cut = closedCgal(m, "subtracted mesh"), out;
        if (!PMP::corefine_and_compute_difference(rest, cut, out)) throw std::runtime_error("corefine_and_compute_difference failed");
        rest = std::move(out);
    }
    return PMP::volume(rest);
}

std::size_t crossingPairsBetweenTows(const TextileMesh& mesh)
{
    std::size_t crossing = 0;
    for (const TowPairCrossings& c : crossingsByTowPair(mesh)) crossing += c.crossings.crossing;
    return crossing;
}

SurfaceCrossings crossingsInSurfaces(const TextileMesh& mesh)
{
    // Each triangle once (a region's is in both its tows' lists): by its sorted nodes, the first
    // owner kept.
    std::vector<std::array<std::size_t, 3>> all;
    std::vector<MeshTriangle> owner;
    std::set<std::array<std::size_t, 3>> seen;
    const auto add = [&](const std::array<std::size_t, 3>& t, MeshTriangle who) {
        std::array<std::size_t, 3> key = t;
        std::sort(key.begin(), key.end());
        if (!seen.insert(key).second) return;
        all.push_back(t);
        owner.push_back(who);
    };
    for (std::size_t t = 0; t < mesh.tows.size(); ++t)
        for (std::size_t k = 0; k < mesh.tows[t].triangles.size(); ++k) add(mesh.tows[t].triangles[k], {t, k});
    if (mesh.cell)
        for (std::size_t k = 0; k < mesh.cell->triangles.size(); ++k) add(mesh.cell->triangles[k], {MeshTriangle::kCellTriangles, k});
    // Each unordered pair comes twice (as (i, j) and (j, i)); a triangle with itself is identical.
    const TriangleCrossings c = crossingTrianglePairs(mesh.nodes, all, all);
    SurfaceCrossings out;
    out.crossing = c.crossing / 2;
    for (const auto& [i, j] : c.first)
        if (i < j && out.first.size() < 50) out.first.push_back({owner[i], owner[j]});
    return out;
}

std::vector<TowPairCrossings> crossingsByTowPair(const TextileMesh& mesh)
{
    std::vector<TowPairCrossings> out;
    for (std::size_t i = 0; i < mesh.tows.size(); ++i)
        for (std::size_t j = i + 1; j < mesh.tows.size(); ++j) {
            TowPairCrossings c;
            c.towA = i;
            c.towB = j;
            c.crossings = crossingTrianglePairs(mesh.nodes, mesh.tows[i].triangles, mesh.tows[j].triangles);
            if (c.crossings.crossing == 0) continue;
            const std::array<std::size_t, 3>& t = mesh.tows[i].triangles[c.crossings.first.front().first];
            const Point3 &p = mesh.nodes[t[0]], &q = mesh.nodes[t[1]], &r = mesh.nodes[t[2]];
            c.firstAt = Point3{(p.x + q.x + r.x) / 3.0, (p.y + q.y + r.y) / 3.0, (p.z + q.z + r.z) / 3.0};
            out.push_back(c);
        }
    return out;
}

}  // namespace towgeom::testing
