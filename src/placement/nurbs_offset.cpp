// Offsets of NURBS curves and surfaces with the same parametrisation (Nguyen et al. 2014): the
// offset shares the input's degree, knots and weights; its poles collocate the exact offset at
// the Greville points (a linear system in the poles, as the rational basis is fixed by the
// weights), and knots are inserted into the input (OpenCASCADE, exactly) where the offset strays
// from the exact one by more than the tolerance.
#include "towgeom/nurbs_offset.hpp"

#include <Standard_Failure.hxx>

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "placement/nurbs_basis.hpp"
#include "placement/nurbs_geometry.hpp"
#include "placement/periodic_surface.hpp"
#include "surface/occt_convert.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

using detail::BasisRow;

/// Greville abscissae of a full knot vector: t_i = mean of knots i+1 .. i+p.
std::vector<double> greville(const std::vector<double>& knots, int p, std::size_t n)
{
    std::vector<double> g(n);
    for (std::size_t i = 0; i < n; ++i) {
        double s = 0.0;
        for (int k = 1; k <= p; ++k) s += knots[i + static_cast<std::size_t>(k)];
        g[i] = s / p;
    }
    return g;
}

/// The size of a control polygon: its bounding box's diagonal.
double sizeOf(const std::vector<Point3>& poles)
{
    BoundingBox b;
    for (const Point3& p : poles) b.add(p);
    return distance(b.min, b.max);
}

double toleranceOf(const OffsetOptions& o, const std::vector<Point3>& poles)
{
    if (!(o.tolerance >= 0.0) || !std::isfinite(o.tolerance) || !(o.relativeTolerance > 0.0) || !std::isfinite(o.relativeTolerance) ||
        o.maxRefinements < 0)
        throw Error(ErrorCode::InvalidArgument, "offset: tolerance must be >= 0, relativeTolerance > 0 (finite), maxRefinements >= 0");
    return o.tolerance > 0.0 ? o.tolerance : o.relativeTolerance * sizeOf(poles);
}

/// The distinct spans [a, b) of a full knot vector.
std::vector<std::pair<double, double>> spans(const std::vector<double>& knots)
{
    std::vector<std::pair<double, double>> s;
    for (std::size_t k = 0; k + 1 < knots.size(); ++k)
        if (knots[k + 1] > knots[k]) s.emplace_back(knots[k], knots[k + 1]);
    return s;
}

