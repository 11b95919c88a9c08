// Faces of a tool shell joined side to side into one B-spline surface (a crease, C0, along each
// shared side), so that curves and geodesics run across them as across one face.
#pragma once

#include <Geom_BSplineSurface.hxx>

#include <string>
#include <vector>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// @p faces (each a face's surface over its whole (u,v) box, its normal out of the material;
/// @p names what to call them in errors) joined into one surface: starting from the first, each
/// next face is the one with a side that coincides with a side of the surface joined so far (9
/// places, within 1e-7 of their size, at the same fractions of both sides' parameters, either
/// way round; a side collapsed to a point never counts). Both are turned so that the side runs
/// along u (the surface so far at its v end, the face at its v start), made compatible (degrees
/// raised, each one's u knots inserted into the other, the face's weights scaled to agree along
/// the side), and the face's poles are appended beyond the side, whose knot gets multiplicity the
/// v degree (a crease). The face's v is scaled so that the rate across the side is the same on
/// both sides on average. A face whose side runs the other way round is turned over (the shell's
/// first face decides which side is out).
/// @throws towgeom::Error (InvalidArgument) naming a face that shares no whole side with the
///         surface joined before it, or whose poles along the shared side differ (parametrised
///         otherwise along it).
Handle(Geom_BSplineSurface) joinFaces(const std::vector<Handle(Geom_BSplineSurface)>& faces, const std::vector<std::string>& names);

}  // namespace detail
TOWGEOM_END_NAMESPACE
