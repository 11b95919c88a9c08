// The CLI's Progress: stage lines on stderr (unless --quiet), and Ctrl-C (SIGINT) or SIGTERM
// cancel the running stage, so the command exits 130 with nothing written.
#pragma once

#include <cstddef>
#include <string>

#include "towgeom/error.hpp"
#include "towgeom/progress.hpp"

namespace towgeom::cli {

/// Prints "towgeom COMMAND: STAGE" once per stage and "[done/total] STAGE" about twenty times per
/// counted stage. While it lives, SIGINT and SIGTERM cancel it (one printer at a time; a
/// disposition of SIG_IGN the process started with is kept; a second signal stops the process
/// at once), and the previous dispositions come back when it goes.
class ProgressPrinter : public Progress {
public:
    ProgressPrinter(const char* command, bool quiet);
    ~ProgressPrinter() override;
    void update(const std::string& stage, std::size_t done, std::size_t total) override;
    /// Throws Error(Cancelled) if a signal came: called before output is committed, so that a
    /// run stopped while writing leaves the output as it was.
    void throwIfCancelled() const;

private:
    void (*previousInt_)(int) = nullptr;
    void (*previousTerm_)(int) = nullptr;
    const char* command_;
    bool quiet_;
    std::string stage_;      // the stage printed last
    std::size_t printed_ = 0;  // its last count printed
};

/// The exit status of a command stopped by cancellation (128 + SIGINT, as shells report it).
constexpr int kExitCancelled = 130;

}  // namespace towgeom::cli
