// The normalised frame: the kernel computes with coordinates of about unit size, whatever the
// user's units, so that its absolute tolerances (OCCT's Precision::Confusion(), the walking
// deflection) mean the same thing at every scale.
#pragma once

#include <gp_Trsf.hxx>

#include <cmath>

#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// A similarity x -> (x - origin) * scale with scale a power of two, so that lengths, areas and
/// volumes go back to the user's units exactly (a division by scale, scale^2, scale^3).
struct Frame {
    Point3 origin;       ///< the user-space point that becomes the frame's origin
    double scale = 1.0;  ///< a power of two

    /// The frame that puts @p box's centre at the origin and gives @p size about unit length.
    static Frame around(const BoundingBox& box, double size)
    {
        Frame f;
        if (!box.empty()) f.origin = 0.5 * (box.min + box.max);
        if (size > 0.0 && std::isfinite(size)) f.scale = std::ldexp(1.0, -std::ilogb(size));
        return f;
    }

    Point3 toFrame(const Point3& p) const { return scale * (p - origin); }
    Point3 toUser(const Point3& p) const { return origin + (1.0 / scale) * p; }
    double lengthToFrame(double l) const { return l * scale; }
    double lengthToUser(double l) const { return l / scale; }
    /// The kernel transformation user -> frame.
    gp_Trsf trsf() const
    {
        gp_Trsf move, grow;
        move.SetTranslation(gp_Vec(-origin.x, -origin.y, -origin.z));
        grow.SetScale(gp_Pnt(0, 0, 0), scale);
        return grow * move;
    }
};

}  // namespace detail
TOWGEOM_END_NAMESPACE
