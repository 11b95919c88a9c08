// TowSurface fitting: tensor-product interpolation / least squares on OCCT B-spline bases.
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

#include <GeomAdaptor_Surface.hxx>
#include <Standard_Failure.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include <algorithm>
#include <cmath>

#include "core/section_geometry.hpp"
#include "surface/bspline_basis.hpp"
#include "surface/tow_surface_impl.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

using Dense = Eigen::MatrixXd;
using Sparse = Eigen::SparseMatrix<double>;

[[noreturn]] void fitFailed(const std::string& tow, const std::string& why)
{
    throw Error(ErrorCode::FitFailed, "surface fit failed: " + why, "tow '" + tow + "'");
}

/// True when the sections go counter-clockwise about the tow's local direction. validateStack
/// has checked that every section agrees with the first, so this is section 0's local sign
/// (local, so that a tow bent beyond 180 degrees cannot mislead it).
bool counterClockwise(const TowStack& stack) { return localOrientation(stack.sections, 0) > 0.0; }

/// The input in the surface's order: every section renumbered cyclically to match the previous
/// one best (cumulativeStartShifts, in the input's own direction, so that the choice is the one
/// validateStack judged), then reversed around (first point kept first) when needed. Sets
/// @p shifts to the shifts in the surface's order: point j of section i of the result is point
/// (j + shifts[i]) mod N of the input section taken in the surface's direction (input point
/// (N - (j + shifts[i]) mod N) mod N when reversed).
std::vector<std::vector<Point3>> orderedSections(const TowStack& stack, bool reverse, std::vector<std::size_t>& shifts)
{
    shifts = cumulativeStartShifts(stack.sections);
    std::vector<std::vector<Point3>> out(stack.sections.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
        out[i] = cyclicallyShifted(stack.sections[i], shifts[i]);
        if (reverse) {
            // Aligned point j is input point j + k; reversed, surface point j is aligned point
            // -j, i.e. input point -(j - k): a shift of -k in the reversed numbering.
            std::reverse(out[i].begin() + 1, out[i].end());
            shifts[i] = (out[i].size() - shifts[i]) % out[i].size();
        }
    }
    return out;
}

/// u of each section: cumulative chord length between sections, averaged over point columns.
std::vector<double> sectionParameters(const std::vector<std::vector<Point3>>& s)
{
    std::vector<double> u(s.size(), 0.0);
    for (std::size_t i = 1; i < s.size(); ++i) {
        double chord = 0.0;
        for (std::size_t j = 0; j < s[i].size(); ++j) chord += distance(s[i][j], s[i - 1][j]);
        u[i] = u[i - 1] + chord / s[i].size();
    }
    for (double& x : u) x /= u.back();
    return u;
}

/// v of each point index: cumulative chord length around, normalised per section, averaged.
std::vector<double> pointParameters(const std::vector<std::vector<Point3>>& s)
{
    const std::size_t n = s.front().size();
    std::vector<double> v(n, 0.0);
    for (const auto& section : s) {
        const double total = perimeter(section);
        double acc = 0.0;
        for (std::size_t j = 1; j < n; ++j) {
            acc += distance(section[j], section[j - 1]);
            v[j] += acc / total / s.size();
        }
    }
    return v;
}

/// The data as an (N x 3M) matrix: column 3i+d holds coordinate d of section i.
Dense dataByPoint(const std::vector<std::vector<Point3>>& s)
{
    const std::size_t m = s.size(), n = s.front().size();
    Dense q(n, 3 * m);
    for (std::size_t i = 0; i < m; ++i)
        for (std::size_t j = 0; j < n; ++j) {
            q(j, 3 * i) = s[i][j].x;
            q(j, 3 * i + 1) = s[i][j].y;
            q(j, 3 * i + 2) = s[i][j].z;
        }
    return q;
}

/// Solves B X = R exactly (square B) or in the least-squares sense (tall B).
Dense solve(const Sparse& b, const Dense& r, const std::string& tow, const char* direction)
{
    if (b.rows() == b.cols()) {
        Eigen::SparseLU<Sparse> lu(b);
        if (lu.info() != Eigen::Success) fitFailed(tow, std::string("singular interpolation system ") + direction);
        return lu.solve(r);
    }
    const Sparse normal = Sparse(b.transpose() * b);
    Eigen::SimplicialLDLT<Sparse> ldlt(normal);
    if (ldlt.info() != Eigen::Success) fitFailed(tow, std::string("singular least-squares system ") + direction);
    return ldlt.solve(b.transpose() * r);
}

/// Tensor-product solve: control points P with Bu P Bv^T ~ data, as an OCCT surface.
Handle(Geom_BSplineSurface) tensorFit(const std::vector<std::vector<Point3>>& s, const std::vector<double>& u,
                                      const std::vector<double>& v, const KnotVector& ku, const KnotVector& kv,
                                      const std::string& tow)
{
    const int m = static_cast<int>(s.size());
    const int nv = kv.poleCount(), nu = ku.poleCount();
    // Around: for every section, the control points of its periodic curve.
    const Dense z = solve(basisMatrix(kv, v), dataByPoint(s), tow, "around the tow");  // nv x 3m
    // Along: rearrange to (m x 3nv) and solve for the control points of every column.
    Dense zt(m, 3 * nv);
    for (int i = 0; i < m; ++i)
        for (int k = 0; k < nv; ++k)
            for (int d = 0; d < 3; ++d) zt(i, 3 * k + d) = z(k, 3 * i + d);
    const Dense p = solve(basisMatrix(ku, u), zt, tow, "along the tow");  // nu x 3nv
    if (!p.allFinite()) fitFailed(tow, "non-finite control points");
    TColgp_Array2OfPnt poles(1, nu, 1, nv);
    for (int i = 0; i < nu; ++i)
        for (int k = 0; k < nv; ++k) poles(i + 1, k + 1) = gp_Pnt(p(i, 3 * k), p(i, 3 * k + 1), p(i, 3 * k + 2));
    return new Geom_BSplineSurface(poles, ku.occtKnots(), kv.occtKnots(), ku.occtMults(), kv.occtMults(), 3, 3,
                                   Standard_False, Standard_True);
}

