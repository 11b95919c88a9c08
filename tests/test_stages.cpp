// The pipeline as stages: intersectTows() once, its report written as JSON and read back, then
// resolveTextile() with that report at several mesh sizes; the chained stages give the same
// meshes as the one-call resolveTextile().
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <chrono>
#include <functional>
#include <sstream>
#include <tuple>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "mesh_checks.hpp"
#include "synthetic_tows.hpp"
#include "towgeom/towgeom.hpp"

using namespace towgeom;

namespace {

ResolveOptions atSize(double relative)
{
    ResolveOptions o;
    o.mesh.relativeEdgeLength = relative;
    return o;
}

std::string jsonOf(const IntersectionReport& report, const std::vector<TowSurface>& tows)
{
    std::ostringstream out;
    writeIntersectionReport(report, tows, out);
    return out.str();
}

IntersectionReport readBack(const std::string& json, const std::vector<TowSurface>& tows)
{
    std::istringstream in(json);
    return readIntersectionReport(in, tows, "report.json");
}

/// The number of closed boundary loops of each tow's final mesh (0: closed by its caps).
std::size_t openTows(const ResolveResult& r)
{
    std::size_t open = 0;
    for (const TowMesh& t : r.mesh.tows) open += testing::boundaryOf(t.triangles).edges > 0;
    return open;
}

ErrorCode codeOf(const std::function<void()>& f)
{
    try {
        f();
    } catch (const Error& e) {
        return e.code();
    }
    FAIL("no towgeom::Error thrown");
    return ErrorCode::Internal;
}

}  // namespace

TEST_CASE("intersection report JSON: exact round trip, and the chained stages give resolveTextile()'s mesh", "[stages][json]")
{
    const std::vector<TowSurface> tows = testing::bundledTwill(TOWGEOM_EXAMPLE_DATA);
    const IntersectionReport found = intersectTows(tows);
    REQUIRE(found.loops.size() == 16);
    const std::string json = jsonOf(found, tows);
    const IntersectionReport back = readBack(json, tows);

    // Every field that meshing reads comes back bit for bit, and writing again gives the same text.
    REQUIRE(back.loops.size() == found.loops.size());
    for (std::size_t k = 0; k < found.loops.size(); ++k) {
        const IntersectionLoop &a = found.loops[k], &b = back.loops[k];
        CHECK(a.towA() == b.towA());
        CHECK(a.towB() == b.towB());
        CHECK(a.closed() == b.closed());
        CHECK(a.length() == b.length());
        CHECK(a.tolerance() == b.tolerance());
        REQUIRE(a.points().size() == b.points().size());
        for (std::size_t i = 0; i < a.points().size(); ++i) {
            const LoopPoint &p = a.points()[i], &q = b.points()[i];
            CHECK((p.point.x == q.point.x && p.point.y == q.point.y && p.point.z == q.point.z));
            CHECK((p.onA.u == q.onA.u && p.onA.v == q.onA.v && p.onB.u == q.onB.u && p.onB.v == q.onB.v));
        }
        CHECK(b.maxDistance(LoopSide::A) <= 1e-6);
        CHECK(b.enclosedArea(LoopSide::B) == Approx(a.enclosedArea(LoopSide::B)).epsilon(1e-12));
    }
    CHECK(back.towPairs == found.towPairs);
    CHECK(back.findings.size() == found.findings.size());
    IntersectionReport again = back;
    again.timings = found.timings;  // written, not read back
    CHECK(jsonOf(again, tows) == json);

    // resolveTextile(tows) against intersectTows -> JSON -> read -> resolveTextile(tows, report).
    const ResolveOptions o = atSize(0.2);
    const ResolveResult one = resolveTextile(tows, o);
    const ResolveResult chained = resolveTextile(tows, back, o);
    CHECK(chained.timings.intersect == 0.0);
    REQUIRE(one.mesh.nodes.size() == chained.mesh.nodes.size());
    std::size_t nodesDiffering = 0;
    for (std::size_t n = 0; n < one.mesh.nodes.size(); ++n) {
        const Point3 &p = one.mesh.nodes[n], &q = chained.mesh.nodes[n];
        nodesDiffering += !(p.x == q.x && p.y == q.y && p.z == q.z);
    }
    CHECK(nodesDiffering == 0);
    REQUIRE(one.mesh.tows.size() == chained.mesh.tows.size());
    for (std::size_t t = 0; t < one.mesh.tows.size(); ++t) CHECK(one.mesh.tows[t].triangles == chained.mesh.tows[t].triangles);
    CHECK(one.mesh.regions.size() == 16);
    CHECK(chained.mesh.regions.size() == 16);
    CHECK(openTows(chained) == 0);

    // The three stages called one by one: the same nodes and triangles again (resolveTextile()
    // is these stages chained, so this checks only that the public stages hand each other
    // everything; that connectRegions(), reading the loops and centroids back from the nodes'
    // (u,v), classifies as the meshes' own data did is checked by the geometry of every
    // [resolve] test: no crossing triangles, regions on both surfaces, volumes against CGAL).
    const ResolveResult staged = connectRegions(tows, meshTows(tows, back, o), o);
    REQUIRE(staged.mesh.nodes.size() == one.mesh.nodes.size());
    nodesDiffering = 0;
    for (std::size_t n = 0; n < one.mesh.nodes.size(); ++n) {
        const Point3 &p = one.mesh.nodes[n], &q = staged.mesh.nodes[n];
        nodesDiffering += !(p.x == q.x && p.y == q.y && p.z == q.z);
    }
    CHECK(nodesDiffering == 0);
    for (std::size_t t = 0; t < one.mesh.tows.size(); ++t) {
        CHECK(one.mesh.tows[t].triangles == staged.mesh.tows[t].triangles);
        CHECK(one.mesh.tows[t].region == staged.mesh.tows[t].region);
    }
    CHECK(staged.mesh.regions.size() == 16);
}

