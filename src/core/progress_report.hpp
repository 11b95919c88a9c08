// How the stages report progress and honour cancellation: through the Progress of their options
// (and, for one minor version, the deprecated callbacks it replaces).
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <type_traits>

#include "towgeom/error.hpp"
#include "towgeom/export.hpp"
#include "towgeom/progress.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// Throws Error(ErrorCode::Cancelled) once @p monitor was cancelled (none: never).
inline void throwIfCancelled(const Progress* monitor)
{
    if (monitor && monitor->cancelled())
        throw Error(ErrorCode::Cancelled, "cancelled by towgeom::Progress::cancel()");
}

/// Reports one stage to @p monitor and to @p legacy (a deprecated std::function callback), either
/// may be empty; then throws if cancelled.
template <class Legacy>
void reportStage(Progress* monitor, const Legacy& legacy, const std::string& stage, std::size_t done, std::size_t total)
{
    if (monitor) monitor->update(stage, done, total);
    if (legacy) {
        if constexpr (std::is_invocable_v<Legacy, const std::string&>)
            legacy(stage);
        else
            legacy(done, total);
    }
    throwIfCancelled(monitor);
}

/// Reports stage @p what (no count) to the Progress of @p options and to its deprecated
/// `progress` callback (ResolveOptions), then throws if cancelled.
template <class Options>
void sayStage(const Options& options, const std::string& what)
{
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"  // ResolveOptions::progress, until 0.3
    reportStage(options.monitor, options.progress, what, 0, 0);
#pragma GCC diagnostic pop
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
