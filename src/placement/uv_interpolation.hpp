// Cubic B-splines in a surface's (u,v) through points (OpenCASCADE's Geom2dAPI_Interpolate).
#pragma once

#include <Geom2d_BSplineCurve.hxx>

#include <vector>

#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// The cubic B-spline through @p uv at the increasing parameters @p params (as many), or null
/// when OpenCASCADE cannot interpolate them (points closer than 1e-14: repeated).
Handle(Geom2d_BSplineCurve) interpolateUV(const std::vector<UV>& uv, const std::vector<double>& params);

}  // namespace detail
TOWGEOM_END_NAMESPACE
