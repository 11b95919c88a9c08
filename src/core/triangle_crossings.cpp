#include "core/triangle_crossings.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <array>

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

bool trianglesCross(const std::array<std::size_t, 3>& s, const std::array<CGAL::Epick::Point_3, 3>& ps,
                    const std::array<std::size_t, 3>& t, const std::array<CGAL::Epick::Point_3, 3>& pt, std::size_t sharedBelow)
{
    int inT[3], common = 0;  // inT[k]: the corner of t that is s's corner k, or -1
    for (int k = 0; k < 3; ++k) {
        inT[k] = -1;
        if (s[k] >= sharedBelow) continue;
        for (int l = 0; l < 3; ++l)
            if (s[k] == t[l]) inT[k] = l;
        common += inT[k] >= 0;
    }
    if (common == 3) return false;
    using Triangle = CGAL::Epick::Triangle_3;
    using Segment = CGAL::Epick::Segment_3;
    if (common == 0) return CGAL::do_intersect(Triangle(ps[0], ps[1], ps[2]), Triangle(pt[0], pt[1], pt[2]));
    if (common == 2) {
        int ks = 0, kt = 0;  // the corners not in common
        while (inT[ks] >= 0) ++ks;
        const int p = (ks + 1) % 3, q = (ks + 2) % 3;  // the common edge, as s's corners
        while (kt == inT[p] || kt == inT[q]) ++kt;
        return CGAL::coplanar(ps[p], ps[q], ps[ks], pt[kt]) && CGAL::coplanar_orientation(ps[p], ps[q], ps[ks], pt[kt]) == CGAL::POSITIVE;
    }
    int ks = 0;  // the corner in common
    while (inT[ks] < 0) ++ks;
    const int kt = inT[ks];
    return CGAL::do_intersect(Segment(ps[(ks + 1) % 3], ps[(ks + 2) % 3]), Triangle(pt[0], pt[1], pt[2])) ||
           CGAL::do_intersect(Segment(pt[(kt + 1) % 3], pt[(kt + 2) % 3]), Triangle(ps[0], ps[1], ps[2]));
}

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;

struct Facet {
    std::array<std::size_t, 3> node;  // 0-based
    std::size_t surface;
};

}  // namespace

std::optional<TriangleCrossing> firstCrossing(const std::vector<Point3>& nodes, const std::vector<const std::vector<std::size_t>*>& surfaces,
                                              const BoundingBox& within)
{
    std::vector<Kernel::Point_3> p;
    p.reserve(nodes.size());
    for (const Point3& n : nodes) p.emplace_back(n.x, n.y, n.z);
    std::vector<Facet> facets;
    for (std::size_t s = 0; s < surfaces.size(); ++s)
        for (std::size_t k = 0; k + 2 < surfaces[s]->size(); k += 3)
            facets.push_back({{(*surfaces[s])[k] - 1, (*surfaces[s])[k + 1] - 1, (*surfaces[s])[k + 2] - 1}, s});
    std::vector<Box> boxes;
    boxes.reserve(facets.size());
    const CGAL::Bbox_3 region = within.empty() ? CGAL::Bbox_3() : CGAL::Bbox_3(within.min.x, within.min.y, within.min.z, within.max.x, within.max.y, within.max.z);
    for (std::size_t f = 0; f < facets.size(); ++f) {
        const std::array<std::size_t, 3>& n = facets[f].node;
        if (CGAL::collinear(p[n[0]], p[n[1]], p[n[2]])) continue;  // no area: CGAL's tests need a plane
        const CGAL::Bbox_3 box = p[n[0]].bbox() + p[n[1]].bbox() + p[n[2]].bbox();
        if (within.empty() || CGAL::do_overlap(box, region)) boxes.emplace_back(box, f);
    }
    std::optional<TriangleCrossing> first;
    std::size_t pairs = 0;
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& x, const Box& y) {
        const Facet &s = facets[x.info()], &t = facets[y.info()];
        if (!trianglesCross(s.node, {p[s.node[0]], p[s.node[1]], p[s.node[2]]}, t.node, {p[t.node[0]], p[t.node[1]], p[t.node[2]]})) return;
        ++pairs;
        if (first) return;
        const Point3 &a = nodes[s.node[0]], &b = nodes[s.node[1]], &c = nodes[s.node[2]];
        first = TriangleCrossing{std::min(s.surface, t.surface), std::max(s.surface, t.surface), (1.0 / 3.0) * (a + b + c), x.info(), 0};
    });
    if (first) first->pairs = pairs;
    return first;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
