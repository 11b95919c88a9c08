// Bézier extraction of a tow's B-spline surface: per span, the B-spline basis (OCCT's BSplCLib)
// and the Bernstein basis sampled at p+1 points; the extraction operator solves N = C B there.
#include "towgeom/bezier_extraction.hpp"

#include <BSplCLib.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <math_Matrix.hxx>

#include <Eigen/Dense>

#include <cmath>
#include <limits>

#include "surface/tow_surface_impl.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

/// The Bernstein polynomials of degree @p p at @p s.
std::vector<double> bernstein(std::size_t p, double s)
{
    std::vector<double> b(p + 1, 0.0);
    b[0] = 1.0;
    for (std::size_t j = 1; j <= p; ++j) {  // de Casteljau's triangle on the basis
        double saved = 0.0;
        for (std::size_t k = 0; k < j; ++k) {
            const double t = b[k];
            b[k] = saved + (1.0 - s) * t;
            saved = s * t;
        }
        b[j] = saved;
    }
    return b;
}

/// One direction's spans: each span's parameter interval, first non-zero function and operator.
struct Span {
    double from = 0.0, to = 0.0;
    std::size_t first = 0;  ///< 0-based index of the first non-zero basis function
    Eigen::MatrixXd c;      ///< (p+1) x (p+1): N_a = sum_b c(a, b) B_b
};

std::vector<Span> spansOf(const TColStd_Array1OfReal& flat, int degree)
{
    std::vector<Span> spans;
    const std::size_t p = static_cast<std::size_t>(degree);
    for (int i = flat.Lower() + degree; i < flat.Upper() - degree; ++i) {
        const double a = flat(i), b = flat(i + 1);
        if (!(b > a)) continue;
        Span s;
        s.from = a;
        s.to = b;
        Eigen::MatrixXd n(p + 1, p + 1), bern(p + 1, p + 1);
        for (std::size_t k = 0; k <= p; ++k) {
            const double x = 0.5 - 0.5 * std::cos((2.0 * static_cast<double>(k) + 1.0) * M_PI / (2.0 * static_cast<double>(p + 1)));
            math_Matrix basis(1, 1, 1, degree + 1);
            int first = 0;
            BSplCLib::EvalBsplineBasis(0, degree + 1, flat, a + x * (b - a), first, basis);
            if (k == 0) s.first = static_cast<std::size_t>(first - 1);
            if (static_cast<std::size_t>(first - 1) != s.first) throw Error(ErrorCode::Internal, "Bézier extraction: a span's basis changed within it");
            const std::vector<double> bx = bernstein(p, x);
            for (std::size_t j = 0; j <= p; ++j) {
                n(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(k)) = basis(1, static_cast<int>(j) + 1);
                bern(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(k)) = bx[j];
            }
        }
        s.c = n * bern.inverse();
        // Exact zeros where the operator has them (round-off of the solve otherwise).
        for (Eigen::Index r = 0; r < s.c.rows(); ++r)
            for (Eigen::Index c = 0; c < s.c.cols(); ++c)
                if (std::abs(s.c(r, c)) < 64.0 * std::numeric_limits<double>::epsilon()) s.c(r, c) = 0.0;
        spans.push_back(std::move(s));
    }
    return spans;
}

}  // namespace

Point3 BezierSurface::point(const BezierElement& e, double s, double t) const
{
    const std::vector<double> bu = bernstein(uDegree, s), bv = bernstein(vDegree, t);
    Point3 p;
    for (std::size_t j = 0; j <= vDegree; ++j)
        for (std::size_t i = 0; i <= uDegree; ++i) p = p + (bu[i] * bv[j]) * e.controlPoints.at(i + (uDegree + 1) * j);
    return p;
}

