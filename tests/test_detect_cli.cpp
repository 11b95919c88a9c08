// towgeom detect: JSON loops on the bundled twill, exit 3 and the pair named for an open curve,
// exit 2 for bad input and usage.
#include <catch2/catch.hpp>

#include <towgeom/towgeom.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "cli_runner.hpp"
#include "synthetic_tows.hpp"

namespace fs = std::filesystem;
using namespace towgeom;
using testing::cli;
using testing::Run;

namespace {

using testing::count;

std::string twillFiles()
{
    std::string files;
    for (const auto& e : fs::directory_iterator(std::string(TOWGEOM_EXAMPLE_DATA) + "/twill"))
        if (e.path().extension() == ".stw") files += " '" + e.path().string() + "'";
    return files;
}

/// Writes @p stack to DIR/NAME.stw and returns the quoted path.
std::string write(const fs::path& dir, const TowStack& stack)
{
    fs::create_directories(dir);
    const fs::path p = dir / (stack.name + ".stw");
    std::ofstream out(p);
    writeStack(out, stack);
    return " '" + p.string() + "'";
}

/// Each loop object of detect's JSON: its "length" and its "points", read by the test.
struct JsonLoop {
    double length = 0.0;
    std::size_t pointCount = 0;
    std::vector<Point3> points;
};

std::vector<JsonLoop> jsonLoops(const std::string& json)
{
    std::vector<JsonLoop> loops;
    const std::regex number("-?[0-9.]+(?:[eE][-+]?[0-9]+)?");
    for (std::size_t at = json.find("{\"tow_a\""); at != std::string::npos; at = json.find("{\"tow_a\"", at + 1)) {
        const std::size_t end = json.find("]]}", at);
        REQUIRE(end != std::string::npos);
        const std::string loop = json.substr(at, end + 2 - at);
        JsonLoop l;
        l.length = testing::jsonNumber(loop, "length");
        l.pointCount = static_cast<std::size_t>(testing::jsonNumber(loop, "point_count"));
        const std::size_t from = loop.find("\"points\":[");
        REQUIRE(from != std::string::npos);
        std::vector<double> xyz;
        for (auto it = std::sregex_iterator(loop.begin() + static_cast<long>(from), loop.end(), number); it != std::sregex_iterator(); ++it)
            xyz.push_back(std::stod(it->str()));
        REQUIRE(xyz.size() % 3 == 0);
        for (std::size_t k = 0; k < xyz.size(); k += 3) l.points.push_back({xyz[k], xyz[k + 1], xyz[k + 2]});
        loops.push_back(l);
    }
    return loops;
}

}  // namespace

TEST_CASE("towgeom detect finds one closed loop per crossing of the bundled twill", "[cli][intersection]")
{
    const Run r = cli("detect" + twillFiles() + " --threads 2");
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK(count(r.out, "\"closed\":true") == 16);
    CHECK(count(r.out, "\"closed\":false") == 0);
    CHECK(testing::jsonNumber(r.out, "pairs_tested") == 16);
    CHECK(testing::jsonNumber(r.out, "tow_pairs") == 28);
    // Refined to rounding level: observed at most 2.0e-15 (tows of size ~0.5; was 1e-7).
    for (std::size_t k = 0; k < 16; ++k) CHECK(testing::jsonNumber(r.out, "max_distance", k) <= 5e-15);
    CHECK(r.out.find("\"timings_ms\":{\"read\":") != std::string::npos);
    CHECK(r.err.find("] intersecting tow pairs") != std::string::npos);  // progress
    const Run quiet = cli("detect" + twillFiles() + " --quiet --spacing 0.1");
    CHECK(quiet.status == 0);
    CHECK(quiet.err.empty());
    CHECK(count(quiet.out, "\"closed\":true") == 16);
    // Every loop (lengths 1.55 to 1.76) resampled to ceil(length / 0.1) points (16 to 18), no
    // chord (closing one included) longer than 0.1, and their sum, the polyline's length, at
    // most the loop's and within 1 % of it (chords of 0.1 on curves of radius ~0.25).
    const std::vector<JsonLoop> loops = jsonLoops(quiet.out);
    REQUIRE(loops.size() == 16);
    for (const JsonLoop& l : loops) {
        INFO("loop of length " << l.length);
        CHECK(l.length > 1.5);
        CHECK(l.length < 1.8);
        CHECK(l.pointCount == static_cast<std::size_t>(std::ceil(l.length / 0.1)));
        REQUIRE(l.points.size() == l.pointCount);
        double longest = 0.0, sum = 0.0;
        for (std::size_t k = 0; k < l.points.size(); ++k) {
            const double chord = distance(l.points[k], l.points[(k + 1) % l.points.size()]);
            longest = std::max(longest, chord);
            sum += chord;
        }
        CHECK(longest <= 0.1 * (1.0 + 1e-9));
        CHECK(sum <= l.length * (1.0 + 1e-12));
        CHECK(sum >= 0.99 * l.length);
    }
}

