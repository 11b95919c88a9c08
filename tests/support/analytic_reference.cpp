#include "analytic_reference.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace towgeom::testing {

namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

double integrateEndpointSingular(const std::function<double(double)>& f, double a, double b, int n)
{
    double sum = 0.0;
    for (int k = 0; k < n; ++k) {
        const double phi = kPi * (k + 0.5) / n;
        sum += f(a + 0.5 * (b - a) * (1.0 - std::cos(phi))) * 0.5 * (b - a) * std::sin(phi);
    }
    return sum * kPi / n;
}

double interpolatingControlRadius(std::size_t n, double r) { return r * 6.0 / (4.0 + 2.0 * std::cos(2.0 * kPi / static_cast<double>(n))); }

BSplineCircle uniformBSplineCircle(std::size_t n, double controlRadius)
{
    static const double g6[6] = {-0.9324695142031521, -0.6612093864662645, -0.2386191860831969,
                                 0.2386191860831969,  0.6612093864662645,  0.9324695142031521};
    static const double w6[6] = {0.1713244923791704, 0.3607615730481386, 0.4679139345726910,
                                 0.4679139345726910, 0.3607615730481386, 0.1713244923791704};
    static const double g8[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
                                 0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
    static const double w8[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
                                 0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
    const double w = 2.0 * kPi / static_cast<double>(n);
    // Every span is the first one (control points 0..3) rotated.
    double px[4], py[4];
    for (int k = 0; k < 4; ++k) {
        px[k] = controlRadius * std::cos(k * w);
        py[k] = controlRadius * std::sin(k * w);
    }
    const auto eval = [&](double t, double& x, double& y, double& dx, double& dy) {
        const double s = 1.0 - t;
        const double basis[4] = {s * s * s / 6, (3 * t * t * t - 6 * t * t + 4) / 6, (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6,
                                 t * t * t / 6};
        const double slope[4] = {-s * s / 2, (3 * t * t - 4 * t) / 2, (-3 * t * t + 2 * t + 1) / 2, t * t / 2};
        x = y = dx = dy = 0.0;
        for (int k = 0; k < 4; ++k) {
            x += basis[k] * px[k];
            y += basis[k] * py[k];
            dx += slope[k] * px[k];
            dy += slope[k] * py[k];
        }
    };
    BSplineCircle c;
    double x, y, dx, dy;
    for (int q = 0; q < 6; ++q) {  // x dy - y dx has degree 5 on a span: exact
        eval(0.5 * (g6[q] + 1.0), x, y, dx, dy);
        c.area += 0.5 * w6[q] * 0.5 * (x * dy - y * dx);
    }
    for (int piece = 0; piece < 8; ++piece)
        for (int q = 0; q < 8; ++q) {
            eval((piece + 0.5 * (g8[q] + 1.0)) / 8.0, x, y, dx, dy);
            c.perimeter += w8[q] * 0.5 / 8.0 * std::hypot(dx, dy);
        }
    eval(0.5, x, y, dx, dy);
    c.midRadius = std::hypot(x, y);
    c.area *= static_cast<double>(n);
    c.perimeter *= static_cast<double>(n);
    return c;
}

namespace {
void checkCrossing(const CrossingCylinders& c)
{
    if (!(c.d > c.R - c.r && c.d < c.R + c.r && c.d - c.r > -c.R))
        throw std::invalid_argument("CrossingCylinders: Y does not dip into the top of X");
}
}  // namespace

double CrossingCylinders::loopLength() const
{
    checkCrossing(*this);
    // Y's circle: x = x0 + r cos t, z = d + r sin t; on X, y = +-sqrt(R^2 - z^2), over the arc
    // where z <= R, from pi - t1 to 2 pi + t1 (sin t1 = (R - d) / r). Two mirror halves (y > 0, y < 0).
    const double t1 = std::asin((R - d) / r);
    const auto speed = [&](double t) {
        const double z = d + r * std::sin(t);
        const double below = 2.0 * r * std::cos(0.5 * (t1 + t)) * std::sin(0.5 * (t1 - t));  // R - z, without cancellation
        const double yy = std::abs(below) * (R + z);                                           // R^2 - z^2
        const double dz = r * std::cos(t);
        return std::sqrt(r * r + z * z * dz * dz / yy);
    };
    return 2.0 * integrateEndpointSingular(speed, kPi - t1, 2.0 * kPi + t1);
}

double CrossingCylinders::areaOnX() const
{
    checkCrossing(*this);
    // Around X (angle t from +y towards +z): Y's chord along x is 2 sqrt(r^2 - (R sin t - d)^2),
    // positive for R sin t > d - r, i.e. t in (t0, pi - t0), sin t0 = (d - r) / R.
    const double t0 = std::asin((d - r) / R);
    const auto chord = [&](double t) {
        const double above = 2.0 * R * std::cos(0.5 * (t + t0)) * std::sin(0.5 * (t - t0));  // R sin t - (d - r)
        return 2.0 * R * std::sqrt(std::max(0.0, std::abs(above) * (2.0 * r - std::abs(above))));
    };
    return integrateEndpointSingular(chord, t0, kPi - t0);
}

double CrossingCylinders::areaOnY() const
{
    checkCrossing(*this);
    // Around Y: X's chord along y is 2 sqrt(R^2 - z^2), z = d + r sin t <= R.
    const double t1 = std::asin((R - d) / r);
    const auto chord = [&](double t) {
        const double z = d + r * std::sin(t);
        const double below = 2.0 * r * std::cos(0.5 * (t1 + t)) * std::sin(0.5 * (t1 - t));
        return 2.0 * r * std::sqrt(std::abs(below) * (R + z));
    };
    return integrateEndpointSingular(chord, kPi - t1, 2.0 * kPi + t1);
}

double CrossingCylinders::overlapVolume() const
{
    checkCrossing(*this);
    // At height z in [d - r, R]: Y's chord along x times X's chord along y.
    const auto slice = [&](double z) {
        return 2.0 * std::sqrt(std::max(0.0, r * r - (z - d) * (z - d))) * 2.0 * std::sqrt(std::max(0.0, R * R - z * z));
    };
    return integrateEndpointSingular(slice, d - r, R);
}

RingBarLoop ringBarLoop(double ringRadius, double a, double barY, double barZ, double b)
{
    if (!(barZ - b < a && a < barZ + b)) throw std::invalid_argument("ringBarLoop: the bar does not dip into the ring's top");
    // The bar's circle: y = barY + b cos t, z = barZ + b sin t, over the arc where z <= a
    // (sin t <= (a - barZ) / b). On the torus sqrt(x^2 + y^2) = rho = ringRadius +- sqrt(a^2 - z^2):
    // two branches (outer and inner wall) that meet where z = a.
    const double t1 = std::asin((a - barZ) / b);
    const double from = kPi - t1, to = 2.0 * kPi + t1;
    RingBarLoop loop;
    loop.xMin = 1e300;
    loop.xMax = -1e300;
    for (const double sign : {1.0, -1.0}) {
        const auto point = [&](double t, double& x, double& speed) {
            const double y = barY + b * std::cos(t), z = barZ + b * std::sin(t);
            const double dy = -b * std::sin(t), dz = b * std::cos(t);
            const double gap = 2.0 * b * std::cos(0.5 * (t1 + t)) * std::sin(0.5 * (t1 - t));  // a - z
            const double w = std::sqrt(std::abs(gap) * (a + z));
            const double rho = ringRadius + sign * w;
            const double drho = sign * (-z * dz / w);
            x = std::sqrt(rho * rho - y * y);
            const double dx = (rho * drho - y * dy) / x;
            speed = std::sqrt(dx * dx + dy * dy + dz * dz);
        };
        loop.length += integrateEndpointSingular(
            [&](double t) {
                double x, s;
                point(t, x, s);
                return s;
            },
            from, to);
        // The extremes of x: a dense scan in phi (t = from + (to - from)(1 - cos phi) / 2, in
        // which x is smooth even where the branches meet), good to ~1e-10.
        const int n = 100000;
        for (int k = 0; k <= n; ++k) {
            const double t = from + 0.5 * (to - from) * (1.0 - std::cos(kPi * k / n));
            double x, s;
            if (k == 0 || k == n)  // the branches meet: w = 0, rho = ringRadius
                x = std::sqrt(ringRadius * ringRadius - std::pow(barY + b * std::cos(t), 2));
            else
                point(t, x, s);
            loop.xMin = std::min(loop.xMin, x);
            loop.xMax = std::max(loop.xMax, x);
        }
    }
    return loop;
}

}  // namespace towgeom::testing
