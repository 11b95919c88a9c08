// The shrink baseline (ResolutionMethod::Shrink, shrinkTows()): tows shrunk until no pair
// interpenetrates. Checked independently: the shrunk tows intersected again (intersectTows())
// and by CGAL's surface intersection of their faceted tubes, volumes against the rank rule's.
#include <catch2/catch.hpp>

#include <towgeom/resolve.hpp>
#include <towgeom/shrink_tows.hpp>
#include <towgeom/tow_intersection.hpp>
#include <towgeom/weave.hpp>

#include <algorithm>
#include <chrono>

#include "cgal_reference.hpp"
#include "mesh_checks.hpp"

using namespace towgeom;

namespace {

std::vector<TowSurface> twill()
{
    WeaveOptions w;
    w.kind = WeaveKind::Twill;
    w.floatOver = w.floatUnder = 2;
    w.overlap = 0.08;
    std::vector<TowSurface> tows;
    for (const TowStack& s : generateWeave(w).stacks()) tows.push_back(TowSurface::fit(s));
    return tows;
}

double totalLoss(const ResolveResult& r)
{
    double sum = 0.0;
    for (const TowResolution& t : r.tows) sum += t.volumeBefore - t.volumeAfter;
    return sum;
}

}  // namespace

TEST_CASE("shrink: the twill's tows shrunk apart, no curve left, more volume lost than the rank rule", "[resolve][shrink][weave]")
{
    const std::vector<TowSurface> tows = twill();
    const IntersectionReport loops = intersectTows(tows);
    REQUIRE(loops.loops.size() == 16);
    for (const bool both : {false, true}) {
        INFO("both: " << both);
        ResolveOptions o;
        o.method = ResolutionMethod::Shrink;
        o.shrink.both = both;
        const auto t0 = std::chrono::steady_clock::now();
        const ShrinkResult s = shrinkTows(tows, loops, o);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        CHECK(s.notSeparated.empty());
        // No curve between the shrunk tows, found again from scratch.
        const IntersectionReport after = intersectTows(s.tows);
        CHECK(after.loops.empty());
        CHECK(after.findings.empty());
        double lost = 0.0, largest = 0.0;
        std::size_t changed = 0;
        for (std::size_t t = 0; t < tows.size(); ++t) {
            const ShrunkTow& f = s.figures[t];
            REQUIRE(f.sectionScale.size() == tows[t].sectionCount());
            CHECK(f.volumeAfter <= f.volumeBefore);
            lost += f.volumeBefore - f.volumeAfter;
            largest = std::max(largest, f.largestSectionChange());
            changed += f.largestSectionChange() > 0.0;
            // Scales in [minScale, 1], 1 far from the crossings (the yarns' ends).
            for (double x : f.sectionScale) CHECK((x >= o.shrink.minScale && x <= 1.0));
            CHECK(f.sectionScale.front() == 1.0);
        }
        WARN((both ? "both" : "secondary") << ": " << changed << " tows shrunk, volume lost " << lost << ", largest section change "
                                           << largest << ", " << s.fits << " trial fits, " << seconds << " s");
        // Input order ranks warps above wefts: only the wefts give way unless both do.
        CHECK(changed == (both ? 8u : 4u));
        CHECK(largest > 0.0);
        CHECK(largest < 0.6);
    }
}

TEST_CASE("shrink through resolveTextile: separate meshes, no shared surface, a larger loss than connect", "[resolve][shrink][weave]")
{
    const std::vector<TowSurface> tows = twill();
    ResolveOptions o;
    const ResolveResult connect = resolveTextile(tows, o);
    o.method = ResolutionMethod::Shrink;
    const ResolveResult shrink = resolveTextile(tows, o);
    CHECK(shrink.method == ResolutionMethod::Shrink);
    CHECK(shrink.mesh.regions.empty());
    CHECK(shrink.intersections.loops.empty());
    CHECK(shrink.unresolved.empty());
    REQUIRE(shrink.shrunk.size() == tows.size());
    // Independent: no two tows' triangles cross (CGAL exact predicates), every tow closed.
    CHECK(testing::crossingPairsBetweenTows(shrink.mesh) == 0);
    for (const TowMesh& m : shrink.mesh.tows) {
        const testing::Boundary b = testing::boundaryOf(m.triangles);
        CHECK(b.edges == 0);
        CHECK(b.nonManifoldEdges == 0);
    }
    for (std::size_t t = 0; t < tows.size(); ++t) {
        // Unchanged tows keep their volume exactly; the mesh measures what CGAL does.
        if (shrink.shrunk[t].largestSectionChange() == 0.0) CHECK(shrink.tows[t].volumeBefore == Approx(shrink.tows[t].volumeAfter).epsilon(1e-12));
        CHECK(testing::closedMeshVolume(shrink.mesh.closedTowSurface(t)) == Approx(shrink.tows[t].volumeAfter).epsilon(1e-9));
    }
    WARN("twill: total volume lost: shrink " << totalLoss(shrink) << ", connect " << totalLoss(connect));
    CHECK(totalLoss(shrink) > totalLoss(connect));
}