TEST_CASE("meshTows alone: every tow's own closed mesh, loops shared node for node, connectRegions on it with two rankings",
          "[stages][connect]")
{
    const std::vector<TowSurface> tows = testing::bundledTwill(TOWGEOM_EXAMPLE_DATA);
    const IntersectionReport found = intersectTows(tows);
    const ResolveOptions o = atSize(0.2);
    const ResolveResult meshed = meshTows(tows, found, o);

    // No swap yet: no region, every tow closed by its caps, its volume that of its own surface.
    CHECK(meshed.mesh.regions.empty());
    CHECK(openTows(meshed) == 0);
    REQUIRE(meshed.mesh.loops.size() == 16);
    for (std::size_t t = 0; t < tows.size(); ++t) {
        const TowResolution& r = meshed.tows[t];
        CHECK(r.volumeBefore == Approx(enclosedVolume(meshed.mesh.towSurface(t))).epsilon(1e-9));  // CGAL: closed, measured
        CHECK(r.volumeBefore == Approx(tows[t].volume()).epsilon(0.02));
        CHECK(r.pieces == 1);
    }
    // Each loop's nodes lie on both tows' meshes, with (u,v) on each, and on both surfaces.
    for (const MeshedLoop& l : meshed.mesh.loops) {
        const IntersectionLoop& loop = found.loops[l.loop];
        REQUIRE(l.nodes.size() >= 3);
        for (const std::size_t t : {loop.towA(), loop.towB()}) {
            const TowMesh& m = meshed.mesh.tows[t];
            std::vector<std::size_t> used;
            for (const auto& tri : m.triangles) used.insert(used.end(), tri.begin(), tri.end());
            std::sort(used.begin(), used.end());
            std::size_t missing = 0, far = 0;
            for (std::size_t n : l.nodes) {
                missing += !std::binary_search(used.begin(), used.end(), n);
                const auto it = std::lower_bound(m.parameters.begin(), m.parameters.end(), n,
                                                 [](const auto& e, std::size_t k) { return e.first < k; });
                REQUIRE(it != m.parameters.end());
                REQUIRE(it->first == n);
                far += norm(tows[t].point(it->second.u, it->second.v) - meshed.mesh.nodes[n]) > 1e-6 * tows[t].towSize();
            }
            CHECK(missing == 0);
            CHECK(far == 0);
        }
    }
    // Still overlapping: the warps' and wefts' volumes add up to more than the textile holds
    // after resolution, by the regions' removed volume.
    const ResolveResult byOrder = connectRegions(tows, meshed, o);
    CHECK(byOrder.mesh.regions.size() == 16);
    CHECK(openTows(byOrder) == 0);
    double removed = 0.0, lost = 0.0;
    for (const ConnectedRegion& g : byOrder.mesh.regions) removed += g.volumeRemoved;
    for (const TowResolution& r : byOrder.tows) lost += r.volumeBefore - r.volumeAfter;
    CHECK(removed > 0.0);
    CHECK(lost == Approx(removed).epsilon(1e-6));

    // The same meshes ranked the other way (wefts first): every region changes hands, the shared
    // surface differs, nothing is meshed again.
    ResolveOptions weftsFirst = o;
    weftsFirst.primaryPatterns = {"weft*"};
    const ResolveResult byWeft = connectRegions(tows, meshed, weftsFirst);
    REQUIRE(byWeft.mesh.regions.size() == 16);
    CHECK(openTows(byWeft) == 0);
    for (const ConnectedRegion& g : byOrder.mesh.regions) CHECK(tows[g.primary].name().rfind("warp", 0) == 0);
    for (const ConnectedRegion& g : byWeft.mesh.regions) CHECK(tows[g.primary].name().rfind("weft", 0) == 0);
    double removedByWeft = 0.0;
    for (const ConnectedRegion& g : byWeft.mesh.regions) removedByWeft += g.volumeRemoved;
    CHECK(removedByWeft == Approx(removed).epsilon(1e-9));  // the same overlaps, bounded by the same two surfaces
}

