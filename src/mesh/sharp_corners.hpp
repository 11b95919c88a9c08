// Sharp constraint corners of a constrained triangulation: the wedges of its domain between two
// constraints meeting at a vertex (two loops, a loop and the seam or a tow's end) whose angle is
// below a bound. Near such a corner no triangle can have all its angles above the bound, so the
// mesh quality (MeshQuality) is judged there against the corner's own angle instead.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <set>
#include <vector>

#include "mesh/mesh_cdt.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// A wedge of the domain at a vertex between two consecutive constraints, sharper than the bound.
struct CornerWedge {
    mesh2::CDT::Vertex_handle vertex;
    double angle = 0.0;  ///< degrees: the sum of the wedge's faces' angles at the vertex
    /// The corner's faces: the wedge's faces at the vertex, and those reachable from them without
    /// crossing a constraint whose vertices all lie within cornerReach() of the vertex.
    std::vector<mesh2::CDT::Face_handle> faces;
};

/// How far from its apex a corner of @p angle degrees is narrower than the mesh size @p h
/// (h / (2 sin(angle / 2))), at most 20 h.
inline double cornerReach(double angle, double h)
{
    return std::min(20.0 * h, h / (2.0 * std::sin(0.5 * angle * 3.14159265358979323846 / 180.0)));
}

/// Adds to @p w's faces every domain face reachable from them across unconstrained edges whose
/// three vertices are all @p near.
template <class Near>
void gatherCorner(const mesh2::CDT& cdt, CornerWedge& w, Near&& near)
{
    using mesh2::CDT;
    std::set<CDT::Face_handle> seen(w.faces.begin(), w.faces.end());
    for (std::size_t k = 0; k < w.faces.size(); ++k)
        for (int e = 0; e < 3; ++e) {
            const CDT::Face_handle f = w.faces[k], g = f->neighbor(e);
            if (f->is_constrained(e) || cdt.is_infinite(g) || !g->is_in_domain() || seen.count(g)) continue;
            if (!near(g->vertex(0)->point()) || !near(g->vertex(1)->point()) || !near(g->vertex(2)->point())) continue;
            seen.insert(g);
            w.faces.push_back(g);
        }
}

/// The wedges of @p cdt's domain sharper than @p boundDegrees: at each vertex with a constrained
/// edge, its domain faces grouped by the unconstrained edges at the vertex that join them (each
/// group a wedge between two constraints), each face's angle at the vertex given by
/// @p angleAt(face, index of the vertex in it) in degrees (the true angle on the surface, not
/// the plane's). Each wedge's faces are gathered out to cornerReach(angle, @p h), a point's
/// distance from the vertex given by @p distanceFrom(vertex, point).
template <class AngleAt, class DistanceFrom>
std::vector<CornerWedge> sharpWedges(const mesh2::CDT& cdt, AngleAt&& angleAt, DistanceFrom&& distanceFrom, double boundDegrees, double h)
{
    using mesh2::CDT;
    std::vector<CornerWedge> out;
    std::vector<CDT::Face_handle> faces;
    std::map<CDT::Face_handle, std::size_t> group;
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
        faces.clear();
        bool constrained = false;
        CDT::Face_circulator fc = cdt.incident_faces(v), done = fc;
        do {
            if (cdt.is_infinite(fc)) continue;
            const int i = fc->index(v);
            constrained = constrained || fc->is_constrained(CDT::cw(i)) || fc->is_constrained(CDT::ccw(i));
            if (fc->is_in_domain()) faces.push_back(fc);
        } while (++fc != done);
        if (!constrained || faces.empty()) continue;
        // Union of faces across the unconstrained edges at v (each such edge joins two faces).
        group.clear();
        std::vector<std::size_t> parent(faces.size());
        for (std::size_t k = 0; k < faces.size(); ++k) {
            parent[k] = k;
            group[faces[k]] = k;
        }
        const auto root = [&](std::size_t k) {
            while (parent[k] != k) k = parent[k] = parent[parent[k]];
            return k;
        };
        for (std::size_t k = 0; k < faces.size(); ++k) {
            const int i = faces[k]->index(v);
            for (const int e : {CDT::cw(i), CDT::ccw(i)}) {
                if (faces[k]->is_constrained(e)) continue;
                const auto it = group.find(faces[k]->neighbor(e));
                if (it != group.end()) parent[root(k)] = root(it->second);
            }
        }
        std::map<std::size_t, double> wedge;
        for (std::size_t k = 0; k < faces.size(); ++k) wedge[root(k)] += angleAt(faces[k], faces[k]->index(v));
        for (const auto& [r, angle] : wedge) {
            if (angle >= boundDegrees) continue;
            CornerWedge w{v, angle, {}};
            for (std::size_t k = 0; k < faces.size(); ++k)
                if (root(k) == r) w.faces.push_back(faces[k]);
            const double reach = cornerReach(angle, h);
            gatherCorner(cdt, w, [&](const mesh2::K::Point_2& p) { return distanceFrom(v, p) <= reach; });
            out.push_back(std::move(w));
        }
    }
    return out;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
