// Loops that wind around a tow, in the internal tests of loops on one tow: a loop around the tow
// closes one period on (its closing chord is no edge across the tow) and bounds no inside, so a
// loop of another pair beside it neither meets nor crosses it unless their curves cross.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "region/connected_region.hpp"
#include "region/winding_loops.hpp"

using namespace towgeom;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// u = 0.5 - 0.1 cos(2 pi v), v from 0 to 1 (64 points): once around a tow of period 1.
std::vector<UV> aroundTheTow()
{
    std::vector<UV> p;
    for (int k = 0; k < 64; ++k) {
        const double v = k / 64.0;
        p.push_back({0.5 - 0.1 * std::cos(2.0 * kPi * v), v});
    }
    return p;
}

std::vector<UV> circle(double u, double v, double r)
{
    std::vector<UV> p;
    for (int k = 0; k < 32; ++k) p.push_back({u + r * std::cos(2.0 * kPi * k / 32.0), v + r * std::sin(2.0 * kPi * k / 32.0)});
    return p;
}

std::vector<std::size_t> numbered(std::size_t n, std::size_t from)
{
    std::vector<std::size_t> v(n);
    for (std::size_t k = 0; k < n; ++k) v[k] = from + k;
    return v;
}

}  // namespace

TEST_CASE("a loop around the tow meets only the loops its curve crosses", "[winding]")
{
    const std::vector<UV> around = aroundTheTow();
    const auto crossings = [&](const std::vector<UV>& c) {
        return detail::loopCrossings(around, numbered(around.size(), 0), c, numbered(c.size(), 100), 1.0).size();
    };
    // Beside the curve (at v = 0.5 it is at u = 0.6), on either side, near where the closing
    // chord of a polygon closed straight back would run (u = 0.4 .. 0.5).
    for (const double u : {0.45, 0.40, 0.7}) {
        INFO("circle at u = " << u);
        CHECK_FALSE(detail::loopsMeet(around, circle(u, 0.5, 0.02), 1.0));
        CHECK(crossings(circle(u, 0.5, 0.02)) == 0);
    }
    // On the curve: two crossings, also across the seam (v = 0 and v = 1 are one line).
    CHECK(detail::loopsMeet(around, circle(0.6, 0.5, 0.02), 1.0));
    CHECK(crossings(circle(0.6, 0.5, 0.02)) == 2);
    CHECK(crossings(circle(0.4, 0.995, 0.02)) == 2);
}

TEST_CASE("loops around the tow before a point count by parity of their crossings", "[winding]")
{
    const std::vector<detail::WindingPolygon> bands{detail::WindingPolygon(aroundTheTow())};
    CHECK(detail::loopsBefore(bands, {0.3, 0.5}, 0.0, 1.0) == 0);  // before the loop in u
    CHECK(detail::loopsBefore(bands, {0.55, 0.5}, 0.0, 1.0) == 0);  // at v = 0.5 the loop is at u = 0.6
    CHECK(detail::loopsBefore(bands, {0.55, 0.0}, 0.0, 1.0) == 1);  // at v = 0 it is at u = 0.4
    CHECK(detail::loopsBefore(bands, {0.55, 1.0}, 0.0, 1.0) == 1);  // the same point one period on
    CHECK(detail::loopsBefore(bands, {0.9, 0.3}, 0.0, 1.0) == 1);   // after it everywhere
}
