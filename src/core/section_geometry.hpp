// Small geometric helpers on one cross-section polygon, shared by validation and fitting.
#pragma once

#include <vector>

#include "towgeom/point.hpp"

namespace towgeom::detail {

/// Mean of the polygon's vertices.
inline Point3 vertexCentroid(const std::vector<Point3>& poly)
{
    Point3 c;
    for (const Point3& p : poly) c = c + p;
    return (1.0 / static_cast<double>(poly.size())) * c;
}

/// The vector area (1/2) sum p_i x p_{i+1} of the closed polygon, taken about its centroid.
inline Vector3 vectorArea(const std::vector<Point3>& poly)
{
    const Point3 c = vertexCentroid(poly);
    Vector3 a;
    for (std::size_t i = 0; i < poly.size(); ++i)
        a = a + cross(poly[i] - c, poly[(i + 1) % poly.size()] - c);
    return 0.5 * a;
}

/// Perimeter of the closed polygon.
inline double perimeter(const std::vector<Point3>& poly)
{
    double l = 0.0;
    for (std::size_t i = 0; i < poly.size(); ++i) l += distance(poly[i], poly[(i + 1) % poly.size()]);
    return l;
}

/// Bounding-box diagonal of the polygon.
inline double extent(const std::vector<Point3>& poly)
{
    BoundingBox b;
    for (const Point3& p : poly) b.add(p);
    return b.diagonal();
}

}  // namespace towgeom::detail
