// NURBS shapes with closed forms for the fibre-placement tests: a rational circle, a cylinder
// built on it, a bicubic saddle.
#pragma once

#include <towgeom/nurbs_offset.hpp>

namespace towgeom::testing {

/// The full circle of radius @p r about (@p cx, @p cy) in the plane z = @p z, counter-clockwise
/// seen from +z: the rational quadratic of 9 poles (the corners of the square and the middles of
/// its sides), parameter in [0, 1].
NurbsCurve circle(double r, double cx, double cy, double z);

/// A cylinder of radius @p r about the z axis from z = 0 to @p length: u around (the circle),
/// v along (degree 1). Its normal dS/du x dS/dv points outward.
NurbsSurface cylinder(double r, double length);

/// A cone's frustum about the z axis, radius @p r0 at z = 0 and @p r1 at z = @p height (the
/// rational circle's poles at both heights, degree 1 between: each generator straight): u
/// around, v along.
NurbsSurface cone(double r0, double r1, double height);

/// A bicubic saddle z = 0.3 (x^2 - y^2) over [-1, 1]^2 (poles on a 5 x 5 grid, not rational).
NurbsSurface saddle();

}  // namespace towgeom::testing