TEST_CASE("connectRegions: a pair whose loop is wrong on one tow is left unresolved (RegionFailed), the rest connected",
          "[stages][connect]")
{
    const std::vector<TowSurface> tows = testing::bundledTwill(TOWGEOM_EXAMPLE_DATA);
    const ResolveOptions o = atSize(0.2);
    ResolveResult meshed = meshTows(tows, intersectTows(tows), o);
    REQUIRE(meshed.mesh.loops.size() == 16);
    // Loop 0's polygon on its tow B moved half way round the tow: that tow's triangles inside it
    // are not the ones the loop bounds, so its mesh cannot close after the swap.
    const MeshedLoop moved = meshed.mesh.loops[0];
    const IntersectionLoop& loop = meshed.intersections.loops[moved.loop];
    const ParameterRange range = tows[loop.towB()].parameterRange();
    for (auto& [node, uv] : meshed.mesh.tows[loop.towB()].parameters)
        if (std::find(moved.nodes.begin(), moved.nodes.end(), node) != moved.nodes.end())
            uv.v = range.vMin + std::fmod(uv.v - range.vMin + 0.5 * range.vPeriod(), range.vPeriod());
    const ResolveResult r = connectRegions(tows, meshed, o);
    // Every pair with a loop on the failed tow is left out (in the twill, a weft crosses four
    // warps); the others keep their regions and every tow stays closed.
    const std::size_t failed = loop.towB();
    std::size_t onFailed = 0, pairs = 0;
    for (const MeshedLoop& l : meshed.mesh.loops) {
        const IntersectionLoop& k = meshed.intersections.loops[l.loop];
        onFailed += k.towA() == failed || k.towB() == failed;
    }
    for (const UnresolvedPair& u : r.unresolved) {
        CHECK(u.reason == UnresolvedPair::Reason::RegionFailed);
        CHECK((u.towA == failed || u.towB == failed));
        CHECK(u.message.find("tow '" + tows[failed].name() + "' could not be connected") == 0);
        ++pairs;
    }
    CHECK(pairs >= 1);
    CHECK(onFailed >= pairs);
    CHECK(r.mesh.regions.size() == 16 - onFailed);
    CHECK(r.mesh.loops.size() == 16 - onFailed);
    CHECK(openTows(r) == 0);
    // The failed tow keeps its own surface whole (its loop nodes stay in its mesh).
    CHECK(r.tows[failed].volumeAfter == Approx(r.tows[failed].volumeBefore).epsilon(1e-12));
    // The reports list the pairs with code region_failed.
    const std::vector<UnresolvedPairEntry> listed = unresolvedPairs(r);
    CHECK(listed.size() == pairs);
    for (const UnresolvedPairEntry& e : listed) CHECK(e.code == "region_failed");
}

