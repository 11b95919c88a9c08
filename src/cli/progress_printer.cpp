#include "cli/progress_printer.hpp"

#include <csignal>
#include <iostream>

namespace towgeom::cli {

namespace {

ProgressPrinter* g_cancelTarget = nullptr;  // set while a printer lives (one command per process)

extern "C" void cancelOnSignal(int)
{
    if (g_cancelTarget) g_cancelTarget->cancel();  // an atomic store: safe in a handler
}

}  // namespace

ProgressPrinter::ProgressPrinter(const char* command, bool quiet) : command_(command), quiet_(quiet)
{
    g_cancelTarget = this;
    std::signal(SIGINT, cancelOnSignal);
    std::signal(SIGTERM, cancelOnSignal);
}

ProgressPrinter::~ProgressPrinter()
{
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    g_cancelTarget = nullptr;
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
