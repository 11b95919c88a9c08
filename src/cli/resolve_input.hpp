// What resolve and export share: the options that say how the tows are resolved, and the
// resolve they run (its triangle budget explained).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cli/args.hpp"
#include "towgeom/error.hpp"
#include "towgeom/resolve.hpp"

namespace towgeom::cli {

/// Reads --primary, --mesh-size, --loop-spacing, --max-triangles, --tolerance, --threads and
/// --cell [--periodic] into @p o.
/// @throws UsageError for a malformed value, --periodic without --cell, --tolerance with --report.
void readResolveOptions(const Args& args, ResolveOptions& o);

/// @p e (TooLarge: a mesh over the triangle budget) saying which options change the budget.
Error budgetExplained(const Error& e);

/// @p run(), its TooLarge error explained (budgetExplained()).
template <typename Run>
auto explainingBudget(Run&& run) -> decltype(run())
{
    try {
        return run();
    } catch (const Error& e) {
        if (e.code() != ErrorCode::TooLarge) throw;
        throw budgetExplained(e);
    }
}

/// resolveTextile() of @p tows with @p o, the loops read from @p reportPath when given, its
/// TooLarge error explained.
ResolveResult resolveExplained(const std::vector<TowSurface>& tows, const ResolveOptions& o, const std::optional<std::string>& reportPath);

}  // namespace towgeom::cli