TEST_CASE("connectRegions refuses meshes that do not fit the tows, naming the tow or loop", "[stages][connect]")
{
    // Fitted, intersected and meshed once for the nine sections (Catch runs this part once per
    // section; each section copies what it breaks).
    static const std::vector<TowSurface> tows = testing::bundledTwill(TOWGEOM_EXAMPLE_DATA);
    const ResolveOptions o = atSize(0.3);
    static const ResolveResult meshed = meshTows(tows, intersectTows(tows), atSize(0.3));
    const auto messageOf = [&](const ResolveResult& bad, const std::vector<TowSurface>& with) {
        try {
            connectRegions(with, bad, o);
        } catch (const Error& e) {
            CHECK(e.code() == ErrorCode::InvalidArgument);
            return std::string(e.what());
        }
        FAIL("not refused");
        return std::string();
    };
    SECTION("fewer tows") { CHECK(messageOf(meshed, {tows.begin(), tows.end() - 1}).find("8 tows, not 7") != std::string::npos); }
    SECTION("regions already made")
    {
        const ResolveResult connected = connectRegions(tows, meshed, o);
        CHECK(messageOf(connected, tows).find("connected already") != std::string::npos);
    }
    SECTION("a loop node without (u,v)")
    {
        ResolveResult bad = meshed;
        const MeshedLoop& l = bad.mesh.loops[3];
        auto& p = bad.mesh.tows[bad.intersections.loops[l.loop].towA()].parameters;
        p.erase(std::find_if(p.begin(), p.end(), [&](const auto& e) { return e.first == l.nodes[0]; }));
        CHECK(messageOf(bad, tows).find("loop " + std::to_string(l.loop)) != std::string::npos);
    }
    SECTION("a tow of another name")
    {
        ResolveResult bad = meshed;
        bad.mesh.tows[4].name = "other";
        CHECK(messageOf(bad, tows).find("named 'other'") != std::string::npos);
    }
    SECTION("per-triangle lists of another length")
    {
        ResolveResult bad = meshed;
        bad.mesh.tows[1].face.pop_back();
        CHECK(messageOf(bad, tows).find("one entry per triangle") != std::string::npos);
    }
    SECTION("parameters out of order")
    {
        ResolveResult bad = meshed;
        auto& p = bad.mesh.tows[0].parameters;
        std::swap(p[0], p[1]);
        CHECK(messageOf(bad, tows).find("increasing order") != std::string::npos);
    }
    SECTION("a loop listed twice, or not in the report")
    {
        ResolveResult twice = meshed;
        twice.mesh.loops.push_back(twice.mesh.loops[0]);
        CHECK(messageOf(twice, tows).find("listed twice") != std::string::npos);
        ResolveResult missing = meshed;
        missing.mesh.loops[0].loop = 99;
        CHECK(messageOf(missing, tows).find("loop 99") != std::string::npos);
    }
    SECTION("a triple point's node out of range")
    {
        ResolveResult bad = meshed;
        bad.mesh.triplePoints.push_back({bad.mesh.nodes.size(), {0, 1, 2}});
        CHECK(messageOf(bad, tows).find("triple point") != std::string::npos);
    }
    SECTION("a triangle's node out of range")
    {
        ResolveResult bad = meshed;
        bad.mesh.tows[2].triangles[5][1] = bad.mesh.nodes.size();
        CHECK(messageOf(bad, tows).find("tow '" + tows[2].name() + "'") != std::string::npos);
    }
}

TEST_CASE("mesh-size study: one intersection report meshed at three sizes", "[stages]")
{
    const std::vector<TowSurface> tows = testing::bundledTwill(TOWGEOM_EXAMPLE_DATA);
    const auto t0 = std::chrono::steady_clock::now();
    const IntersectionReport loops = intersectTows(tows);
    const double intersectS = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::size_t previous = 0;
    std::ostringstream timing;
    for (double h : {0.3, 0.15, 0.075}) {
        const auto t1 = std::chrono::steady_clock::now();
        const ResolveResult r = resolveTextile(tows, loops, atSize(h));
        timing << " h=" << h << ": " << std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count() << " s,";
        CHECK(r.mesh.regions.size() == 16);
        CHECK(r.unresolved.empty());
        CHECK(openTows(r) == 0);
        // Halving h about quadruples the triangles (the loops' nodes add a little more).
        CHECK(r.quality.triangles > 3 * previous);
        CHECK(r.quality.triangles < 6 * previous + 20000);
        for (const ConnectedRegion& g : r.mesh.regions) CHECK(g.volumeRemoved > 0.0);
        previous = r.quality.triangles;
    }
    WARN("intersection once: " << intersectS << " s; meshes:" << timing.str());
}

