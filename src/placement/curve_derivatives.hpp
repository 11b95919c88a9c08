// A curve on a tool surface, given by points, as a smooth curve: its (u,v) cubic interpolation
// (across the joint of a closed curve), its 3D derivatives and its geodesic curvature.
#pragma once

#include <Geom_BSplineSurface.hxx>
#include <gp_Vec.hxx>

#include <vector>

#include "towgeom/surface_offset_curves.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// Whether @p c is closed: its last point is its first (to 1e-12 of its extent).
bool isClosed(const CurveOnSurface& c);

/// The first and second derivatives of C(t) = S(u(t), v(t)) at each point of @p c, (u(t), v(t))
/// the cubic interpolating its (u,v) at their chord lengths (OpenCASCADE). A closed curve is
/// interpolated with three points either side of its joint carried over by the period it
/// spans (its last (u,v) less its first), so its ends are as smooth as the rest.
struct CurveDerivatives {
    std::vector<gp_Vec> first;   ///< dC/dt per point
    std::vector<gp_Vec> second;  ///< d2C/dt2 per point
};

/// See CurveDerivatives. Empty when the points cannot be interpolated (repeated); for fewer than
/// 3 points the chord, second derivatives 0.
CurveDerivatives curveDerivatives(const Handle(Geom_BSplineSurface)& s, const CurveOnSurface& c);

/// The 3D direction of @p c at each point (curveDerivatives(), or the chord between a point's
/// neighbours where those cannot be had).
std::vector<gp_Vec> curveTangents(const Handle(Geom_BSplineSurface)& s, const CurveOnSurface& c);

/// The geodesic curvature of @p c at each point, (C' x C'') . N / |C'|^3: positive where it
/// turns to its left (towards N x T), its inverse the steering radius a head must follow.
std::vector<double> geodesicCurvatures(const Handle(Geom_BSplineSurface)& s, const CurveOnSurface& c);

}  // namespace detail
TOWGEOM_END_NAMESPACE
