#include "core/triangle_crossings.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <array>

TOWGEOM_BEGIN_NAMESPACE
namespace detail {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;

struct Facet {
    std::array<std::size_t, 3> node;  // 0-based
    std::size_t surface;
};

/// Whether two triangles meet beyond what they share (see firstCrossing()).
bool cross(const Facet& s, const Facet& t, const std::vector<Kernel::Point_3>& p)
{
    int inT[3], shared = 0;  // inT[k]: the index in t of s's corner k, or -1
    for (int k = 0; k < 3; ++k) {
        inT[k] = -1;
        for (int l = 0; l < 3; ++l)
            if (s.node[k] == t.node[l]) inT[k] = l;
        shared += inT[k] >= 0;
    }
    const auto corner = [&](const Facet& f, int k) -> const Kernel::Point_3& { return p[f.node[(k % 3 + 3) % 3]]; };
    const Kernel::Triangle_3 ts(corner(s, 0), corner(s, 1), corner(s, 2)), tt(corner(t, 0), corner(t, 1), corner(t, 2));
    if (shared == 3) return false;
    if (shared == 0) return CGAL::do_intersect(ts, tt);
    if (shared == 2) {
        int ks = 0, kt = 0;  // the corners not shared
        while (inT[ks] >= 0) ++ks;
        const std::size_t a = s.node[(ks + 1) % 3], b = s.node[(ks + 2) % 3];
        while (t.node[kt] == a || t.node[kt] == b) ++kt;
        return CGAL::coplanar(p[a], p[b], corner(s, ks), corner(t, kt)) &&
               CGAL::coplanar_orientation(p[a], p[b], corner(s, ks), corner(t, kt)) == CGAL::POSITIVE;
    }
    int ks = 0;  // the shared corner
    while (inT[ks] < 0) ++ks;
    const int kt = inT[ks];
    return CGAL::do_intersect(Kernel::Segment_3(corner(s, ks + 1), corner(s, ks + 2)), tt) ||
           CGAL::do_intersect(Kernel::Segment_3(corner(t, kt + 1), corner(t, kt + 2)), ts);
}

}  // namespace

std::optional<TriangleCrossing> firstCrossing(const std::vector<Point3>& nodes, const std::vector<const std::vector<std::size_t>*>& surfaces)
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
    for (std::size_t f = 0; f < facets.size(); ++f)
        boxes.emplace_back(p[facets[f].node[0]].bbox() + p[facets[f].node[1]].bbox() + p[facets[f].node[2]].bbox(), f);
    std::optional<TriangleCrossing> first;
    std::size_t pairs = 0;
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& x, const Box& y) {
        const Facet &s = facets[x.info()], &t = facets[y.info()];
        if (!cross(s, t, p)) return;
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
