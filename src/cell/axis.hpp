// A cell face's axis and side, and a point's coordinate along an axis (0 x, 1 y, 2 z).
#pragma once

#include "towgeom/cell.hpp"
#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

inline int axisOf(CellFace f) { return static_cast<int>(f) / 2; }
inline bool isMaxFace(CellFace f) { return static_cast<int>(f) % 2 == 1; }
inline double coord(const Point3& p, int a) { return a == 0 ? p.x : a == 1 ? p.y : p.z; }
inline double& coord(Point3& p, int a) { return a == 0 ? p.x : a == 1 ? p.y : p.z; }

}  // namespace detail
TOWGEOM_END_NAMESPACE
