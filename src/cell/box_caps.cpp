#include "cell/box_caps.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>

#include "cell/axis.hpp"
#include "cell/box_edges.hpp"
#include "cell/face_size.hpp"
#include "mesh/constraint_keeping_mesher.hpp"
#include "mesh/graded_size_criteria.hpp"
#include "mesh/mesh_cdt.hpp"
#include "mesh/mesh_measures.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

using mesh2::CDT;
using mesh2::K;
using Triangle = std::array<std::size_t, 3>;

namespace {

/// An edge of a tow's clipped mesh that one of its triangles uses and no other: its nodes in
/// that triangle's direction, the tow and the triangle.
struct OpenEdge {
    std::size_t a = 0, b = 0, tow = 0, triangle = 0;
};

std::vector<OpenEdge> openEdges(const TowMesh& m, std::size_t tow)
{
    std::vector<std::pair<std::pair<std::size_t, std::size_t>, std::pair<std::size_t, int>>> edges;
    for (std::size_t k = 0; k < m.triangles.size(); ++k)
        for (int i = 0; i < 3; ++i)
            edges.push_back({std::minmax(m.triangles[k][static_cast<std::size_t>(i)], m.triangles[k][static_cast<std::size_t>((i + 1) % 3)]),
                             {k, i}});
    std::sort(edges.begin(), edges.end());
    std::vector<OpenEdge> out;
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        while (j < edges.size() && edges[j].first == edges[i].first) ++j;
        if (j == i + 1) {
            const auto [k, c] = edges[i].second;
            out.push_back({m.triangles[k][static_cast<std::size_t>(c)], m.triangles[k][static_cast<std::size_t>((c + 1) % 3)], tow, k});
        }
        i = j;
    }
    return out;
}

/// The faces of @p cell whose planes @p p lies on exactly, as a bit set.
unsigned planesThrough(const Cell& cell, const Point3& p)
{
    unsigned on = 0;
    for (int f = 0; f < 6; ++f)
        if (coord(p, axisOf(static_cast<CellFace>(f))) == cell.plane(static_cast<CellFace>(f))) on |= 1u << f;
    return on;
}

/// A tow's closed surface before clipping and its bounding box.
struct Solid {
    const std::vector<Triangle>* triangles = nullptr;
    Point3 lo, hi;
    bool contains(const Point3& p) const { return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z; }
};

/// What meshing the faces shares.
struct FaceJob {
    TextileMesh& mesh;
    const Cell& cell;
    const std::vector<Solid>& solids;
    BoxEdges& edges;
    const FaceGrading& grading;
    double h = 0.0;
    double minAngle = 0.0;
};

/// How far inside the box (a fraction of the faces' mesh size) a face's part is tested.
constexpr double kProbeDepth = 1e-4;

std::string towName(const TextileMesh& mesh, std::size_t t) { return "tow '" + mesh.tows[t].name + "'"; }

/// The tows a part of a face's mesh lies in that no cut borders (a face all inside a tow): those
/// whose closed surface before clipping winds around its largest triangle's centroid, tested
/// on the face, or a hair inside the box where a tow's surface lies in the face's plane there.
std::vector<std::size_t> towsAround(const FaceJob& job, CellFace face, const std::vector<CDT::Face_handle>& part)
{
    const int a = axisOf(face);
    const auto [b, c] = inPlane(a);
    const auto area = [](const CDT::Face_handle& g) { return std::abs(CGAL::area(g->vertex(0)->point(), g->vertex(1)->point(), g->vertex(2)->point())); };
    const CDT::Face_handle largest = *std::max_element(part.begin(), part.end(), [&](const auto& x, const auto& y) { return area(x) < area(y); });
    const K::Point_2 centre = CGAL::centroid(largest->vertex(0)->point(), largest->vertex(1)->point(), largest->vertex(2)->point());
    Point3 probe;
    coord(probe, a) = job.cell.plane(face);
    coord(probe, b) = centre.x();
    coord(probe, c) = centre.y();
    std::vector<std::size_t> in;
    for (std::size_t t = 0; t < job.solids.size(); ++t) {
        if (!job.solids[t].contains(probe)) continue;
        double w = windingNumber(job.mesh.nodes, *job.solids[t].triangles, probe);
        if (w > 0.25 && w < 0.75) {  // on its surface
            Point3 inside = probe;
            coord(inside, a) += (isMaxFace(face) ? -1.0 : 1.0) * kProbeDepth * job.h;
            w = windingNumber(job.mesh.nodes, *job.solids[t].triangles, inside);
        }
        if (w > 0.5) in.push_back(t);
    }
    return in;
}

