// CrossSection: closed forms and sampling of the generator's section shapes.
#include "towgeom/cross_section.hpp"

#include <array>
#include <cmath>

#include "core/elapsed.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

using detail::kPi;

using Bezier = std::array<Point2, 4>;

Point2 at(const Bezier& b, double t)
{
    const double s = 1.0 - t;
    const double c0 = s * s * s, c1 = 3 * s * s * t, c2 = 3 * s * t * t, c3 = t * t * t;
    return {c0 * b[0].x + c1 * b[1].x + c2 * b[2].x + c3 * b[3].x, c0 * b[0].y + c1 * b[1].y + c2 * b[2].y + c3 * b[3].y};
}

/// Integral of x dy along the Bezier curve: exact (degree 5) with 3-point Gauss.
double xdy(const Bezier& b)
{
    const double g[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, w[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
    double sum = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double t = 0.5 * (g[k] + 1.0), s = 1.0 - t;
        const Point2 p = at(b, t);
        const double dy = 3 * (s * s * (b[1].y - b[0].y) + 2 * s * t * (b[2].y - b[1].y) + t * t * (b[3].y - b[2].y));
        sum += 0.5 * w[k] * p.x * dy;
    }
    return sum;
}

/// The two Hermite caps (top from the right corner to the left, bottom back) with the cap
/// tangent magnitude scaled by @p f.
std::array<Bezier, 2> hermiteCaps(double width, double height, double f)
{
    const double alpha = 2.0 * std::atan(height / width);  // half-angle of the matching circular arc
    const double r = width / (2.0 * std::sin(alpha));
    const double u = f * 4.0 * r * (1.0 - std::cos(alpha)) / std::sin(alpha);
    const double c = std::cos(alpha), s = std::sin(alpha), k = u / 3.0, h = width / 2.0;
    const Bezier top{{{h, 0.0}, {h - k * c, k * s}, {-h + k * c, k * s}, {-h, 0.0}}};
    const Bezier bottom{{{-h, 0.0}, {-h + k * c, -k * s}, {h - k * c, -k * s}, {h, 0.0}}};
    return {top, bottom};
}

double hermiteArea(double width, double height, double f)
{
    const auto caps = hermiteCaps(width, height, f);
    return xdy(caps[0]) + xdy(caps[1]);
}

/// Points on the racetrack boundary at arc length s from (w/2, 0), counter-clockwise.
Point2 racetrackAt(double w, double h, double s)
{
    const double r = h / 2.0, l = w - h, quarter = kPi * r / 2.0;
    if (s < quarter) return {l / 2 + r * std::cos(s / r), r * std::sin(s / r)};
    s -= quarter;
    if (s < l) return {l / 2 - s, r};
    s -= l;
    if (s < 2 * quarter) {
        const double a = kPi / 2 + s / r;
        return {-l / 2 + r * std::cos(a), r * std::sin(a)};
    }
    s -= 2 * quarter;
    if (s < l) return {-l / 2 + s, -r};
    s -= l;
    const double a = 3 * kPi / 2 + s / r;
    return {l / 2 + r * std::cos(a), r * std::sin(a)};
}

/// The lateral widening that goes with a flattening factor f: proportional to the flattening.
double widening(double f) { return 1.0 + 0.5 * (1.0 - f); }

[[noreturn]] void invalid(const std::string& why) { throw Error(ErrorCode::InvalidArgument, "cross-section: " + why); }

}  // namespace

const char* sectionShapeName(SectionShape shape) noexcept
{
    switch (shape) {
    case SectionShape::Circle: return "circle";
    case SectionShape::Ellipse: return "ellipse";
    case SectionShape::Racetrack: return "racetrack";
    case SectionShape::Lenticular: return "lenticular";
    case SectionShape::Hermite: return "hermite";
    }
    return "unknown";
}