/// Solves the collocation system (a row per collocation point, p + 1 or (p + 1)(q + 1) entries).
Eigen::MatrixXd solveSparse(std::size_t n, const std::vector<Eigen::Triplet<double>>& entries, const Eigen::MatrixXd& rhs)
{
    Eigen::SparseMatrix<double> a(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    a.setFromTriplets(entries.begin(), entries.end());
    a.makeCompressed();
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
    lu.compute(a);
    if (lu.info() != Eigen::Success) throw Error(ErrorCode::Internal, "offset: the collocation system is singular");
    return lu.solve(rhs);
}

/// Whether the cross product @p n of two vectors of lengths @p a and @p b is too small to give a
/// direction (relative: at a collapsed row of poles it is zero only up to rounding).
bool degenerate(double n, double a, double b) { return !(n > 1e-10 * a * b); }

/// Which boundary rows (v = v0, v1: poles (i, 0), (i, vCount - 1)) and columns (u = u0, u1) of
/// a surface's poles collapse to one point (within 1e-10 of the control net's size): its poles
/// in the parametrisation, as a sphere face's.
struct CollapsedEdges {
    bool u0 = false, u1 = false, v0 = false, v1 = false;
};

CollapsedEdges collapsedEdges(const NurbsSurface& s)
{
    const double tol = 1e-10 * sizeOf(s.poles);
    const auto point = [&](std::size_t first, std::size_t stride, std::size_t count) {
        for (std::size_t k = 1; k < count; ++k)
            if (distance(s.poles[first + k * stride], s.poles[first]) > tol) return false;
        return true;
    };
    const std::size_t nu = s.uCount, nv = s.vCount;
    return {point(0, 1, nv), point((nu - 1) * nv, 1, nv), point(0, nv, nu), point(nv - 1, nv, nu)};
}

/// The direction of @p s's normal at (@p u, @p v), dS/du x dS/dv, also on a collapsed boundary
/// row or column @p edges names: there the limit from inside the surface. On v = v0 with the
/// row a point, dS/du ~ (v - v0) d2S/dudv nearby, so the normal points along
/// (d2S/dudv x dS/dv) (negated on v = v1; on a collapsed column, along dS/du x d2S/dudv).
/// @throws towgeom::Error (InvalidArgument) where neither gives a normal.
gp_Vec normalDirection(const Handle(Geom_BSplineSurface)& s, const CollapsedEdges& edges, double u, double v)
{
    double u0, u1, v0, v1;
    s->Bounds(u0, u1, v0, v1);
    const bool onRow = (edges.v0 && v == v0) || (edges.v1 && v == v1), onColumn = (edges.u0 && u == u0) || (edges.u1 && u == u1);
    gp_Pnt p;
    gp_Vec du, dv, duu, dvv, duv;
    if (onRow || onColumn) {
        s->D2(u, v, p, du, dv, duu, dvv, duv);  // the mixed derivative for the limit
    } else {
        s->D1(u, v, p, du, dv);
    }
    gp_Vec n = du.Crossed(dv);
    double a = du.Magnitude(), b = dv.Magnitude();
    if (onRow && !onColumn) {
        n = duv.Crossed(dv) * (v == v0 ? 1.0 : -1.0);
        a = duv.Magnitude();
    } else if (onColumn && !onRow) {
        n = du.Crossed(duv) * (u == u0 ? 1.0 : -1.0);
        b = duv.Magnitude();
    }
    if (degenerate(n.Magnitude(), a, b))
        throw Error(ErrorCode::InvalidArgument, "offsetSurface: the normal is not defined at (" + std::to_string(u) + ", " + std::to_string(v) +
                                                    ") (dS/du x dS/dv vanishes, and its limit at a collapsed edge is not of first order)");
    return n;
}

/// Refuses a collapsed boundary row or column of @p s (@p edges) whose normal's limit differs
/// along it (beyond 1e-6 radians, at @p samples points): a cone's apex, where no offset point
/// is the offset of the apex.
void requireSingleNormals(const Handle(Geom_BSplineSurface)& s, const CollapsedEdges& edges, int samples = 16)
{
    double u0, u1, v0, v1;
    s->Bounds(u0, u1, v0, v1);
    const auto check = [&](bool collapsed, bool alongU, double fixed) {
        if (!collapsed) return;
        gp_Vec first;
        for (int k = 0; k <= samples; ++k) {
            const double t = alongU ? u0 + (u1 - u0) * k / samples : v0 + (v1 - v0) * k / samples;
            const gp_Vec n = (alongU ? normalDirection(s, edges, t, fixed) : normalDirection(s, edges, fixed, t)).Normalized();
            if (k == 0) {
                first = n;
            } else if (first.Angle(n) > 1e-6) {
                const gp_Pnt q = alongU ? s->Value(t, fixed) : s->Value(fixed, t);
                throw Error(ErrorCode::Unsupported, "offsetSurface: the surface has no single normal at its point (" + std::to_string(q.X()) + ", " +
                                                        std::to_string(q.Y()) + ", " + std::to_string(q.Z()) +
                                                        ") where an edge of its parametrisation collapses (a cone's apex): no offset point there");
            }
        }
    };
    check(edges.v0, true, v0);
    check(edges.v1, true, v1);
    check(edges.u0, false, u0);
    check(edges.u1, false, u1);
}

/// Runs @p f, OpenCASCADE's failures (on input the checks let through) as InvalidArgument.
template <class F>
auto guardedEvaluation(const char* what, F f)
{
    try {
        return f();
    } catch (const Standard_Failure& e) {
        throw Error(ErrorCode::InvalidArgument, std::string(what) + ": OpenCASCADE refused the NURBS: " + e.GetMessageString());
    }
}

}  // namespace

