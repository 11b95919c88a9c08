// findFold() against CGAL's exact predicates on a dense tessellation of the same surface (an
// oracle that knows nothing of the sampling findFold() uses): on every tow of the 60-tow
// scan-like textile of seed 1, a fold is found exactly where the oracle finds the surface
// crossing itself.
#include <catch2/catch.hpp>
#include <towgeom/towgeom.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "cgal_reference.hpp"
#include "scan_like.hpp"
#include "synthetic_tows.hpp"

using namespace towgeom;

namespace {

/// Where CGAL finds the tow's surface, tessellated at nu x nv, crossing itself: the centroids of
/// the first crossing pairs' triangles (empty if none).
std::vector<Point3> oracleFold(const TowSurface& tow, std::size_t nu, std::size_t nv)
{
    const TriangleMesh m = tow.tessellate(nu, nv);
    const testing::TriangleCrossings c = testing::crossingTrianglePairs(m.vertices, m.triangles, m.triangles);
    std::vector<Point3> out;
    for (const auto& [a, b] : c.first)
        for (std::size_t k : {a, b}) {
            const auto& t = m.triangles[k];
            out.push_back((1.0 / 3.0) * (m.vertices[t[0]] + m.vertices[t[1]] + m.vertices[t[2]]));
        }
    return out;
}

/// findFold()'s sampling step along the tow at parameter u: the distance between the centroids
/// of the two sections around u, over FoldSearchOptions::perSpan.
double samplingStep(const TowSurface& tow, double u)
{
    const std::vector<double>& us = tow.sectionParameters();
    std::size_t i = 0;
    while (i + 2 < us.size() && us[i + 1] <= u) ++i;
    const auto centroid = [&](std::size_t k) {
        Point3 c;
        for (const Point3& p : tow.sections()[k]) c = c + p;
        return (1.0 / static_cast<double>(tow.sections()[k].size())) * c;
    };
    return distance(centroid(i), centroid(i + 1)) / static_cast<double>(FoldSearchOptions{}.perSpan);
}

}  // namespace

TEST_CASE("findFold: the scan-like textile's folded binder is found where CGAL finds it crossing itself, no other tow", "[fold]")
{
    const testing::ScanLikeTextile textile = testing::largeScanLikeTextile(1);
    const std::vector<TowSurface> tows = testing::fitAll(textile.stacks);
    std::size_t folded = 0;
    for (const TowSurface& tow : tows) {
        INFO("tow " << tow.name());
        const std::optional<SurfaceFold> fold = findFold(tow);
        // The oracle: uniform in u, 8 samples per section span on average (twice findFold's), 96
        // around (three times).
        const std::vector<Point3> oracle = oracleFold(tow, 8 * (tow.sectionCount() - 1) + 1, 96);
        CHECK(fold.has_value() == !oracle.empty());
        if (!fold || oracle.empty()) continue;
        ++folded;
        CHECK(tow.name() == "binder_2_p1");
        CHECK(fold->crossingPairs > 0);
        // The same fold: a crossing of the oracle's within one of findFold's sampling steps (its
        // triangles are that long) of the place found.
        double nearest = 1e300;
        for (const Point3& p : oracle) nearest = std::min(nearest, distance(p, fold->at));
        CHECK(nearest < samplingStep(tow, fold->uv.u));
        // Its parameters give a point of the surface there, within the same step.
        CHECK(distance(tow.point(fold->uv.u, fold->uv.v), fold->at) < samplingStep(tow, fold->uv.u));
    }
    CHECK(folded == 1);  // binder_2_p1 (see test_volume_mesh.cpp)
}

TEST_CASE("findFold refuses a grid too coarse to be a surface, naming the tow", "[fold]")
{
    const std::vector<TowSurface> tows = testing::fitAll({testing::tubeAlongX(0.5, 4.0, 0.0, 0.0, 0.0, testing::Sampling{9, 16}, "straight")});
    CHECK_FALSE(findFold(tows[0]).has_value());
    FoldSearchOptions o;
    o.around = 4;
    CHECK_THROWS_WITH(findFold(tows[0], o), Catch::Matchers::Contains("tow 'straight'") && Catch::Matchers::Contains("8 around"));
    o.around = 32;
    o.perSpan = 0;
    CHECK_THROWS_WITH(findFold(tows[0], o), Catch::Matchers::Contains("tow 'straight'") && Catch::Matchers::Contains("1 sample per section span"));
}

TEST_CASE("findFold within a box: the binder's fold is found in a box around it and not in a box beside it", "[fold]")
{
    const std::vector<TowStack> one{testing::foldingBinder()};
    const TowSurface tow = testing::fitAll(one).front();
    const std::optional<SurfaceFold> anywhere = findFold(tow);
    REQUIRE(anywhere);
    FoldSearchOptions o;
    o.within.add(anywhere->at - Vector3{0.3, 0.3, 0.3});
    o.within.add(anywhere->at + Vector3{0.3, 0.3, 0.3});
    const std::optional<SurfaceFold> around = findFold(tow, o);
    REQUIRE(around);
    CHECK(around->crossingPairs <= anywhere->crossingPairs);
    // A box over the tow's first half (x below 3; the fold is at x = 6.4 to 6.6): none.
    FoldSearchOptions beside;
    beside.within.add(tow.boundingBox().min);
    beside.within.add(Point3{3.0, tow.boundingBox().max.y, tow.boundingBox().max.z});
    CHECK_FALSE(findFold(tow, beside).has_value());
}
