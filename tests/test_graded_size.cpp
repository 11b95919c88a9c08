// The size field meshVolumes() gives Gmsh (issue 39, item 3): h(x) = min(largest, min_i (h_i +
// slope |x - p_i|)) over the surface nodes, tabulated on a grid. Checked against that formula
// evaluated by brute force, and against closed forms on a flat sheet of equal triangles.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "volume/graded_size.hpp"

using namespace towgeom;

namespace {

struct Sheet {
    std::vector<Point3> nodes;
    std::vector<std::array<std::size_t, 3>> triangles;
};

/// A flat square [0, n a] x [0, n a] at z = 0 of right triangles with legs @p a, plus (when
/// @p fine) a second, finer square [0, 1] x [0, 1] at z = @p fineZ with legs @p a / 4.
Sheet sheet(std::size_t n, double a, bool fine = false, double fineZ = 0.0)
{
    Sheet s;
    const auto grid = [&](std::size_t m, double step, double z) {
        const std::size_t first = s.nodes.size();
        for (std::size_t j = 0; j <= m; ++j)
            for (std::size_t i = 0; i <= m; ++i) s.nodes.push_back({static_cast<double>(i) * step, static_cast<double>(j) * step, z});
        const auto at = [&](std::size_t i, std::size_t j) { return first + j * (m + 1) + i; };
        for (std::size_t j = 0; j < m; ++j)
            for (std::size_t i = 0; i < m; ++i) {
                s.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
                s.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
            }
    };
    grid(n, a, 0.0);
    if (fine) grid(static_cast<std::size_t>(std::lround(4.0 / a)), a / 4.0, fineZ);
    return s;
}

/// The field's definition evaluated by brute force.
double exact(const Sheet& s, const Point3& x, double slope, double largest)
{
    std::vector<double> sum(s.nodes.size(), 0.0), count(s.nodes.size(), 0.0);
    for (const auto& t : s.triangles)
        for (std::size_t e = 0; e < 3; ++e) {
            const double l = distance(s.nodes[t[e]], s.nodes[t[(e + 1) % 3]]);
            for (std::size_t n : {t[e], t[(e + 1) % 3]}) sum[n] += l, count[n] += 1.0;
        }
    double best = largest;
    for (std::size_t n = 0; n < s.nodes.size(); ++n)
        if (count[n] > 0.0) best = std::min(best, sum[n] / count[n] + slope * distance(x, s.nodes[n]));
    return best;
}

}  // namespace

TEST_CASE("The graded size of a flat sheet: the surface's edge length at it, growing by the slope away from it, capped", "[volume][grading]")
{
    // A sheet of legs 0.1: an inner node's 6 edges are 0.1 (4) and 0.1 sqrt 2 (2), mean
    // 0.1 (4 + 2 sqrt 2) / 6; above the sheet's middle at height d the nearest node is under
    // it, so h = h0 + slope d until the cap.
    const double a = 0.1, slope = 0.3, largest = 0.5;
    const Sheet s = sheet(40, a);
    const detail::GradedSize size(s.nodes, s.triangles, slope, largest);
    const double h0 = a * (4.0 + 2.0 * std::sqrt(2.0)) / 6.0;
    CHECK(size.medianSurfaceSize() == Approx(h0).epsilon(1e-12));
    // Trilinear reading of a slope-Lipschitz function on a grid of spacing h0 (the median node
    // size): within slope x half the grid cell's diagonal.
    const double reading = slope * 0.5 * std::sqrt(3.0) * h0;
    for (double d : {0.0, 0.05, 0.2, 0.6, 1.0, 1.2, 3.0}) {
        const Point3 x{2.0, 2.0, d};
        INFO("height " << d);
        CHECK(size(x) == Approx(std::min(largest, h0 + slope * d)).margin(reading));
        CHECK(size(x) <= largest);
    }
    // Below the sheet the same, by symmetry; far outside the grid the largest size.
    CHECK(size({2.0, 2.0, -0.6}) == Approx(h0 + slope * 0.6).margin(reading));
    CHECK(size({100.0, -50.0, 20.0}) == largest);
}

TEST_CASE("The graded size agrees with its definition at random points: a fine patch over a coarse sheet", "[volume][grading]")
{
    // Two sizes (0.1 below, 0.025 in a patch 0.3 above): the field at a point is the least of
    // the two sheets' growing sizes; the grid holds it within slope x its spacing (trilinear
    // reading of a slope-Lipschitz function) and never below it by more.
    const double slope = 0.25, largest = 0.4;
    const Sheet s = sheet(30, 0.1, true, 0.3);
    const detail::GradedSize size(s.nodes, s.triangles, slope, largest, std::size_t(1) << 18);
    std::mt19937 random(39);
    std::uniform_real_distribution<double> xy(0.0, 3.0), z(0.0, 0.3);  // the grid's box (the nodes')
    double worst = 0.0, spacingBound = 0.0;
    // The grid's spacing: the median node size, grown by 1.25 until it fits 2^18 nodes.
    double spacing = size.medianSurfaceSize();
    const auto nodesFor = [&](double h) { return (std::floor(3.0 / h) + 3) * (std::floor(3.0 / h) + 3) * (std::floor(0.3 / h) + 3); };
    while (nodesFor(spacing) > static_cast<double>(std::size_t(1) << 18)) spacing *= 1.25;
    spacingBound = slope * 0.5 * std::sqrt(3.0) * spacing;
    for (int k = 0; k < 2000; ++k) {
        const Point3 x{xy(random), xy(random), z(random)};
        const double want = exact(s, x, slope, largest), got = size(x);
        worst = std::max(worst, std::abs(got - want));
        INFO("at (" << x.x << ", " << x.y << ", " << x.z << "): " << got << " against " << want);
        REQUIRE(std::abs(got - want) <= spacingBound);
    }
    WARN("graded size on 2000 random points: worst difference " << worst << ", bound " << spacingBound);
    // Just above the fine patch the fine size, not the coarse sheet's.
    CHECK(size({0.5, 0.5, 0.31}) < 0.5 * (0.1 + 0.25 * 0.31));
}

TEST_CASE("The graded size of single triangles at any scale and place: within the surface's size and the cap", "[volume][grading]")
{
    // Grids of 4 x 4 x 3 nodes and the like, where the grid's node count and a node's cell can
    // round differently at the top face (a triangle whose extent is a multiple of its size).
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int k = 0; k < 300; ++k) {
        const double scale = std::pow(10.0, -3.0 + 6.0 * unit(random)), offset = (unit(random) - 0.5) * 1e3 * scale;
        const double side = k % 2 ? 0.7 : 0.1 * (1 + k % 7);
        Sheet s;
        s.nodes = {{offset, offset, offset}, {offset + side * scale, offset, offset}, {offset + 0.5 * side * scale, offset + side * scale * std::sqrt(0.75), offset}};
        s.triangles = {{0, 1, 2}};
        const detail::GradedSize size(s.nodes, s.triangles, 0.3, -8.0);
        const double h = side * scale;
        for (const Point3& p : s.nodes) {
            INFO("triangle " << k << ", side " << h);
            CHECK(size(p) >= h * (1 - 1e-6));
            CHECK(size(p) <= h * (1 + 0.3 * std::sqrt(3.0)) + 1e-9 * h);
        }
        CHECK(size(s.nodes[0] + Point3{0, 0, 100 * h}) == Approx(8 * h));
    }
}