TEST_CASE("intersection report JSON: a report for other tows or a broken file is refused", "[stages][json]")
{
    // Once for the four sections.
    static const std::vector<TowSurface> tows = testing::bundledTwill(TOWGEOM_EXAMPLE_DATA);
    static const IntersectionReport found = intersectTows(tows);
    static const std::string json = jsonOf(found, tows);

    SECTION("the tows in another order: by name on reading, by name in resolveTextile()")
    {
        std::vector<TowSurface> swapped = tows;
        std::swap(swapped[0], swapped[4]);
        CHECK(codeOf([&] { readBack(json, swapped); }) == ErrorCode::MalformedReport);
        CHECK(codeOf([&] { resolveTextile(swapped, found, atSize(0.3)); }) == ErrorCode::InvalidArgument);
    }
    SECTION("the same names, other geometry: points off the surfaces")
    {
        std::vector<TowSurface> moved;
        for (const TowSurface& t : tows) {
            TowStack s;
            s.name = t.name();
            s.sections = t.sections();
            for (auto& section : s.sections)
                for (Point3& p : section) p.z += 0.05;
            moved.push_back(TowSurface::fit(s));
        }
        try {
            readBack(json, moved);
            FAIL("read a report for other geometry");
        } catch (const Error& e) {
            CHECK(e.code() == ErrorCode::MalformedReport);
            CHECK(std::string(e.what()).find("off the surfaces") != std::string::npos);
            CHECK(e.file() == "report.json");
        }
    }
    SECTION("truncated, not JSON, another version, a point of 7 numbers")
    {
        CHECK(codeOf([&] { readBack(json.substr(0, json.size() / 2), tows); }) == ErrorCode::MalformedReport);
        CHECK(codeOf([&] { readBack("tow a\n0 0 0\n", tows); }) == ErrorCode::MalformedReport);
        std::string v2 = json;
        v2.replace(v2.find("\"version\":1"), 11, "\"version\":2");
        CHECK(codeOf([&] { readBack(v2, tows); }) == ErrorCode::MalformedReport);
        std::string shortPoint = json;
        const std::size_t at = shortPoint.find("\"points\":[[") + 11;
        shortPoint.erase(at, shortPoint.find(',', at) + 1 - at);  // drops x of the first point
        CHECK(codeOf([&] { readBack(shortPoint, tows); }) == ErrorCode::MalformedReport);
    }
    SECTION("a file that does not exist")
    {
        CHECK(codeOf([&] { readIntersectionReport("/nonexistent/loops.json", tows); }) == ErrorCode::FileNotFound);
    }
}

namespace {

/// Records every update; cancels at the first update of the stage that starts with @p cancelAt.
struct Recorder : Progress {
    std::vector<std::tuple<std::string, std::size_t, std::size_t>> updates;
    std::string cancelAt;
    void update(const std::string& stage, std::size_t done, std::size_t total) override
    {
        updates.emplace_back(stage, done, total);
        if (!cancelAt.empty() && stage.rfind(cancelAt, 0) == 0) cancel();
    }
    bool saw(const std::string& prefix) const
    {
        for (const auto& u : updates)
            if (std::get<0>(u).rfind(prefix, 0) == 0) return true;
        return false;
    }
};

}  // namespace

TEST_CASE("one Progress for every stage: counted updates, and cancel() stops the stage in hand", "[stages][progress]")
{
    static const std::vector<TowSurface> tows = testing::bundledTwill(TOWGEOM_EXAMPLE_DATA);  // once for the three sections
    ResolveOptions o = atSize(0.3);
    o.threads = 2;

    SECTION("updates: the tow pairs counted up to their number, then meshing and connecting")
    {
        Recorder r;
        o.monitor = &r;
        const ResolveResult res = resolveTextile(tows, o);
        CHECK(res.mesh.regions.size() == 16);
        std::size_t pairs = 0, last = 0, meshedTows = 0;
        for (const auto& [stage, done, total] : r.updates) {
            if (stage == "intersecting tow pairs") {
                CHECK(done <= total);
                CHECK(done >= last);  // never concurrently, so never out of order
                last = done;
                pairs = total;
            }
            if (stage == "meshing tows") meshedTows = std::max(meshedTows, done);
        }
        CHECK(pairs == res.intersections.pairsTested);
        CHECK(last == pairs);
        CHECK(meshedTows == tows.size());
        CHECK(r.saw("intersecting 8 tows"));
        CHECK(r.saw("connecting 16 regions"));
    }
    SECTION("cancelled in each stage: Error(Cancelled), never a mesh failure or an unresolved pair")
    {
        for (const char* stage : {"intersecting tow pairs", "meshing 8 tows", "meshing tows", "connecting"}) {
            INFO(stage);
            Recorder r;
            r.cancelAt = stage;
            o.monitor = &r;
            try {
                resolveTextile(tows, o);
                FAIL("not cancelled");
            } catch (const Error& e) {
                CHECK(e.code() == ErrorCode::Cancelled);
            }
            CHECK(!r.saw("meshing again"));  // the cancellation was not taken for a failed tow
        }
    }
    SECTION("cancelled before the call: intersectTows() does no work")
    {
        Recorder r;
        r.cancel();
        IntersectionOptions io;
        io.monitor = &r;
        try {
            intersectTows(tows, io);
            FAIL("not cancelled");
        } catch (const Error& e) {
            CHECK(e.code() == ErrorCode::Cancelled);
        }
        CHECK(r.updates.size() == 1);  // the stage announced, no pair done
    }
}

