// Yarn paths (Hermite, Catmull-Rom, cardinal) and cross-sections against closed forms.
#include <catch2/catch.hpp>

#include <towgeom/towgeom.hpp>

#include <cmath>

#include "analytic_reference.hpp"

using namespace towgeom;

namespace {

constexpr double kPi = 3.14159265358979323846;

double polygonArea(const std::vector<Point2>& p)
{
    double a = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) a += p[i].x * p[(i + 1) % p.size()].y - p[(i + 1) % p.size()].x * p[i].y;
    return 0.5 * a;
}

/// A straight tube along x whose sections are @p section sampled with @p n points.
TowStack straightTube(const CrossSection& section, std::size_t n)
{
    TowStack s;
    s.name = "section_test";
    for (int i = 0; i < 9; ++i) {
        std::vector<Point3> ring;
        for (const Point2& p : section.sample(n)) ring.push_back({0.25 * i, p.x, p.y});
        s.sections.push_back(ring);
    }
    return s;
}

}  // namespace

TEST_CASE("Catmull-Rom interpolates its points with a continuous tangent", "[yarn]")
{
    const std::vector<Point3> p{{0, 0, 0}, {1, 0.2, 0.1}, {2, -0.1, 0.0}, {3, 0.3, -0.2}, {4, 0.0, 0.0}};
    const YarnPath path = YarnPath::catmullRom(p);
    REQUIRE(path.lastParameter() == 4.0);
    for (std::size_t i = 0; i < p.size(); ++i) CHECK(distance(path.point(static_cast<double>(i)), p[i]) < 1e-14);
    for (std::size_t i = 1; i + 1 < p.size(); ++i) {
        const double t = static_cast<double>(i);
        const Vector3 expected = 0.5 * (p[i + 1] - p[i - 1]);
        CHECK(distance(path.derivative(t), expected) < 1e-12);
        const Vector3 left = path.derivative(t - 1e-9), right = path.derivative(t + 1e-9);
        CHECK(distance(left, right) < 1e-7);
    }
    // Cardinal tension scales the tangents by (1 - s).
    const YarnPath tense = YarnPath::cardinal(p, 0.5);
    CHECK(distance(tense.derivative(2.0), 0.25 * (p[3] - p[1])) < 1e-12);
    CHECK(distance(tense.point(3.0), p[3]) < 1e-14);
}

TEST_CASE("a Hermite path with exact tangents reproduces a parabola and its curvature", "[yarn]")
{
    std::vector<Point3> p;
    std::vector<Vector3> m;
    for (int i = 0; i < 4; ++i) {
        p.push_back({double(i), double(i * i), 0.0});
        m.push_back({1.0, 2.0 * i, 0.0});
    }
    const YarnPath path = YarnPath::hermite(p, m);
    for (const double t : {0.3, 1.5, 2.75}) {
        CHECK(distance(path.point(t), Point3{t, t * t, 0.0}) < 1e-12);
        CHECK(path.curvature(t) == Approx(2.0 / std::pow(1.0 + 4.0 * t * t, 1.5)).epsilon(1e-10));
    }
    // Arc length of y = x^2 from 0 to 1: (2 sqrt5 + asinh 2) / 4.
    CHECK(path.length(0.0, 1.0) == Approx((2 * std::sqrt(5.0) + std::asinh(2.0)) / 4).epsilon(1e-9));
    CHECK_THROWS_AS(YarnPath::catmullRom({{0, 0, 0}}), Error);
    CHECK_THROWS_AS(YarnPath::catmullRom({{0, 0, 0}, {0, 0, 0}}), Error);
    CHECK_THROWS_AS(YarnPath::cardinal({{0, 0, 0}, {1, 0, 0}}, 1.5), Error);
}

