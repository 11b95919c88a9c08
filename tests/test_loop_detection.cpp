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

/// A random shallow crossing: angle 5-90 degrees, sections 0.3-0.6 wide and 0.1-0.3 high, depth
/// log-uniform from 1e-4 to 1e-1 of the height (the facets' sagitta at the top is about 5e-3 of
/// the width: most of the family crosses below it).
ShallowCrossing randomCrossing(std::mt19937& rng)
{
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    ShallowCrossing c;
    c.degrees = 1.0 + 89.0 * unit(rng);
    c.width = 0.3 + 0.3 * unit(rng);
    c.height = 0.1 + 0.2 * unit(rng);
    c.depth = c.height * std::pow(10.0, -6.0 + 5.0 * unit(rng));
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
        CHECK(report.loops.size() == 1);
        CHECK(report.openCount() == 0);
    }
    CHECK(missed == 0);
}