/// Largest distance of an input point from the surface point at its own parameters (an upper
/// bound of its closest-point distance).
double parametricDeviation(const Handle(Geom_BSplineSurface)& surface, const TowSurface::Impl& t)
{
    GeomAdaptor_Surface adaptor(surface);
    double worst = 0.0;
    for (std::size_t i = 0; i < t.sections.size(); ++i)
        for (std::size_t j = 0; j < t.sections[i].size(); ++j) {
            const gp_Pnt p = adaptor.Value(t.uParams[i], t.vParams[j]);
            const Point3& q = t.sections[i][j];
            worst = std::max(worst, p.Distance(gp_Pnt(q.x, q.y, q.z)));
        }
    return worst;
}

Handle(Geom_BSplineSurface) fitApproximate(const TowSurface::Impl& t, double tolerance)
{
    const int m = static_cast<int>(t.sections.size());
    const int n = static_cast<int>(t.vParams.size());
    const int maxU = std::max(4, (3 * m) / 4), maxV = std::max(4, (3 * n) / 4);
    int nu = std::clamp(m / 4, 4, maxU), nv = std::clamp(n / 4, 4, maxV);
    for (;;) {
        Handle(Geom_BSplineSurface) s =
            tensorFit(t.sections, t.uParams, t.vParams, approximationKnotsOpen(t.uParams, nu),
                      approximationKnotsPeriodic(t.vParams, 1.0, nv), t.name);
        if (parametricDeviation(s, t) <= tolerance) return s;
        if (nu == maxU && nv == maxV) break;
        nu = std::min(maxU, (3 * nu + 1) / 2);
        nv = std::min(maxV, (3 * nv + 1) / 2);
    }
    // Nothing coarser meets the tolerance: interpolate (deviation zero up to rounding).
    return tensorFit(t.sections, t.uParams, t.vParams, interpolationKnotsOpen(t.uParams),
                     interpolationKnotsPeriodic(t.vParams, 1.0), t.name);
}

Handle(Geom_BSplineSurface) fitControlNet(TowSurface::Impl& t)
{
    const int m = static_cast<int>(t.sections.size());
    const int n = static_cast<int>(t.sections.front().size());
    const KnotVector ku = uniformKnotsOpen(m, 0.0, 1.0);
    const KnotVector kv = uniformKnotsPeriodic(n, 0.0, 1.0);
    TColgp_Array2OfPnt poles(1, m, 1, n);
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < n; ++j) {
            const Point3& p = t.sections[i][j];
            poles(i + 1, j + 1) = gp_Pnt(p.x, p.y, p.z);
        }
    // The input points are not on the surface; their nominal parameters are the Greville
    // abscissae (where each control point has most influence), shifted into OCCT's numbering.
    const auto flat = [](const KnotVector& k) {
        std::vector<double> f;
        for (std::size_t i = 0; i < k.knots.size(); ++i) f.insert(f.end(), k.mults[i], k.knots[i]);
        return f;
    };
    const std::vector<double> fu = flat(ku);
    for (int i = 0; i < m; ++i) t.uParams[i] = (fu[i + 1] + fu[i + 2] + fu[i + 3]) / 3.0;
    // Periodic uniform: pole j peaks where basisMatrix puts its largest weight.
    const std::vector<double> probe{0.0};
    const Eigen::SparseMatrix<double> b = basisMatrix(kv, probe);
    int peak = 0;
    double best = -1.0;
    for (int k = 0; k < n; ++k)
        if (b.coeff(0, k) > best) {
            best = b.coeff(0, k);
            peak = k;
        }
    for (int j = 0; j < n; ++j) t.vParams[j] = std::fmod(static_cast<double>(((j - peak) % n + n) % n) / n, 1.0);
    return new Geom_BSplineSurface(poles, ku.occtKnots(), kv.occtKnots(), ku.occtMults(), kv.occtMults(), 3, 3,
                                   Standard_False, Standard_True);
}

}  // namespace

std::shared_ptr<const TowSurface::Impl> fitSurface(const TowStack& stack, const FitOptions& options)
{
    auto t = std::make_shared<TowSurface::Impl>();
    t->name = stack.name;
    t->mode = options.mode;
    t->reversed = counterClockwise(stack);
    t->sections = orderedSections(stack, t->reversed, t->startShifts);
    t->uParams = sectionParameters(t->sections);
    t->vParams = pointParameters(t->sections);
    for (const auto& section : t->sections) t->towSize += perimeter(section) / M_PI / t->sections.size();

    try {
        switch (options.mode) {
        case FitMode::Interpolate:
            t->surface = tensorFit(t->sections, t->uParams, t->vParams, interpolationKnotsOpen(t->uParams),
                                   interpolationKnotsPeriodic(t->vParams, 1.0), t->name);
            break;
        case FitMode::Approximate: {
            const double tol = options.tolerance > 0.0 ? options.tolerance : options.relativeTolerance * t->towSize;
            t->surface = fitApproximate(*t, tol);
            break;
        }
        case FitMode::ControlNet: t->surface = fitControlNet(*t); break;
        }
    } catch (const Standard_Failure& e) {
        fitFailed(t->name, std::string("OpenCASCADE: ") + e.GetMessageString());
    }
    setUnitFrame(*t);
    return t;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
