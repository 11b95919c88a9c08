// compareMethods(): the three methods side by side on one intersection and one set of meshes.
// Checked against resolveTextile() run on its own, the exact section areas of the tows
// (TowSurface::sectionArea), and the methods' expected order of volume loss.
#include <catch2/catch.hpp>

#include <towgeom/error.hpp>
#include <towgeom/method_comparison.hpp>
#include <towgeom/resolve.hpp>
#include <towgeom/weave.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

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

double worstLoss(const MethodFigures& m)
{
    double worst = 0.0;
    for (const TowMethodFigures& t : m.tows) worst = std::max(worst, t.volumeBefore - t.volumeAfter);
    return worst;
}

double totalLoss(const MethodFigures& m)
{
    double sum = 0.0;
    for (const TowMethodFigures& t : m.tows) sum += t.volumeBefore - t.volumeAfter;
    return sum;
}

}  // namespace

TEST_CASE("compareMethods on the twill: connect as resolveTextile, symmetric halves the worst loss, shrink loses most", "[report][symmetric][shrink]")
{
    const std::vector<TowSurface> tows = twill();
    std::vector<ResolveResult> results;
    const MethodComparison c =
        compareMethods(tows, {ResolutionMethod::Connect, ResolutionMethod::Symmetric, ResolutionMethod::Shrink}, {}, &results);
    REQUIRE(c.methods.size() == 3);
    REQUIRE(results.size() == 3);
    CHECK(c.loops.size() == 16);
    CHECK(c.regions.size() == 16);
    // The first method is what resolveTextile() gives on its own.
    const ResolveResult alone = resolveTextile(tows);
    for (std::size_t t = 0; t < tows.size(); ++t) {
        CHECK(c.methods[0].tows[t].volumeAfter == Approx(alone.tows[t].volumeAfter).epsilon(1e-12));
        CHECK(c.methods[0].tows[t].role == alone.tows[t].role());
    }
    CHECK(worstLoss(c.methods[1]) <= 0.6 * worstLoss(c.methods[0]));
    CHECK(totalLoss(c.methods[2]) > totalLoss(c.methods[0]));
    CHECK(c.methods[2].regions == 0);
    // Section areas before: the tows' meshes cut by the sections' planes, against the exact
    // section areas of the fitted surfaces (the mesh's chords make it slightly smaller).
    double worst = 0.0;
    for (std::size_t t = 0; t < tows.size(); ++t) {
        const std::vector<double>& u = tows[t].sectionParameters();
        REQUIRE(c.sectionAreaBefore[t].size() == u.size());
        for (std::size_t i = 0; i < u.size(); ++i) {
            const double exact = tows[t].sectionArea(u[i]);
            const double rel = std::abs(c.sectionAreaBefore[t][i] - exact) / exact;
            worst = std::max(worst, rel);
            CHECK(rel < 0.02);
        }
        // Connect: a primary's cuts are unchanged; a secondary's smaller where it gave way.
        const TowMethodFigures& f = c.methods[0].tows[t];
        double smallest = 1e300;
        for (std::size_t i = 0; i < u.size(); ++i) {
            smallest = std::min(smallest, f.sectionArea[i] / c.sectionAreaBefore[t][i]);
            if (f.role == "primary") CHECK(f.sectionArea[i] == Approx(c.sectionAreaBefore[t][i]).epsilon(1e-9));
        }
        if (f.role == "secondary") CHECK(smallest < 0.99);
        // Shrink: the largest section change shows in the cuts (area scales by its square).
        const TowMethodFigures& s = c.methods[2].tows[t];
        if (s.largestSectionChange > 0.0) {
            double least = 1e300;
            for (std::size_t i = 0; i < u.size(); ++i) least = std::min(least, s.sectionArea[i] / c.sectionAreaBefore[t][i]);
            CHECK(least == Approx((1.0 - s.largestSectionChange) * (1.0 - s.largestSectionChange)).epsilon(0.03));
        }
    }
    WARN("section areas of the meshes vs exact: worst " << 100.0 * worst << " %");

    std::ostringstream html, csv;
    writeReportHtml(c, results.front().mesh, html);
    writeReportCsv(c, csv);
    const std::string page = html.str(), table = csv.str();
    CHECK(page.find("<script type=\"importmap\">") != std::string::npos);
    CHECK(page.find("src=\"http") == std::string::npos);  // nothing fetched
    CHECK(std::count(table.begin(), table.end(), '\n') == 1 + 3 * static_cast<long>(tows.size()));
    CHECK_THROWS_AS(compareMethods(tows, {}), Error);
    CHECK_THROWS_AS(compareMethods(tows, {ResolutionMethod::Connect, ResolutionMethod::Connect}), Error);
}
