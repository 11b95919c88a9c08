#include "mesh/end_caps.hpp"

#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "mesh/constraint_keeping_mesher.hpp"
#include "core/parallel.hpp"
#include "mesh/mesh_cdt.hpp"
#include "mesh/mesh_measures.hpp"
#include "mesh/sharp_corners.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

using mesh2::CDT;
using mesh2::K;


CapMesh meshCap(const NodeAt& nodes, const std::vector<std::size_t>& loop, double h, double minAngle,
                std::size_t firstNewNode, const std::string& where, const std::vector<CapConstraint>& paths)
{
    // The plane: Newell's normal (along the loop's right-hand turn) through the centroid.
    Point3 c;
    Vector3 n;
    for (std::size_t k = 0; k < loop.size(); ++k) {
        const Point3& p = nodes(loop[k]);
        const Point3& q = nodes(loop[(k + 1) % loop.size()]);
        c = c + p;
        n = n + Vector3{(p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y)};
    }
    c = (1.0 / static_cast<double>(loop.size())) * c;
    n = (1.0 / norm(n)) * n;
    const Vector3 helper = std::abs(n.x) < 0.6 ? Vector3{1.0, 0.0, 0.0} : Vector3{0.0, 1.0, 0.0};
    const Vector3 e1 = (1.0 / norm(cross(helper, n))) * cross(helper, n);
    const Vector3 e2 = cross(n, e1);
    std::vector<K::Point_2> polygon;
    for (std::size_t node : loop) polygon.emplace_back(dot(nodes(node) - c, e1), dot(nodes(node) - c, e2));
    if (loop.size() < 3 || !CGAL::is_simple_2(polygon.begin(), polygon.end(), K()))
        throw Error(ErrorCode::SelfIntersectingSection, "the end of the tow's mesh is not a simple polygon in its plane", where);

    CDT cdt;
    std::vector<CDT::Vertex_handle> vs;
    for (std::size_t k = 0; k < loop.size(); ++k) {
        vs.push_back(cdt.insert(polygon[k]));
        vs.back()->info().node = static_cast<long>(loop[k]);
    }
    for (std::size_t k = 0; k < vs.size(); ++k) cdt.insert_constraint(vs[k], vs[(k + 1) % vs.size()]);
    if (cdt.number_of_vertices() != loop.size())
        throw Error(ErrorCode::SelfIntersectingSection, "two nodes of the end of the tow's mesh coincide in its plane", where);
    // Loop pieces on the cap: their rim nodes are the boundary's vertices, the others new ones.
    std::map<std::size_t, CDT::Vertex_handle> vertexOf;
    for (std::size_t k = 0; k < loop.size(); ++k) vertexOf[loop[k]] = vs[k];
    for (const CapConstraint& path : paths) {
        std::vector<CDT::Vertex_handle> line;
        for (std::size_t node : path.nodes) {
            auto it = vertexOf.find(node);
            if (it == vertexOf.end()) {
                const K::Point_2 at(dot(nodes(node) - c, e1), dot(nodes(node) - c, e2));
                // A loop node on the cap must lie inside the tube's end polygon: one on or
                // beyond it (a loop grazing the rim, between two rim nodes with no end node
                // between them) would make triangles outside the cap.
                if (CGAL::bounded_side_2(polygon.begin(), polygon.end(), at, K()) != CGAL::ON_BOUNDED_SIDE)
                    throw Error(ErrorCode::Internal, "an intersection-loop node on the tow's end cap lies on or beyond its rim polygon", where);
                const CDT::Vertex_handle v = cdt.insert(at);
                if (v->info().node >= 0 && static_cast<std::size_t>(v->info().node) != node)
                    throw Error(ErrorCode::Internal, "two intersection-loop nodes fall on the same point of the tow's end cap", where);
                v->info().node = static_cast<long>(node);
                it = vertexOf.emplace(node, v).first;
            }
            line.push_back(it->second);
        }
        for (std::size_t k = 0; k + 1 < line.size(); ++k) cdt.insert_constraint(line[k], line[k + 1]);
        if (path.closed && line.size() > 2) cdt.insert_constraint(line.back(), line.front());
    }
    mesh2::markInside(cdt);
    const double a = std::clamp(minAngle, 1.0, 30.0) * 3.14159265358979323846 / 180.0;
    refineKeepingConstraints(cdt, CGAL::Delaunay_mesh_size_criteria_2<CDT>(std::sin(a) * std::sin(a), h), false);

    CapMesh out;
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
        if (v->info().node >= 0) continue;
        v->info().own = firstNewNode + out.newNodes.size();
        out.newNodes.push_back(c + v->point().x() * e1 + v->point().y() * e2);
    }
    const auto nodeOf = [](CDT::Vertex_handle v) { return v->info().node >= 0 ? static_cast<std::size_t>(v->info().node) : v->info().own; };
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
        if (f->is_in_domain())  // counter-clockwise in the plane, the loop's turn: reversed
            out.triangles.push_back({nodeOf(f->vertex(0)), nodeOf(f->vertex(2)), nodeOf(f->vertex(1))});
    const auto angleAt = [](CDT::Face_handle f, int i) {
        const K::Point_2& p = f->vertex(i)->point();
        const K::Vector_2 a = f->vertex(CDT::ccw(i))->point() - p, b = f->vertex(CDT::cw(i))->point() - p;
        return std::atan2(std::abs(a.x() * b.y() - a.y() * b.x()), a * b) * 180.0 / 3.14159265358979323846;
    };
    const auto distanceFrom = [](CDT::Vertex_handle v, const K::Point_2& p) { return std::sqrt(CGAL::squared_distance(v->point(), p)); };
    for (const CornerWedge& w : sharpWedges(cdt, angleAt, distanceFrom, surfaceAngleBound(minAngle), h)) {
        SharpCorner corner{nodeOf(w.vertex), 0, TowFace::Side, w.angle, {}};
        for (CDT::Face_handle f : w.faces) corner.triangles.push_back({nodeOf(f->vertex(0)), nodeOf(f->vertex(1)), nodeOf(f->vertex(2))});
        out.sharpCorners.push_back(std::move(corner));
    }
    return out;
}

