#include "region/connected_region.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <cmath>

namespace towgeom::detail {

std::vector<std::size_t> trianglesInside(const ParametricMesh& mesh, const std::vector<UV>& polygon, double period)
{
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    std::vector<K::Point_2> poly;
    double vLo = 1e300, vHi = -1e300, uLo = 1e300, uHi = -1e300;
    for (const UV& p : polygon) {
        poly.emplace_back(p.u, p.v);
        vLo = std::min(vLo, p.v);
        vHi = std::max(vHi, p.v);
        uLo = std::min(uLo, p.u);
        uHi = std::max(uHi, p.u);
    }
    std::vector<std::size_t> inside;
    if (poly.size() < 3) return inside;
    for (std::size_t t = 0; t < mesh.centroids.size(); ++t) {
        const UV c = mesh.centroids[t];
        if (c.u < uLo || c.u > uHi) continue;  // outside the loop's box: no exact test needed
        // The copy of the centroid, one period over or not, that can lie in the loop's v range.
        const double shift = period * std::floor((c.v - vLo) / period);
        for (const double v : {c.v - shift, c.v - shift + period}) {
            if (v < vLo || v > vHi) continue;
            if (CGAL::bounded_side_2(poly.begin(), poly.end(), K::Point_2(c.u, v), K()) == CGAL::ON_BOUNDED_SIDE) {
                inside.push_back(t);
                break;
            }
        }
    }
    return inside;
}

}  // namespace towgeom::detail
