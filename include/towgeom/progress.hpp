/// @file progress.hpp
/// @brief Progress reports and cancellation, one object shared by every stage.
#pragma once

#include <atomic>
#include <cstddef>
#include <string>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// @defgroup progress Progress and cancellation
/// @brief One Progress object watched by every stage.
/// @{

/// Watches long work and can stop it: give a pointer to one Progress to the options of every
/// stage (IntersectionOptions::monitor, ResolveOptions::monitor). The stages call update() as
/// they go; cancel(), from any thread (a signal handler too: it only sets a flag), makes the
/// running stage stop at its next check — after the tow pair or tow in hand — by throwing
/// Error(ErrorCode::Cancelled). Nothing is half-done: a cancelled call returns no result.
///
/// @code
/// struct Printer : towgeom::Progress {
///     void update(const std::string& stage, std::size_t done, std::size_t total) override {
///         std::cerr << stage << " " << done << "/" << total << "\n";
///     }
/// };
/// Printer printer;
/// towgeom::ResolveOptions options;
/// options.monitor = &printer;   // intersection and meshing report here
/// // another thread, or a SIGINT handler: printer.cancel();
/// try {
///     towgeom::ResolveResult r = towgeom::resolveTextile(tows, options);
/// } catch (const towgeom::Error& e) {
///     if (e.code() == towgeom::ErrorCode::Cancelled) std::cerr << "stopped\n";
/// }
/// @endcode
class TOWGEOM_EXPORT Progress {
public:
    Progress() = default;
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;
    virtual ~Progress();

    /// Called by the stages: @p stage says what runs (e.g. "intersecting tow pairs", "meshing 8
    /// tows at h = 0.05"), @p done of @p total steps of it are finished (total 0: a stage that
    /// has just begun and counts no steps). Called from the calling thread or a worker, never
    /// concurrently. The default does nothing.
    virtual void update(const std::string& stage, std::size_t done, std::size_t total);

    /// Asks the running stage to stop (it throws Error(ErrorCode::Cancelled) at its next
    /// check). Safe from any thread and from a signal handler. Stays set: a cancelled Progress
    /// cancels every later stage given it too.
    void cancel() noexcept { cancelled_.store(true, std::memory_order_relaxed); }

    /// True once cancel() was called.
    bool cancelled() const noexcept { return cancelled_.load(std::memory_order_relaxed); }

private:
    std::atomic<bool> cancelled_{false};
};

/// @}

TOWGEOM_END_NAMESPACE
