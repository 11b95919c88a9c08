// Replays every input of the fuzz targets' seed corpus (tests/fuzz/corpus/TARGET) and every
// regression input (tests/fuzz/regressions/TARGET: inputs that once broke a target) in every
// build including the sanitized one, and asserts the one outcome each input has:
//  - through the harness the fuzzers run (no abort, nothing but towgeom::Error escaping);
//  - an invalid input is refused by readStack() with a towgeom::Error (nothing else), with the
//    code and line it expects: corpus files copied from the malformed-input matrix take theirs
//    from tests/data/malformed/cases.txt, regressions from their folder's expected.txt;
//  - a valid input (every other corpus file; "valid" in expected.txt) is read, passes
//    validateStack(), survives writeStack() unchanged and, for the fit target, fits in every
//    mode with a finite, positive volume, faceted volume, area and section area.
#include <catch2/catch.hpp>

#include <towgeom/towgeom.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "fuzz_harness.hpp"

namespace fs = std::filesystem;
using namespace towgeom;

namespace {

/// What an input must give: valid, or refused with this code at this line (0: none).
struct Expected {
    bool valid = true;
    std::string code;
    std::size_t line = 0;
};

struct Input {
    fs::path path;
    Expected expected;
};

std::map<std::string, Expected> manifest(const fs::path& file)
{
    std::map<std::string, Expected> m;
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream s(line);
        std::string name, what;
        s >> name >> what;
        Expected e;
        if (what != "valid") {
            e.valid = false;
            e.code = what;
            s >> e.line;
        }
        m[name] = e;
    }
    return m;
}

/// The seeds: copies of the malformed-input matrix refused as cases.txt says, the others valid.
std::vector<Input> corpus(const std::string& target)
{
    const std::map<std::string, Expected> malformed = manifest(fs::path(TOWGEOM_TEST_DATA) / "malformed" / "cases.txt");
    std::vector<Input> inputs;
    for (const auto& entry : fs::directory_iterator(fs::path(TOWGEOM_FUZZ_DIR) / "corpus" / target)) {
        if (!entry.is_regular_file()) continue;
        const auto it = malformed.find(entry.path().filename().string());
        inputs.push_back({entry.path(), it == malformed.end() ? Expected{} : it->second});
    }
    std::sort(inputs.begin(), inputs.end(), [](const Input& a, const Input& b) { return a.path < b.path; });
    return inputs;
}

/// The regression inputs, each with its line of expected.txt; a file without one (or a line
/// without its file) fails the test.
std::vector<Input> regressions(const std::string& target)
{
    const fs::path dir = fs::path(TOWGEOM_FUZZ_DIR) / "regressions" / target;
    REQUIRE(fs::is_regular_file(dir / "expected.txt"));
    std::map<std::string, Expected> expected = manifest(dir / "expected.txt");
    std::vector<Input> inputs;
    for (const auto& entry : fs::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        if (!entry.is_regular_file() || name == "expected.txt") continue;
        INFO("regression input " << entry.path().string() << " has no line in expected.txt");
        const auto it = expected.find(name);
        REQUIRE(it != expected.end());
        inputs.push_back({entry.path(), it->second});
        expected.erase(it);
    }
    for (const auto& [name, e] : expected) FAIL_CHECK("expected.txt names " << name << ", which is not in " << dir.string());
    std::sort(inputs.begin(), inputs.end(), [](const Input& a, const Input& b) { return a.path < b.path; });
    return inputs;
}