TEST_CASE("intersection report JSON: numbers out of range, far v, wrong arc lengths, repeats, huge tolerances are refused", "[stages][json]")
{
    const std::vector<TowSurface> tows = testing::bundledTwill(TOWGEOM_EXAMPLE_DATA);
    const IntersectionReport found = intersectTows(tows);
    const nlohmann::json good = nlohmann::json::parse(jsonOf(found, tows));
    const auto refused = [&](const std::function<void(nlohmann::json&)>& edit) {
        nlohmann::json j = good;
        edit(j);
        return codeOf([&] { readBack(j.dump(), tows); }) == ErrorCode::MalformedReport;
    };
    // A number beyond double's range (nlohmann's out_of_range, not JSON's syntax).
    std::string huge = good.dump();
    const std::size_t at = huge.find("\"tolerance\":") + 12;
    huge.replace(at, huge.find(',', at) - at, "1e999");
    CHECK(codeOf([&] { readBack(huge, tows); }) == ErrorCode::MalformedReport);
    CHECK(refused([](nlohmann::json& j) { j["loops"][0]["points"][3][4] = 1e20; }));      // vA
    CHECK(refused([](nlohmann::json& j) { j["loops"][0]["points"][3][7] = 0.5; }));       // s
    CHECK(refused([](nlohmann::json& j) {                                                  // all s and length 0
        for (auto& p : j["loops"][0]["points"]) p[7] = 0.0;
        j["loops"][0]["length"] = 0.0;
    }));
    CHECK(refused([](nlohmann::json& j) {  // the closing chord of no length
        const auto& pts = j["loops"][0]["points"];
        j["loops"][0]["length"] = pts[pts.size() - 1][7];
    }));
    CHECK(refused([](nlohmann::json& j) { j["loops"].push_back(j["loops"][0]); }));      // a loop twice
    CHECK(refused([](nlohmann::json& j) {                                                  // a tolerance that would pass anything
        j["loops"][0]["tolerance"] = 1e300;
        for (auto& p : j["loops"][0]["points"]) p[0] = p[1] = p[2] = 0.0;
    }));
    CHECK(refused([](nlohmann::json& j) { j["loops"][0]["tow_a"] = -1; }));
    CHECK(refused([](nlohmann::json& j) { j["loops"][0]["open_reason"] = "closed anyway"; }));  // a reason on a closed loop
    CHECK_NOTHROW(readBack(good.dump(), tows));  // the untouched report reads

    // The writer refuses what the reader would: tows in another order, a name that is not UTF-8.
    std::vector<TowSurface> swapped = tows;
    std::swap(swapped[0], swapped[4]);
    CHECK(codeOf([&] { jsonOf(found, swapped); }) == ErrorCode::InvalidArgument);
    TowStack odd;
    odd.name = "w\xff";
    odd.sections = tows[0].sections();
    CHECK(codeOf([&] { jsonOf(IntersectionReport{}, {TowSurface::fit(odd)}); }) == ErrorCode::InvalidArgument);
    // A loop computed with a tolerance the reader could not check against: refused on writing.
    IntersectionOptions loose;
    loose.relativeTolerance = 0.02;
    CHECK(codeOf([&] { jsonOf(intersectTows(tows, loose), tows); }) == ErrorCode::InvalidArgument);
}