void CrossSection::validate() const
{
    if (!(width > 0.0 && std::isfinite(width))) invalid("width must be positive");
    if (!(height > 0.0 && std::isfinite(height)) && shape != SectionShape::Circle) invalid("height must be positive");
    if (!(flattening > 0.0 && flattening <= 1.0)) invalid("flattening must lie in (0, 1]");
    if ((shape == SectionShape::Racetrack || shape == SectionShape::Lenticular || shape == SectionShape::Hermite) &&
        height > width)
        invalid(std::string(sectionShapeName(shape)) + " sections need height <= width");
}

double CrossSection::area() const
{
    validate();
    const double w = width, h = height;
    switch (shape) {
    case SectionShape::Circle: return kPi * w * w / 4.0;
    case SectionShape::Ellipse: return kPi * w * h / 4.0;
    case SectionShape::Racetrack: return (w - h) * h + kPi * h * h / 4.0;
    case SectionShape::Lenticular: {
        const double r = (w * w + h * h) / (4.0 * h);
        const double alpha = std::asin(std::min(1.0, w / (2.0 * r)));
        return r * r * (2.0 * alpha - std::sin(2.0 * alpha));
    }
    case SectionShape::Hermite: return hermiteArea(w, h, 1.0);
    }
    return 0.0;
}

std::vector<Point2> CrossSection::sample(std::size_t count) const
{
    validate();
    if (count < 6) invalid("at least 6 points are needed");
    const bool needsEven = shape == SectionShape::Lenticular || shape == SectionShape::Hermite;
    if (needsEven && count % 2) invalid(std::string(sectionShapeName(shape)) + " sections need an even point count");
    const double w = width, h = height, f = flattening;
    const double n = static_cast<double>(count);
    std::vector<Point2> out;
    out.reserve(count);
    // Flattening: y scaled by f, x widened in proportion, by 1 + (1 - f) / 2.
    const double sx = widening(f), sy = f;
    switch (shape) {
    case SectionShape::Circle:
    case SectionShape::Ellipse: {
        const double a = w / 2.0, b = shape == SectionShape::Circle ? w / 2.0 : h / 2.0;
        for (std::size_t k = 0; k < count; ++k) {
            const double t = 2.0 * kPi * k / n;
            out.push_back({sx * a * std::cos(t), sy * b * std::sin(t)});
        }
        break;
    }
    case SectionShape::Racetrack: {
        const double perimeter = 2.0 * (w - h) + kPi * h;
        for (std::size_t k = 0; k < count; ++k) {
            const Point2 p = racetrackAt(w, h, perimeter * k / n);
            out.push_back({sx * p.x, sy * p.y});
        }
        break;
    }
    case SectionShape::Lenticular: {
        const double r = (w * w + h * h) / (4.0 * h), d = r - h / 2.0;
        const double alpha = std::asin(std::min(1.0, w / (2.0 * r)));
        const std::size_t half = count / 2;
        for (int arc = 0; arc < 2; ++arc) {
            const double start = arc == 0 ? kPi / 2 - alpha : 3 * kPi / 2 - alpha;
            const double cy = arc == 0 ? -d : d;
            for (std::size_t k = 0; k < half; ++k) {
                const double a = start + 2.0 * alpha * k / static_cast<double>(half);
                out.push_back({sx * r * std::cos(a), sy * (cy + r * std::sin(a))});
            }
        }
        break;
    }
    case SectionShape::Hermite: {
        // The caps' height is proportional to the tangent magnitude: scale it by f, then widen.
        const auto caps = hermiteCaps(w, h, f);
        const double widen = widening(f);
        const std::size_t half = count / 2;
        for (const Bezier& cap : caps)
            for (std::size_t k = 0; k < half; ++k) {
                const Point2 p = at(cap, static_cast<double>(k) / static_cast<double>(half));
                out.push_back({widen * p.x, p.y});
            }
        break;
    }
    }
    return out;
}

TOWGEOM_END_NAMESPACE
