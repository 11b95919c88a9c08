#include "cell/cell_faces.hpp"

#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "cell/axis.hpp"
#include "cell/box_edges.hpp"
#include "cell/face_size.hpp"
#include "mesh/constraint_keeping_mesher.hpp"
#include "mesh/graded_size_criteria.hpp"
#include "mesh/mesh_cdt.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

using mesh2::CDT;
using mesh2::K;
using Triangle = std::array<std::size_t, 3>;

namespace {

/// A cut on a face: the tow, the end it closes, its nodes around.
struct FaceCut {
    std::size_t tow = 0;
    int end = 0;
    const std::vector<std::size_t>* nodes = nullptr;
};

/// One face meshed: triangles counter-clockwise in the face's (b, c) plane, each labelled with
/// the index of the cut it lies in (-1: the matrix).
struct FaceMesh {
    std::vector<Triangle> triangles;
    std::vector<long> cut;
    std::vector<std::vector<long>> alsoIn;  ///< per triangle: the other cuts it lies in (lower-ranked tows')
    std::vector<std::size_t> boundary;  ///< the rectangle's nodes, counter-clockwise from (min, min)
};

/// Meshes the face of axis @p a at coordinate @p at: the rectangle @p boundary with @p cuts inside.
/// @p twin: with a periodic cell, the opposite face's coordinate (the mesh is also that face's).
FaceMesh meshFace(const std::vector<TowSurface>& tows, CellFace face, int a, double at, std::vector<std::size_t> boundary,
                  const std::vector<FaceCut>& cuts, double h, const FaceGrading& grading, double minAngle, std::vector<Point3>& nodes,
                  const std::vector<std::size_t>& rank, std::optional<double> twin = std::nullopt)
{
    std::vector<double> planes{at};
    if (twin) planes.push_back(*twin);
    const auto [b, c] = inPlane(a);
    const auto flat = [&, b = b, c = c](std::size_t n) { return K::Point_2(coord(nodes[n], b), coord(nodes[n], c)); };
    std::vector<std::vector<K::Point_2>> polygons;
    for (const FaceCut& cut : cuts) {
        polygons.emplace_back();
        for (std::size_t n : *cut.nodes) polygons.back().push_back(flat(n));
    }
    const std::string onFace = std::string(" on the cell's face ") + cellFaceName(face);
    for (std::size_t i = 0; i < cuts.size(); ++i) {
        if (!CGAL::is_simple_2(polygons[i].begin(), polygons[i].end(), K()))
            throw Error(ErrorCode::InvalidArgument, "tow '" + tows[cuts[i].tow].name() + "': its cut" + onFace +
                                                        " is no simple polygon at its mesh size: use a smaller mesh size");
        for (std::size_t j = 0; j < i; ++j) {
            // Cuts of two tows whose loop crosses the face share the crossings' nodes and cross
            // only there.
            std::vector<std::size_t> ni = *cuts[i].nodes, nj = *cuts[j].nodes;
            std::sort(ni.begin(), ni.end());
            std::sort(nj.begin(), nj.end());
            std::vector<std::size_t> common;
            std::set_intersection(ni.begin(), ni.end(), nj.begin(), nj.end(), std::back_inserter(common));
            const bool crossed = common.size() >= 2;
            bool meet = !crossed &&
                        (CGAL::bounded_side_2(polygons[j].begin(), polygons[j].end(), polygons[i][0], K()) != CGAL::ON_UNBOUNDED_SIDE ||
                         CGAL::bounded_side_2(polygons[i].begin(), polygons[i].end(), polygons[j][0], K()) != CGAL::ON_UNBOUNDED_SIDE);
            const std::vector<std::size_t>&ci = *cuts[i].nodes, &cj = *cuts[j].nodes;
            for (std::size_t p = 0; p < polygons[i].size() && !meet; ++p)
                for (std::size_t q = 0; q < polygons[j].size() && !meet; ++q) {
                    const std::size_t p1 = (p + 1) % ci.size(), q1 = (q + 1) % cj.size();
                    if (ci[p] == cj[q] || ci[p] == cj[q1] || ci[p1] == cj[q] || ci[p1] == cj[q1]) continue;  // two chords from one crossing
                    meet = CGAL::do_intersect(K::Segment_2(polygons[i][p], polygons[i][p1]), K::Segment_2(polygons[j][q], polygons[j][q1]));
                }
            if (meet)
                throw Error(ErrorCode::InvalidArgument,
                            "tows '" + tows[cuts[j].tow].name() + "' and '" + tows[cuts[i].tow].name() + "' overlap" + onFace +
                                (crossed ? " (their cuts cross there away from where their loop crosses the face, at this mesh size)"
                                         : " (their cuts meet there): the cell's faces must pass where the tows do not touch, or "
                                           "through their overlaps where an intersection loop of the two crosses the face"));
        }
    }
    CDT cdt;
    const auto insertLoop = [&](const std::vector<std::size_t>& loop) {
        std::vector<CDT::Vertex_handle> vs;
        for (std::size_t n : loop) {
            vs.push_back(cdt.insert(flat(n)));
            vs.back()->info().node = static_cast<long>(n);
        }
        for (std::size_t k = 0; k < vs.size(); ++k) cdt.insert_constraint(vs[k], vs[(k + 1) % vs.size()]);
    };
    insertLoop(boundary);
    std::vector<std::size_t> distinct = boundary;  // nodes; a crossing is on two cuts
    for (const FaceCut& cut : cuts) {
        insertLoop(*cut.nodes);
        distinct.insert(distinct.end(), cut.nodes->begin(), cut.nodes->end());
    }
    std::sort(distinct.begin(), distinct.end());
    const std::size_t expected = static_cast<std::size_t>(std::unique(distinct.begin(), distinct.end()) - distinct.begin());
    if (cdt.number_of_vertices() != expected)
        throw Error(ErrorCode::InvalidArgument, std::string("two nodes coincide") + onFace + ": a tow's cut touches the box's edge");
    mesh2::markInside(cdt);
    const double angle = std::clamp(minAngle, 1.0, 30.0) * 3.14159265358979323846 / 180.0;
    const FaceSize size(polygons, a, planes, h, grading);
    refineKeepingConstraints(cdt, GradedSizeCriteria<CDT>(std::sin(angle) * std::sin(angle), [&size](const K::Point_2& p) { return size(p); }),
                             false);
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
        if (v->info().node >= 0) continue;
        Point3 p;
        coord(p, a) = at;
        coord(p, b) = v->point().x();
        coord(p, c) = v->point().y();
        v->info().node = static_cast<long>(nodes.size());
        nodes.push_back(p);
    }
    // Each part between constraints labelled once: inside which cut, or none.
    std::map<CDT::Face_handle, std::vector<long>> label;  // the cuts it lies in, the highest-ranked tow's first
    FaceMesh out;
    out.boundary = std::move(boundary);
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
        if (!f->is_in_domain() || label.count(f)) continue;
        const K::Point_2 centre = CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
        std::vector<long> in;
        for (std::size_t i = 0; i < polygons.size(); ++i)
            if (CGAL::bounded_side_2(polygons[i].begin(), polygons[i].end(), centre, K()) == CGAL::ON_BOUNDED_SIDE) in.push_back(static_cast<long>(i));
        std::sort(in.begin(), in.end(), [&](long x, long y) {
            return rank[cuts[static_cast<std::size_t>(x)].tow] < rank[cuts[static_cast<std::size_t>(y)].tow];
        });
        std::vector<CDT::Face_handle> stack{f};
        label[f] = in;
        while (!stack.empty()) {
            const CDT::Face_handle g = stack.back();
            stack.pop_back();
            for (int k = 0; k < 3; ++k) {
                const CDT::Face_handle n = g->neighbor(k);
                if (g->is_constrained(k) || !n->is_in_domain() || cdt.is_infinite(n) || label.count(n)) continue;
                label[n] = in;
                stack.push_back(n);
            }
        }
    }
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
        if (!f->is_in_domain()) continue;
        const std::vector<long>& in = label.at(f);
        out.triangles.push_back({static_cast<std::size_t>(f->vertex(0)->info().node), static_cast<std::size_t>(f->vertex(1)->info().node),
                                 static_cast<std::size_t>(f->vertex(2)->info().node)});
        out.cut.push_back(in.empty() ? -1 : in[0]);
        out.alsoIn.emplace_back(in.empty() ? in.begin() : in.begin() + 1, in.end());
    }
    return out;
}

}  // namespace

