// The commands' stage timings (report.json "timings_ms").
#pragma once

#include <chrono>

namespace towgeom::cli {

/// Milliseconds since @p t0.
inline double msSince(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace towgeom::cli
