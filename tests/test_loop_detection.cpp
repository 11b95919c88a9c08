// Loop detection that cannot miss a shallow overlap (issue 38): tows that cross with a depth far
// below their facets' chord error, nearly tangent, at any angle. The oracle is closed form: two
// elliptical tubes of height h whose horizontal axes are 2h - depth apart vertically overlap in
// exactly one closed loop for any crossing angle (their common normal is vertical).
#include <catch2/catch.hpp>

#include <towgeom/towgeom.hpp>

#include <cmath>
#include <random>
#include <sstream>

#include "synthetic_tows.hpp"

using namespace towgeom;

namespace {

struct ShallowCrossing {
    double degrees = 90.0;
    double width = 0.5;
    double height = 0.2;
    double depth = 1e-3;  ///< of the overlap, along the common normal
    double side = 0.0;

    std::string describe() const
    {
        std::ostringstream s;
        s << "crossing at " << degrees << " deg, width " << width << ", height " << height << ", depth " << depth << ", side "
          << side;
        return s.str();
    }
};

/// A random shallow crossing: angle 2-90 degrees, sections 0.3-0.6 wide and 0.1-0.3 high, depth
/// log-uniform from 3e-6 to 1e-1 of the height (the facets' sagitta at the top is about 5e-3 of
/// the width: most of the family crosses below it; the smallest depth is still 4 times the point
/// tolerance, 1e-7 of the tow size, under which an overlap counts as a touch).
ShallowCrossing randomCrossing(std::mt19937& rng)
{
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    ShallowCrossing c;
    c.degrees = 2.0 + 88.0 * unit(rng);
    c.width = 0.3 + 0.3 * unit(rng);
    c.height = 0.1 + 0.2 * unit(rng);
    c.depth = c.height * std::pow(10.0, -5.5 + 4.5 * unit(rng));
    c.side = 0.2 * (unit(rng) - 0.5);
    return c;
}

}  // namespace

TEST_CASE("shallow crossings far below the facets' chord error: one closed loop each, none missed",
          "[intersection][detection][shallow]")
{
    std::mt19937 rng(20261205);
    std::size_t missed = 0;
    for (int k = 0; k < 40; ++k) {
        const ShallowCrossing c = randomCrossing(rng);
        INFO(c.describe());
        const std::vector<TowStack> stacks = testing::tubesCrossingAt(c.degrees, c.width, c.height, 2.0 * c.height - c.depth, c.side);
        const IntersectionReport report = intersectTows(testing::fitAll(stacks));
        if (report.loops.size() != 1) ++missed;
        REQUIRE(report.loops.size() == 1);
        CHECK(report.openCount() == 0);
        // Where: the axes cross (in plan) at x = 2 - side / tan(angle), y = 0, and the loop lies
        // around the top of a there, z = height - depth / 2; on a's top its width across a's axis
        // is the overlap ellipse's (closed form above: semi-axes sqrt(2 w^2 depth / h / (1 -+ cos))).
        const double angle = c.degrees * 3.14159265358979323846 / 180.0;
        Point3 centre;
        const auto& points = report.loops.front().points();
        for (const LoopPoint& p : points) centre = centre + p.point;
        centre = (1.0 / static_cast<double>(points.size())) * centre;
        const double semiMajor = std::sqrt(2.0 * c.width * c.width * c.depth / c.height / (1.0 - std::cos(angle)));
        const Point3 expected{2.0 - c.side / std::tan(angle), 0.0, c.height - 0.5 * c.depth};
        INFO("loop centre (" << centre.x << ", " << centre.y << ", " << centre.z << "), expected near (" << expected.x << ", 0, "
                             << expected.z << "), overlap semi-axis " << semiMajor);
        CHECK(distance(centre, expected) < 0.05 * semiMajor + 1e-3 * c.width);
    }
    CHECK(missed == 0);
}
