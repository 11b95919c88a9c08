// B-spline and rational basis functions on full knot vectors (OCCT's BSplCLib), and the checks
// of the NURBS value types' knots and weights.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// The p + 1 basis functions that do not vanish at a parameter: indices first .. first + p.
struct BasisRow {
    std::size_t first = 0;        ///< index of the first
    std::vector<double> values;   ///< their values
    std::vector<double> slopes;   ///< their first derivatives
};

/// B-spline basis of degree @p p on the full knot vector @p knots at @p t (values and slopes).
BasisRow bsplineBasis(const std::vector<double>& knots, int p, double t);
/// The rational basis N_i w_i / sum_j N_j w_j at @p t (values only).
BasisRow rationalBasis(const std::vector<double>& knots, int p, const std::vector<double>& weights, double t);

/// Refuses (InvalidArgument, naming @p what) a knot vector that is not a clamped, non-decreasing,
/// finite full knot vector of degree @p p for @p poles poles.
void checkKnots(const std::vector<double>& knots, int p, std::size_t poles, const std::string& what);
/// Refuses poles that are not finite.
void checkPoles(const std::vector<Point3>& poles, const std::string& what);
/// Refuses weights that are not @p poles positive finite numbers.
void checkWeights(const std::vector<double>& weights, std::size_t poles, const std::string& what);

}  // namespace detail
TOWGEOM_END_NAMESPACE
