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

#include "synthetic_tows.hpp"

using namespace towgeom;

namespace {

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
    const std::vector<TowSurface> tows = testing::fittedTwill22();
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
            CHECK(rel < 0.01);  // observed 0.55 %
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
    CHECK(page.find(" src=") == std::string::npos);  // nothing loaded from elsewhere
    CHECK(std::count(table.begin(), table.end(), '\n') == 1 + 3 * static_cast<long>(tows.size()));
    CHECK_THROWS_AS(compareMethods(tows, {}), Error);
    CHECK_THROWS_AS(compareMethods(tows, {ResolutionMethod::Connect, ResolutionMethod::Connect}), Error);
}

TEST_CASE("section areas count only the tow's own pass through a section's plane", "[report]")
{
    // A U-turn (a half torus, tube radius 0.1, legs 0.25 apart): the first section's plane also
    // cuts the last end's leg, within twice the section's radius of its centre.
    testing::Sampling s;
    s.sections = 25;
    s.points = 32;
    const std::vector<TowSurface> tows = {TowSurface::fit(testing::bentTube(0.1, 0.125, 3.14159265358979323846, s, "u_turn"))};
    const MethodComparison c = compareMethods(tows, {ResolutionMethod::Connect});
    const std::vector<double>& u = tows[0].sectionParameters();
    REQUIRE(c.sectionAreaBefore[0].size() == u.size());
    for (std::size_t i = 0; i < u.size(); ++i) {
        INFO("section " << i);
        CHECK(c.sectionAreaBefore[0][i] == Approx(tows[0].sectionArea(u[i])).epsilon(0.01));
        CHECK(c.methods[0].tows[0].sectionArea[i] == Approx(c.sectionAreaBefore[0][i]).epsilon(1e-12));
    }
}

TEST_CASE("compareMethods refuses no method, or a method asked for twice, before any work", "[report]")
{
    testing::Sampling s;
    s.sections = 9;
    s.points = 16;
    const std::vector<TowSurface> two = {TowSurface::fit(testing::tubeAlongX(0.05, 1.0, 0.0, 10.0, 0.0, s, "x")),
                                         TowSurface::fit(testing::tubeAlongX(0.05, 1.0, 0.5, 10.0, 0.0, s, "y"))};
    CHECK_THROWS_WITH(compareMethods(two, {}), Catch::Contains("needs at least one method"));
    CHECK_THROWS_WITH(compareMethods(two, {ResolutionMethod::Connect, ResolutionMethod::Symmetric, ResolutionMethod::Connect}),
                      Catch::Contains("method 'connect' is asked for twice"));
}

TEST_CASE("report.html keeps its scripts whatever the tows are called", "[report]")
{
    std::vector<TowSurface> tows = testing::fittedTwill22();
    testing::Sampling s;
    s.sections = 9;
    s.points = 16;
    TowStack odd = testing::tubeAlongX(0.05, 1.0, 0.0, 10.0, 0.0, s, "x");
    odd.name = "a<!--<script></script>&b";
    const std::vector<TowSurface> two = {tows.front(), TowSurface::fit(odd)};
    std::vector<ResolveResult> results;
    const MethodComparison c = compareMethods(two, {ResolutionMethod::Connect}, {}, &results);
    std::ostringstream html;
    writeReportHtml(c, results.front().mesh, html);
    const std::string page = html.str();
    CHECK(page.find("<!--<script>") == std::string::npos);
    CHECK(page.find("a&lt;!--&lt;script&gt;&lt;/script&gt;&amp;b") != std::string::npos);  // in the tables
    CHECK(page.find("a\\u003c!--\\u003cscript\\u003e") != std::string::npos);             // in the data
    // A stream with another locale and precision is left as it was and does not change the CSV.
    std::ostringstream csv;
    csv.precision(3);
    writeReportCsv(c, csv);
    CHECK(csv.precision() == 3);
    CHECK(csv.str().find("a<!--<script></script>&b,connect,") != std::string::npos);
}
