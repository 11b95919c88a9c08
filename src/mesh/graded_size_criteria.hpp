// CGAL's size-and-shape criteria for a planar mesh whose size bound varies over the plane: a
// face is too big when its longest edge exceeds the size wanted at its centroid; its shape is
// CGAL's own test (smallest angle against the bound).
#pragma once

#include <CGAL/Delaunay_mesh_size_criteria_2.h>

#include <algorithm>
#include <functional>
#include <utility>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

template <class CDT>
class GradedSizeCriteria : public CGAL::Delaunay_mesh_size_criteria_2<CDT> {
public:
    using Base = CGAL::Delaunay_mesh_size_criteria_2<CDT>;
    using Point = typename CDT::Point;
    using Quality = typename Base::Quality;
    /// The edge length wanted at a point (> 0).
    using Size = std::function<double(const Point&)>;

    /// @p shapeBound: CGAL's bound on the squared sine of the smallest angle.
    GradedSizeCriteria(double shapeBound, Size size)
        : CGAL::Delaunay_mesh_criteria_2<CDT>(shapeBound), Base(shapeBound, 0.0), size_(std::move(size))
    {
    }

    class Is_bad : public Base::Is_bad {
    public:
        Is_bad(double shapeBound, Size size) : Base::Is_bad(shapeBound, 0.0, traits()), size_(std::move(size)) {}
        using Base::Is_bad::operator();
        CGAL::Mesh_2::Face_badness operator()(const typename CDT::Face_handle& f, Quality& q) const
        {
            const Point &a = f->vertex(0)->point(), &b = f->vertex(1)->point(), &c = f->vertex(2)->point();
            const auto distance2 = traits().compute_squared_distance_2_object();
            const double s = size_(traits().construct_centroid_2_object()(a, b, c));
            const double longest2 = CGAL::to_double(std::max({distance2(a, b), distance2(b, c), distance2(c, a)}));
            if (longest2 > s * s) {
                q = Quality(1.0, longest2 / (s * s));
                return CGAL::Mesh_2::IMPERATIVELY_BAD;
            }
            // The shape: CGAL's own test, its size bound off (0).
            const CGAL::Mesh_2::Face_badness badness = Base::Is_bad::operator()(f, q);
            q.second = longest2 / (s * s);
            return badness;
        }

    private:
        /// CGAL's Is_bad keeps a reference to the traits: one that outlives every Is_bad.
        static const typename CDT::Geom_traits& traits()
        {
            static const typename CDT::Geom_traits k;
            return k;
        }
        Size size_;
    };
    Is_bad is_bad_object() const { return Is_bad(this->bound(), size_); }

private:
    Size size_;
};

}  // namespace detail
TOWGEOM_END_NAMESPACE
