// The distance from a point to a segment in 3D (loop tracing, triple points).
#pragma once

#include <algorithm>

#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// The distance from @p p to the segment [a, b].
inline double segmentDistance(const Point3& p, const Point3& a, const Point3& b)
{
    const Vector3 ab = b - a;
    const double l2 = dot(ab, ab);
    const double t = l2 > 0.0 ? std::clamp(dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
    return distance(p, a + t * ab);
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