BezierSurface extractBezier(const TowSurface& tow)
{
    const Handle(Geom_BSplineSurface)& periodic = tow.impl().surface;
    Handle(Geom_BSplineSurface) s = Handle(Geom_BSplineSurface)::DownCast(periodic->Copy());
    if (s.IsNull() || s->IsURational() || s->IsVRational() || s->IsUPeriodic())
        throw Error(ErrorCode::Internal, "tow '" + tow.name() + "': Bézier extraction needs a polynomial surface open along the tow");
    // The periodic v direction unrolled (OCCT: the same geometry, open knots reaching beyond the
    // period, the first q poles repeated at the end); each unrolled function is then numbered as
    // the periodic function it is a piece of, so the basis stays periodic (no slit at the seam).
    const bool vPeriodic = s->IsVPeriodic();
    if (vPeriodic) s->SetVNotPeriodic();
    BezierSurface out;
    out.vPeriodic = vPeriodic;
    out.uDegree = static_cast<std::size_t>(s->UDegree());
    out.vDegree = static_cast<std::size_t>(s->VDegree());
    out.uFunctions = static_cast<std::size_t>(periodic->NbUPoles());
    out.vFunctions = static_cast<std::size_t>(periodic->NbVPoles());
    TColStd_Array1OfReal uFlat(1, s->NbUPoles() + s->UDegree() + 1), vFlat(1, s->NbVPoles() + s->VDegree() + 1);
    s->UKnotSequence(uFlat);
    s->VKnotSequence(vFlat);
    for (int i = uFlat.Lower(); i <= uFlat.Upper(); ++i) out.uKnots.push_back(uFlat(i));
    for (int i = vFlat.Lower(); i <= vFlat.Upper(); ++i) out.vKnots.push_back(vFlat(i));
    for (int i = 1; i <= periodic->NbUPoles(); ++i)
        for (int j = 1; j <= periodic->NbVPoles(); ++j) {
            const gp_Pnt& p = periodic->Pole(i, j);
            out.controlPoints.push_back({p.X(), p.Y(), p.Z()});
        }
    // Unrolled v pole -> periodic v pole, matched by position along the first u row (the
    // unrolled poles are the periodic ones, some repeated).
    std::vector<std::size_t> vOf(static_cast<std::size_t>(s->NbVPoles()));
    const double same = 1e-9 * tow.towSize();
    for (int j = 1; j <= s->NbVPoles(); ++j) {
        int found = 0;
        for (int k = 1; k <= periodic->NbVPoles() && !found; ++k)
            if (s->Pole(1, j).Distance(periodic->Pole(1, k)) <= same && s->Pole(s->NbUPoles(), j).Distance(periodic->Pole(periodic->NbUPoles(), k)) <= same)
                found = k;
        if (!found) throw Error(ErrorCode::Internal, "tow '" + tow.name() + "': an unrolled control point is none of the periodic surface's");
        vOf[static_cast<std::size_t>(j - 1)] = static_cast<std::size_t>(found - 1);
    }
    if (s->NbUPoles() != periodic->NbUPoles()) throw Error(ErrorCode::Internal, "tow '" + tow.name() + "': unrolling v changed the poles along u");
    const std::vector<Span> us = spansOf(uFlat, s->UDegree()), vs = spansOf(vFlat, s->VDegree());
    const std::size_t p = out.uDegree, q = out.vDegree, n = (p + 1) * (q + 1);
    for (std::size_t i = 0; i < us.size(); ++i)
        for (std::size_t j = 0; j < vs.size(); ++j) {
            BezierElement e;
            e.uSpan = i;
            e.vSpan = j;
            e.uMin = us[i].from;
            e.uMax = us[i].to;
            e.vMin = vs[j].from;
            e.vMax = vs[j].to;
            e.extraction.assign(n * n, 0.0);
            e.controlPoints.assign(n, Point3{});
            for (std::size_t av = 0; av <= q; ++av)
                for (std::size_t au = 0; au <= p; ++au) {
                    const std::size_t a = au + (p + 1) * av;
                    const std::size_t global = (us[i].first + au) * out.vFunctions + vOf[vs[j].first + av];
                    e.functions.push_back(global);
                    for (std::size_t bv = 0; bv <= q; ++bv)
                        for (std::size_t bu = 0; bu <= p; ++bu) {
                            const std::size_t b = bu + (p + 1) * bv;
                            const double c = us[i].c(static_cast<Eigen::Index>(au), static_cast<Eigen::Index>(bu)) *
                                             vs[j].c(static_cast<Eigen::Index>(av), static_cast<Eigen::Index>(bv));
                            e.extraction[a * n + b] = c;
                            e.controlPoints[b] = e.controlPoints[b] + c * out.controlPoints[global];
                        }
                }
            out.elements.push_back(std::move(e));
        }
    return out;
}

TOWGEOM_END_NAMESPACE