Point3 NurbsCurve::point(double t) const
{
    return guardedEvaluation("NurbsCurve::point", [&] { return detail::fromOcct(detail::occtCurve(*this)->Value(t)); });
}

Vector3 NurbsCurve::derivative(double t) const
{
    return guardedEvaluation("NurbsCurve::derivative", [&] {
        gp_Pnt p;
        gp_Vec d;
        detail::occtCurve(*this)->D1(t, p, d);
        return detail::fromOcct(d);
    });
}

Point3 NurbsSurface::point(double u, double v) const
{
    return guardedEvaluation("NurbsSurface::point", [&] { return detail::fromOcct(detail::toolSurface(*this)->Value(u, v)); });
}

Vector3 NurbsSurface::normal(double u, double v) const
{
    return guardedEvaluation("NurbsSurface::normal", [&] {
        gp_Pnt p;
        gp_Vec du, dv;
        detail::toolSurface(*this)->D1(u, v, p, du, dv);
        const gp_Vec n = du.Crossed(dv);
        if (degenerate(n.Magnitude(), du.Magnitude(), dv.Magnitude()))
            throw Error(ErrorCode::InvalidArgument, "NURBS surface: no normal where dS/du x dS/dv vanishes (a pole of the surface?)");
        return detail::fromOcct(n.Normalized());
    });
}

CurveOffset offsetCurve(const NurbsCurve& curve, double d, const Vector3& planeNormal, const OffsetOptions& options)
{
    if (!(norm(planeNormal) > 0.0) || !std::isfinite(d)) throw Error(ErrorCode::InvalidArgument, "offsetCurve: a zero plane normal or a non-finite distance");
    const double tol = toleranceOf(options, curve.poles);
    const Vector3 z = (1.0 / norm(planeNormal)) * planeNormal;
    CurveOffset result;
    try {
        Handle(Geom_BSplineCurve) c = detail::occtCurve(curve);
        const auto exact = [&](double t) {
            gp_Pnt p;
            gp_Vec dp;
            c->D1(t, p, dp);
            const Vector3 n = cross(detail::fromOcct(dp), z);
            if (degenerate(norm(n), dp.Magnitude(), 1.0) || !(dp.Magnitude() > 0.0))
                throw Error(ErrorCode::InvalidArgument, "offsetCurve: the curve's derivative vanishes (or is along the plane normal)");
            return detail::fromOcct(p) + (d / norm(n)) * n;
        };
        int flat = 0;  // rounds in a row that did not cut the error
        for (int round = 0;; ++round) {
            NurbsCurve base = detail::nurbsCurve(c);
            // OCCT keeps no weights for a curve whose weights are all equal: give back the input's.
            if (!c->IsRational()) base.weights.assign(base.poles.size(), curve.weights.front());
            const std::size_t n = base.poles.size();
            const std::vector<double> g = greville(base.knots, base.degree, n);
            std::vector<Eigen::Triplet<double>> a;
            Eigen::MatrixXd rhs(static_cast<Eigen::Index>(n), 3);
            for (std::size_t i = 0; i < n; ++i) {
                const BasisRow row = detail::rationalBasis(base.knots, base.degree, base.weights, g[i]);
                for (std::size_t k = 0; k < row.values.size(); ++k)
                    if (row.values[k] != 0.0) a.emplace_back(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(row.first + k), row.values[k]);
                const Point3 q = exact(g[i]);
                rhs.row(static_cast<Eigen::Index>(i)) << q.x, q.y, q.z;
            }
            const Eigen::MatrixXd poles = solveSparse(n, a, rhs);
            NurbsCurve offset = base;
            for (std::size_t i = 0; i < n; ++i)
                offset.poles[i] = {poles(static_cast<Eigen::Index>(i), 0), poles(static_cast<Eigen::Index>(i), 1), poles(static_cast<Eigen::Index>(i), 2)};
            const Handle(Geom_BSplineCurve) o = detail::occtCurve(offset);
            double worst = 0.0;
            std::vector<double> refine;
            for (const auto& [lo, hi] : spans(base.knots)) {
                double e = 0.0;
                for (int k = 0; k <= 16; ++k) {
                    const double t = lo + (hi - lo) * k / 16.0;
                    e = std::max(e, distance(detail::fromOcct(o->Value(t)), exact(t)));
                }
                worst = std::max(worst, e);
                if (e > tol) refine.push_back(0.5 * (lo + hi));
            }
            result.base = base;
            result.offset = offset;
            // Where the exact offset is not continuous (the curve turns a corner at a knot) no
            // refinement helps: stop after two rounds in a row that did not cut the error by 5 %.
            flat = round > 0 && worst > 0.95 * result.maxError ? flat + 1 : 0;
            const bool stalled = flat >= 2;
            result.maxError = worst;
            result.converged = refine.empty();
            if (refine.empty() || round >= options.maxRefinements || stalled) break;
            for (double t : refine) c->InsertKnot(t);
            result.knotsInserted += refine.size();
        }
    } catch (const Standard_Failure& e) {
        throw Error(ErrorCode::Internal, std::string("offsetCurve: OpenCASCADE failed: ") + e.GetMessageString());
    }
    return result;
}

