// Conversions between towgeom's plain value types and OCCT's.
#pragma once

#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

inline gp_Pnt toOcct(const Point3& p) { return {p.x, p.y, p.z}; }
inline Point3 fromOcct(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }
inline Vector3 fromOcct(const gp_Vec& v) { return {v.X(), v.Y(), v.Z()}; }

}  // namespace detail
TOWGEOM_END_NAMESPACE
