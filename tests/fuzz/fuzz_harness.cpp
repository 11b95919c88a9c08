#include "fuzz_harness.hpp"

#include <towgeom/towgeom.hpp>

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <string>

namespace towgeom::fuzz {

namespace {

std::optional<TowStack> read(const std::uint8_t* data, std::size_t size)
{
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    try {
        return readStack(in, "fuzz.stw", "fuzz");
    } catch (const Error&) {
        return std::nullopt;  // refused with a typed error: what the reader promises
    }
}

[[noreturn]] void broken(const char* what)
{
    std::fprintf(stderr, "towgeom fuzz: %s\n", what);
    std::abort();
}

}  // namespace

void readStackBytes(const std::uint8_t* data, std::size_t size)
{
    const std::optional<TowStack> stack = read(data, size);
    if (!stack) return;
    std::stringstream io;
    writeStack(io, *stack);
    TowStack back;
    try {
        back = readStack(io, "round_trip.stw", "other");
    } catch (const Error& e) {
        std::fprintf(stderr, "%s\n", e.what());
        broken("a stack that was read is refused after writeStack()");
    }
    if (back.name != stack->name || back.sections.size() != stack->sections.size())
        broken("writeStack() changed the name or the number of sections");
    for (std::size_t i = 0; i < back.sections.size(); ++i) {
        if (back.sections[i].size() != stack->sections[i].size()) broken("writeStack() changed a section's size");
        for (std::size_t j = 0; j < back.sections[i].size(); ++j) {
            const Point3 &a = back.sections[i][j], &b = stack->sections[i][j];
            if (a.x != b.x || a.y != b.y || a.z != b.z) broken("writeStack() changed a coordinate");
        }
    }
}

void fitStackBytes(const std::uint8_t* data, std::size_t size)
{
    if (size > kMaxFitInput) return;
    const std::optional<TowStack> stack = read(data, size);
    if (!stack) return;
    for (const FitMode mode : {FitMode::Interpolate, FitMode::Approximate, FitMode::ControlNet}) {
        FitOptions options;
        options.mode = mode;
        try {
            const TowSurface surface = TowSurface::fit(*stack, options);
            (void)surface.volume();
        } catch (const Error&) {
            // A valid stack the fit cannot handle is refused with a typed error: allowed.
        }
    }
}

}  // namespace towgeom::fuzz
