#include "cli/progress_printer.hpp"

#include <atomic>
#include <csignal>
#include <iostream>

namespace towgeom::cli {

namespace {

std::atomic<ProgressPrinter*> g_cancelTarget{nullptr};  // set while a printer lives (one command per process)

extern "C" void cancelOnSignal(int signal)
{
    ProgressPrinter* target = g_cancelTarget.load();
    if (target && !target->cancelled()) {
        target->cancel();  // an atomic store: the running stage stops at its next check
        return;
    }
    // A second signal (the stage in hand is long): stop at once, as without a handler.
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

/// Installs the handler for @p signal unless the process was started with it ignored (kept so);
/// returns the disposition to restore.
void (*install(int signal))(int)
{
    void (*previous)(int) = std::signal(signal, cancelOnSignal);
    if (previous == SIG_IGN) std::signal(signal, SIG_IGN);
    return previous;
}

}  // namespace

ProgressPrinter::ProgressPrinter(const char* command, bool quiet) : command_(command), quiet_(quiet)
{
    g_cancelTarget.store(this);
    previousInt_ = install(SIGINT);
    previousTerm_ = install(SIGTERM);
}

ProgressPrinter::~ProgressPrinter()
{
    std::signal(SIGINT, previousInt_ == SIG_ERR ? SIG_DFL : previousInt_);
    std::signal(SIGTERM, previousTerm_ == SIG_ERR ? SIG_DFL : previousTerm_);
    g_cancelTarget.store(nullptr);
}

void ProgressPrinter::throwIfCancelled() const
{
    if (cancelled()) throw Error(ErrorCode::Cancelled, "stopped by a signal");
}

void ProgressPrinter::update(const std::string& stage, std::size_t done, std::size_t total)
{
    if (quiet_) return;
    if (total == 0) {
        std::cerr << "towgeom " << command_ << ": " << stage << "\n";
        stage_ = stage;
        return;
    }
    // About twenty lines per counted stage, however many steps it has; the last always.
    const bool first = stage != stage_;
    if (first) printed_ = 0;
    stage_ = stage;
    if (done == 0 && !first) return;
    if (done == total || first || done * 20 / total > printed_ * 20 / total) {
        std::cerr << "towgeom " << command_ << ": [" << done << "/" << total << "] " << stage << "\n";
        printed_ = done;
    }
}

}  // namespace towgeom::cli
