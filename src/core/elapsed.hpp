// Wall time for the stages' timings, and the constants several sources share (one definition,
// so that the sources can be compiled together in a unity build).
#pragma once

#include <chrono>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// Milliseconds from @p start to now (steady clock).
inline double msSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

/// pi to double precision.
inline constexpr double kPi = 3.14159265358979323846;

}  // namespace detail
TOWGEOM_END_NAMESPACE