TEST_CASE("section areas match their closed forms", "[yarn][section]")
{
    const double w = 0.8, h = 0.2;
    const double r = (w * w + h * h) / (4 * h), alpha = std::asin(w / (2 * r));
    // polygon: relative shortfall of the 20000-gon's area (observed 1.6e-8 circle and ellipse,
    // where it is exactly (n/2) sin(2 pi / n) / pi - 1, 2.9e-8 racetrack, 1.05e-8 lenticular and
    // Hermite); fitted: relative error of the fitted tow's section area at 64 points (observed:
    // circle -2.6e-7, exactly the reference B-spline's; ellipse 3.0e-6; racetrack -4.1e-6;
    // lenticular 8.4e-4 and Hermite 8.7e-4, the smooth fit overshooting the pointed tips).
    const struct {
        SectionShape shape;
        double exact;
        double polygon, fitted;
    } cases[] = {
        {SectionShape::Circle, kPi * w * w / 4, 0.0, 0.0},
        {SectionShape::Ellipse, kPi * w * h / 4, 0.0, 7e-6},
        {SectionShape::Racetrack, (w - h) * h + kPi * h * h / 4, 7e-8, 1e-5},
        {SectionShape::Lenticular, r * r * (2 * alpha - std::sin(2 * alpha)), 3e-8, 1e-3},
        {SectionShape::Hermite, -1.0, 3e-8, 1e-3},  // its own exact polynomial integral; checked by sampling
    };
    for (const auto& c : cases) {
        DYNAMIC_SECTION(sectionShapeName(c.shape))
        {
            const CrossSection section{c.shape, w, h, 1.0};
            if (c.exact > 0) CHECK(section.area() == Approx(c.exact).epsilon(1e-12));
            // The closed form against a fine polygon, inscribed: a little smaller. Circle and ellipse
            // are sampled evenly in angle, so the polygon's area is (n/2) sin(2 pi / n) / pi of theirs.
            const double polygon = polygonArea(section.sample(20000)) / section.area() - 1;
            CHECK(polygon < 0.0);
            if (c.polygon == 0.0)
                CHECK(polygonArea(section.sample(20000)) == Approx(section.area() * 10000.0 * std::sin(2 * kPi / 20000) / kPi).epsilon(1e-12));
            else
                CHECK(polygon > -c.polygon);
            // At N = 64, the fitted tow's section area.
            const TowSurface tow = TowSurface::fit(straightTube(section, 64));
            const double area = tow.sectionArea(0.5);
            WARN(sectionShapeName(c.shape) << ": fitted section area " << area << ", exact " << section.area() << " ("
                                           << area / section.area() - 1 << "), polygon of 64 " << polygonArea(section.sample(64)));
            if (c.fitted == 0.0)  // the periodic cubic B-spline through the 64-gon (testing::uniformBSplineCircle)
                CHECK(area == Approx(testing::uniformBSplineCircle(64, testing::interpolatingControlRadius(64, w / 2)).area).epsilon(1e-12));
            else
                CHECK(std::fabs(area / section.area() - 1) < c.fitted);
            // The first point sits at (xmax, 0); points go counter-clockwise.
            const auto pts = section.sample(64);
            CHECK(pts.front().y == Approx(0.0).margin(1e-12));
            CHECK(polygonArea(pts) > 0);
        }
    }
}

TEST_CASE("flattening lowers the section and widens it in proportion", "[yarn][section]")
{
    for (const SectionShape shape : {SectionShape::Ellipse, SectionShape::Lenticular, SectionShape::Hermite}) {
        const CrossSection flat{shape, 0.8, 0.2, 0.6};
        double ymax = 0.0, xmax = 0.0;
        for (const Point2& p : flat.sample(64)) {
            ymax = std::max(ymax, p.y);
            xmax = std::max(xmax, p.x);
        }
        CHECK(ymax == Approx(0.6 * 0.1).epsilon(1e-9));
        CHECK(xmax == Approx(0.4 * (1 + 0.5 * 0.4)).epsilon(1e-9));
    }
    CHECK_THROWS_AS((CrossSection{SectionShape::Lenticular, 0.2, 0.8, 1.0}.sample(32)), Error);
    CHECK_THROWS_AS((CrossSection{SectionShape::Hermite, 0.8, 0.2, 1.0}.sample(33)), Error);
    CHECK_THROWS_AS((CrossSection{SectionShape::Ellipse, 0.8, 0.2, 0.0}.sample(32)), Error);
}
