// The points a tow's triangulation starts from, before Delaunay refinement: they already make
// triangles of the size and shape asked for, so refinement works only where they cannot.
#pragma once

#include <vector>

#include "mesh/mesh_cdt.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail::mesh2 {

/// Inserts into @p cdt (its constraints already in, the rectangle [x0,x1] x [0,ly]):
/// - along every loop chord of @p chords (polylines, closed ones closed), the apexes on both
///   sides of the triangle on it that is equilateral in 3D (by @p metric), or isosceles with
///   sides 0.97 h when the chord is nearly h long already;
/// - a hexagonal lattice of spacing h, kept 0.7 h away from the constraints and 0.6 h from the
///   apexes.
/// Points that would encroach on a constrained edge (the mesher would split it), or crowd one
/// another, are left out.
void insertStartingPoints(CDT& cdt, const std::vector<std::vector<K::Point_2>>& chords, const SurfaceMetric& metric,
                          double x0, double x1, double ly, double h);

}  // namespace detail::mesh2
TOWGEOM_END_NAMESPACE
