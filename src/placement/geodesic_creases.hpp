// Geodesics across a crease of a tool surface (faces joined side to side meet at a knot line
// where the surface is only C0): the geodesic passes straight on, as the two faces unfolded
// into one plane at the crossing would carry it.
#pragma once

#include <Geom_BSplineSurface.hxx>

#include <array>
#include <vector>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// The creases of @p s across @p alongU (the lines u = k, else v = k): its interior knots in
/// that direction of multiplicity at least the degree, where it is not periodic.
std::vector<double> creaseKnots(const Handle(Geom_BSplineSurface)& s, bool alongU);

/// The parameter rates of a geodesic with rates (@p du, @p dv) at (@p u, @p v) on the crease
/// (u = @p u when @p creaseInU, else v = @p v), carried across it to the side where that
/// parameter grows (@p towards +1) or falls (-1): its component along the crease and its speed
/// kept, its direction across the crease turned into the other face (the faces unfolded about
/// the crease). The derivatives on each side are taken 1e-12 of the box off the crease.
std::array<double, 2> ratesAcrossCrease(const Handle(Geom_BSplineSurface)& s, double u, double v, double du, double dv, bool creaseInU, int towards);

}  // namespace detail
TOWGEOM_END_NAMESPACE
