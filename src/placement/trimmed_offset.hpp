// A curve on a tool surface offset along it, ending at the surface's boundary: offsets that
// leave the surface are cut where the offset meets the boundary, and a curve whose base runs to
// the boundary is carried on to it.
#pragma once

#include <Geom_BSplineSurface.hxx>

#include <string>
#include <vector>

#include "placement/tool_face.hpp"
#include "towgeom/surface_offset_curves.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// An offset curve kept on the surface.
struct TrimmedOffset {
    CurveOnSurface curve;  ///< its points (none if every offset left the surface)
    std::vector<double> geodesicDistance;  ///< per point, the true distance from its base point (NaN where extended)
    std::vector<double> estimatedError;    ///< per point, Schueler's estimate (NaN where extended)
    /// The side of the face (a side of the parameter box, "u_min", "u_max", "v_min", "v_max", or a
    /// trimmed face's "edge K"; see faceSide()) where the curve's start was cut or carried to,
    /// empty where it starts as its base does.
    std::string startSide;
    std::string endSide;  ///< likewise for its end
};

/// @p base (on @p f's surface) offset by @p d point by point (offsetPoint()). Where
/// offsets leave the face (its box, or a trimmed face's curves: onFace()), the longest run of points that stay on it is kept, and each of its
/// ends that the surface cut is completed by the offset of the base point (on the base's (u,v)
/// cubic interpolation) whose offset lands on the boundary (bisection to 1e-15 of the base's
/// parameter). Where the base ends on a side of the face (within 1e-9 of it) and its offset ends
/// inside, the offset is carried on along its end direction by a geodesic to the boundary. A
/// closed base all of whose offsets stay on the surface gives a closed curve.
/// @throws towgeom::Error (InvalidArgument) for a singular point met on the way.
TrimmedOffset offsetWithinSurface(const ToolFace& f, const CurveOnSurface& base, double d, const SurfaceOffsetOptions& options);

/// @p c's longest run of points on the face @p f, each end that the face's boundary cut ended
/// where the curve's (u,v) cubic crosses it (as offsetWithinSurface() with d = 0: a trimmed
/// face's holes between two points found by probing); @p c itself where it lies on the face
/// (always on an untrimmed face); empty where it lies off.
CurveOnSurface trimToFace(const ToolFace& f, const CurveOnSurface& c);

/// The length along the surface of the curve through @p c's points (its (u,v) cubic
/// interpolation, integrated by OpenCASCADE); 0 for fewer than 2 points.
double lengthOnSurface(const Handle(Geom_BSplineSurface)& s, const CurveOnSurface& c);

}  // namespace detail
TOWGEOM_END_NAMESPACE
