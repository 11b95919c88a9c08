#include "placement/nurbs_geometry.hpp"

#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include <string>
#include <vector>

#include "placement/nurbs_basis.hpp"
#include "surface/occt_convert.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

/// Distinct knots and multiplicities of a full knot vector (OCCT's form).
void splitKnots(const std::vector<double>& full, TColStd_Array1OfReal& knots, TColStd_Array1OfInteger& mults)
{
    std::vector<double> k;
    std::vector<int> m;
    for (double x : full) {
        if (!k.empty() && x == k.back()) ++m.back();
        else {
            k.push_back(x);
            m.push_back(1);
        }
    }
    knots.Resize(1, static_cast<int>(k.size()), Standard_False);
    mults.Resize(1, static_cast<int>(m.size()), Standard_False);
    for (std::size_t i = 0; i < k.size(); ++i) {
        knots.SetValue(static_cast<int>(i) + 1, k[i]);
        mults.SetValue(static_cast<int>(i) + 1, m[i]);
    }
}

std::vector<double> fullKnots(const TColStd_Array1OfReal& knots, const TColStd_Array1OfInteger& mults)
{
    std::vector<double> full;
    for (int i = knots.Lower(); i <= knots.Upper(); ++i)
        for (int k = 0; k < mults(i); ++k) full.push_back(knots(i));
    return full;
}

}  // namespace

Handle(Geom_BSplineCurve) occtCurve(const NurbsCurve& c)
{
    checkKnots(c.knots, c.degree, c.poles.size(), "curve");
    checkWeights(c.weights, c.poles.size(), "curve");
    checkPoles(c.poles, "curve");
    TColgp_Array1OfPnt poles(1, static_cast<int>(c.poles.size()));
    TColStd_Array1OfReal weights(1, static_cast<int>(c.poles.size()));
    for (std::size_t i = 0; i < c.poles.size(); ++i) {
        poles.SetValue(static_cast<int>(i) + 1, detail::toOcct(c.poles[i]));
        weights.SetValue(static_cast<int>(i) + 1, c.weights[i]);
    }
    TColStd_Array1OfReal knots(1, 1);
    TColStd_Array1OfInteger mults(1, 1);
    splitKnots(c.knots, knots, mults);
    return new Geom_BSplineCurve(poles, weights, knots, mults, c.degree);
}

NurbsCurve nurbsCurve(const Handle(Geom_BSplineCurve)& g)
{
    NurbsCurve c;
    c.degree = g->Degree();
    c.knots = fullKnots(g->Knots(), g->Multiplicities());
    for (int i = 1; i <= g->NbPoles(); ++i) {
        c.poles.push_back(detail::fromOcct(g->Pole(i)));
        c.weights.push_back(g->Weight(i));
    }
    return c;
}

Handle(Geom_BSplineSurface) occtSurface(const NurbsSurface& s)
{
    checkKnots(s.uKnots, s.uDegree, s.uCount, "surface (u)");
    checkKnots(s.vKnots, s.vDegree, s.vCount, "surface (v)");
    checkWeights(s.weights, s.uCount * s.vCount, "surface");
    checkPoles(s.poles, "surface");
    if (s.poles.size() != s.uCount * s.vCount)
        throw Error(ErrorCode::InvalidArgument, "NURBS surface: " + std::to_string(s.poles.size()) + " poles, not uCount x vCount");
    const int nu = static_cast<int>(s.uCount), nv = static_cast<int>(s.vCount);
    TColgp_Array2OfPnt poles(1, nu, 1, nv);
    TColStd_Array2OfReal weights(1, nu, 1, nv);
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const std::size_t k = static_cast<std::size_t>(i) * s.vCount + static_cast<std::size_t>(j);
            poles.SetValue(i + 1, j + 1, detail::toOcct(s.poles[k]));
            weights.SetValue(i + 1, j + 1, s.weights[k]);
        }
    TColStd_Array1OfReal uk(1, 1), vk(1, 1);
    TColStd_Array1OfInteger um(1, 1), vm(1, 1);
    splitKnots(s.uKnots, uk, um);
    splitKnots(s.vKnots, vk, vm);
    return new Geom_BSplineSurface(poles, weights, uk, vk, um, vm, s.uDegree, s.vDegree);
}

NurbsSurface nurbsSurface(const Handle(Geom_BSplineSurface)& g)
{
    NurbsSurface s;
    s.uDegree = g->UDegree();
    s.vDegree = g->VDegree();
    s.uKnots = fullKnots(g->UKnots(), g->UMultiplicities());
    s.vKnots = fullKnots(g->VKnots(), g->VMultiplicities());
    s.uCount = static_cast<std::size_t>(g->NbUPoles());
    s.vCount = static_cast<std::size_t>(g->NbVPoles());
    for (int i = 1; i <= g->NbUPoles(); ++i)
        for (int j = 1; j <= g->NbVPoles(); ++j) {
            s.poles.push_back(detail::fromOcct(g->Pole(i, j)));
            s.weights.push_back(g->Weight(i, j));
        }
    return s;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
