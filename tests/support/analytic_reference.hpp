// Exact (closed-form or quadrature-to-rounding) references for the tests, computed without any
// towgeom routine: the B-spline a circle's samples are fitted with, and the intersection curve,
// areas and overlap volume of two crossing circular tubes.
#pragma once

#include <cstddef>
#include <functional>

namespace towgeom::testing {

/// The integral of @p f over [a, b], where f may behave like sqrt(t - a) or 1 / sqrt(t - a) at
/// a (and likewise at b): the substitution t = a + (b - a)(1 - cos phi) / 2 makes the integrand
/// smooth and even at phi = 0 and pi, so the midpoint rule in phi converges faster than any power
/// of 1/n (rounding level at the default n).
double integrateEndpointSingular(const std::function<double(double)>& f, double a, double b, int n = 4000);

/// A uniform periodic cubic B-spline whose n control points lie equally spaced on a circle of
/// radius controlRadius: its enclosed area and perimeter (Gauss quadrature with the test's own
/// basis functions) and its distance from the centre at the middle of a span (the least).
struct BSplineCircle {
    double area = 0.0, perimeter = 0.0, midRadius = 0.0;
};
BSplineCircle uniformBSplineCircle(std::size_t n, double controlRadius);

/// The control radius of the periodic cubic B-spline that interpolates n equally spaced points
/// of a circle of radius r with uniform parameters: (P[j-1] + 4 P[j] + P[j+1]) / 6 = sample, so
/// r 6 / (4 + 2 cos(2 pi / n)).
double interpolatingControlRadius(std::size_t n, double r);

/// Two crossing circular cylinders: X of radius R about the x axis, Y of radius r parallel to
/// the y axis, its axis at height d (and any x). Valid when Y dips into the top of X without
/// passing through it: R - r < d < R + r and d - r > -R (one closed intersection loop).
struct CrossingCylinders {
    double R, r, d;
    double loopLength() const;     ///< length of the intersection curve
    double areaOnX() const;        ///< area of X inside Y
    double areaOnY() const;        ///< area of Y inside X
    double overlapVolume() const;  ///< volume inside both
};

/// A straight bar (radius b, along x, axis at y = barY, z = barZ) dipping into the top of a
/// tube of radius a whose centre line is a circle of radius ringRadius about the z axis (the
/// torus (sqrt(x^2 + y^2) - ringRadius)^2 + z^2 = a^2): the loop at x > 0 (the one at x < 0 is
/// its mirror image). Valid when barZ - b < a < barZ + b (the bar's bottom dips into the ring's
/// top and no deeper than its centre line's height).
struct RingBarLoop {
    double length = 0.0, xMin = 0.0, xMax = 0.0;
};
RingBarLoop ringBarLoop(double ringRadius, double a, double barY, double barZ, double b);

}  // namespace towgeom::testing