std::vector<TubeEnd> tubeEnds(const TowSurface& tow, const std::vector<std::array<std::size_t, 3>>& tube, const NodeAt& nodes,
                              const std::vector<char>* cutNode, const std::array<bool, 2>* cutEnds)
{
    const auto centroid = [](const std::vector<Point3>& points) {
        Point3 c;
        for (const Point3& p : points) c = c + p;
        return (1.0 / static_cast<double>(points.size())) * c;
    };
    const Point3 first = centroid(tow.sections().front()), last = centroid(tow.sections().back());
    std::vector<std::vector<std::size_t>> ends = boundaryLoops(tube);
    if (ends.size() != 2) return {};  // not a tube (or wholly outside a cell): reported by the check of the final mesh
    // An end cut by a cell's face is closed with that face's mesh, not here.
    if (cutNode)
        ends.erase(std::remove_if(ends.begin(), ends.end(),
                                  [&](const std::vector<std::size_t>& loop) {
                                      return std::all_of(loop.begin(), loop.end(),
                                                         [&](std::size_t n) { return n < cutNode->size() && (*cutNode)[n]; });
                                  }),
                   ends.end());
    std::vector<Point3> c;
    for (const std::vector<std::size_t>& end : ends) {
        std::vector<Point3> points;
        for (std::size_t n : end) points.push_back(nodes(n));
        c.push_back(centroid(points));
    }
    // The two ends together: the pairing with the first and last sections that is nearer; one
    // end alone: the nearer section.
    bool firstIsStart = c.size() == 2 && distance(c[0], first) + distance(c[1], last) <= distance(c[0], last) + distance(c[1], first);
    if (c.size() == 1)  // the other end was cut: this one is the end that was not
        firstIsStart = cutEnds ? !(*cutEnds)[0] : distance(c[0], first) <= distance(c[0], last);
    std::vector<TubeEnd> out;
    for (std::size_t e = 0; e < ends.size(); ++e)
        out.push_back({std::move(ends[e]), (e == 0) == firstIsStart ? TowFace::Start : TowFace::End});
    return out;
}

