// The plane a tow is meshed in: y = (v - vMin) sv around the tow, and x along it, x = (u - uMin)
// su plus a correction that makes the lines of constant x cross the tow square. Where a tow's
// sections are cut obliquely (a binder sliced by the scan's planes at 40-60 degrees), the lines
// of constant u do not: dS/du and dS/dv meet at 40 degrees, and triangles that are good in the
// plane are poor on the surface. The correction removes that shear. And where a tow's girth
// changes along it (a stub of a few sections swelling between them), x runs conformally: as
// fast as the tow is long for its girth there, so that the plane's good triangles are good on
// the surface (else a plane three times too short across the tow refines to slivers' size).
#pragma once

#include <cstddef>
#include <vector>

#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

class ScaledSpace {
public:
    /// @p su, @p sv: the plane's length per unit u and v. With @p unshear, x runs conformally
    /// along u (between the grid's first and last cells, linear in u within them; su is best
    /// conformalLength() / (uMax - uMin)), and is corrected so that
    /// dS/dx and dS/dy are about square: dx/dv = x_u (S_u . S_v) / |S_u|^2 (x_u the base's rate
    /// along u at that row), integrated around each
    /// section (a drift over the whole turn, as a tow's twist gives, is left), blended to nothing
    /// towards each end (none in the grid's last cell there) so that the ends stay at x = 0 and
    /// x = (uMax - uMin) su, and scaled down where it would let x fall along u. Without it,
    /// x = (u - uMin) su.
    ScaledSpace(const TowSurface& surface, double su, double sv, bool unshear);

    /// The length along u of a conformal plane @p ly around: ly times the integral over u of
    /// the tow's speed along u over its girth.
    static double conformalLength(const TowSurface& surface, double ly);

    double su() const { return su_; }
    double sv() const { return sv_; }
    /// The plane's point of (u, v). v = vMin and v = vMax give the same x.
    void toXY(double u, double v, double& x, double& y) const;
    /// The (u, v) of the plane's point (x, y): the inverse of toXY (u beyond the tow's range
    /// where x lies beyond its ends).
    UV toUV(double x, double y) const;
    /// dx/du and dx/dv at (u, v) (dy/dv is sv, dy/du 0).
    struct Slopes {
        double xu = 0.0, xv = 0.0;
    };
    Slopes slopes(double u, double v) const;
    /// Whether x has a correction (false: x = (u - uMin) su).
    bool corrected() const { return !x_.empty(); }

private:
    /// The grid cell and fractions of (u, v): row i, i + 1 along u; columns j, j1 around v.
    struct Cell {
        std::size_t i = 0, j = 0, j1 = 0;
        double a = 0.0, b = 0.0;
    };
    Cell cellAt(double u, double v) const;
    double at(std::size_t i, std::size_t j) const { return x_[i * nv_ + j]; }
    void column(double v, std::size_t& j, std::size_t& j1, double& b) const;

    ParameterRange range_;
    double su_, sv_;
    std::size_t nu_ = 0, nv_ = 0;  ///< grid rows along u (both ends included), columns around v
    std::vector<double> u_;        ///< the rows' u
    std::vector<double> x_;        ///< x at (row, column); empty: no correction
    std::vector<bool> shifted_;    ///< per row: whether it has a correction
};

}  // namespace detail
TOWGEOM_END_NAMESPACE
