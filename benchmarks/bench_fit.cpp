// Fitting benchmark: a crimped elliptical tow of M x N points (default 400 x 64, the size of a
// tow in a production textile model), fitted by each mode. Prints the median wall time of the
// fit and of the volume and deviation queries, and the process's peak memory.
//   bench_fit [--sections M] [--points N] [--repeat R] [--smoke]
// Target (issue 2): Interpolate fit of 400 x 64 in <= 100 ms on one core; exits 3 when it is
// missed (bench_goal.hpp; --smoke: the time is only required to be measured).
#include <towgeom/towgeom.hpp>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "bench_goal.hpp"
#include "synthetic_tows.hpp"

namespace {

double medianMs(int repeat, const std::function<void()>& work)
{
    std::vector<double> ms;
    for (int k = 0; k < repeat; ++k) {
        const auto start = std::chrono::steady_clock::now();
        work();
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    std::sort(ms.begin(), ms.end());
    return ms[ms.size() / 2];
}

double peakMiB()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

}  // namespace

int main(int argc, char** argv)
{
    std::size_t m = 400, n = 64;
    int repeat = 7;
    bool smoke = false;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--smoke")) smoke = true;
        else if (i + 1 == argc) break;
        else if (!std::strcmp(argv[i], "--sections")) m = std::stoul(argv[++i]);
        else if (!std::strcmp(argv[i], "--points")) n = std::stoul(argv[++i]);
        else if (!std::strcmp(argv[i], "--repeat")) repeat = std::max(1, std::stoi(argv[++i]));
    }
    towgeom::bench::Goals goals(smoke);
    towgeom::testing::Sampling sampling;
    sampling.sections = m;
    sampling.points = n;
    const towgeom::TowStack stack = towgeom::testing::crimpedTow(0.5, 0.12, 20.0, 0.1, 2.0, sampling, "bench");
    std::printf("towgeom bench_fit: tow of %zu sections x %zu points, median of %d runs\n", m, n, repeat);
    double interpolateMs = 0.0;
    std::printf("%-12s %10s %10s %12s %12s %14s\n", "mode", "fit_ms", "volume_ms", "deviation_ms", "max_dev", "control_pts");
    for (const towgeom::FitMode mode :
         {towgeom::FitMode::Interpolate, towgeom::FitMode::Approximate, towgeom::FitMode::ControlNet}) {
        towgeom::FitOptions options;
        options.mode = mode;
        towgeom::TowSurface surface = towgeom::TowSurface::fit(stack, options);
        const double fitMs = medianMs(repeat, [&] { surface = towgeom::TowSurface::fit(stack, options); });
        double volume = 0.0;
        const double volumeMs = medianMs(repeat, [&] { volume = surface.volume(); });
        towgeom::Deviation dev;
        const double devMs = medianMs(std::min(repeat, 3), [&] { dev = surface.deviation(); });
        std::printf("%-12s %10.2f %10.2f %12.2f %12.3g %8zu x %zu\n", towgeom::fitModeName(mode), fitMs, volumeMs, devMs,
                    dev.max, surface.controlPointCount(true), surface.controlPointCount(false));
        goals.require(std::string(towgeom::fitModeName(mode)) + " volume finite and positive", std::isfinite(volume) && volume > 0.0);
        if (mode == towgeom::FitMode::Interpolate) interpolateMs = fitMs;
    }
    std::printf("peak memory: %.1f MiB\n", peakMiB());
    goals.secondsAtMost("interpolate fit", interpolateMs / 1e3, 0.1);
    return goals.exitStatus();
}
