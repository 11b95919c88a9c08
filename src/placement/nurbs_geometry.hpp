// NurbsCurve and NurbsSurface to and from OpenCASCADE's B-splines (validated on the way in).
#pragma once

#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>

#include "towgeom/nurbs_offset.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// @p c as an OCCT curve. @throws towgeom::Error (InvalidArgument) for an ill-formed curve.
Handle(Geom_BSplineCurve) occtCurve(const NurbsCurve& c);
/// @p g as a NurbsCurve (full knot vector).
NurbsCurve nurbsCurve(const Handle(Geom_BSplineCurve)& g);
/// @p s as an OCCT surface. @throws towgeom::Error (InvalidArgument) for an ill-formed surface.
Handle(Geom_BSplineSurface) occtSurface(const NurbsSurface& s);
/// @p g as a NurbsSurface (full knot vectors).
NurbsSurface nurbsSurface(const Handle(Geom_BSplineSurface)& g);

}  // namespace detail
TOWGEOM_END_NAMESPACE
