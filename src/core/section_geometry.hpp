// Small geometric helpers on one cross-section polygon, shared by validation and fitting.
#pragma once

#include <cmath>
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

/// The largest coordinate magnitude a stack may hold, and the smallest extent of a section:
/// within these a tow's volume (about size^3) and area stay finite and normal in double
/// precision, whatever the units.
constexpr double kMaxCoordinate = 1e100;
constexpr double kMinSectionExtent = 1e-100;

/// A unit vector along @p v (zero for a zero vector), scaled first so that components near
/// 1e100 cannot overflow.
inline Vector3 unitVector(const Vector3& v)
{
    const double big = std::fmax(std::fabs(v.x), std::fmax(std::fabs(v.y), std::fabs(v.z)));
    if (!(big > 0.0)) return {};
    const Vector3 w = (1.0 / big) * v;
    return (1.0 / norm(w)) * w;
}

/// The cosine between the vector area of section @p i and the tow's local direction there
/// (from the previous to the next section's centroid, one-sided at the ends): positive when the
/// section goes counter-clockwise about the tow, near 0 when it lies along the tow.
inline double localOrientation(const std::vector<std::vector<Point3>>& sections, std::size_t i)
{
    const std::size_t m = sections.size();
    const Vector3 along = vertexCentroid(sections[i + 1 < m ? i + 1 : m - 1]) - vertexCentroid(sections[i == 0 ? 0 : i - 1]);
    return dot(unitVector(vectorArea(sections[i])), unitVector(along));
}

}  // namespace towgeom::detail
