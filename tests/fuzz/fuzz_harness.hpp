// What the fuzz targets do with one input, shared with the test that replays the seed corpus and
// every regression input (tests/test_fuzz_replay.cpp), so both check exactly the same contract:
// any input is either read (fitted) or refused with a towgeom::Error. Any other exception
// escapes; a broken round trip aborts.
#pragma once

#include <cstddef>
#include <cstdint>

namespace towgeom::fuzz {

/// The fit target ignores larger inputs: they only make it slower, not different.
constexpr std::size_t kMaxFitInput = 64 * 1024;

/// readStack() on the bytes; a stack that is read must survive writeStack() and readStack()
/// unchanged (else abort()).
void readStackBytes(const std::uint8_t* data, std::size_t size);

/// readStack() (which validates) and TowSurface::fit() in every FitMode, for inputs up to
/// kMaxFitInput bytes.
void fitStackBytes(const std::uint8_t* data, std::size_t size);

}  // namespace towgeom::fuzz