SurfaceOffset offsetSurface(const NurbsSurface& surface, double d, const OffsetOptions& options)
{
    if (!std::isfinite(d)) throw Error(ErrorCode::InvalidArgument, "offsetSurface: a non-finite distance");
    const double tol = toleranceOf(options, surface.poles);
    SurfaceOffset result;
    try {
        Handle(Geom_BSplineSurface) s = detail::occtSurface(surface);
        // A pole of the parametrisation (a boundary row of poles collapsed to one point): its
        // offset the normal's limit there, the same along the row (refused where it is not).
        const CollapsedEdges edges = collapsedEdges(surface);
        requireSingleNormals(s, edges);
        const auto exact = [&](double u, double v) {
            const gp_Vec n = normalDirection(s, edges, u, v);
            return detail::fromOcct(s->Value(u, v)) + (d / n.Magnitude()) * detail::fromOcct(n);
        };
        int flat = 0;  // rounds in a row that did not cut the error
        for (int round = 0;; ++round) {
            NurbsSurface base = detail::nurbsSurface(s);
            const std::size_t nu = base.uCount, nv = base.vCount, n = nu * nv;
            const std::vector<double> gu = greville(base.uKnots, base.uDegree, nu), gv = greville(base.vKnots, base.vDegree, nv);
            // The rational basis at (u_i, v_j): B-spline products times weights over their sum.
            std::vector<Eigen::Triplet<double>> entries;
            Eigen::MatrixXd rhs(static_cast<Eigen::Index>(n), 3);
            for (std::size_t i = 0; i < nu; ++i)
                for (std::size_t j = 0; j < nv; ++j) {
                    const std::size_t r = i * nv + j;
                    const BasisRow bu = detail::bsplineBasis(base.uKnots, base.uDegree, gu[i]);
                    const BasisRow bv = detail::bsplineBasis(base.vKnots, base.vDegree, gv[j]);
                    double sum = 0.0;
                    for (std::size_t a = 0; a < bu.values.size(); ++a)
                        for (std::size_t b = 0; b < bv.values.size(); ++b)
                            sum += bu.values[a] * bv.values[b] * base.weights[(bu.first + a) * nv + bv.first + b];
                    for (std::size_t a = 0; a < bu.values.size(); ++a)
                        for (std::size_t b = 0; b < bv.values.size(); ++b) {
                            const std::size_t c = (bu.first + a) * nv + bv.first + b;
                            const double value = bu.values[a] * bv.values[b] * base.weights[c] / sum;
                            if (value != 0.0)
                                entries.emplace_back(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c), value);
                        }
                    const Point3 q = exact(gu[i], gv[j]);
                    rhs.row(static_cast<Eigen::Index>(r)) << q.x, q.y, q.z;
                }
            const Eigen::MatrixXd poles = solveSparse(n, entries, rhs);
            NurbsSurface offset = base;
            for (std::size_t k = 0; k < n; ++k)
                offset.poles[k] = {poles(static_cast<Eigen::Index>(k), 0), poles(static_cast<Eigen::Index>(k), 1), poles(static_cast<Eigen::Index>(k), 2)};
            const Handle(Geom_BSplineSurface) o = detail::occtSurface(offset);
            double worst = 0.0;
            std::set<double> refineU, refineV;
            const auto su = spans(base.uKnots), sv = spans(base.vKnots);
            for (const auto& [u0, u1] : su)
                for (const auto& [v0, v1] : sv) {
                    double e = 0.0;
                    for (int a = 0; a <= 8; ++a)
                        for (int b = 0; b <= 8; ++b) {
                            const double u = u0 + (u1 - u0) * a / 8.0, v = v0 + (v1 - v0) * b / 8.0;
                            e = std::max(e, distance(detail::fromOcct(o->Value(u, v)), exact(u, v)));
                        }
                    worst = std::max(worst, e);
                    if (e > tol) {
                        refineU.insert(0.5 * (u0 + u1));
                        refineV.insert(0.5 * (v0 + v1));
                    }
                }
            result.base = base;
            result.offset = offset;
            flat = round > 0 && worst > 0.95 * result.maxError ? flat + 1 : 0;  // a crease: see offsetCurve()
            const bool stalled = flat >= 2;
            result.maxError = worst;
            result.converged = refineU.empty() && refineV.empty();
            if (result.converged || round >= options.maxRefinements || stalled) break;
            for (double u : refineU) s->InsertUKnot(u, 1, 0.0);
            for (double v : refineV) s->InsertVKnot(v, 1, 0.0);
            result.knotsInserted += refineU.size() + refineV.size();
        }
    } catch (const Standard_Failure& e) {
        throw Error(ErrorCode::Internal, std::string("offsetSurface: OpenCASCADE failed: ") + e.GetMessageString());
    }
    return result;
}