TEST_CASE("typed reasons: a tow through another is resolved with caps, skipped as AroundTowWithoutCaps without", "[stages][reasons]")
{
    // y (r = 0.3) passes right through x (R = 0.5): two loops around y.
    const std::vector<TowSurface> tows = {TowSurface::fit(testing::tubeAlongX(0.5, 4.0, 0.0, 0.0, 0.0, {}, "x")),
                                          TowSurface::fit(testing::tubeAlongY(0.3, 0.0, {}, "y"))};
    const IntersectionReport loops = intersectTows(tows);
    REQUIRE(loops.loops.size() == 2);
    ResolveOptions o = atSize(0.2);
    const ResolveResult capped = resolveTextile(tows, loops, o);
    CHECK(capped.skippedLoops.empty());
    CHECK(capped.tows[1].pieces == 2);  // y, ranked below x, gives way: cut into two pieces
    o.mesh.caps = false;
    const ResolveResult open = resolveTextile(tows, loops, o);
    REQUIRE(open.skippedLoops.size() == 2);
    for (std::size_t k = 0; k < 2; ++k) {
        CHECK(open.skippedLoops[k].loop == k);
        CHECK(open.skippedLoops[k].reason == SkippedLoop::Reason::AroundTowWithoutCaps);
        CHECK(open.skippedLoops[k].message.find("'y'") != std::string::npos);
    }
    CHECK(open.mesh.regions.empty());
}

TEST_CASE("TextileMesh: each triangle's fibre direction and each node's (u,v) on the tows it lies on", "[stages][fibre]")
{
    const std::vector<TowSurface> tows = testing::bundledTwill(TOWGEOM_EXAMPLE_DATA);
    const ResolveResult r = resolveTextile(tows, atSize(0.2));
    const TextileMesh& mesh = r.mesh;
    for (std::size_t t = 0; t < tows.size(); ++t) {
        INFO(tows[t].name());
        const TowMesh& m = mesh.tows[t];
        REQUIRE(m.fibreDirection.size() == m.triangles.size());
        // Warps run along x, wefts along y (with crimp): the fibre directions follow, on the
        // tow's own triangles; on a region's triangles taken from the other tow, that tow's.
        const bool warp = t < 4;
        std::size_t own = 0, taken = 0;
        for (std::size_t k = 0; k < m.triangles.size(); ++k) {
            const Vector3& d = m.fibreDirection[k];
            CHECK(norm(d) == Approx(1.0).epsilon(1e-12));
            const bool fromOther = m.region[k] >= 0 && !warp;  // the wefts took the warps' surface
            const double along = std::abs(warp != fromOther ? d.x : d.y);
            CHECK(along > 0.9);
            (fromOther ? taken : own)++;
        }
        CHECK(own > 0);
        CHECK(taken == (warp ? 0u : std::size_t(std::count_if(m.region.begin(), m.region.end(), [](long g) { return g >= 0; }))));
        // (u,v) of every node on the tow's own surface: sorted, on the surface; the caps'
        // inner nodes and the nodes of the surface taken from another tow have none.
        std::size_t previous = 0;
        for (std::size_t k = 0; k < m.parameters.size(); ++k) {
            const auto& [node, uv] = m.parameters[k];
            if (k > 0) CHECK(node > previous);
            previous = node;
            const ParameterRange range = tows[t].parameterRange();
            CHECK(uv.v >= range.vMin);
            CHECK(uv.v < range.vMax);
            CHECK(distance(mesh.nodes[node], tows[t].point(uv.u, uv.v)) <= 1e-6 * tows[t].towSize());
        }
        const std::size_t used = mesh.towNodes(t).size();
        CHECK(m.parameters.size() < used);        // cap interiors (and taken surfaces) have none
        CHECK(m.parameters.size() > used * 8 / 10);
    }
}

