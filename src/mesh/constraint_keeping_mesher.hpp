// CGAL Delaunay refinement that never splits a constrained edge: a refinement point that would
// encroach on one (or that lies on one, or outside the domain) is not inserted and its face is
// left as it is; the caller finds such faces afterwards (badFacesByConstraint) and decides what
// to add to the constraints before meshing again.
//
// CGAL's own Delaunay_mesher_no_edge_refinement_2 does this too, but also gives up every point
// that falls exactly on an unconstrained edge, which happens all the time when refining a
// regular lattice (the circumcentre of a right triangle is the middle of its hypotenuse) and
// leaves thousands of faces too big. The edge level below differs from CGAL's
// Mesh_2::Do_not_refine_edges only there.
#pragma once

#include <CGAL/Delaunay_mesher_no_edge_refinement_2.h>

#include <algorithm>
#include <vector>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

template <class CDT>
class KeepConstrainedEdges
    : public CGAL::Mesh_2::Refine_edges_base<CDT, CGAL::Mesh_2::Is_locally_conforming_Gabriel<CDT>,
                                             typename CGAL::Mesh_2::details::Refine_edges_base_types<CDT>::Default_container> {
    using Super = CGAL::Mesh_2::Refine_edges_base<CDT, CGAL::Mesh_2::Is_locally_conforming_Gabriel<CDT>,
                                                  typename CGAL::Mesh_2::details::Refine_edges_base_types<CDT>::Default_container>;
    using Zone = typename CGAL::Triangulation_mesher_level_traits_2<CDT>::Zone;

public:
    explicit KeepConstrainedEdges(CDT& cdt) : Super(cdt) {}

    void scan_triangulation_impl() {}

    CGAL::Mesher_level_conflict_status test_point_conflict_from_superior_impl(const typename CDT::Point& p, Zone& z)
    {
        if (!z.fh->is_in_domain() || z.locate_type == CDT::VERTEX || z.locate_type == CDT::OUTSIDE_CONVEX_HULL ||
            z.locate_type == CDT::OUTSIDE_AFFINE_HULL)
            return CGAL::CONFLICT_AND_ELEMENT_SHOULD_BE_DROPPED;
        if (z.locate_type == CDT::EDGE && z.fh->is_constrained(z.i)) return CGAL::CONFLICT_AND_ELEMENT_SHOULD_BE_DROPPED;
        // The point must see the face it refines: a point behind a constraint (the face is not
        // in its conflict zone) leaves the face as it is, so the face is refined again and again
        // (the same circumcentre rounded differently: clusters of coincident vertices).
        if (std::find(z.faces.begin(), z.faces.end(), z.parent_face) == z.faces.end())
            return CGAL::CONFLICT_AND_ELEMENT_SHOULD_BE_DROPPED;
        for (const typename CDT::Edge& e : z.boundary_edges)
            if (e.first->is_constrained(e.second) && !this->is_locally_conform(this->tr, e.first, e.second, p))
                return CGAL::CONFLICT_AND_ELEMENT_SHOULD_BE_DROPPED;
        return CGAL::NO_CONFLICT;
    }
};

/// Refines the faces of @p cdt in its domain until @p criteria are met, except where that would
/// split a constraint. The domain is the convex hull when @p wholeHull, else the faces the
/// caller marked (Delaunay_mesh_face_base_2::set_in_domain).
template <class CDT, class Criteria>
void refineKeepingConstraints(CDT& cdt, Criteria criteria, bool wholeHull = true)
{
    using EdgesBase = KeepConstrainedEdges<CDT>;
    using EdgesLevel = CGAL::Mesh_2::Refine_edges<CDT, CGAL::Mesh_2::Is_locally_conforming_Gabriel<CDT>, EdgesBase>;
    using FacesLevel = CGAL::Mesh_2::Refine_faces<CDT, Criteria, EdgesLevel>;
    CGAL::Null_mesher_level nullLevel;
    CGAL::Null_mesh_visitor nullVisitor;
    EdgesLevel edges(cdt, nullLevel);
    FacesLevel faces(cdt, criteria, edges);
    if (wholeHull) CGAL::Delaunay_mesher_no_edge_refinement_2<CDT, Criteria>::mark_convex_hull(cdt);
    edges.scan_triangulation();
    faces.scan_triangulation();
    faces.refine(nullVisitor);
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
