/// @file reference_curve.hpp
/// @brief A fibre-placement course's reference curve on a NURBS surface: from points near the
/// surface, or as the surface's intersection with a plane (the 0° direction). A (u,v) polyline
/// is curveOnSurface().
#pragma once

#include <cstddef>
#include <vector>

#include "towgeom/nurbs_offset.hpp"
#include "towgeom/placement_surface.hpp"
#include "towgeom/point.hpp"
#include "towgeom/surface_offset_curves.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// @addtogroup placement
/// @{

/// The curve on @p surface through the nearest surface points of @p points, in their order
/// (OpenCASCADE's point projection).
/// @param surface the surface
/// @param points the curve's points, in order
/// @param maxDistance the farthest a point may lie from the surface, in your units; 0: 1e-3 x
///        the size of the surface's control net.
/// @throws towgeom::Error (InvalidArgument) for fewer than 2 points, a point farther than
///         @p maxDistance from the surface (the message gives its index and distance), or two
///         consecutive points with the same nearest surface point; (Internal) if OpenCASCADE
///         fails.
TOWGEOM_EXPORT CurveOnSurface referenceFromPoints(const NurbsSurface& surface, const std::vector<Point3>& points,
                                                  double maxDistance = 0.0);

/// The intersection of @p surface with the plane through @p origin of normal @p normal
/// (OpenCASCADE's surface-surface intersection), sampled at @p points points equally spaced
/// along its length, with their (u,v). Where the plane cuts the surface in several curves, the
/// one passing nearest @p origin. The curve runs the way OpenCASCADE returns it unless
/// @p reverse; the courses laid from it go to its left (see layCourses()).
/// @throws towgeom::Error (InvalidArgument) for a zero normal, fewer than 2 points, or a plane
///         that does not cut the surface; (Internal) if OpenCASCADE fails.
TOWGEOM_EXPORT CurveOnSurface referenceFromPlane(const NurbsSurface& surface, const Point3& origin, const Vector3& normal,
                                                 std::size_t points, bool reverse = false);

/// As the other overload, on the face @p tool: where it is trimmed (PlacementSurface::trim), the
/// run of the cut on the face passing nearest @p origin (its ends where the cut crosses the
/// face's trimming curves, bisected on the cut's parameter), sampled at @p points points equally
/// spaced along its length.
/// @throws towgeom::Error as the other overload; (InvalidArgument) also when the cut lies off
///         the face.
TOWGEOM_EXPORT CurveOnSurface referenceFromPlane(const PlacementSurface& tool, const Point3& origin, const Vector3& normal, std::size_t points,
                                                 bool reverse = false);

/// @}

TOWGEOM_END_NAMESPACE