TEST_CASE("towgeom detect exits 3 naming the pair when a curve is open", "[cli][intersection][open]")
{
    const fs::path dir = fs::temp_directory_path() / ("towgeom_detect_open_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    testing::Sampling s;
    s.points = 48;
    // Neighbours overlapping along their whole length and ending in the same planes: their
    // curves reach both tows' ends at once (cap against cap), and stay open.
    const std::string files = write(dir, testing::tubeAlongX(0.5, 4.0, 0.0, 0.0, 0.0, s, "left")) +
                              write(dir, testing::tubeAlongX(0.5, 4.0, 0.0, 0.9, 0.0, s, "right"));
    const Run r = cli("detect" + files + " --quiet");
    CHECK(r.status == 3);
    CHECK(count(r.out, "\"closed\":false") == 2);
    CHECK(r.out.find("\"open_reason\":\"the curve reaches an end of the first tow\"") != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(r.err.find("'left' and 'right'") != std::string::npos);
    CHECK(r.err.find("[open_curve]") != std::string::npos);
    const Run allowed = cli("detect" + files + " --quiet --allow-open");
    CHECK(allowed.status == 0);
    CHECK(allowed.err == r.err);  // still named: a warning, not progress
    // The same report apart from the timings.
    CHECK(allowed.out.substr(0, allowed.out.find("\"timings_ms\"")) == r.out.substr(0, r.out.find("\"timings_ms\"")));
    fs::remove_all(dir);
}

TEST_CASE("towgeom detect closes a curve across the end cap of a tow ending inside another", "[cli][intersection][caps]")
{
    const fs::path dir = fs::temp_directory_path() / ("towgeom_detect_cap_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    testing::Sampling s;
    s.points = 48;
    const std::string files = write(dir, testing::tubeAlongX(0.5, 2.0, 0.0, 0.0, 0.0, s, "short")) +
                              write(dir, testing::tubeAlongY(0.5, 0.7, s, "crossing"));
    const Run r = cli("detect" + files + " --quiet");
    CHECK(r.status == 0);
    CHECK(count(r.out, "\"closed\":false") == 0);
    CHECK(count(r.out, "\"closed\":true") == 1);
    CHECK(r.err.empty());
    fs::remove_all(dir);
}

TEST_CASE("towgeom detect exits 3 naming nested and identical tows, --quiet or not", "[cli][intersection][unresolved]")
{
    // A complete overlap has no intersection curve, yet the tows are not resolved: the pair is
    // named on stderr whatever --quiet and --allow-open say, and the exit status is 3.
    const fs::path dir = fs::temp_directory_path() / ("towgeom_detect_nested_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    testing::Sampling s;
    s.points = 32;
    const std::string outer = write(dir, testing::tubeAlongX(0.5, 4.0, 0.0, 0.0, 0.0, s, "outer"));
    const std::string inner = write(dir, testing::tubeAlongX(0.25, 4.0, 0.0, 0.0, 0.0, s, "inner"));  // scaled about the axis
    const std::string twin = write(dir, testing::tubeAlongX(0.5, 4.0, 0.0, 0.0, 0.0, s, "twin"));
    const std::string nestedLine =
        "towgeom detect: unresolved tow pair 'outer' and 'inner': tow 'inner' lies inside tow 'outer' (a complete overlap: no "
        "intersection curve) [nested]\n";
    // Plain blocks, not sections: Catch would run the whole case again per section.
    for (const char* options : {" --quiet", " --quiet --allow-open", ""}) {
        {
            INFO("nested," << options);
            const Run r = cli("detect" + outer + inner + options);
            CHECK(r.status == 3);
            CHECK(r.out.find("\"loops\":[]") != std::string::npos);
            CHECK(r.out.find("\"findings\":[{\"tow_a\":\"outer\",\"tow_b\":\"inner\",\"kind\":\"nested\"") != std::string::npos);
            if (std::string(options).find("--quiet") != std::string::npos)
                CHECK(r.err == nestedLine);
            else
                CHECK(count(r.err, nestedLine) == 1);
        }
        {
            INFO("identical," << options);
            const Run r = cli("detect" + outer + twin + options);
            CHECK(r.status == 3);
            CHECK(r.out.find("\"loops\":[]") != std::string::npos);
            const std::string line =
                "towgeom detect: unresolved tow pair 'outer' and 'twin': the surfaces touch or coincide (their facets cross) but "
                "do not cross each other along a curve: no interpenetration loop [identical_or_touching]\n";
            if (std::string(options).find("--quiet") != std::string::npos)
                CHECK(r.err == line);
            else
                CHECK(count(r.err, line) == 1);
        }
    }
    // Given the other way round, the pair is named in the order given.
    const Run reversed = cli("detect" + inner + outer + " --quiet");
    CHECK(reversed.status == 3);
    CHECK(reversed.err ==
          "towgeom detect: unresolved tow pair 'inner' and 'outer': tow 'inner' lies inside tow 'outer' (a complete overlap: no "
          "intersection curve) [nested]\n");
    fs::remove_all(dir);
}

TEST_CASE("towgeom detect refuses bad input and usage with exit 2", "[cli][intersection]")
{
    const std::string bad = std::string(TOWGEOM_TEST_DATA) + "/malformed/figure_eight.stw";
    const Run r = cli("detect" + twillFiles() + " '" + bad + "'");
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(r.err.find(bad + ":") != std::string::npos);
    CHECK(r.err.find("[self_intersecting_section]") != std::string::npos);
    for (const std::string& args : {std::string("detect"), "detect" + twillFiles() + " --threads 0",
                                    "detect" + twillFiles() + " --tolerance -1", "detect" + twillFiles() + " --spacing x"}) {
        {  // a block, not a section: Catch would rerun the whole case per section
            INFO(args);
            const Run u = cli(args);
            CHECK(u.status == 2);
            CHECK(u.out.empty());
            CHECK(std::count(u.err.begin(), u.err.end(), '\n') == 1);
        }
    }
    const Run help = cli("detect --help");
    CHECK(help.status == 0);
    for (const char* word : {"--tolerance", "--allow-open", "--threads", "Exit status", "Example", "pairs_tested"})
        CHECK(help.out.find(word) != std::string::npos);
}