TEST_CASE("intersection loops from the host's own points: refined onto both surfaces, resolved like intersectTows()'s", "[stages][host-loops]")
{
    const std::vector<TowSurface> tows = testing::bundledTwill(TOWGEOM_EXAMPLE_DATA);
    const IntersectionReport found = intersectTows(tows);
    // Every 4th exact point, moved off the curve by 1 % of the tow size: a coarser, noisier
    // polyline such as another program gives.
    IntersectionReport mine;
    for (const IntersectionLoop& l : found.loops) {
        std::vector<Point3> points;
        for (std::size_t k = 0; k < l.points().size(); k += 4)
            points.push_back(l.points()[k].point + Vector3{0.01 * tows[0].towSize(), 0.0, 0.0});
        const IntersectionLoop back = intersectionLoopFromPoints(tows, l.towA(), l.towB(), points, true);
        CHECK(back.closed());
        CHECK(back.openKind() == IntersectionLoop::OpenKind::None);
        CHECK(back.maxDistance(LoopSide::A) <= 1e-6 * tows[l.towA()].towSize());
        CHECK(back.maxDistance(LoopSide::B) <= 1e-6 * tows[l.towB()].towSize());
        // A polygon through a quarter of the points: its area within 1 % of the dense loop's.
        CHECK(back.enclosedArea(LoopSide::B) == Approx(l.enclosedArea(LoopSide::B)).epsilon(0.01));
        mine.loops.push_back(back);
    }
    const ResolveResult a = resolveTextile(tows, found, atSize(0.2));
    const ResolveResult b = resolveTextile(tows, mine, atSize(0.2));
    REQUIRE(b.mesh.regions.size() == 16);
    CHECK(b.unresolved.empty());
    for (std::size_t g = 0; g < 16; ++g) CHECK(b.mesh.regions[g].volumeRemoved == Approx(a.mesh.regions[g].volumeRemoved).epsilon(0.02));

    // A point far from the curve, a wrong pair, too few points: refused.
    std::vector<Point3> far = {found.loops[0].points()[0].point, found.loops[0].points()[5].point, Point3{50.0, 50.0, 50.0}};
    CHECK(codeOf([&] { intersectionLoopFromPoints(tows, found.loops[0].towA(), found.loops[0].towB(), far, true); }) ==
          ErrorCode::InvalidArgument);
    CHECK(codeOf([&] { intersectionLoopFromPoints(tows, 5, 2, {}, true); }) == ErrorCode::InvalidArgument);
    CHECK(codeOf([&] { intersectionLoopFromPoints(tows, 0, 4, {Point3{}, Point3{1, 0, 0}}, true); }) == ErrorCode::InvalidArgument);
}

TEST_CASE("reports: writeResolveReport and writeDetectReport give the CLI's JSON, numbers exact, bad input refused", "[stages][report]")
{
    const std::vector<TowSurface> tows = testing::bundledTwill(TOWGEOM_EXAMPLE_DATA);
    const IntersectionReport found = intersectTows(tows);
    const ResolveResult r = resolveTextile(tows, found, atSize(0.3));
    std::ostringstream out;
    ResolveReportOptions written;
    written.times.read = 1.5;  // the caller's stage; fit, write and total are left out
    writeResolveReport(r, tows, out, written);
    const nlohmann::json j = nlohmann::json::parse(out.str());
    REQUIRE(j["tows"].size() == 8);
    for (std::size_t t = 0; t < tows.size(); ++t) {
        CHECK(j["tows"][t]["name"] == tows[t].name());
        CHECK(j["tows"][t]["volume_after"].get<double>() == r.tows[t].volumeAfter);  // round trip, bit for bit
        CHECK(j["tows"][t]["triangles"] == r.mesh.tows[t].triangles.size());
    }
    CHECK(j["regions"].size() == 16);
    CHECK(j["loops"].size() == 16);
    CHECK(j["unresolved"].empty());
    CHECK(j["node_count"] == r.mesh.nodes.size());
    CHECK(j["mesh_quality"]["min_angle_deg"].get<double>() == r.quality.minAngle);
    CHECK(j["timings_ms"]["read"] == 1.5);
    CHECK(!j["timings_ms"].contains("fit"));
    CHECK(j["timings_ms"].contains("mesh"));

    std::ostringstream detect;
    DetectReportOptions spaced;
    spaced.spacing = 0.05;
    writeDetectReport(found, tows, detect, spaced);
    const nlohmann::json d = nlohmann::json::parse(detect.str());
    REQUIRE(d["loops"].size() == 16);
    for (std::size_t k = 0; k < 16; ++k) {
        // Resampled at 0.05: about length / 0.05 points.
        const double expected = found.loops[k].length() / 0.05;
        CHECK(d["loops"][k]["point_count"].get<double>() == Approx(expected).margin(2.0));
        CHECK(d["loops"][k]["length"].get<double>() == found.loops[k].length());
    }
    CHECK(d["tow_pairs"] == found.towPairs);

    // The result of other tows is refused, and nothing is written.
    std::ostringstream none;
    const std::vector<TowSurface> fewer(tows.begin(), tows.end() - 1);
    CHECK(codeOf([&] { writeResolveReport(r, fewer, none); }) == ErrorCode::InvalidArgument);
    CHECK(codeOf([&] { writeDetectReport(found, fewer, none); }) == ErrorCode::InvalidArgument);
    CHECK(none.str().empty());
}
