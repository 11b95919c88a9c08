#include "interruptible.hpp"

namespace towgeom::python {

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
    py::gil_scoped_acquire held;
    try {
        callback_(stage, done, total);
    } catch (py::error_already_set& e) {
        e.restore();
        stopWithPythonError();
    }
}

void PythonProgress::stopWithPythonError()
{
    std::lock_guard<std::mutex> lock(keptMutex_);
    if (keptType_) {
        PyErr_Clear();  // the first error wins
    } else {
        PyErr_Fetch(&keptType_, &keptValue_, &keptTrace_);
    }
    cancel();
}

void PythonProgress::raiseKeptError()
{
    std::lock_guard<std::mutex> lock(keptMutex_);
    if (!keptType_) return;
    PyErr_Restore(keptType_, keptValue_, keptTrace_);
    keptType_ = keptValue_ = keptTrace_ = nullptr;
    throw py::error_already_set();
}

}  // namespace towgeom::python
