// Cubic B-splines in a surface's (u,v) through points (OpenCASCADE's Geom2dAPI_Interpolate).
#pragma once

#include <Geom2d_BSplineCurve.hxx>

#include <utility>
#include <vector>

#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// The cubic B-spline through @p uv at the increasing parameters @p params (as many), or null
/// when OpenCASCADE cannot interpolate them (points closer than 1e-14: repeated).
Handle(Geom2d_BSplineCurve) interpolateUV(const std::vector<UV>& uv, const std::vector<double>& params);

/// The (u,v) chord lengths of @p uv from its first point: interpolateUV()'s usual parameters.
std::vector<double> chordParameters(const std::vector<UV>& uv);

/// Signed distance in (u,v) of @p p from the curve @p c (positive to its left), from its nearest
/// point (OpenCASCADE's projection, or an end), and whether that point lies within the curve (an
/// orthogonal foot short of either end).
std::pair<double, bool> sideOfCurve(const Handle(Geom2d_BSplineCurve)& c, const UV& p);

}  // namespace detail
TOWGEOM_END_NAMESPACE
