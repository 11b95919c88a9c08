// Replays every input of the fuzz targets' seed corpus (tests/fuzz/corpus/TARGET) and every
// regression input (tests/fuzz/regressions/TARGET: inputs that once broke a target) through the
// harness the fuzzers run, in every build including the sanitized one: each input is read (and
// fitted) or refused with a towgeom::Error, and what is read survives writeStack().
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz_harness.hpp"

namespace fs = std::filesystem;

namespace {

std::vector<fs::path> inputs(const std::string& target)
{
    std::vector<fs::path> files;
    for (const char* kind : {"corpus", "regressions"}) {
        const fs::path dir = fs::path(TOWGEOM_FUZZ_DIR) / kind / target;
        if (!fs::is_directory(dir)) continue;
        for (const auto& entry : fs::directory_iterator(dir))
            if (entry.is_regular_file() && entry.path().filename() != "README.md") files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

std::vector<std::uint8_t> bytes(const fs::path& p)
{
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_CASE("fuzz inputs: the reader reads or refuses each and round-trips what it reads", "[fuzz]")
{
    const std::vector<fs::path> files = inputs("stack_reader");
    REQUIRE(files.size() >= 20);
    for (const fs::path& f : files) {
        INFO(f.string());
        const std::vector<std::uint8_t> data = bytes(f);
        CHECK_NOTHROW(towgeom::fuzz::readStackBytes(data.data(), data.size()));
    }
}

TEST_CASE("fuzz inputs: read, validate and fit succeed or refuse each with a typed error", "[fuzz]")
{
    const std::vector<fs::path> files = inputs("stack_fit");
    REQUIRE(files.size() >= 20);
    for (const fs::path& f : files) {
        INFO(f.string());
        const std::vector<std::uint8_t> data = bytes(f);
        CHECK_NOTHROW(towgeom::fuzz::fitStackBytes(data.data(), data.size()));
    }
}
