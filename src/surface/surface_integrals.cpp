// TowSurface integrals: volume, lateral area, section area, faceted volume of the input.
#include <GeomAdaptor_Surface.hxx>
#include <math.hxx>
#include <math_Vector.hxx>

#include <algorithm>
#include <cmath>

#include "surface/occt_convert.hpp"
#include "surface/occt_guard.hpp"
#include "surface/tow_surface_impl.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

using detail::fromOcct;

namespace {

/// Gauss-Legendre rule with N points. 5 are exact for the degree-8 polynomial integrands of a
/// bicubic patch (volume); the area's |S_u x S_v| is no polynomial: 12 bring it to about 1e-9
/// relative (5 left 5e-6 on the twill's tows).
template <int N = 5>
struct GaussRule {
    static constexpr int kPoints = N;
    double x[kPoints];
    double w[kPoints];
    GaussRule()
    {
        math_Vector p(1, kPoints), q(1, kPoints);
        math::GaussPoints(kPoints, p);
        math::GaussWeights(kPoints, q);
        for (int i = 0; i < kPoints; ++i) {
            x[i] = p(i + 1);
            w[i] = q(i + 1);
        }
    }
};

template <int N = 5>
const GaussRule<N>& gauss()
{
    static const GaussRule<N> rule;
    return rule;
}

std::vector<double> knots(const Geom_BSplineSurface& s, bool alongU)
{
    std::vector<double> k;
    const int n = alongU ? s.NbUKnots() : s.NbVKnots();
    for (int i = 1; i <= n; ++i) k.push_back(alongU ? s.UKnot(i) : s.VKnot(i));
    return k;
}

/// Calls f(u, v, weight) at the N x N Gauss points of every knot span of the surface.
template <int N = 5, class F>
void integrate(const Geom_BSplineSurface& s, F&& f)
{
    const GaussRule<N>& g = gauss<N>();
    const std::vector<double> ku = knots(s, true), kv = knots(s, false);
    for (std::size_t a = 0; a + 1 < ku.size(); ++a) {
        const double hu = 0.5 * (ku[a + 1] - ku[a]), mu = 0.5 * (ku[a + 1] + ku[a]);
        for (std::size_t b = 0; b + 1 < kv.size(); ++b) {
            const double hv = 0.5 * (kv[b + 1] - kv[b]), mv = 0.5 * (kv[b + 1] + kv[b]);
            for (int i = 0; i < N; ++i)
                for (int j = 0; j < N; ++j)
                    f(mu + hu * g.x[i], mv + hv * g.x[j], hu * hv * g.w[i] * g.w[j]);
        }
    }
}

struct SectionIntegral {
    gp_XYZ vectorArea;  // (1/2) integral of C x C' dv
    gp_XYZ centroid;    // arc-length centroid of the curve
};

SectionIntegral sectionIntegral(const GeomAdaptor_Surface& adaptor, const std::vector<double>& kv, double u)
{
    const GaussRule<>& g = gauss();
    SectionIntegral r{gp_XYZ(0, 0, 0), gp_XYZ(0, 0, 0)};
    double length = 0.0;
    for (std::size_t b = 0; b + 1 < kv.size(); ++b) {
        const double hv = 0.5 * (kv[b + 1] - kv[b]), mv = 0.5 * (kv[b + 1] + kv[b]);
        for (int j = 0; j < GaussRule<>::kPoints; ++j) {
            gp_Pnt p;
            gp_Vec du, dv;
            adaptor.D1(u, mv + hv * g.x[j], p, du, dv);
            const double w = hv * g.w[j];
            r.vectorArea += 0.5 * w * p.XYZ().Crossed(dv.XYZ());
            const double dl = w * dv.Magnitude();
            r.centroid += dl * p.XYZ();
            length += dl;
        }
    }
    r.centroid /= length;
    return r;
}

}  // namespace

double TowSurface::sectionArea(double u) const
{
    return detail::guarded(impl_->name, "sectionArea", [&]() -> double {
        const ParameterRange r = parameterRange();
        point(u, 0.0);  // range check
        // In the unit frame (see TowSurface::Impl::unit), scaled back exactly (a power of two).
        GeomAdaptor_Surface adaptor(impl_->unit);
        const double s = impl_->unitFrame.scale;
        return sectionIntegral(adaptor, knots(*impl_->unit, false), std::clamp(u, r.uMin, r.uMax)).vectorArea.Modulus() / (s * s);
    });
}

double TowSurface::volume() const
{
    return detail::guarded(impl_->name, "volume", [&]() -> double {
        // In the unit frame (see TowSurface::Impl::unit), scaled back exactly (a power of two).
        const Geom_BSplineSurface& s = *impl_->unit;
        GeomAdaptor_Surface adaptor(impl_->unit);
        const double scale = impl_->unitFrame.scale;
        // Divergence theorem with F = (x - ref) / 3; ref near the tow keeps the sum well conditioned.
        BoundingBox box;
        const TColgp_Array2OfPnt& poles = s.Poles();
        for (int i = poles.LowerRow(); i <= poles.UpperRow(); ++i)
            for (int j = poles.LowerCol(); j <= poles.UpperCol(); ++j) box.add(fromOcct(poles(i, j)));
        const gp_XYZ ref = 0.5 * (detail::toOcct(box.min).XYZ() + detail::toOcct(box.max).XYZ());
        double lateral = 0.0;
        integrate(s, [&](double u, double v, double w) {
            gp_Pnt p;
            gp_Vec du, dv;
            adaptor.D1(u, v, p, du, dv);
            lateral += w * (p.XYZ() - ref).Dot(du.XYZ().Crossed(dv.XYZ()));
        });
        // Ends: dS/du x dS/dv points outwards, so v runs clockwise about the tow's direction and the
        // vector area of an end curve points backwards along the tow: outward at the first end,
        // inward at the last.
        const std::vector<double> kv = knots(s, false);
        const ParameterRange r = parameterRange();
        const SectionIntegral first = sectionIntegral(adaptor, kv, r.uMin);
        const SectionIntegral last = sectionIntegral(adaptor, kv, r.uMax);
        const double caps = (first.centroid - ref).Dot(first.vectorArea) - (last.centroid - ref).Dot(last.vectorArea);
        return (lateral + caps) / 3.0 / (scale * scale * scale);
    });
}

double TowSurface::area() const
{
    return detail::guarded(impl_->name, "area", [&]() -> double {
        GeomAdaptor_Surface adaptor(impl_->unit);
        const double scale = impl_->unitFrame.scale;
        double total = 0.0;
        integrate<12>(*impl_->unit, [&](double u, double v, double w) {
            gp_Pnt p;
            gp_Vec du, dv;
            adaptor.D1(u, v, p, du, dv);
            total += w * du.Crossed(dv).Magnitude();
        });
        return total / (scale * scale);
    });
}

double TowSurface::facetedVolume() const
{
    return detail::guarded(impl_->name, "facetedVolume", [&]() -> double {
        // The sections are in the surface's order, so the tube's triangles face outwards.
        TowStack stack;
        stack.sections = impl_->sections;
        return enclosedVolume(facetedTube(stack, true));
    });
}

TOWGEOM_END_NAMESPACE
