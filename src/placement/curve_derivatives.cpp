// Curves on a tool surface as (u,v) cubics: their 3D derivatives through the surface's, their
// tangents and geodesic curvature.
#include "placement/curve_derivatives.hpp"

#include <Geom2d_BSplineCurve.hxx>

#include <algorithm>

#include "placement/uv_interpolation.hpp"
#include "surface/occt_convert.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

bool isClosed(const CurveOnSurface& c)
{
    if (c.points.size() < 3) return false;
    BoundingBox box;
    for (const Point3& p : c.points) box.add(p);
    return distance(c.points.front(), c.points.back()) <= 1e-12 * distance(box.min, box.max);
}

CurveDerivatives curveDerivatives(const Handle(Geom_BSplineSurface)& s, const CurveOnSurface& c)
{
    const std::size_t n = c.uv.size();
    CurveDerivatives out;
    if (n < 2) return out;
    // Points to interpolate: a closed curve's with three more either side of its joint.
    std::vector<UV> uv = c.uv;
    std::size_t lead = 0;
    if (isClosed(c) && n >= 5) {
        const UV period{c.uv.back().u - c.uv.front().u, c.uv.back().v - c.uv.front().v};
        std::vector<UV> wide;
        for (std::size_t k = n - 4; k + 1 < n; ++k) wide.push_back({c.uv[k].u - period.u, c.uv[k].v - period.v});
        lead = wide.size();
        wide.insert(wide.end(), c.uv.begin(), c.uv.end());
        for (std::size_t k = 1; k <= 3; ++k) wide.push_back({c.uv[k].u + period.u, c.uv[k].v + period.v});
        uv = std::move(wide);
    }
    const std::vector<double> params = chordParameters(uv);
    const Handle(Geom2d_BSplineCurve) cubic = n >= 3 ? interpolateUV(uv, params) : Handle(Geom2d_BSplineCurve)();
    if (n >= 3 && cubic.IsNull()) return out;
    for (std::size_t i = 0; i < n; ++i) {
        gp_Pnt p;
        gp_Vec su, sv, suu, svv, suv;
        s->D2(c.uv[i].u, c.uv[i].v, p, su, sv, suu, svv, suv);
        gp_Vec2d d1(c.uv[n - 1].u - c.uv[0].u, c.uv[n - 1].v - c.uv[0].v), d2(0.0, 0.0);
        if (!cubic.IsNull()) {
            gp_Pnt2d q;
            cubic->D2(params[i + lead], q, d1, d2);
        }
        out.first.push_back(su * d1.X() + sv * d1.Y());
        out.second.push_back(suu * (d1.X() * d1.X()) + suv * (2.0 * d1.X() * d1.Y()) + svv * (d1.Y() * d1.Y()) + su * d2.X() + sv * d2.Y());
    }
    // A closed curve's two copies of its joint: one point, one direction (the cubic's global
    // solve leaves them a rounding of its ends apart), so that its offsets close too.
    if (lead > 0) {
        out.first.front() = out.first.back() = 0.5 * (out.first.front() + out.first.back());
        out.second.front() = out.second.back() = 0.5 * (out.second.front() + out.second.back());
    }
    return out;
}

std::vector<gp_Vec> curveTangents(const Handle(Geom_BSplineSurface)& s, const CurveOnSurface& c)
{
    CurveDerivatives d = curveDerivatives(s, c);
    if (d.first.size() == c.uv.size()) return std::move(d.first);
    // Points OpenCASCADE cannot interpolate: the chord between the neighbours.
    std::vector<gp_Vec> out;
    const std::size_t n = c.points.size();
    for (std::size_t i = 0; i < n; ++i)
        out.emplace_back(toOcct(c.points[i > 0 ? i - 1 : i]), toOcct(c.points[i + 1 < n ? i + 1 : i]));
    return out;
}

std::vector<double> geodesicCurvatures(const Handle(Geom_BSplineSurface)& s, const CurveOnSurface& c)
{
    const CurveDerivatives d = curveDerivatives(s, c);
    std::vector<double> out;
    for (std::size_t i = 0; i < d.first.size(); ++i) {
        gp_Pnt p;
        gp_Vec su, sv;
        s->D1(c.uv[i].u, c.uv[i].v, p, su, sv);
        gp_Vec normal = su.Crossed(sv);
        const double speed = d.first[i].Magnitude();
        if (!(normal.Magnitude() > 0.0) || !(speed > 0.0)) {
            out.push_back(0.0);
            continue;
        }
        normal.Normalize();
        out.push_back(d.first[i].Crossed(d.second[i]).Dot(normal) / (speed * speed * speed));
    }
    return out;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
