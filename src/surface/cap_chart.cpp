#include "surface/cap_chart.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "core/elapsed.hpp"
#include "surface/occt_convert.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

constexpr int kRimSamples = 256;
using detail::kPi;

/// The mean point of the section at @p u (from kRimSamples points).
gp_XYZ sectionMean(const GeomAdaptor_Surface& s, double u, double v0, double period, int n)
{
    gp_XYZ sum(0, 0, 0);
    for (int k = 0; k < n; ++k) sum += s.Value(u, v0 + period * k / n).XYZ();
    return sum / n;
}

CapChart makeCap(const GeomAdaptor_Surface& s, double uRim, bool start, double depth, double v0, double period)
{
    CapChart c;
    c.uRim = uRim;
    c.uPole = start ? uRim - depth : uRim + depth;
    std::vector<gp_XYZ> rim;
    gp_XYZ alongU(0, 0, 0), newell(0, 0, 0);
    for (int k = 0; k <= kRimSamples; ++k) {
        const double v = v0 + period * k / kRimSamples;
        gp_Pnt p;
        gp_Vec du, dv;
        s.D1(uRim, v, p, du, dv);
        c.v.push_back(v);
        rim.push_back(p.XYZ());
        if (k < kRimSamples) alongU += du.XYZ();
    }
    for (int k = 0; k < kRimSamples; ++k) c.centre += rim[static_cast<std::size_t>(k)];
    c.centre /= kRimSamples;
    for (int k = 0; k < kRimSamples; ++k) newell += (rim[static_cast<std::size_t>(k)] - c.centre).Crossed(rim[static_cast<std::size_t>(k) + 1] - c.centre);
    if (newell.Modulus() <= 0.0) return c;
    c.normal = newell / newell.Modulus();
    if ((c.normal.Dot(alongU) > 0.0) == start) c.normal.Reverse();  // out of the tow
    const gp_XYZ helper = std::abs(c.normal.X()) < 0.6 ? gp_XYZ(1, 0, 0) : gp_XYZ(0, 1, 0);
    c.e1 = helper.Crossed(c.normal);
    c.e1 /= c.e1.Modulus();
    c.e2 = c.normal.Crossed(c.e1);
    // Polar angles of the rim samples, unwrapped; the chart is one-to-one when they turn one way
    // once around.
    double sign = 0.0;
    bool monotone = true;
    for (std::size_t k = 0; k < rim.size(); ++k) {
        const gp_XYZ q = rim[k] - c.centre;
        double a = std::atan2(q.Dot(c.e2), q.Dot(c.e1));
        c.radius += k < rim.size() - 1 ? q.Modulus() / kRimSamples : 0.0;
        if (!c.angle.empty()) {
            a += 2.0 * kPi * std::round((c.angle.back() - a) / (2.0 * kPi));
            const double step = a - c.angle.back();
            if (sign == 0.0) sign = step > 0.0 ? 1.0 : -1.0;
            if (!(step * sign > 0.0)) monotone = false;
        }
        c.angle.push_back(a);
    }
    c.valid = monotone && std::abs(std::abs(c.angle.back() - c.angle.front()) - 2.0 * kPi) < 1e-6;
    return c;
}

}  // namespace

TowCaps capChartsOf(const Handle(Geom_BSplineSurface)& surface)
{
    TowCaps caps;
    double u0, u1, v0, v1;
    surface->Bounds(u0, u1, v0, v1);
    caps.uMin = u0;
    caps.uMax = u1;
    const GeomAdaptor_Surface s(surface);
    const double period = v1 - v0;
    // The tube's length along its centre line, and its mean radius at the ends: the caps' depth
    // in u makes a step in u on a cap about as long as one along the tube.
    constexpr int kAlong = 32;
    double length = 0.0;
    gp_XYZ previous = sectionMean(s, u0, v0, period, 16);
    for (int i = 1; i <= kAlong; ++i) {
        const gp_XYZ m = sectionMean(s, u0 + (u1 - u0) * i / kAlong, v0, period, 16);
        length += (m - previous).Modulus();
        previous = m;
    }
    caps.start = makeCap(s, u0, true, 1.0, v0, period);
    caps.end = makeCap(s, u1, false, 1.0, v0, period);
    const double radius = 0.5 * (caps.start.radius + caps.end.radius);
    const double depth = length > 0.0 && radius > 0.0 ? (u1 - u0) * std::min(1.0, radius / length) : 0.1 * (u1 - u0);
    caps.start.uPole = u0 - depth;
    caps.end.uPole = u1 + depth;
    return caps;
}

