#include "surface/bspline_basis.hpp"

#include <BSplCLib.hxx>
#include <math_Matrix.hxx>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

int KnotVector::poleCount() const
{
    const int sum = std::accumulate(mults.begin(), mults.end(), 0);
    return periodic ? sum - mults.back() : sum - degree - 1;
}

TColStd_Array1OfReal KnotVector::occtKnots() const
{
    TColStd_Array1OfReal a(1, static_cast<int>(knots.size()));
    for (std::size_t i = 0; i < knots.size(); ++i) a(static_cast<int>(i) + 1) = knots[i];
    return a;
}

TColStd_Array1OfInteger KnotVector::occtMults() const
{
    TColStd_Array1OfInteger a(1, static_cast<int>(mults.size()));
    for (std::size_t i = 0; i < mults.size(); ++i) a(static_cast<int>(i) + 1) = mults[i];
    return a;
}

KnotVector interpolationKnotsOpen(const std::vector<double>& t)
{
    KnotVector kv;
    const std::size_t m = t.size();  // m >= 4
    kv.knots.push_back(t.front());
    kv.mults.push_back(4);
    for (std::size_t i = 2; i + 2 < m; ++i) {
        kv.knots.push_back(t[i]);
        kv.mults.push_back(1);
    }
    kv.knots.push_back(t.back());
    kv.mults.push_back(4);
    return kv;
}

KnotVector interpolationKnotsPeriodic(const std::vector<double>& t, double period)
{
    KnotVector kv;
    kv.periodic = true;
    kv.knots = t;
    kv.knots.push_back(t.front() + period);
    kv.mults.assign(kv.knots.size(), 1);
    return kv;
}

KnotVector approximationKnotsOpen(const std::vector<double>& t, int poles)
{
    KnotVector kv;
    const int m = static_cast<int>(t.size());
    const int n = poles;  // n <= m
    kv.knots.push_back(t.front());
    kv.mults.push_back(4);
    const double d = static_cast<double>(m) / static_cast<double>(n - 3);
    for (int j = 1; j <= n - 4; ++j) {
        const int i = static_cast<int>(std::floor(j * d));
        const double alpha = j * d - i;
        const double k = (1.0 - alpha) * t[std::max(i - 1, 0)] + alpha * t[std::min(i, m - 1)];
        kv.knots.push_back(k);
        kv.mults.push_back(1);
    }
    kv.knots.push_back(t.back());
    kv.mults.push_back(4);
    return kv;
}

KnotVector approximationKnotsPeriodic(const std::vector<double>& t, double period, int poles)
{
    KnotVector kv;
    kv.periodic = true;
    const double n = static_cast<double>(t.size());
    for (int k = 0; k < poles; ++k) {
        const double x = k * n / poles;  // fractional data index
        const std::size_t i = static_cast<std::size_t>(x);
        const double next = i + 1 < t.size() ? t[i + 1] : t.front() + period;
        kv.knots.push_back(t[i] + (x - static_cast<double>(i)) * (next - t[i]));
        kv.mults.push_back(1);
    }
    kv.knots.push_back(t.front() + period);
    kv.mults.push_back(1);
    return kv;
}

KnotVector uniformKnotsOpen(int poles, double a, double b)
{
    KnotVector kv;
    const int spans = poles - 3;
    for (int i = 0; i <= spans; ++i) {
        kv.knots.push_back(a + (b - a) * i / spans);
        kv.mults.push_back(i == 0 || i == spans ? 4 : 1);
    }
    return kv;
}

KnotVector uniformKnotsPeriodic(int poles, double a, double period)
{
    KnotVector kv;
    kv.periodic = true;
    for (int i = 0; i <= poles; ++i) {
        kv.knots.push_back(a + period * i / poles);
        kv.mults.push_back(1);
    }
    return kv;
}

Eigen::SparseMatrix<double> basisMatrix(const KnotVector& kv, const std::vector<double>& params)
{
    const TColStd_Array1OfReal knots = kv.occtKnots();
    const TColStd_Array1OfInteger mults = kv.occtMults();
    const int length = BSplCLib::KnotSequenceLength(mults, kv.degree, kv.periodic);
    TColStd_Array1OfReal flat(1, length);
    BSplCLib::KnotSequence(knots, mults, kv.degree, kv.periodic, flat);
    const int poles = kv.poleCount();
    const double first = kv.knots.front();
    const double period = kv.knots.back() - first;

    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(params.size() * (kv.degree + 1));
    math_Matrix basis(1, 1, 1, kv.degree + 1);
    for (std::size_t r = 0; r < params.size(); ++r) {
        double t = params[r];
        if (kv.periodic) {
            t = first + std::fmod(t - first, period);
            if (t < first) t += period;
        }
        int firstIndex = 0;
        BSplCLib::EvalBsplineBasis(0, kv.degree + 1, flat, t, firstIndex, basis);
        for (int k = 0; k <= kv.degree; ++k) {
            // In the flat sequence of a periodic vector, the basis function of flat index f
            // (1-based) belongs to pole (f - 1) mod poles: OCCT's periodic evaluation starts its
            // pole window at the span's flat index minus the degree, wrapping around.
            int col = firstIndex - 1 + k;
            if (kv.periodic) col = ((col % poles) + poles) % poles;
            const double value = basis(1, k + 1);
            if (value != 0.0) entries.emplace_back(static_cast<int>(r), col, value);
        }
    }
    Eigen::SparseMatrix<double> b(static_cast<int>(params.size()), poles);
    b.setFromTriplets(entries.begin(), entries.end());
    return b;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
