// The element size meshVolumes() asks Gmsh for inside the volumes: the surface mesh's own size
// at its nodes, growing linearly with the distance from them up to a largest size.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// h(x) = min over surface nodes i of min(h_i + slope * |x - p_i|, max(largest, h_i)), where h_i
/// is the mean length of the surface edges at node i: a size that equals the surface mesh's at
/// the surface, changes by at most @p slope per unit length (neighbouring layers of tetrahedra
/// differ in size by a factor of about 1 + slope) and grows to the largest size but is never
/// made smaller than the surface's own by it.
/// Tabulated on a regular grid at the median surface edge length (coarsened in steps of 1.25
/// while it would exceed the node budget), each grid node's source found by two raster sweeps
/// (each node taking the best of its neighbours' sources: an upper bound of the exact value,
/// found exact on the tests' sheets) and read by trilinear interpolation, O(1) a point.
class GradedSize {
public:
    /// @p nodes and @p triangles the surface mesh (triangles index nodes; nodes no triangle uses
    /// are ignored); @p slope >= 0; @p largest > 0, or -f: f times the median surface size; at most @p gridNodes grid nodes.
    GradedSize(const std::vector<Point3>& nodes, const std::vector<std::array<std::size_t, 3>>& triangles, double slope, double largest,
               std::size_t gridNodes = std::size_t(1) << 21);

    /// The size at @p x (outside the grid: at the nearest grid point plus the slope times the
    /// distance to it).
    double operator()(const Point3& x) const;

    /// The median of the surface nodes' sizes h_i (0 with no triangles).
    double medianSurfaceSize() const { return median_; }
    /// The largest size (@p largest, or the median's multiple it asked for).
    double largest() const { return largest_; }

private:
    std::size_t at(std::size_t i, std::size_t j, std::size_t k) const { return (k * n_[1] + j) * n_[0] + i; }
    Point3 gridPoint(std::size_t i, std::size_t j, std::size_t k) const;

    double slope_, largest_, median_ = 0.0, spacing_ = 1.0;
    double cap_ = 0.0;  // max(largest, the largest node size): no size above it
    Point3 origin_{};
    std::array<std::size_t, 3> n_{0, 0, 0};
    std::vector<float> size_;  // per grid node
};

}  // namespace detail
TOWGEOM_END_NAMESPACE
