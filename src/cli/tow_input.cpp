#include "cli/tow_input.hpp"

#include <chrono>
#include <iostream>
#include <map>
#include <mutex>
#include <optional>

#include "core/parallel.hpp"
#include "towgeom/error.hpp"
#include "towgeom/stack_reader.hpp"

namespace towgeom::cli {

std::vector<TowStack> readStacks(const std::vector<std::string>& paths, std::size_t threads)
{
    // Read in parallel; report the first bad file in command-line order.
    std::vector<TowStack> stacks(paths.size());
    std::vector<std::exception_ptr> errors(paths.size());
    detail::parallelFor(paths.size(), detail::workerCount(threads), [&](std::size_t k) {
        try {
            stacks[k] = readStackFile(paths[k]);
        } catch (...) {
            errors[k] = std::current_exception();
        }
    });
    std::map<std::string, std::string> seen;
    for (std::size_t k = 0; k < paths.size(); ++k) {
        if (errors[k]) std::rethrow_exception(errors[k]);
        const auto [it, fresh] = seen.emplace(stacks[k].name, paths[k]);
        if (!fresh) throw Error(ErrorCode::BadName, "tow name '" + it->first + "' is also used by " + it->second, paths[k]);
    }
    return stacks;
}

std::vector<TowSurface> fitSurfaces(const std::vector<TowStack>& stacks, const FitOptions& options,
                                    const char* command, bool quiet, std::size_t threads)
{
    // Fit in parallel; progress as tows finish; the first failure in input order is reported.
    std::vector<std::optional<TowSurface>> fitted(stacks.size());
    std::vector<std::exception_ptr> errors(stacks.size());
    std::mutex progress;
    std::size_t done = 0;
    detail::parallelFor(stacks.size(), detail::workerCount(threads), [&](std::size_t k) {
        const auto start = std::chrono::steady_clock::now();
        try {
            fitted[k] = TowSurface::fit(stacks[k], options);
        } catch (...) {
            errors[k] = std::current_exception();
            return;
        }
        if (quiet) return;
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::lock_guard<std::mutex> lock(progress);
        std::cerr << "towgeom " << command << ": [" << ++done << "/" << stacks.size() << "] " << stacks[k].name << ": "
                  << stacks[k].sectionCount() << " x " << stacks[k].pointsPerSection() << " points fitted in " << seconds
                  << " s\n";
    });
    std::vector<TowSurface> surfaces;
    surfaces.reserve(stacks.size());
    for (std::size_t k = 0; k < stacks.size(); ++k) {
        if (errors[k]) std::rethrow_exception(errors[k]);
        surfaces.push_back(*fitted[k]);
    }
    return surfaces;
}

}  // namespace towgeom::cli
