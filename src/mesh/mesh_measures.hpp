// Volumes of triangle meshes over a global node list, without copying them (the resolve
// reports' figures). The meshes are closed by construction, so no check is made here; the
// public enclosedVolume() checks and measures any TriangleMesh with CGAL.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "towgeom/point.hpp"

namespace towgeom::detail {

/// The signed volume bounded by @p triangles (a closed surface; outward orientation gives a
/// positive volume), by the divergence theorem.
double signedVolume(const std::vector<Point3>& nodes, const std::vector<std::array<std::size_t, 3>>& triangles);

/// The signed volume of @p triangles with every boundary loop closed by a fan around its
/// centroid (as closedSurface() does); @p loopCount, if given, gets the number of loops.
double closedVolume(const std::vector<Point3>& nodes, const std::vector<std::array<std::size_t, 3>>& triangles,
                    std::size_t* loopCount = nullptr);

}  // namespace towgeom::detail
