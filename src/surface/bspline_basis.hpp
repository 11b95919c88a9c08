// Knot vectors and B-spline collocation matrices for fitting, evaluated with OCCT's BSplCLib.
#pragma once

#include <Eigen/SparseCore>

#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>

#include <vector>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// A cubic B-spline knot vector in OCCT's form (distinct knots and multiplicities).
struct KnotVector {
    int degree = 3;
    bool periodic = false;
    std::vector<double> knots;
    std::vector<int> mults;

    /// Number of control points it carries.
    int poleCount() const;
    TColStd_Array1OfReal occtKnots() const;
    TColStd_Array1OfInteger occtMults() const;
};

/// Not-a-knot interpolation knots for an open direction: as many poles as parameters.
KnotVector interpolationKnotsOpen(const std::vector<double>& params);
/// Periodic interpolation knots: one simple knot per parameter, period end = params[0] + period.
KnotVector interpolationKnotsPeriodic(const std::vector<double>& params, double period);
/// Clamped open knots for least squares with @p poles poles, placed by averaging the parameters
/// (Piegl & Tiller, eq. 9.69) so every span holds data.
KnotVector approximationKnotsOpen(const std::vector<double>& params, int poles);
/// Periodic knots for least squares with @p poles poles on the period [params[0], params[0] +
/// period): one knot every params.size() / poles data points, so every span holds data.
KnotVector approximationKnotsPeriodic(const std::vector<double>& params, double period, int poles);
/// Clamped open knots with uniform spacing on [a, b].
KnotVector uniformKnotsOpen(int poles, double a, double b);
/// Periodic uniform knots on [a, a + period).
KnotVector uniformKnotsPeriodic(int poles, double a, double period);

/// B(r, c) = value at params[r] of the basis function of pole c (OCCT's pole numbering, 0-based).
Eigen::SparseMatrix<double> basisMatrix(const KnotVector& kv, const std::vector<double>& params);

}  // namespace detail
TOWGEOM_END_NAMESPACE
