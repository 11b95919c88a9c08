#include "interruptible.hpp"

namespace towgeom::python {

PythonProgress::PythonProgress(py::object callback) : callback_(std::move(callback))
{
    if (!callback_.is_none() && !PyCallable_Check(callback_.ptr()))
        throw py::type_error("progress must be a callable progress(stage, done, total) or None");
}

PythonProgress::~PythonProgress()
{
    // Only reached with the GIL held (the object lives in a bound function's frame).
    Py_XDECREF(keptType_);
    Py_XDECREF(keptValue_);
    Py_XDECREF(keptTrace_);
}

void PythonProgress::update(const std::string& stage, std::size_t done, std::size_t total)
{
    if (callback_.is_none() || cancelled()) return;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!pending_.empty() && pending_.back().stage == stage) pending_.back() = {stage, done, total};
        else pending_.push_back({stage, done, total});
    }
    news_.notify_all();
}

void PythonProgress::finish()
{
    {
        std::lock_guard<std::mutex> lock(mutex_);
        finished_ = true;
    }
    news_.notify_all();
}

bool PythonProgress::waitForNews(std::chrono::milliseconds timeout)
{
    std::unique_lock<std::mutex> lock(mutex_);
    news_.wait_for(lock, timeout, [&] { return finished_ || !pending_.empty(); });
    return finished_;
}

void PythonProgress::deliverUpdates()
{
    std::deque<Update> updates;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        updates.swap(pending_);
    }
    for (const Update& u : updates) {
        if (keptType_) return;  // the callable already failed: the work is being cancelled
        try {
            callback_(u.stage, u.done, u.total);
        } catch (py::error_already_set& e) {
            e.restore();
            stopWithPythonError();
        }
    }
}

void PythonProgress::stopWithPythonError()
{
    if (keptType_) PyErr_Clear();  // the first error wins
    else PyErr_Fetch(&keptType_, &keptValue_, &keptTrace_);
    cancel();
}

void PythonProgress::raiseKeptError()
{
    if (!keptType_) return;
    PyErr_Restore(keptType_, keptValue_, keptTrace_);
    keptType_ = keptValue_ = keptTrace_ = nullptr;
    throw py::error_already_set();
}

}  // namespace towgeom::python