/// Face @p face meshed around the open edges @p cuts, the tows' edges @p edgesInPlane and nodes
/// @p nodesInPlane on it: its triangles outward from the box, and per triangle the tow whose cap
/// it is (-1: the matrix).
std::pair<std::vector<Triangle>, std::vector<long>> meshFace(FaceJob& job, CellFace face, const std::vector<OpenEdge>& cuts,
                                                             const std::vector<std::pair<std::size_t, std::size_t>>& edgesInPlane,
                                                             const std::vector<std::size_t>& nodesInPlane)
{
    std::vector<Point3>& nodes = job.mesh.nodes;
    const int a = axisOf(face);
    const double at = job.cell.plane(face);
    const auto [b, c] = inPlane(a);
    const auto flat = [&, b = b, c = c](std::size_t n) { return K::Point_2(coord(nodes[n], b), coord(nodes[n], c)); };
    const std::string onFace = std::string(" on the cell's face ") + cellFaceName(face);
    const auto spatialOf = [&, b = b, c = c](const K::Point_2& p) {
        Point3 q;
        coord(q, a) = at;
        coord(q, b) = p.x();
        coord(q, c) = p.y();
        return q;
    };
    CDT cdt;
    std::map<std::size_t, CDT::Vertex_handle> handle;
    const auto vertex = [&](std::size_t n) {
        const CDT::Vertex_handle v = cdt.insert(flat(n));
        if (v->info().node >= 0 && v->info().node != static_cast<long>(n)) {
            std::ostringstream where;
            where << " at (" << nodes[n].x << ", " << nodes[n].y << ", " << nodes[n].z << ")";
            throw Error(ErrorCode::InvalidArgument, "two nodes coincide" + onFace + where.str() + ": tows touch there at a point");
        }
        v->info().node = static_cast<long>(n);
        handle[n] = v;
        return v;
    };
    const std::vector<std::size_t> rectangle = job.edges.rectangle(a, isMaxFace(face) ? 1 : 0);
    std::vector<CDT::Vertex_handle> corners;
    for (std::size_t n : rectangle) corners.push_back(vertex(n));
    for (std::size_t k = 0; k < corners.size(); ++k) cdt.insert_constraint(corners[k], corners[(k + 1) % corners.size()]);
    std::map<std::size_t, std::vector<K::Point_2>> towPoints;  // per tow its cut's points: faces there at h
    for (const OpenEdge& e : cuts) {
        cdt.insert_constraint(vertex(e.a), vertex(e.b));
        towPoints[e.tow].push_back(flat(e.a));
        towPoints[e.tow].push_back(flat(e.b));
    }
    for (const auto& [x, y] : edgesInPlane) cdt.insert_constraint(vertex(x), vertex(y));
    for (std::size_t n : nodesInPlane) vertex(n);
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
        if (v->info().node >= 0) continue;
        // Two cuts cross here: name the tows whose cut edges pass nearest.
        std::set<std::size_t> tows;
        for (const OpenEdge& e : cuts)
            if (CGAL::squared_distance(K::Segment_2(flat(e.a), flat(e.b)), v->point()) < 1e-20 + 1e-12 * job.h * job.h) tows.insert(e.tow);
        std::string names;
        for (std::size_t t : tows) names += (names.empty() ? "" : " and ") + towName(job.mesh, t);
        std::ostringstream where;
        where << " near (" << coord(spatialOf(v->point()), 0) << ", " << coord(spatialOf(v->point()), 1) << ", " << coord(spatialOf(v->point()), 2) << ")";
        throw Error(ErrorCode::InvalidArgument, tows.size() == 1 ? names + ": its cut crosses itself" + onFace + where.str() +
                                                                       " (its surface folds there at this mesh size: a smaller mesh size helps)"
                                                                 : (names.empty() ? std::string("two tows") : names) + ": their cuts cross" + onFace +
                                                                       where.str() + ": they overlap there (a pair left unresolved)");
    }
    for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->set_in_domain(!cdt.is_infinite(f));
    std::vector<std::vector<K::Point_2>> polygons;
    for (auto& [t, points] : towPoints) polygons.push_back(std::move(points));
    const FaceSize size(polygons, a, {at}, job.h, job.grading);
    const double angle = std::clamp(job.minAngle, 1.0, 30.0) * 3.14159265358979323846 / 180.0;
    refineKeepingConstraints(cdt, GradedSizeCriteria<CDT>(std::sin(angle) * std::sin(angle), [&size](const K::Point_2& p) { return size(p); }),
                             false);
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
        if (v->info().node >= 0) continue;
        v->info().node = static_cast<long>(nodes.size());
        nodes.push_back(spatialOf(v->point()));
    }
    // Counter-clockwise in (b, c) is along +a for x and z, along -a for y; outward is -a on a
    // min face.
    // The parts between constraints. Each is the cap of the tow whose cut edges it lies inside
    // of (the side the cap closing an open edge takes: it runs along the edge the other way
    // round), else the matrix's; a part no cut borders (a face all inside a tow) is tested by the
    // winding number of the tows' surfaces before clipping.
    const bool ccwOutward = (a != 1) == isMaxFace(face);
    std::map<CDT::Face_handle, std::size_t> partOf;
    std::vector<std::vector<CDT::Face_handle>> parts;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
        if (partOf.count(f)) continue;
        parts.emplace_back(1, f);
        partOf[f] = parts.size() - 1;
        for (std::size_t i = 0; i < parts.back().size(); ++i) {
            const CDT::Face_handle g = parts.back()[i];
            for (int k = 0; k < 3; ++k) {
                const CDT::Face_handle n = g->neighbor(k);
                if (g->is_constrained(k) || cdt.is_infinite(n) || partOf.count(n)) continue;
                partOf[n] = parts.size() - 1;
                parts.back().push_back(n);
            }
        }
    }
    std::vector<std::set<std::size_t>> towsOf(parts.size());
    std::vector<char> bordered(parts.size(), 0);
    for (const OpenEdge& e : cuts) {
        const CDT::Vertex_handle va = handle.at(e.a), vb = handle.at(e.b);
        CDT::Face_handle f;
        int i = 0;
        if (!cdt.is_edge(va, vb, f, i)) throw Error(ErrorCode::Internal, towName(job.mesh, e.tow) + ": a cut edge is missing" + onFace);
        for (const CDT::Face_handle& g : {f, f->neighbor(i)}) {
            if (cdt.is_infinite(g)) continue;
            const bool ccwFromA = g->vertex(CDT::ccw(g->index(va))) == vb;
            bordered[partOf.at(g)] = 1;
            if (ccwFromA != ccwOutward) towsOf[partOf.at(g)].insert(e.tow);  // written b to a: the cap's side
        }
    }
    std::vector<long> label(parts.size(), -1);
    for (std::size_t p = 0; p < parts.size(); ++p) {
        std::vector<std::size_t> in(towsOf[p].begin(), towsOf[p].end());
        if (in.empty() && !bordered[p]) in = towsAround(job, face, parts[p]);
        if (in.size() > 1) {
            const Point3 at = nodes[static_cast<std::size_t>(parts[p][0]->vertex(0)->info().node)];
            std::ostringstream where;
            where << " near (" << at.x << ", " << at.y << ", " << at.z << ")";
            throw Error(ErrorCode::InvalidArgument, towName(job.mesh, in[0]) + " and " + towName(job.mesh, in[1]) + " overlap" + onFace +
                                                        where.str() + " (a pair left unresolved there)");
        }
        if (!in.empty()) label[p] = static_cast<long>(in[0]);
    }
    std::pair<std::vector<Triangle>, std::vector<long>> out;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
        Triangle tri{static_cast<std::size_t>(f->vertex(0)->info().node), static_cast<std::size_t>(f->vertex(1)->info().node),
                     static_cast<std::size_t>(f->vertex(2)->info().node)};
        if (!ccwOutward) std::swap(tri[1], tri[2]);
        out.first.push_back(tri);
        out.second.push_back(label[partOf.at(f)]);
    }
    return out;
}

