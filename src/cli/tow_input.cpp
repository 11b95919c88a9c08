#include "cli/tow_input.hpp"

#include <chrono>
#include <iostream>
#include <map>

#include "towgeom/error.hpp"
#include "towgeom/stack_reader.hpp"

namespace towgeom::cli {

std::vector<TowStack> readStacks(const std::vector<std::string>& paths)
{
    std::vector<TowStack> stacks;
    std::map<std::string, std::string> seen;
    for (const std::string& path : paths) {
        stacks.push_back(readStackFile(path));
        const auto [it, fresh] = seen.emplace(stacks.back().name, path);
        if (!fresh) throw Error(ErrorCode::BadName, "tow name '" + it->first + "' is also used by " + it->second, path);
    }
    return stacks;
}

std::vector<TowSurface> fitSurfaces(const std::vector<TowStack>& stacks, const FitOptions& options,
                                    const char* command, bool quiet)
{
    std::vector<TowSurface> surfaces;
    surfaces.reserve(stacks.size());
    for (std::size_t k = 0; k < stacks.size(); ++k) {
        const auto start = std::chrono::steady_clock::now();
        surfaces.push_back(TowSurface::fit(stacks[k], options));
        if (!quiet)
            std::cerr << "towgeom " << command << ": [" << k + 1 << "/" << stacks.size() << "] " << stacks[k].name << ": "
                      << stacks[k].sectionCount() << " x " << stacks[k].pointsPerSection() << " points fitted in "
                      << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s\n";
    }
    return surfaces;
}

}  // namespace towgeom::cli
