// Running a long library call from Python: the GIL released, progress reported to a Python
// callable, and Ctrl-C (KeyboardInterrupt) turned into Progress::cancel().
#pragma once

#include <pybind11/pybind11.h>

#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>

#include "towgeom/progress.hpp"

namespace towgeom::python {

namespace py = pybind11;

/// A towgeom::Progress that forwards each update to a Python callable (stage, done, total), taking
/// the GIL for it. An exception raised by the callable cancels the work and is raised again when
/// the call returns (runInterruptible()).
class PythonProgress : public Progress {
public:
    explicit PythonProgress(py::object callback) : callback_(std::move(callback)) {}
    ~PythonProgress() override;

    void update(const std::string& stage, std::size_t done, std::size_t total) override;

    /// Called with the GIL held: keeps the Python error now set (Ctrl-C, or the callable's) to
    /// raise when the work has stopped, and cancels the work.
    void stopWithPythonError();
    /// Called with the GIL held after the work stopped: raises the kept error, if any.
    void raiseKeptError();

private:
    py::object callback_;
    std::mutex keptMutex_;
    PyObject* keptType_ = nullptr;  // PyErr_Fetch's triple, owned
    PyObject* keptValue_ = nullptr;
    PyObject* keptTrace_ = nullptr;
};

/// Runs @p work (a callable returning a value) on a worker thread with the GIL released, while
/// the calling thread checks for Ctrl-C every 50 ms: a KeyboardInterrupt cancels the work through
/// @p progress and is raised once the work has stopped (a towgeom::Error with code Cancelled from
/// the work is then replaced by it). Any other exception of the work is raised as is.
template <class Work>
auto runInterruptible(PythonProgress& progress, Work&& work) -> decltype(work())
{
    using Result = decltype(work());
    std::optional<Result> result;
    std::exception_ptr failure;
    std::mutex mutex;
    std::condition_variable finished;
    bool done = false;
    {
        py::gil_scoped_release released;
        std::thread worker([&] {
            try {
                result.emplace(work());
            } catch (...) {
                failure = std::current_exception();
            }
            std::lock_guard<std::mutex> lock(mutex);
            done = true;
            finished.notify_all();
        });
        for (;;) {
            {
                std::unique_lock<std::mutex> lock(mutex);
                if (finished.wait_for(lock, std::chrono::milliseconds(50), [&] { return done; })) break;
            }
            py::gil_scoped_acquire held;
            if (PyErr_CheckSignals() != 0) progress.stopWithPythonError();
        }
        worker.join();
    }
    progress.raiseKeptError();
    if (failure) std::rethrow_exception(failure);
    return std::move(*result);
}

}  // namespace towgeom::python
