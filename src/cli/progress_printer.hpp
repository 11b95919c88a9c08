// The CLI's Progress: stage lines on stderr (unless --quiet), and Ctrl-C (SIGINT) or SIGTERM
// cancel the running stage, so the command exits 130 with nothing written.
#pragma once

#include <cstddef>
#include <string>

#include "towgeom/progress.hpp"

namespace towgeom::cli {

/// Prints "towgeom COMMAND: STAGE" once per stage and "[done/total] STAGE" about twenty times per
/// counted stage; while it lives, SIGINT and SIGTERM cancel it (one at a time: the last made).
class ProgressPrinter : public Progress {
public:
    ProgressPrinter(const char* command, bool quiet);
    ~ProgressPrinter() override;
    void update(const std::string& stage, std::size_t done, std::size_t total) override;

private:
    const char* command_;
    bool quiet_;
    std::string stage_;      // the stage printed last
    std::size_t printed_ = 0;  // its last count printed
};

/// The exit status of a command stopped by cancellation (128 + SIGINT, as shells report it).
constexpr int kExitCancelled = 130;

}  // namespace towgeom::cli