double cellFaceSize(const Cell& cell, const std::vector<double>& towH)
{
    if (!towH.empty()) return *std::min_element(towH.begin(), towH.end());
    return std::max({cell.max.x - cell.min.x, cell.max.y - cell.min.y, cell.max.z - cell.min.z}) / 20.0;
}

CellFaces meshCellFaces(const std::vector<TowSurface>& tows, const Cell& cell, const CellCuts& cuts, double h, double minAngle,
                        std::vector<Point3>& nodes, const std::vector<std::size_t>& rank)
{
    CellFaces out;
    out.caps.resize(tows.size());
    out.mesh.box = cell;
    // Every node so far is a tow's (the box's own come next).
    std::vector<K::Point_3> towNodes;
    for (const Point3& p : nodes) towNodes.emplace_back(p.x, p.y, p.z);
    NearestNode::Tree towTree(towNodes.begin(), towNodes.end());
    if (!towNodes.empty()) towTree.build();  // CGAL asserts on building an empty tree (no tow)
    const FaceGrading grading{cell.faceSizeGrowth, tows.empty() ? 1.0 : cell.faceSizeMax, &towTree};
    BoxEdges edges(cell, h, nodes);
    const auto cutsOn = [&](CellFace face) {
        std::vector<FaceCut> list;
        for (std::size_t t = 0; t < tows.size(); ++t)
            for (int end = 0; end < 2; ++end) {
                const auto& cut = cuts.cuts[t][static_cast<std::size_t>(end)];
                if (cut && cut->face == face) list.push_back({t, end, &cut->nodes});
            }
        return list;
    };
    const auto add = [&](CellFace face, const FaceMesh& m, const std::vector<FaceCut>& on, bool ccwOutward) {
        std::vector<std::size_t>& faceNodes = out.mesh.faceNodes[static_cast<std::size_t>(face)];
        for (std::size_t k = 0; k < m.triangles.size(); ++k) {
            Triangle tri = m.triangles[k];
            if (!ccwOutward) std::swap(tri[1], tri[2]);
            faceNodes.insert(faceNodes.end(), tri.begin(), tri.end());
            if (m.cut[k] < 0) {
                out.mesh.triangles.push_back(tri);
                out.mesh.face.push_back(face);
            } else {
                const FaceCut& cut = on[static_cast<std::size_t>(m.cut[k])];
                out.caps[cut.tow][static_cast<std::size_t>(cut.end)].push_back(tri);
                // Also a cap of each lower-ranked tow whose cut it lies in (until its regions
                // are made: connectRegions() takes it off that tow, which gives way there).
                for (const long other : m.alsoIn[k]) {
                    const FaceCut& also = on[static_cast<std::size_t>(other)];
                    out.caps[also.tow][static_cast<std::size_t>(also.end)].push_back(tri);
                }
            }
        }
        std::sort(faceNodes.begin(), faceNodes.end());
        faceNodes.erase(std::unique(faceNodes.begin(), faceNodes.end()), faceNodes.end());
    };
    for (int a = 0; a < 3; ++a) {
        // Counter-clockwise in (b, c) is along +a for x and z, along -a for y.
        const bool ccwAlongA = a != 1;
        const CellFace lo = static_cast<CellFace>(2 * a), hi = static_cast<CellFace>(2 * a + 1);
        const std::vector<FaceCut> onLo = cutsOn(lo), onHi = cutsOn(hi);
        const FaceMesh mLo = meshFace(tows, lo, a, coord(cell.min, a), edges.rectangle(a, 0), onLo, h, grading, minAngle, nodes, rank,
                                      cell.periodic ? std::optional<double>(coord(cell.max, a)) : std::nullopt);
        add(lo, mLo, onLo, !ccwAlongA);
        if (!cell.periodic) {
            add(hi, meshFace(tows, hi, a, coord(cell.max, a), edges.rectangle(a, 1), onHi, h, grading, minAngle, nodes, rank), onHi, ccwAlongA);
            continue;
        }
        // The min face moved onto the max face: its rectangle, its cuts (the same tow's, same
        // stations) and its own nodes moved.
        FaceMesh mHi;
        mHi.boundary = edges.rectangle(a, 1);
        std::map<std::size_t, std::size_t> partner;
        for (std::size_t k = 0; k < mLo.boundary.size(); ++k) partner[mLo.boundary[k]] = mHi.boundary[k];
        std::vector<long> cutOf(onLo.size(), -1);
        for (std::size_t i = 0; i < onLo.size(); ++i)
            for (std::size_t j = 0; j < onHi.size(); ++j)
                if (onHi[j].tow == onLo[i].tow && onHi[j].nodes->size() == onLo[i].nodes->size()) {
                    cutOf[i] = static_cast<long>(j);
                    for (std::size_t k = 0; k < onLo[i].nodes->size(); ++k) partner[(*onLo[i].nodes)[k]] = (*onHi[j].nodes)[k];
                }
        for (std::size_t i = 0; i < onLo.size(); ++i)
            if (cutOf[i] < 0)
                throw Error(ErrorCode::Internal, "tow '" + tows[onLo[i].tow].name() + "': its periodic cut has no partner");
        for (std::size_t k = 0; k < mLo.triangles.size(); ++k) {
            Triangle tri = mLo.triangles[k];
            for (std::size_t& n : tri) {
                auto it = partner.find(n);
                if (it == partner.end()) {
                    Point3 p = nodes[n];
                    coord(p, a) = coord(cell.max, a);
                    nodes.push_back(p);
                    it = partner.emplace(n, nodes.size() - 1).first;
                }
                n = it->second;
            }
            mHi.triangles.push_back(tri);
            mHi.cut.push_back(mLo.cut[k] < 0 ? -1 : cutOf[static_cast<std::size_t>(mLo.cut[k])]);
            mHi.alsoIn.emplace_back();
            for (const long other : mLo.alsoIn[k]) mHi.alsoIn.back().push_back(cutOf[static_cast<std::size_t>(other)]);
        }
        add(hi, mHi, onHi, ccwAlongA);
        auto& pairs = out.mesh.periodicPairs[static_cast<std::size_t>(a)];
        pairs.assign(partner.begin(), partner.end());
    }
    return out;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
