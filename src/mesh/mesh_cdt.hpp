// The constrained Delaunay triangulation each tow is meshed in (its scaled (u,v) rectangle), and
// the refinement criteria: size measured in 3D with the surface metric, shape in the plane.
#pragma once

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <queue>

#include "mesh/angle_bound.hpp"
#include "mesh/surface_metric.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail::mesh2 {

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

/// CGAL's size-and-shape criteria measured in 3D: an edge is too long when the surface metric
/// makes it longer than h; a face is badly shaped when its smallest angle is below the bound in
/// the scaled space (CGAL's own test) or, for faces longer than h/8, by the metric's lengths
/// (to kMetricShare of the bound). Loop chords (constrained edges between two loop
/// nodes) are the loop's own sampling, at the loop spacing: they are exempt from the size
/// bound, so the mesher does not split them only for being a little over h.
class Criteria : public CGAL::Delaunay_mesh_size_criteria_2<CDT> {
public:
    using Base = CGAL::Delaunay_mesh_size_criteria_2<CDT>;
    /// @p localH, if given, is the target edge length at a point of the scaled space, taken
    /// within [h / 100, h].
    using LocalSize = std::function<double(double, double)>;
    Criteria(double shapeBound, double h, const SurfaceMetric& metric, LocalSize localH = {})
        : CGAL::Delaunay_mesh_criteria_2<CDT>(shapeBound), Base(shapeBound, h), metric_(&metric), localH_(std::move(localH)) {}

    class Is_bad : public Base::Is_bad {
    public:
        Is_bad(double shapeBound, double h, const SurfaceMetric& metric, LocalSize localH = {})
            : Base::Is_bad(shapeBound, h, traits()), metric_(&metric), localH_(std::move(localH)),
              metricBound_(std::pow(std::sin(kMetricShare * std::asin(std::sqrt(std::clamp(shapeBound, 0.0, 1.0)))), 2))
        {
        }
        using Base::Is_bad::operator();
        CGAL::Mesh_2::Face_badness operator()(const CDT::Face_handle& f, Quality& q) const
        {
            q.second = 0.0;
            double bound2 = this->squared_size_bound;
            if (localH_) {
                const K::Point_2 &p0 = f->vertex(0)->point(), &p1 = f->vertex(1)->point(), &p2 = f->vertex(2)->point();
                const double h = std::sqrt(this->squared_size_bound);
                const double hl = std::clamp(localH_((p0.x() + p1.x() + p2.x()) / 3.0, (p0.y() + p1.y() + p2.y()) / 3.0), h / 100.0, h);
                bound2 = hl * hl;
            }
            double l2[3];
            for (int k = 0; k < 3; ++k) {
                const CDT::Vertex_handle a = f->vertex(CDT::cw(k)), b = f->vertex(CDT::ccw(k));
                const K::Point_2 &p = a->point(), &r = b->point();
                l2[k] = metric_->squaredLength(0.5 * (p.x() + r.x()), 0.5 * (p.y() + r.y()), r.x() - p.x(), r.y() - p.y());
                if (f->is_constrained(k) && a->info().node >= 0 && b->info().node >= 0) continue;
                q.second = std::max(q.second, l2[k] / bound2);
            }
            if (q.size() > 1.0) {
                q.first = 1.0;
                return CGAL::Mesh_2::IMPERATIVELY_BAD;
            }
            // The shape, in the scaled space: CGAL's own measure with the size bound off.
            Quality shape;
            CGAL::Mesh_2::Face_badness badness = Base::Is_bad(this->B, 0.0, traits())(f, shape);
            q.first = shape.first;
            std::sort(l2, l2 + 3);
            if (64.0 * l2[2] > bound2) {
                // The same measure with the edges' 3D lengths, so that angles are good in 3D
                // where the metric is not the plane's: sine^2 of the smallest angle is
                // (2 area)^2 / (longest^2 second^2), the area by Heron's formula. Only for faces
                // longer than h/8: an xy refinement may not converge on a metric's shape, and
                // the plane's bound (CGAL's, which terminates) still holds below.
                const double area4sq = 2.0 * (l2[0] * l2[1] + l2[1] * l2[2] + l2[2] * l2[0]) - (l2[0] * l2[0] + l2[1] * l2[1] + l2[2] * l2[2]);
                const double sine2 = std::max(area4sq, 0.0) / 4.0 / (l2[2] * l2[1]);
                if (sine2 < metricBound_) {
                    q.first = std::min(q.first, sine2);
                    badness = CGAL::Mesh_2::BAD;
                }
            }
            return badness;
        }

    private:
        /// CGAL keeps a reference to the traits: one that outlives every Is_bad.
        static const K& traits()
        {
            static const K k;
            return k;
        }
        const SurfaceMetric* metric_;
        LocalSize localH_;
        double metricBound_;  ///< sine^2 of the smallest angle in 3D
    };
    Is_bad is_bad_object() const { return Is_bad(this->bound(), this->size_bound(), *metric_, localH_); }

private:
    const SurfaceMetric* metric_;
    LocalSize localH_;
};


/// Marks the faces inside the constraints as the domain: every face reachable from the
/// infinite face without crossing a constraint is outside.
inline void markInside(CDT& cdt)
{
    for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->set_in_domain(true);
    std::queue<CDT::Face_handle> queue;
    const CDT::Face_handle infinite = cdt.infinite_face();
    infinite->set_in_domain(false);
    queue.push(infinite);
    // Every face around the infinite vertex is outside too (they are not separated from it).
    CDT::Face_circulator fc = cdt.incident_faces(cdt.infinite_vertex()), done = fc;
    do {
        if (fc->is_in_domain()) {
            fc->set_in_domain(false);
            queue.push(fc);
        }
    } while (++fc != done);
    while (!queue.empty()) {
        const CDT::Face_handle f = queue.front();
        queue.pop();
        for (int k = 0; k < 3; ++k) {
            const CDT::Face_handle n = f->neighbor(k);
            if (!n->is_in_domain() || f->is_constrained(k)) continue;
            n->set_in_domain(false);
            queue.push(n);
        }
    }
}

}  // namespace detail::mesh2
TOWGEOM_END_NAMESPACE