std::vector<CapConstraint> pathsOnCap(const std::vector<CapConstraint>& paths, TowFace face)
{
    std::vector<CapConstraint> out;
    for (const CapConstraint& p : paths)
        if ((p.end < 0) == (face == TowFace::Start)) out.push_back(p);
    return out;
}

CapMesh provisionalCaps(const TowSurface& tow, double h, double minAngle, const std::vector<std::array<std::size_t, 3>>& tube,
                        const NodeAt& nodes, const std::vector<CapConstraint>& paths, std::size_t firstNewNode,
                        const std::vector<char>* cutNode, const std::array<bool, 2>* cutEnds)
{
    CapMesh out;
    for (const TubeEnd& end : tubeEnds(tow, tube, nodes, cutNode, cutEnds)) {
        try {
            CapMesh cap = meshCap(nodes, end.loop, h, minAngle, firstNewNode + out.newNodes.size(), "tow '" + tow.name() + "'",
                                  pathsOnCap(paths, end.face));
            out.triangles.insert(out.triangles.end(), cap.triangles.begin(), cap.triangles.end());
            out.newNodes.insert(out.newNodes.end(), cap.newNodes.begin(), cap.newNodes.end());
        } catch (const Error&) {
            // left out: closeEnds() reports it
        }
    }
    return out;
}

void closeEnds(const std::vector<TowSurface>& tows, const std::vector<double>& towH, double minAngle, std::size_t threads,
               std::vector<ParametricMesh>& meshes, std::vector<std::vector<TowFace>>& face, std::vector<Point3>& nodes,
               const std::vector<std::vector<CapConstraint>>& capPaths, std::vector<std::string>* failed,
               const std::vector<char>* cutNode, const std::vector<std::array<bool, 2>>* cutEnds)
{
    constexpr std::size_t kLocal = std::size_t(1) << 60;  // marks a cap's own new nodes
    const NodeAt at = [&](std::size_t n) -> const Point3& { return nodes[n]; };
    std::vector<std::vector<std::pair<CapMesh, TowFace>>> caps(tows.size());
    parallelFor(tows.size(), threads, [&](std::size_t t) {
        const std::array<bool, 2>* cut = cutEnds && t < cutEnds->size() ? &(*cutEnds)[t] : nullptr;
        for (const TubeEnd& end : tubeEnds(tows[t], meshes[t].triangles, at, cutNode, cut)) {
            const TowFace f = end.face;
            const std::vector<CapConstraint> paths = t < capPaths.size() ? pathsOnCap(capPaths[t], f) : std::vector<CapConstraint>{};
            try {
                caps[t].emplace_back(meshCap(at, end.loop, towH[t], minAngle, kLocal, "tow '" + tows[t].name() + "'", paths), f);
            } catch (const Error& x) {
                if (failed && !paths.empty()) {  // with loop pieces on it: the caller leaves those loops out
                    (*failed)[t] = std::string(f == TowFace::Start ? "start" : "end") + " cap: " + x.message();
                    return;
                }
                throw Error(ErrorCode::InvalidArgument,
                            std::string("its ") + (f == TowFace::Start ? "start" : "end") + " cap cannot be meshed: " + x.message() +
                                " (the tube's end nodes, about h apart, make no simple polygon of a section this concave "
                                "at this mesh size): use a smaller mesh size, or no caps (MeshOptions::caps, --no-caps)",
                            x.file());
            }
        }
    });
    for (std::size_t t = 0; t < tows.size(); ++t)
        for (auto& [cap, f] : caps[t]) {
            const std::size_t base = nodes.size();
            nodes.insert(nodes.end(), cap.newNodes.begin(), cap.newNodes.end());
            for (std::array<std::size_t, 3> tri : cap.triangles) {
                for (std::size_t& n : tri)
                    if (n >= kLocal) n = base + (n - kLocal);
                meshes[t].triangles.push_back(tri);
                face[t].push_back(f);
            }
            for (SharpCorner& c : cap.sharpCorners) {
                if (c.node >= kLocal) c.node = base + (c.node - kLocal);
                for (std::array<std::size_t, 3>& tri : c.triangles)
                    for (std::size_t& n : tri)
                        if (n >= kLocal) n = base + (n - kLocal);
                c.face = f;
                meshes[t].sharpCorners.push_back(std::move(c));
            }
        }
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