NurbsSurface withKnotsOf(const NurbsSurface& surface, const NurbsSurface& finer)
{
    if (surface.uDegree != finer.uDegree || surface.vDegree != finer.vDegree)
        throw Error(ErrorCode::InvalidArgument, "withKnotsOf: the surfaces' degrees differ");
    // Each knot of finer's with the multiplicity it has there, inserted up to it.
    const auto contains = [](const std::vector<double>& big, const std::vector<double>& small) {
        return std::includes(big.begin(), big.end(), small.begin(), small.end());
    };
    if (!contains(finer.uKnots, surface.uKnots) || !contains(finer.vKnots, surface.vKnots))
        throw Error(ErrorCode::InvalidArgument, "withKnotsOf: the finer surface's knots do not contain the surface's");
    try {
        const Handle(Geom_BSplineSurface) s = detail::occtSurface(surface);
        for (std::size_t i = 0; i < finer.uKnots.size();) {
            std::size_t j = i;
            while (j < finer.uKnots.size() && finer.uKnots[j] == finer.uKnots[i]) ++j;
            if (i > 0 && j < finer.uKnots.size()) s->InsertUKnot(finer.uKnots[i], static_cast<int>(j - i), 0.0, Standard_False);  // interior
            i = j;
        }
        for (std::size_t i = 0; i < finer.vKnots.size();) {
            std::size_t j = i;
            while (j < finer.vKnots.size() && finer.vKnots[j] == finer.vKnots[i]) ++j;
            if (i > 0 && j < finer.vKnots.size()) s->InsertVKnot(finer.vKnots[i], static_cast<int>(j - i), 0.0, Standard_False);  // interior
            i = j;
        }
        NurbsSurface out = detail::nurbsSurface(s);
        if (out.uKnots != finer.uKnots || out.vKnots != finer.vKnots)
            throw Error(ErrorCode::InvalidArgument, "withKnotsOf: the knot vectors could not be matched");
        return out;
    } catch (const Standard_Failure& e) {
        throw Error(ErrorCode::Internal, std::string("withKnotsOf: OpenCASCADE failed: ") + e.GetMessageString());
    }
}

TOWGEOM_END_NAMESPACE
