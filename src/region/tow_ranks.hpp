// The tows' rank (ResolveOptions::primaryPatterns, then input order): who gives way to whom.
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include "core/glob_match.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// Each tow's rank (0 first): tows whose name matches a primary pattern, then the others, each
/// in input order. A tow gives way to every tow ranked above it.
inline std::vector<std::size_t> towRanks(const std::vector<TowSurface>& tows, const std::vector<std::string>& primaryPatterns)
{
    std::vector<std::size_t> order(tows.size());
    for (std::size_t t = 0; t < tows.size(); ++t) order[t] = t;
    std::stable_partition(order.begin(), order.end(), [&](std::size_t t) {
        return std::any_of(primaryPatterns.begin(), primaryPatterns.end(),
                           [&](const std::string& p) { return globMatch(p, tows[t].name()); });
    });
    std::vector<std::size_t> rank(tows.size());
    for (std::size_t r = 0; r < order.size(); ++r) rank[order[r]] = r;
    return rank;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
