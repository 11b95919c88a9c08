// libFuzzer target: read + validate + TowSurface::fit in every mode, inputs up to 64 KiB.
#include "fuzz_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    towgeom::fuzz::fitStackBytes(data, size);
    return 0;
}
