/// @file point.hpp
/// @brief Plain value types for points and vectors in 3D and in a surface's (u,v) space.
#pragma once

#include <cmath>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// A point or vector in 3D, in the user's units.
struct Point3 {
    double x = 0.0;  ///< x coordinate
    double y = 0.0;  ///< y coordinate
    double z = 0.0;  ///< z coordinate
};

/// A vector in 3D; the same layout as Point3, named for readability.
using Vector3 = Point3;

/// A point in a plane, e.g. in a cross-section's own coordinates.
struct Point2 {
    double x = 0.0;  ///< first coordinate
    double y = 0.0;  ///< second coordinate
};

/// A point in a surface's parameter space: u along the tow, v around it.
struct UV {
    double u = 0.0;  ///< parameter along the tow
    double v = 0.0;  ///< parameter around the tow (periodic)
};

/// Component-wise sum.
inline Point3 operator+(const Point3& a, const Point3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
/// Component-wise difference.
inline Point3 operator-(const Point3& a, const Point3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
/// Scaling by a scalar.
inline Point3 operator*(double s, const Point3& a) { return {s * a.x, s * a.y, s * a.z}; }
/// Dot product.
inline double dot(const Vector3& a, const Vector3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
/// Cross product.
inline Vector3 cross(const Vector3& a, const Vector3& b)
{
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
/// Euclidean length.
inline double norm(const Vector3& a) { return std::sqrt(dot(a, a)); }
/// Euclidean distance.
inline double distance(const Point3& a, const Point3& b) { return norm(a - b); }

/// An axis-aligned box; empty() until a point has been added.
struct BoundingBox {
    Point3 min{1e300, 1e300, 1e300};     ///< lower corner
    Point3 max{-1e300, -1e300, -1e300};  ///< upper corner

    /// True when no point has been added.
    bool empty() const { return min.x > max.x; }
    /// Grows the box to hold @p p.
    void add(const Point3& p)
    {
        min = {std::fmin(min.x, p.x), std::fmin(min.y, p.y), std::fmin(min.z, p.z)};
        max = {std::fmax(max.x, p.x), std::fmax(max.y, p.y), std::fmax(max.z, p.z)};
    }
    /// Length of the diagonal; 0 for an empty box.
    double diagonal() const { return empty() ? 0.0 : distance(min, max); }
    /// True when the two boxes share at least one point.
    bool overlaps(const BoundingBox& o) const
    {
        return !(empty() || o.empty() || max.x < o.min.x || o.max.x < min.x || max.y < o.min.y ||
                 o.max.y < min.y || max.z < o.min.z || o.max.z < min.z);
    }
};

TOWGEOM_END_NAMESPACE
