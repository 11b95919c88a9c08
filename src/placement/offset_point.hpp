// One point of a curve on a surface offset along the surface (Schueler's tangent step or a
// geodesic), the building block of offsetOnSurface() and of courses trimmed at the boundary.
#pragma once

#include <Geom_BSplineSurface.hxx>
#include <gp_Vec.hxx>

#include <cstddef>
#include <vector>

#include "towgeom/surface_offset_curves.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// Where a point offset along the surface lands.
struct OffsetPoint {
    UV uv;    ///< its parameters, clamped into the box where not periodic (a seam crossed: past it)
    UV raw;   ///< the parameters as reached (may lie up to 1e-6 of the box outside it)
    double geodesicDistance = 0.0;  ///< the true distance along the surface from the start
    double estimatedError = 0.0;    ///< Schueler's Eq. 2 estimate
};

/// The point @p at (on @p s, see toolSurface()) offset by @p d along O = N x @p tangent (a 3D
/// direction along the curve) by @p options.method. @throws towgeom::Error (InvalidArgument) when
/// the offset leaves the surface or meets a singular point. Without @p measure the true
/// distance is not measured (geodesicDistance NaN; for a tangent step, its foot is only checked
/// to be orthogonal): a cheap test of where the offset lands.
OffsetPoint offsetPoint(const Handle(Geom_BSplineSurface)& s, const UV& at, const gp_Vec& tangent, double d, const SurfaceOffsetOptions& options,
                        bool measure = true);

}  // namespace detail
TOWGEOM_END_NAMESPACE
