// towgeom detect: JSON loops on the bundled twill, exit 3 and the pair named for an open curve,
// exit 2 for bad input and usage.
#include <catch2/catch.hpp>

#include <towgeom/towgeom.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "cli_runner.hpp"
#include "synthetic_tows.hpp"

namespace fs = std::filesystem;
using namespace towgeom;
using testing::cli;
using testing::Run;

namespace {

std::size_t count(const std::string& text, const std::string& what)
{
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

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
    for (std::size_t k = 0; k < 16; ++k) CHECK(testing::jsonNumber(r.out, "max_distance", k) <= 1e-7);
    CHECK(r.out.find("\"timings_ms\":{\"read\":") != std::string::npos);
    CHECK(r.err.find("tow pairs intersected") != std::string::npos);  // progress
    const Run quiet = cli("detect" + twillFiles() + " --quiet --spacing 0.1");
    CHECK(quiet.status == 0);
    CHECK(quiet.err.empty());
    // Points spaced by at most 0.1 along loops of length ~1.7: 17 or 18 each.
    CHECK(testing::jsonNumber(quiet.out, "point_count") >= 17);
    CHECK(testing::jsonNumber(quiet.out, "point_count") <= 18);
}

TEST_CASE("towgeom detect exits 3 naming the pair when a curve is open", "[cli][intersection][open]")
{
    const fs::path dir = fs::temp_directory_path() / ("towgeom_detect_open_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    testing::Sampling s;
    s.points = 48;
    const std::string files = write(dir, testing::tubeAlongX(0.5, 2.0, 0.0, 0.0, 0.0, s, "short")) +
                              write(dir, testing::tubeAlongY(0.5, 0.7, s, "crossing"));
    const Run r = cli("detect" + files + " --quiet");
    CHECK(r.status == 3);
    CHECK(count(r.out, "\"closed\":false") == 1);
    CHECK(r.out.find("\"open_reason\":\"the curve reaches an end of the first tow\"") != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(r.err.find("'short' and 'crossing'") != std::string::npos);
    CHECK(r.err.find("[open_curve]") != std::string::npos);
    const Run allowed = cli("detect" + files + " --quiet --allow-open");
    CHECK(allowed.status == 0);
    CHECK(allowed.err == r.err);  // still named: a warning, not progress
    // The same report apart from the timings.
    CHECK(allowed.out.substr(0, allowed.out.find("\"timings_ms\"")) == r.out.substr(0, r.out.find("\"timings_ms\"")));
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
    for (const char* options : {" --quiet", " --quiet --allow-open", ""}) {
        DYNAMIC_SECTION("nested," << options)
        {
            const Run r = cli("detect" + outer + inner + options);
            CHECK(r.status == 3);
            CHECK(r.out.find("\"loops\":[]") != std::string::npos);
            CHECK(r.out.find("\"findings\":[{\"tow_a\":\"outer\",\"tow_b\":\"inner\",\"kind\":\"nested\"") != std::string::npos);
            if (std::string(options).find("--quiet") != std::string::npos)
                CHECK(r.err == nestedLine);
            else
                CHECK(count(r.err, nestedLine) == 1);
        }
        DYNAMIC_SECTION("identical," << options)
        {
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
        DYNAMIC_SECTION(args)
        {
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
