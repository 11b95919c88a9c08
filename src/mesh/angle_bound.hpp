// The smallest angle the mesher asks of a triangle on a tow's surface, against the bound it keeps
// in the plane the tow is meshed in.
#pragma once

#include <algorithm>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// The smallest angle a face must keep on the surface (by the metric), as a share of the
/// plane's bound. At the plane's own bound, refinement in the plane (by circumcentres) does not
/// converge on the metric's shape wherever the two differ a little: a face a hair over the
/// bound in the plane may be a hair under on the surface, and so on at every scale (a tow
/// stretched 1.5 times across refined to a fourteenth of the mesh size). With 3/4 of it, a
/// plane good to 20 degrees keeps 15 on the surface wherever the metric stretches by less than
/// 1.36, and the test refines only where it stretches more.
inline constexpr double kMetricShare = 0.75;

/// The smallest angle (degrees) asked of a triangle on the surface for MeshOptions::minAngle
/// @p minAngle (degrees, taken within [1, 30] as the mesher does): MeshQuality::angleBound.
inline double surfaceAngleBound(double minAngle)
{
    return kMetricShare * std::clamp(minAngle, 1.0, 30.0);
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
