// The mesh size that follows a tow surface's curvature: where the largest principal curvature
// is k, an edge of length s stands off the surface by about s^2 k / 8, so the size that keeps
// that chord deviation under d is sqrt(8 d / k), taken within [smallest, largest] and graded
// (it grows by at most `slope` per unit length over the surface). Sampled once on a (u,v) grid
// and interpolated: the mesher asks for it at every face it tests.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "towgeom/mesh_options.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

class CurvatureSize {
public:
    /// Samples @p surface (lengths in its units) on a grid fine enough for sizes down to
    /// @p smallest across the tow and @p largest / 2 along it.
    CurvatureSize(const TowSurface& surface, double deviation, double largest, double smallest, double slope = 1.0);

    /// The size at (u,v) (v wrapped into the period, u clamped to the range).
    double at(const UV& p) const;

    /// The mean of (largest / size)^2 over the surface's area: how many times more triangles
    /// the graded mesh has than one at the largest size everywhere.
    double densityOverLargest() const { return density_; }

private:
    double& node(std::size_t i, std::size_t j) { return size_[i * nv_ + j]; }
    double node(std::size_t i, std::size_t j) const { return size_[i * nv_ + j]; }
    void grade(const std::vector<Point3>& points, double slope);

    ParameterRange range_;
    std::size_t nu_ = 2, nv_ = 4;  ///< grid nodes along u (ends included) and around v (period)
    std::vector<double> size_;     ///< (i, j) at i * nv_ + j
    double density_ = 1.0;
};

/// The largest absolute principal curvature where a surface's derivatives are @p d (from its
/// fundamental forms: |H| + sqrt(H^2 - K)), or 0 where it is singular.
double largestCurvature(const SurfaceSecondDerivatives& d);

/// The size field @p mesh asks for on @p tow meshed at @p h (its chord deviation and smallest
/// size, absolute or relative to the tow's size), or null when it grades nothing.
std::shared_ptr<const CurvatureSize> curvatureSizeFor(const TowSurface& tow, const MeshOptions& mesh, double h);

}  // namespace detail
TOWGEOM_END_NAMESPACE