void chartD1(const GeomAdaptor_Surface& tube, const TowCaps& caps, double u, double v, gp_Pnt& p, gp_Vec& du, gp_Vec& dv)
{
    const CapChart* cap = caps.capAt(u);
    if (!cap) {
        tube.D1(u, v, p, du, dv);
        return;
    }
    gp_Pnt r;
    gp_Vec ru, rv;
    tube.D1(cap->uRim, v, r, ru, rv);
    const double depth = cap->uRim - cap->uPole;  // negative at the end
    const double rho = (u - cap->uPole) / depth;
    const gp_XYZ radial = r.XYZ() - cap->centre;
    p = gp_Pnt(cap->centre + rho * radial);
    du = gp_Vec(radial / depth);
    dv = rho * rv;
}

Point3 chartPoint(const GeomAdaptor_Surface& tube, const TowCaps& caps, double u, double v)
{
    gp_Pnt p;
    gp_Vec du, dv;
    chartD1(tube, caps, u, v, p, du, dv);
    return fromOcct(p);
}

bool capParameters(const GeomAdaptor_Surface& tube, const CapChart& cap, const gp_Pnt& p, double vNear, double& u, double& v)
{
    if (!cap.valid) return false;
    const gp_XYZ q = p.XYZ() - cap.centre;
    const double qx = q.Dot(cap.e1), qy = q.Dot(cap.e2);
    const double r = std::hypot(qx, qy);
    if (!(r > 1e-12 * cap.radius)) return false;
    // The polar angle within the table's turn, bracketed by two samples.
    const double first = cap.angle.front(), last = cap.angle.back();
    const bool increasing = last > first;
    double phi = std::atan2(qy, qx);
    const double lo = std::min(first, last);
    phi += 2.0 * kPi * std::floor((lo + 2.0 * kPi - phi) / (2.0 * kPi));
    if (phi < lo) phi += 2.0 * kPi;
    std::size_t k = 0;
    if (increasing)
        k = static_cast<std::size_t>(std::upper_bound(cap.angle.begin(), cap.angle.end(), phi) - cap.angle.begin());
    else
        k = static_cast<std::size_t>(std::upper_bound(cap.angle.begin(), cap.angle.end(), phi, std::greater<double>()) - cap.angle.begin());
    k = std::clamp<std::size_t>(k, 1, cap.angle.size() - 1);
    double a = cap.v[k - 1], b = cap.v[k];
    const double fa = cap.angle[k - 1] - phi, fb = cap.angle[k] - phi;
    const double t = fb != fa ? std::clamp(-fa / (fb - fa), 0.0, 1.0) : 0.5;
    v = a + t * (b - a);
    // Newton on the rim's polar angle, safeguarded by the bracket [a, b] (bisection when a step
    // would leave it).
    const bool faPositive = fa > 0.0;
    double ru = 0.0;
    for (int it = 0; it < 40; ++it) {
        gp_Pnt rp;
        gp_Vec rdu, rdv;
        tube.D1(cap.uRim, v, rp, rdu, rdv);
        const gp_XYZ s = rp.XYZ() - cap.centre;
        const double sx = s.Dot(cap.e1), sy = s.Dot(cap.e2);
        ru = std::hypot(sx, sy);
        double diff = std::atan2(sy, sx) - phi;
        diff -= 2.0 * kPi * std::round(diff / (2.0 * kPi));
        if (std::abs(diff) < 1e-14) break;
        if ((diff > 0.0) == faPositive)
            a = v;
        else
            b = v;
        const double dx = rdv.XYZ().Dot(cap.e1), dy = rdv.XYZ().Dot(cap.e2);
        const double rate = (sx * dy - sy * dx) / (ru * ru);
        const double next = std::abs(rate) > 0.0 ? v - diff / rate : 0.5 * (a + b);
        v = next > std::min(a, b) && next < std::max(a, b) ? next : 0.5 * (a + b);
    }
    if (!(ru > 0.0)) return false;
    const double period = cap.v.back() - cap.v.front();
    v += period * std::round((vNear - v) / period);
    u = cap.uPole + (r / ru) * (cap.uRim - cap.uPole);
    return std::isfinite(u) && std::isfinite(v);
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
