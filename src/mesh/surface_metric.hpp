// The first fundamental form of a tow surface over the mesher's scaled parameter space,
// sampled on a grid and interpolated: how long a short (x,y) step is in 3D. The mesher measures
// edge lengths with it, so the size asked for is met in 3D wherever the surface's speed along or
// around the tow differs from the mean the scaling assumes.
#pragma once

#include <cstddef>
#include <vector>

#include "mesh/scaled_space.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

class SurfaceMetric {
public:
    /// Samples @p surface on a grid of about @p spacing over the rectangle [0, lx] x [0, ly] of
    /// @p space.
    SurfaceMetric(const TowSurface& surface, const ScaledSpace& space, double lx, double ly, double spacing);

    /// The metric at (x, y): the squared 3D length of (dx, dy) is e dx^2 + 2 f dx dy + g dy^2
    /// (interpolated bilinearly; points outside the rectangle use its nearest side).
    struct Form {
        double e = 0.0, f = 0.0, g = 0.0;  ///< |S_x|^2, S_x . S_y, |S_y|^2
    };
    Form at(double x, double y) const;

    /// The squared 3D length of the step (dx, dy) taken at (x, y), by the metric there.
    double squaredLength(double x, double y, double dx, double dy) const;

private:
    std::size_t nx_ = 2, ny_ = 2;
    double cellX_ = 1.0, cellY_ = 1.0;
    std::vector<Form> forms_;  ///< (i, j) at i * ny_ + j
};

}  // namespace detail
TOWGEOM_END_NAMESPACE
