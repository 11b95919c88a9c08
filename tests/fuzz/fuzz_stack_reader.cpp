// libFuzzer target: the .stw reader (readStack) and its writeStack round trip.
#include "fuzz_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    towgeom::fuzz::readStackBytes(data, size);
    return 0;
}
