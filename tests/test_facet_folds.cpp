// detail::sharpestFold(): the angle between two triangles around their shared edge, on edges
// where surfaces meet (both nodes on two or more surfaces), against hinges of known angles.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "volume/facet_folds.hpp"

using namespace towgeom;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Nodes of a hinge along the z axis (0 and 1 at z = 0 and 1), one wing along +x (node 2) and
/// one at @p angle from it around the axis (node 3), both at distance 0.5 from the axis.
std::vector<Point3> hinge(double angle)
{
    return {{0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, {0.5, 0.0, 0.3}, {0.5 * std::cos(angle), 0.5 * std::sin(angle), 0.7}};
}

}  // namespace

TEST_CASE("sharpestFold: the angle around a shared edge between triangles of two surfaces", "[volume][folds]")
{
    const std::vector<std::size_t> first{1, 2, 3}, second{2, 1, 4};  // 1-based, the hinge's two wings
    for (const double degrees : {0.0002, 0.005, 0.5, 30.0, 90.0, 179.0}) {
        INFO(degrees << " degrees");
        const double angle = degrees * kPi / 180.0;
        const std::vector<Point3> nodes = hinge(angle);
        // Below the tolerance: found, with its angle, the surfaces and the edge's middle.
        const auto fold = detail::sharpestFold(nodes, {&first, &second}, angle * 1.01);
        REQUIRE(fold);
        CHECK(fold->angle == Approx(angle).epsilon(1e-9));
        CHECK(fold->surfaceA + fold->surfaceB == 1);
        CHECK(fold->at.z == Approx(0.5));
        CHECK(std::hypot(fold->at.x, fold->at.y) < 1e-15);
        // At or above it: none.
        CHECK_FALSE(detail::sharpestFold(nodes, {&first, &second}, angle * 0.99));
    }
}

TEST_CASE("sharpestFold: the sharpest of several wings, and only edges where surfaces meet", "[volume][folds]")
{
    std::vector<Point3> nodes = hinge(1.0 * kPi / 180.0);
    nodes.push_back({0.5 * std::cos(0.4 * kPi / 180.0), 0.5 * std::sin(0.4 * kPi / 180.0), 0.5});  // node 5: 0.4 degrees from 3
    const std::vector<std::size_t> a{1, 2, 3}, b{2, 1, 4}, c{2, 1, 5};
    const auto fold = detail::sharpestFold(nodes, {&a, &b, &c}, 2.0 * kPi / 180.0);
    REQUIRE(fold);
    CHECK(fold->angle == Approx(0.4 * kPi / 180.0).epsilon(1e-9));
    CHECK(((fold->surfaceA == 0 && fold->surfaceB == 2) || (fold->surfaceA == 2 && fold->surfaceB == 0)));
    // A wing of no area (its third node on the edge's line) has no direction: passed over.
    std::vector<Point3> flat = hinge(0.0);
    flat[3] = {0.0, 0.0, 0.5};
    CHECK_FALSE(detail::sharpestFold(flat, {&a, &b}, 2.0 * kPi / 180.0));
    // The same wings in one surface: no node lies on two surfaces, so no edge is looked at.
    const std::vector<std::size_t> one{1, 2, 3, 2, 1, 4, 2, 1, 5};
    CHECK_FALSE(detail::sharpestFold(nodes, {&one}, 2.0 * kPi / 180.0));
}
