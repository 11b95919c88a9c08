// Geodesics on a NURBS surface (OCCT's exact derivatives): the local frame, the geodesic
// equation integrated by adaptive RK4, shooting to a target, the normal curvature along a direction.
#pragma once

#include <Geom_BSplineSurface.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include <array>
#include <string>

#include "towgeom/error.hpp"
#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// What a geodesic or an offset throws when it leaves the surface's box (where it is not
/// periodic): the one failure trimming at the boundary takes as the surface's end.
class OffSurface : public Error {
public:
    using Error::Error;
};

/// A surface's point, first derivatives and unit normal at a parameter.
struct SurfaceFrame {
    gp_Pnt p;
    gp_Vec su, sv, n;  ///< n: unit normal
};

/// The frame at (@p u, @p v). @throws towgeom::Error (InvalidArgument) where the normal vanishes.
SurfaceFrame frameAt(const Handle(Geom_BSplineSurface)& s, double u, double v);

/// (du, dv) with S_u du + S_v dv the tangent-plane part of @p t. @throws towgeom::Error
/// (InvalidArgument) where the parametrisation is singular.
std::array<double, 2> parameterRates(const SurfaceFrame& f, const gp_Vec& t);

/// Whether (@p u, @p v) lies in the surface's parameter box (any value in a periodic direction:
/// see toolSurface()).
bool insideParameters(const Handle(Geom_BSplineSurface)& s, double u, double v);

/// The end of the geodesic of length @p length from @p from in the 3D tangent direction @p t
/// (adaptive RK4, at most length / @p steps per step). It crosses a periodic surface's seam (the
/// parameters run on past the box: the end is not wrapped back). Along the box's edge it may end
/// up to 1e-6 of the box outside it (not clamped: callers clamp what they keep).
/// @throws towgeom::Error (InvalidArgument) when it leaves the box by more, or meets a singular
/// point (a pole named with its place).
UV shootGeodesic(const Handle(Geom_BSplineSurface)& s, const UV& from, const gp_Vec& t, double length, int steps);

/// Names the singular point of @p s's parametrisation at (@p u, @p v) (a pole: a side of the box
/// that is one point) with its position, for messages.
std::string singularPlace(const Handle(Geom_BSplineSurface)& s, double u, double v);

/// The normal curvature of @p s at (@p u, @p v) along the tangent direction @p t.
double normalCurvature(const Handle(Geom_BSplineSurface)& s, double u, double v, const gp_Vec& t);

/// The length of the geodesic from @p from to @p to (see towgeom::geodesicDistance()).
/// With @p direction (a 3D tangent at @p from, not null) and @p length, Newton's method starts from
/// that geodesic instead of the chord's (one shot when it already ends at @p to).
double geodesicDistanceOn(const Handle(Geom_BSplineSurface)& s, const UV& from, const UV& to, int steps, const gp_Vec* direction = nullptr,
                          double length = 0.0);

}  // namespace detail
TOWGEOM_END_NAMESPACE
