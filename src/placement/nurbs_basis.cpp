#include "placement/nurbs_basis.hpp"

#include <BSplCLib.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <math_Matrix.hxx>

#include <cmath>

#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

BasisRow bsplineBasis(const std::vector<double>& knots, int p, double t)
{
    if (knots.empty()) throw Error(ErrorCode::InvalidArgument, "the B-spline basis needs knots");
    // OCCT's view of the knots in place (NCollection_Array1's buffer constructor): no copy per call.
    const TColStd_Array1OfReal flat(knots.front(), 1, static_cast<int>(knots.size()));
    math_Matrix basis(1, 2, 1, p + 1, 0.0);
    int first = 0;
    if (BSplCLib::EvalBsplineBasis(1, p + 1, flat, t, first, basis) != 0)
        throw Error(ErrorCode::InvalidArgument, "the B-spline basis cannot be evaluated at " + std::to_string(t));
    BasisRow row;
    row.first = static_cast<std::size_t>(first - 1);
    for (int k = 1; k <= p + 1; ++k) {
        row.values.push_back(basis(1, k));
        row.slopes.push_back(basis(2, k));
    }
    return row;
}

BasisRow rationalBasis(const std::vector<double>& knots, int p, const std::vector<double>& weights, double t)
{
    BasisRow row = bsplineBasis(knots, p, t);
    double sum = 0.0;
    for (std::size_t k = 0; k < row.values.size(); ++k) sum += row.values[k] * weights[row.first + k];
    for (std::size_t k = 0; k < row.values.size(); ++k) row.values[k] *= weights[row.first + k] / sum;
    row.slopes.clear();
    return row;
}

void checkKnots(const std::vector<double>& knots, int p, std::size_t poles, const std::string& what)
{
    const std::string which = "NURBS " + what + ": ";
    if (p < 1) throw Error(ErrorCode::InvalidArgument, which + "the degree must be at least 1");
    if (poles < static_cast<std::size_t>(p) + 1)
        throw Error(ErrorCode::InvalidArgument, which + "needs at least degree + 1 poles");
    if (knots.size() != poles + static_cast<std::size_t>(p) + 1)
        throw Error(ErrorCode::InvalidArgument, which + std::to_string(knots.size()) + " knots, not poles + degree + 1 = " +
                                                    std::to_string(poles + static_cast<std::size_t>(p) + 1));
    for (std::size_t k = 0; k < knots.size(); ++k) {
        if (!std::isfinite(knots[k])) throw Error(ErrorCode::InvalidArgument, which + "a knot is not finite");
        if (k > 0 && knots[k] < knots[k - 1]) throw Error(ErrorCode::InvalidArgument, which + "the knots decrease");
    }
    if (p > BSplCLib::MaxDegree()) throw Error(ErrorCode::InvalidArgument, which + "a degree over " + std::to_string(BSplCLib::MaxDegree()));
    // Clamped: the first and last knots exactly p + 1 times; inside, no knot more than p times
    // (the curve stays continuous) and distinct knots apart.
    const std::size_t q = static_cast<std::size_t>(p);
    for (std::size_t k = 0; k < knots.size();) {
        std::size_t m = 1;
        while (k + m < knots.size() && knots[k + m] == knots[k]) ++m;
        const bool end = k == 0 || k + m == knots.size();
        if (end && m != q + 1)
            throw Error(ErrorCode::InvalidArgument, which + "the knot vector is not clamped (first and last knots degree + 1 times)");
        if (!end && m > q) throw Error(ErrorCode::InvalidArgument, which + "an inner knot repeated more than degree times");
        if (k + m < knots.size() && !(knots[k + m] - knots[k] > 1e-12 * (std::abs(knots.back()) + std::abs(knots.front()) + 1.0)))
            throw Error(ErrorCode::InvalidArgument, which + "two distinct knots closer than 1e-12 of the range");
        k += m;
    }
}

void checkPoles(const std::vector<Point3>& poles, const std::string& what)
{
    for (const Point3& p : poles)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw Error(ErrorCode::InvalidArgument, "NURBS " + what + ": a pole is not finite");
}

void checkWeights(const std::vector<double>& weights, std::size_t poles, const std::string& what)
{
    if (weights.size() != poles)
        throw Error(ErrorCode::InvalidArgument, "NURBS " + what + ": " + std::to_string(weights.size()) + " weights for " +
                                                    std::to_string(poles) + " poles");
    for (double w : weights)
        if (!(w > 0.0) || !std::isfinite(w)) throw Error(ErrorCode::InvalidArgument, "NURBS " + what + ": a weight is not positive and finite");
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
