// The weave generator: interlacement patterns, collision detection against brute force, CGAL's
// surface intersection as an independent check of the overlap, flattening to just touching.
#include <catch2/catch.hpp>

#include <towgeom/towgeom.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cgal_reference.hpp"

using namespace towgeom;

namespace {

bool definedOver(const WeaveOptions& o, int i, int j)
{
    const auto mod = [](int a, int n) { return ((a % n) + n) % n; };
    switch (o.kind) {
    case WeaveKind::Plain: return mod(i + j, 2) == 0;
    case WeaveKind::Twill: return mod(j - o.step * i, o.floatOver + o.floatUnder) < o.floatOver;
    case WeaveKind::Satin: return mod(j - o.step * i, o.floatOver) == 0;
    case WeaveKind::Basket: return mod(i / o.floatOver + j / o.floatOver, 2) == 0;
    default: return false;
    }
}

double seconds(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

WeaveOptions twill22(double overlap)
{
    WeaveOptions o;
    o.kind = WeaveKind::Twill;
    o.floatOver = 2;
    o.floatUnder = 2;
    o.overlap = overlap;
    return o;
}

}  // namespace

TEST_CASE("every weave's interlacement matches its definition, in the geometry too", "[weave]")
{
    WeaveOptions plain, twill = twill22(0.0), satin, basket;
    satin.kind = WeaveKind::Satin;
    satin.floatOver = 5;
    satin.step = 2;
    satin.warps = satin.wefts = 5;
    basket.kind = WeaveKind::Basket;
    basket.floatOver = 2;
    for (const WeaveOptions& o : {plain, twill, satin, basket}) {
        {  // a block, not a section: Catch would rerun the whole case per section
            INFO(weaveKindName(o.kind));
            const Textile t = generateWeave(o);
            REQUIRE(t.yarns.size() == o.warps + o.wefts);
            REQUIRE(t.crossings.size() == o.warps * o.wefts);
            for (const Crossing& c : t.crossings) {
                const int i = static_cast<int>(c.warp), j = static_cast<int>(c.weft - o.warps);
                CHECK(c.warpOver == definedOver(o, i, j));
                // The warp's centre line is above the weft's exactly where the warp is over.
                const double tw = static_cast<double>(j + 1), tf = static_cast<double>(i + 1);
                const double zw = t.yarns[c.warp].path.point(tw).z, zf = t.yarns[c.weft].path.point(tf).z;
                CHECK((zw > zf) == c.warpOver);
                CHECK(std::fabs(t.yarns[c.warp].path.point(tw).x - c.position.x) < 1e-12);
            }
            if (o.kind == WeaveKind::Satin)  // one over per warp per repeat
                for (std::size_t i = 0; i < o.warps; ++i) {
                    int overs = 0;
                    for (const Crossing& c : t.crossings) overs += c.warp == i && c.warpOver;
                    CHECK(overs == 1);
                }
            for (const TowStack& s : t.stacks()) CHECK_NOTHROW(validateStack(s));
        }
    }
}

TEST_CASE("hierarchical and brute-force collision detection find the same pairs", "[weave][collision]")
{
    WeaveOptions o = twill22(0.05);
    o.sectionsPerYarn = 41;
    o.pointsPerSection = 12;
    const std::vector<TowStack> stacks = generateWeave(o).stacks();
    auto t0 = std::chrono::steady_clock::now();
    const CollisionReport fast = detectCollisions(stacks, CollisionMethod::Hierarchy);
    const double fastSeconds = seconds(t0);
    t0 = std::chrono::steady_clock::now();
    const CollisionReport brute = detectCollisions(stacks, CollisionMethod::BruteForce);
    const double bruteSeconds = seconds(t0);
    WARN("collision detection, 8 yarns of 41 x 12: hierarchy " << fastSeconds << " s (" << fast.trianglePairsTested
                                                                << " exact tests), brute force " << bruteSeconds << " s ("
                                                                << brute.trianglePairsTested << " tests)");
    REQUIRE(fast.collisions.size() == 16);  // every warp-weft crossing, nothing else
    REQUIRE(fast.collisions.size() == brute.collisions.size());
    for (std::size_t k = 0; k < fast.collisions.size(); ++k) {
        CHECK(fast.collisions[k].yarnA == brute.collisions[k].yarnA);
        CHECK(fast.collisions[k].yarnB == brute.collisions[k].yarnB);
        CHECK(fast.collisions[k].triangles == brute.collisions[k].triangles);
    }
    CHECK(fast.trianglePairsTested * 1000 < brute.trianglePairsTested);  // observed 6726 of 25804800 (was 1/20)
    // Every crossing has its own collisions, and every colliding pair is attributed to one.
    const Textile textile = generateWeave(o);
    const std::vector<std::size_t> perCrossing = collisionsPerCrossing(textile, stacks, fast);
    REQUIRE(perCrossing.size() == 16);
    std::size_t total = 0;
    for (const std::size_t n : perCrossing) {
        CHECK(n > 0);
        total += n;
    }
    CHECK(total == fast.trianglePairCount());
}

TEST_CASE("2/2 twill with overlap 0.08: CGAL finds one closed loop per crossing", "[weave][overlap]")
{
    const Textile t = generateWeave(twill22(0.08));
    const std::vector<TowStack> stacks = t.stacks();
    std::size_t loops = 0;
    for (const Crossing& c : t.crossings) {
        const testing::IntersectionPolylines p =
            testing::surfaceIntersection(facetedTube(stacks[c.warp], false), facetedTube(stacks[c.weft], false));
        INFO(t.yarns[c.warp].name << " x " << t.yarns[c.weft].name);
        CHECK(p.closed == 1);
        CHECK(p.open == 0);
        loops += p.closed;
    }
    CHECK(loops == 16);
    // Parallel neighbours do not touch.
    const testing::IntersectionPolylines side =
        testing::surfaceIntersection(facetedTube(stacks[0], false), facetedTube(stacks[1], false));
    CHECK(side.closed + side.open == 0);
}

TEST_CASE("flattening leaves the yarns just touching", "[weave][flatten]")
{
    Textile t = generateWeave(twill22(0.08));
    REQUIRE(detectCollisions(t.stacks()).collisions.size() == 16);
    const double tau = 1e-4;
    const std::vector<CrossingResponse> responses = flattenToTouching(t, tau);
    REQUIRE(responses.size() == 16);
    for (const CrossingResponse& r : responses) {
        CHECK(r.collided);
        CHECK(r.flattening < 1.0);
        CHECK(r.flattening > 0.5);
        CHECK(r.gap > 0.0);
        CHECK(r.gap <= tau);
    }
    CHECK(detectCollisions(t.stacks()).collisions.empty());
    // Measured independently of the generator's own gap: the faceted yarns of every crossing
    // (the facets the flattening works on) are apart, by at most tau (CGAL's exact distances of
    // triangle pairs: vertex-triangle and edge-edge).
    const std::vector<TowStack> stacks = t.stacks();
    for (const Crossing& c : t.crossings) {
        INFO(t.yarns[c.warp].name << " x " << t.yarns[c.weft].name);
        const double d = testing::minimumDistance(facetedTube(stacks[c.warp], false), facetedTube(stacks[c.weft], false), 10.0 * tau);
        CHECK(d > 0.0);
        CHECK(d <= tau);
    }
}

TEST_CASE("3D orthogonal weave: layers and binders, all stacks valid", "[weave]")
{
    WeaveOptions o;
    o.kind = WeaveKind::Orthogonal;
    o.layers = 2;
    o.warps = 3;
    o.wefts = 4;
    o.shape = SectionShape::Ellipse;
    const Textile t = generateWeave(o);
    std::size_t binders = 0;
    for (const GeneratedYarn& y : t.yarns) binders += y.role == YarnRole::Binder;
    CHECK(binders == 2);
    CHECK(t.yarns.size() == 2 * 3 + 3 * 4 + 2);
    for (const TowStack& s : t.stacks()) {
        INFO(s.name);
        CHECK_NOTHROW(TowSurface::fit(s));
    }
    // Binders pass over the top weft layer (centre z = 4 * 0.2) and under the bottom one (z = 0).
    double zmin = 1e9, zmax = -1e9;
    for (const auto& section : t.yarns.back().stack(o.pointsPerSection).sections)
        for (const Point3& p : section) {
            zmin = std::min(zmin, p.z);
            zmax = std::max(zmax, p.z);
        }
    CHECK(zmax > 0.8 + 0.1);
    CHECK(zmin < -0.1);
    // Without overlap, only layers that touch tangentially meet: binders collide with nothing.
    const CollisionReport report = detectCollisions(t.stacks());
    for (const YarnCollision& c : report.collisions) {
        CHECK(t.yarns[c.yarnA].role != YarnRole::Binder);
        CHECK(t.yarns[c.yarnB].role != YarnRole::Binder);
    }
}

TEST_CASE("writeTextile writes readable stacks and textile.json with roles", "[weave][io]")
{
    WeaveOptions o = twill22(0.0);
    o.sectionsPerYarn = 33;
    const Textile t = generateWeave(o);
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "towgeom_textile_test";
    std::filesystem::remove_all(dir);
    writeTextile(t, dir.string());
    for (const GeneratedYarn& y : t.yarns) {
        const TowStack s = readStackFile((dir / (y.name + ".stw")).string());
        CHECK(s.name == y.name);
        CHECK(s.sectionCount() == 33);
        CHECK(s.pointsPerSection() == o.pointsPerSection);
    }
    std::ifstream in(dir / "textile.json");
    std::stringstream json;
    json << in.rdbuf();
    CHECK(json.str().find("\"weave\":\"twill\"") != std::string::npos);
    CHECK(json.str().find("\"name\":\"weft_2\",\"role\":\"weft\"") != std::string::npos);
    std::filesystem::remove_all(dir);
}

TEST_CASE("invalid weave options are refused", "[weave]")
{
    WeaveOptions satin;
    satin.kind = WeaveKind::Satin;
    satin.floatOver = 6;
    satin.step = 2;  // not coprime with 6
    CHECK_THROWS_AS(generateWeave(satin), Error);
    WeaveOptions o;
    o.overlap = 1.5;
    CHECK_THROWS_AS(generateWeave(o), Error);
    o = WeaveOptions{};
    o.pointsPerSection = 31;  // lenticular needs an even count
    CHECK_THROWS_AS(generateWeave(o), Error);
}

TEST_CASE("a yarn's section may vary along it", "[weave][section]")
{
    WeaveOptions o;
    o.shape = SectionShape::Ellipse;
    Textile t = generateWeave(o);
    GeneratedYarn& y = t.yarns.front();
    const std::size_t m = y.sections.size();
    for (std::size_t k = 0; k < m; ++k) {
        const double s = 1.0 - 0.5 * static_cast<double>(k) / static_cast<double>(m - 1);  // taper to half size
        y.sections[k].width = o.width * s;
        y.sections[k].height = o.height * s;
    }
    const TowSurface tow = TowSurface::fit(y.stack(o.pointsPerSection));
    const double full = 3.14159265358979323846 * o.width * o.height / 4;
    // Ends of a crimped yarn are straight here (one spacing beyond the last crossing).
    // Observed 5.0e-5 above the ellipse at both ends (32 points around).
    CHECK(tow.sectionArea(0.0) == Approx(full).epsilon(1.2e-4));
    CHECK(tow.sectionArea(1.0) == Approx(full / 4).epsilon(1.2e-4));
    y.sections.pop_back();
    CHECK_THROWS_AS(y.stack(o.pointsPerSection), Error);
}

TEST_CASE("the generator's unit cell: one repeat where the textile repeats exactly, none where it cannot", "[weave][cell]")
{
    const auto cellOf = [](WeaveKind kind, std::size_t over, std::size_t under, std::size_t step, std::size_t warps, std::size_t wefts,
                           double crimp) {
        WeaveOptions o;
        o.crimp = crimp;
        o.kind = kind;
        o.floatOver = over;
        o.floatUnder = under;
        o.step = step;
        o.warps = warps;
        o.wefts = wefts;
        o.overlap = 0.08;
        return generateWeave(o);
    };
    struct Case {
        WeaveKind kind;
        std::size_t over, under, step, warps, wefts;
        double x, y;    // the expected repeat along x (wefts) and y (warps); 0: no cell
        double crimp;   // 0: the default
        bool resolve;   // resolve with the cell (the periodic check must accept it)
    };
    for (const Case& k : {Case{WeaveKind::Twill, 2, 2, 1, 6, 6, 4, 4, 0.0, true}, Case{WeaveKind::Twill, 2, 2, 1, 4, 4, 0, 0, 0.0, false},
                         Case{WeaveKind::Twill, 2, 2, 2, 4, 6, 4, 2, 0.0, true}, Case{WeaveKind::Plain, 1, 1, 1, 4, 4, 2, 2, 0.0, false},
                         Case{WeaveKind::Satin, 5, 1, 2, 7, 7, 5, 5, 0.0, false}, Case{WeaveKind::Basket, 2, 2, 1, 6, 6, 4, 4, 0.0, false},
                         // groups of one are the plain weave (index -1 once fell in the wrong group)
                         Case{WeaveKind::Basket, 1, 1, 1, 4, 4, 2, 2, 0.0, true},
                         // a crimp over twice the height: the paths overshoot along the floats, the box holds them
                         Case{WeaveKind::Twill, 2, 2, 1, 6, 6, 4, 4, 0.5, true}, Case{WeaveKind::Orthogonal, 2, 2, 1, 6, 6, 0, 0, 0.0, false}}) {
        INFO("kind " << static_cast<int>(k.kind) << ", " << k.over << "/" << k.under << " step " << k.step << ", " << k.warps << " x " << k.wefts
                     << ", crimp " << k.crimp);
        const Textile t = cellOf(k.kind, k.over, k.under, k.step, k.warps, k.wefts, k.crimp);
        const std::optional<Cell> cell = t.unitCell();
        REQUIRE(cell.has_value() == (k.x > 0.0));
        if (!cell) continue;
        CHECK(cell->periodic);
        CHECK(cell->min.x == 0.5);
        CHECK(cell->min.y == 0.5);
        CHECK(cell->max.x - cell->min.x == k.x);
        CHECK(cell->max.y - cell->min.y == k.y);
        if (!k.resolve) continue;
        // The textile does repeat there: resolveTextile's periodic check (cuts on the max faces
        // equal the min faces' moved by the cell, within 1e-3 of the tow size) accepts it.
        std::vector<TowSurface> tows;
        for (const TowStack& s : t.stacks()) tows.push_back(TowSurface::fit(s));
        ResolveOptions o;
        o.cell = cell;
        o.mesh.edgeLength = 0.2;
        const ResolveResult r = resolveTextile(tows, o);
        REQUIRE(r.mesh.cell.has_value());
        CHECK_FALSE(r.mesh.cell->periodicPairs.empty());
    }
}
