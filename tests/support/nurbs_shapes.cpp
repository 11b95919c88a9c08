// NURBS shapes with closed forms (see nurbs_shapes.hpp).
#include "nurbs_shapes.hpp"

#include <cmath>
#include <utility>

namespace towgeom::testing {

/// The full circle of radius @p r about (@p cx, @p cy) in the plane z = @p z, counter-clockwise
/// seen from +z: the rational quadratic of 9 poles (the corners of the square and the middles of
/// its sides), parameter in [0, 1].
NurbsCurve circle(double r, double cx, double cy, double z)
{
    NurbsCurve c;
    c.degree = 2;
    c.knots = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
    const double h = std::sqrt(0.5);
    const double px[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, py[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
    for (int k = 0; k < 9; ++k) {
        c.poles.push_back({cx + r * px[k], cy + r * py[k], z});
        c.weights.push_back(k % 2 ? h : 1.0);
    }
    return c;
}

/// A cylinder of radius @p r about the z axis from z = 0 to @p length: u around (the circle),
/// v along (degree 1). Its normal dS/du x dS/dv points outward.
NurbsSurface cylinder(double r, double length)
{
    const NurbsCurve c = circle(r, 0.0, 0.0, 0.0);
    NurbsSurface s;
    s.uDegree = 2;
    s.vDegree = 1;
    s.uKnots = c.knots;
    s.vKnots = {0, 0, 1, 1};
    s.uCount = c.poles.size();
    s.vCount = 2;
    for (std::size_t i = 0; i < c.poles.size(); ++i)
        for (double z : {0.0, length}) {
            s.poles.push_back({c.poles[i].x, c.poles[i].y, z});
            s.weights.push_back(c.weights[i]);
        }
    return s;
}

NurbsSurface cone(double r0, double r1, double height)
{
    const NurbsCurve c = circle(1.0, 0.0, 0.0, 0.0);
    NurbsSurface s;
    s.uDegree = 2;
    s.vDegree = 1;
    s.uKnots = c.knots;
    s.vKnots = {0, 0, 1, 1};
    s.uCount = c.poles.size();
    s.vCount = 2;
    for (std::size_t i = 0; i < c.poles.size(); ++i)
        for (const auto& [r, z] : {std::pair{r0, 0.0}, std::pair{r1, height}}) {
            s.poles.push_back({r * c.poles[i].x, r * c.poles[i].y, z});
            s.weights.push_back(c.weights[i]);
        }
    return s;
}

/// A bicubic saddle z = 0.3 (x^2 - y^2) over [-1, 1]^2 (poles on a 5 x 5 grid, not rational).
NurbsSurface saddle()
{
    NurbsSurface s;
    s.uDegree = s.vDegree = 3;
    s.uKnots = s.vKnots = {0, 0, 0, 0, 0.5, 1, 1, 1, 1};
    s.uCount = s.vCount = 5;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j) {
            const double x = -1.0 + 0.5 * i, y = -1.0 + 0.5 * j;
            s.poles.push_back({x, y, 0.3 * (x * x - y * y)});
            s.weights.push_back(1.0);
        }
    return s;
}

}  // namespace towgeom::testing
