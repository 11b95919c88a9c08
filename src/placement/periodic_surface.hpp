// A tool surface as OpenCASCADE evaluates it for placement: periodic in each direction in which
// it closes smoothly (a cylinder's, sphere's or torus's angle), so that curves and geodesics
// run across the seam; the box's edges elsewhere are the surface's boundary.
#pragma once

#include <Geom_BSplineSurface.hxx>

#include <string>

#include "towgeom/nurbs_offset.hpp"
#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// @p surface as OpenCASCADE's B-spline, made periodic (SetUPeriodic / SetVPeriodic) in each
/// direction in which its two end rows of points coincide and its first derivative across them
/// is the same on both sides (to 1e-9 of its size and 1e-7 of the derivative): there (u,v) may
/// run past the box by whole periods and mean the same point. Elsewhere the box is the surface.
/// @throws towgeom::Error (InvalidArgument) for an ill-formed surface.
Handle(Geom_BSplineSurface) toolSurface(const NurbsSurface& surface);

/// The diagonal of the box of @p s's poles (its size; corners may all coincide, as a torus's do).
double poleBoxSize(const Handle(Geom_BSplineSurface)& s);

/// @p uv moved by whole periods (in each periodic direction) to lie nearest @p near.
UV nearestCopy(const Handle(Geom_BSplineSurface)& s, UV uv, const UV& near);

/// Whether @p uv lies in @p s's parameter box in every direction that is not periodic.
bool onSurface(const Handle(Geom_BSplineSurface)& s, const UV& uv);

/// The side of the box (not periodic) that @p uv lies on within @p tolerance of the box's size:
/// "u_min", "u_max", "v_min" or "v_max", or empty if none.
std::string boundarySide(const Handle(Geom_BSplineSurface)& s, const UV& uv, double tolerance);

/// @p uv moved onto the side @p side of the box (see boundarySide()).
UV onSide(const Handle(Geom_BSplineSurface)& s, UV uv, const std::string& side);

}  // namespace detail
TOWGEOM_END_NAMESPACE