/// The mean of @p directions, each turned to agree with the first (a fibre has no sense).
Vector3 meanDirection(const std::vector<Vector3>& directions)
{
    Vector3 sum{0.0, 0.0, 0.0};
    for (const Vector3& d : directions) sum = sum + (directions.empty() || dot(d, directions[0]) >= 0.0 ? 1.0 : -1.0) * d;
    const double n = norm(sum);
    return n > 0.0 ? (1.0 / n) * sum : sum;
}

}  // namespace

CellMesh meshBoxCaps(TextileMesh& mesh, const std::vector<std::vector<Triangle>>& solids, const Cell& cell, double h, double minAngle)
{
    std::array<std::vector<OpenEdge>, 6> onFace;
    std::vector<std::size_t> onEdges;
    std::set<std::pair<std::size_t, std::size_t>> whole;
    for (std::size_t t = 0; t < mesh.tows.size(); ++t)
        for (const OpenEdge& e : openEdges(mesh.tows[t], t)) {
            const unsigned shared = planesThrough(cell, mesh.nodes[e.a]) & planesThrough(cell, mesh.nodes[e.b]);
            if (shared == 0)
                throw Error(ErrorCode::InvalidArgument, towName(mesh, t) + ": its clipped mesh is open away from the cell's faces "
                                                                           "(its surface was not closed)");
            for (std::size_t n : {e.a, e.b})
                if (__builtin_popcount(planesThrough(cell, mesh.nodes[n])) >= 2) onEdges.push_back(n);
            if (__builtin_popcount(shared) >= 2) {
                whole.insert(std::minmax(e.a, e.b));  // along an edge of the box: the edge's division keeps it
                continue;
            }
            onFace[static_cast<std::size_t>(__builtin_ctz(shared))].push_back(e);
        }
    // A tow touching a face without being cut there (its nodes moved onto the plane): its edges
    // and nodes in the plane are the face's too.
    std::array<std::vector<std::pair<std::size_t, std::size_t>>, 6> touching;
    std::array<std::vector<std::size_t>, 6> touchingNodes;
    for (const TowMesh& m : mesh.tows)
        for (const Triangle& tri : m.triangles)
            for (std::size_t i = 0; i < 3; ++i) {
                const std::size_t a = tri[i], b = tri[(i + 1) % 3];
                const unsigned onA = planesThrough(cell, mesh.nodes[a]), shared = onA & planesThrough(cell, mesh.nodes[b]);
                if (__builtin_popcount(onA) >= 2) onEdges.push_back(a);
                else if (onA != 0) touchingNodes[static_cast<std::size_t>(__builtin_ctz(onA))].push_back(a);
                if (__builtin_popcount(shared) >= 2) whole.insert(std::minmax(a, b));
                else if (shared != 0) touching[static_cast<std::size_t>(__builtin_ctz(shared))].push_back(std::minmax(a, b));
            }
    const auto distinct = [](auto& list) {
        std::sort(list.begin(), list.end());
        list.erase(std::unique(list.begin(), list.end()), list.end());
    };
    for (std::size_t f = 0; f < 6; ++f) {
        distinct(touching[f]);
        distinct(touchingNodes[f]);
    }
    distinct(onEdges);
    std::vector<Solid> bounded;
    std::vector<K::Point_3> solidNodes;
    for (const std::vector<Triangle>& s : solids) {
        Solid solid{&s, {1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}};
        for (const Triangle& t : s)
            for (std::size_t n : t) {
                const Point3& p = mesh.nodes[n];
                solid.lo = {std::min(solid.lo.x, p.x), std::min(solid.lo.y, p.y), std::min(solid.lo.z, p.z)};
                solid.hi = {std::max(solid.hi.x, p.x), std::max(solid.hi.y, p.y), std::max(solid.hi.z, p.z)};
                solidNodes.emplace_back(p.x, p.y, p.z);
            }
        bounded.push_back(solid);
    }
    NearestNode::Tree tree(solidNodes.begin(), solidNodes.end());
    if (!solidNodes.empty()) tree.build();
    const FaceGrading grading{cell.faceSizeGrowth, solidNodes.empty() ? 1.0 : cell.faceSizeMax, &tree};
    BoxEdges edges(cell, h, mesh.nodes, onEdges, whole);
    FaceJob job{mesh, cell, bounded, edges, grading, h, minAngle};
    CellMesh out;
    out.box = cell;
    std::vector<std::vector<std::pair<Triangle, CellFace>>> caps(mesh.tows.size());
    for (int f = 0; f < 6; ++f) {
        const CellFace face = static_cast<CellFace>(f);
        const auto [triangles, tow] = meshFace(job, face, onFace[static_cast<std::size_t>(f)], touching[static_cast<std::size_t>(f)],
                                               touchingNodes[static_cast<std::size_t>(f)]);
        std::vector<std::size_t>& faceNodes = out.faceNodes[static_cast<std::size_t>(f)];
        for (std::size_t k = 0; k < triangles.size(); ++k) {
            faceNodes.insert(faceNodes.end(), triangles[k].begin(), triangles[k].end());
            if (tow[k] >= 0) {
                caps[static_cast<std::size_t>(tow[k])].push_back({triangles[k], face});
                continue;
            }
            out.triangles.push_back(triangles[k]);
            out.face.push_back(face);
        }
        std::sort(faceNodes.begin(), faceNodes.end());
        faceNodes.erase(std::unique(faceNodes.begin(), faceNodes.end()), faceNodes.end());
    }
    for (std::size_t t = 0; t < mesh.tows.size(); ++t) {
        TowMesh& m = mesh.tows[t];
        if (caps[t].empty()) continue;
        // A cap's fibre direction: that of the tow's triangles along its cuts on the face.
        std::array<std::vector<Vector3>, 6> along;
        if (m.fibreDirection.size() == m.triangles.size())
            for (std::size_t f = 0; f < 6; ++f)
                for (const OpenEdge& e : onFace[f])
                    if (e.tow == t) along[f].push_back(m.fibreDirection[e.triangle]);
        const bool fibres = m.fibreDirection.size() == m.triangles.size();
        const Vector3 overall = fibres ? meanDirection(m.fibreDirection) : Vector3{};
        for (const auto& [tri, face] : caps[t]) {
            const std::vector<Vector3>& on = along[static_cast<std::size_t>(face)];
            m.triangles.push_back(tri);
            if (m.region.size() + 1 == m.triangles.size()) m.region.push_back(-1);
            if (m.face.size() + 1 == m.triangles.size()) m.face.push_back(TowFace::Cell);
            if (fibres) m.fibreDirection.push_back(on.empty() ? overall : meanDirection(on));
        }
    }
    return out;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
