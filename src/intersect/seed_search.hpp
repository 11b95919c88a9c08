// Start points for the surface-surface walk: the two surfaces sampled on their section grids
// within a window pair, and CGAL's exact triangle-triangle tests between the two faceted
// windows. Every crossing of the facets gives a guess of a point on an intersection curve.
#pragma once

#include <cstddef>
#include <vector>

#include "intersect/broad_phase.hpp"
#include "intersect/intersection_point.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// A surface sampled at its sections' u and its points' v (subdivided where the input is
/// coarse): the vertices of its facets, each exactly on the surface with known (u, v).
struct SurfaceGrid {
    std::vector<double> u;       ///< M stations
    std::vector<double> v;       ///< N stations around; the facet after the last wraps to v[0] + period
    std::vector<Point3> points;  ///< M x N, row i = station u[i]
    double period = 1.0;
};

/// The grid of @p tow: its sections' and points' parameters, subdivided where coarse.
SurfaceGrid sampleGrid(const TowSurface& tow);

/// A guess of a point on an intersection curve, with the size of the smaller facet it came from.
struct Seed {
    PointOn2 guess;
    double facetSize = 0.0;  ///< the longest edge of the smaller of the two facets
};

/// Guesses where the facets of @p a within @p window.a cross those of @p b within @p window.b,
/// one per crossing facet pair, in a deterministic order.
std::vector<Seed> findSeeds(const SurfaceGrid& a, const SurfaceGrid& b, const WindowPair& window);

}  // namespace detail
TOWGEOM_END_NAMESPACE