std::string bytes(const fs::path& p)
{
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

double finitePositive(double x) { return std::isfinite(x) && x > 0.0 ? x : 0.0; }

/// Checks one input; returns whether it was valid.
bool check(const Input& input, bool fit)
{
    INFO(input.path.string() << (input.expected.valid ? " (valid)" : " (refused: " + input.expected.code + ")"));
    const std::string data = bytes(input.path);
    const auto* raw = reinterpret_cast<const std::uint8_t*>(data.data());
    // The fuzz target's own contract (a broken round trip aborts the process).
    if (fit)
        CHECK_NOTHROW(fuzz::fitStackBytes(raw, data.size()));
    else
        CHECK_NOTHROW(fuzz::readStackBytes(raw, data.size()));

    std::istringstream in(data);
    TowStack stack;
    try {
        stack = readStack(in, "fuzz.stw", "fuzz");
    } catch (const Error& e) {
        INFO(e.what());
        CHECK_FALSE(input.expected.valid);
        CHECK(errorCodeName(e.code()) == input.expected.code);
        CHECK(e.line() == input.expected.line);
        CHECK(std::string(e.what()).rfind("fuzz.stw", 0) == 0);
        return false;
    } catch (const std::exception& e) {
        FAIL_CHECK("readStack threw something other than towgeom::Error: " << e.what());
        return false;
    }
    CHECK(input.expected.valid);
    if (!input.expected.valid) return false;
    CHECK_NOTHROW(validateStack(stack));
    std::stringstream io;
    writeStack(io, stack);
    const TowStack back = readStack(io, "round_trip.stw", "other");
    CHECK(back.name == stack.name);
    REQUIRE(back.sections.size() == stack.sections.size());
    std::size_t changed = 0;
    for (std::size_t i = 0; i < back.sections.size(); ++i) {
        REQUIRE(back.sections[i].size() == stack.sections[i].size());
        for (std::size_t j = 0; j < back.sections[i].size(); ++j) {
            const Point3 &p = back.sections[i][j], &q = stack.sections[i][j];
            changed += p.x != q.x || p.y != q.y || p.z != q.z;
        }
    }
    CHECK(changed == 0);
    if (!fit) return true;
    for (const FitMode mode : {FitMode::Interpolate, FitMode::Approximate, FitMode::ControlNet}) {
        INFO("mode " << fitModeName(mode));
        FitOptions options;
        options.mode = mode;
        try {
            const TowSurface s = TowSurface::fit(stack, options);
            const double volume = s.volume(), faceted = s.facetedVolume(), area = s.area(), section = s.sectionArea(0.5);
            INFO("volume " << volume << ", faceted " << faceted << ", area " << area << ", section area " << section);
            CHECK(finitePositive(volume) > 0.0);
            CHECK(finitePositive(faceted) > 0.0);
            CHECK(finitePositive(area) > 0.0);
            CHECK(finitePositive(section) > 0.0);
            // A sanity bound, not an accuracy one: the seeds are coarse (6 to 8 points around
            // give the fitted volume up to 27 % above the faceted input's, the control net
            // below it), so a wrong sign or a factor of 2 fails, a coarse fit does not.
            CHECK(std::abs(volume / faceted - 1.0) < 0.5);
        } catch (const std::exception& e) {
            FAIL_CHECK("a valid stack did not fit: " << e.what());
        }
    }
    return true;
}

void replay(const std::string& target, bool fit)
{
    std::size_t valid = 0, refused = 0;
    SECTION("seed corpus")
    {
        const std::vector<Input> inputs = corpus(target);
        for (const Input& input : inputs) (check(input, fit) ? valid : refused) += 1;
        // make_corpus.sh: the matrix's files up to 16 KiB, the tube, three generated yarns, variants.
        CHECK(refused >= 25);
        CHECK(valid >= 5);
    }
    SECTION("regressions")
    {
        const std::vector<Input> inputs = regressions(target);
        for (const Input& input : inputs) (check(input, fit) ? valid : refused) += 1;
        CHECK(refused >= 9);
        CHECK(valid >= 3);
    }
}

}  // namespace

TEST_CASE("fuzz inputs: the reader reads or refuses each as expected and round-trips what it reads", "[fuzz]")
{
    replay("stack_reader", false);
}

TEST_CASE("fuzz inputs: valid stacks fit with finite positive volumes, invalid ones are refused as expected", "[fuzz]")
{
    replay("stack_fit", true);
}
