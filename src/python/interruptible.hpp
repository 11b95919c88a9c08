// Running a long library call from Python: the work on a worker thread with the GIL released,
// its progress handed to a Python callable on the caller's thread, and Ctrl-C (KeyboardInterrupt)
// turned into Progress::cancel().
#pragma once

#include <pybind11/pybind11.h>

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>

#include "towgeom/progress.hpp"

namespace towgeom::python {

namespace py = pybind11;

/// A towgeom::Progress whose updates, made on the library's threads, are queued and handed to a
/// Python callable (stage, done, total) on the thread that called (runInterruptible()): library
/// threads never take the GIL, and a GUI's progress bar is updated from its own thread. An
/// exception raised by the callable, or Ctrl-C, cancels the work and is raised when it returns.
class PythonProgress : public Progress {
public:
    /// @p callback: None or a callable (TypeError otherwise).
    explicit PythonProgress(py::object callback);
    ~PythonProgress() override;

    void update(const std::string& stage, std::size_t done, std::size_t total) override;

    /// Called by the worker when the work has ended (returned or thrown).
    void finish();
    /// Waits (the GIL released) up to @p timeout for an update or the end; true once ended.
    bool waitForNews(std::chrono::milliseconds timeout);
    /// With the GIL held on the calling thread: calls the callable with each queued update; a
    /// Python error it raises is kept and the work cancelled.
    void deliverUpdates();
    /// With the GIL held: keeps the Python error now set (Ctrl-C, or the callable's) to raise
    /// when the work has stopped, and cancels the work.
    void stopWithPythonError();
    /// With the GIL held after the work stopped: raises the kept error, if any.
    void raiseKeptError();

private:
    struct Update {
        std::string stage;
        std::size_t done = 0, total = 0;
    };
    py::object callback_;
    std::mutex mutex_;
    std::condition_variable news_;
    std::deque<Update> pending_;  // consecutive updates of one stage coalesced: the latest counts
    bool finished_ = false;
    PyObject* keptType_ = nullptr;  // PyErr_Fetch's triple, owned (touched with the GIL held only)
    PyObject* keptValue_ = nullptr;
    PyObject* keptTrace_ = nullptr;
};

/// Runs @p work (a callable returning a value) on a worker thread with the GIL released, while
/// the calling thread hands progress to Python and checks for Ctrl-C at least every 50 ms: a
/// KeyboardInterrupt cancels the work through @p progress and is raised once the work has
/// stopped (a towgeom::Error with code Cancelled from the work is then replaced by it). Any other
/// exception of the work is raised as is.
template <class Work>
auto runInterruptible(PythonProgress& progress, Work&& work) -> decltype(work())
{
    using Result = decltype(work());
    std::optional<Result> result;
    std::exception_ptr failure;
    std::thread worker;
    {
        py::gil_scoped_release released;
        worker = std::thread([&] {
            try {
                result.emplace(work());
            } catch (...) {
                failure = std::current_exception();
            }
            progress.finish();
        });
    }
    const auto join = [&] {
        py::gil_scoped_release released;
        worker.join();
    };
    try {
        for (bool ended = false; !ended;) {
            {
                py::gil_scoped_release released;
                ended = progress.waitForNews(std::chrono::milliseconds(50));
            }
            progress.deliverUpdates();
            if (PyErr_CheckSignals() != 0) progress.stopWithPythonError();
        }
    } catch (...) {  // never leave the worker running (std::thread's destructor would terminate)
        progress.cancel();
        join();
        throw;
    }
    join();
    progress.raiseKeptError();
    if (failure) std::rethrow_exception(failure);
    return std::move(*result);
}

}  // namespace towgeom::python
