// towgeom::Error raised in Python as towgeom.Error (a RuntimeError) carrying the error code's
// name, the file, the line and the message.
#include <pybind11/eval.h>
#include <pybind11/pybind11.h>

#include <optional>
#include <string>

#include "bindings.hpp"
#include "towgeom/error.hpp"

namespace towgeom::python {

namespace {

PyObject* g_errorType = nullptr;  // towgeom.Error, owned by the module for the interpreter's life

/// NAME of a text starting "tow 'NAME'" (the whole text, or followed by ':' or ' ').
std::optional<std::string> towNamedIn(const std::string& text)
{
    if (text.compare(0, 5, "tow '") != 0) return std::nullopt;
    const std::size_t close = text.find('\'', 5);
    if (close == std::string::npos || close == 5) return std::nullopt;
    if (close + 1 < text.size() && text[close + 1] != ':' && text[close + 1] != ' ') return std::nullopt;
    return text.substr(5, close - 5);
}

void translateError(std::exception_ptr thrown)
{
    try {
        if (thrown) std::rethrow_exception(thrown);
    } catch (const Error& e) {
        py::object error = py::reinterpret_borrow<py::object>(g_errorType)(e.what());
        error.attr("code") = errorCodeName(e.code());
        error.attr("message") = e.message();
        // The library names the tow an error is about where a file's error names the file
        // ("tow 'NAME'"), or at the start of its message ("tow 'NAME': ...").
        const std::string& where = e.file();
        const std::optional<std::string> towInFile = towNamedIn(where), towInMessage = towNamedIn(e.message());
        const std::optional<std::string> tow = towInFile ? towInFile : towInMessage;
        error.attr("tow") = tow ? py::object(py::str(*tow)) : py::object(py::none());
        error.attr("file") = where.empty() || towInFile ? py::object(py::none()) : py::object(py::str(where));
        error.attr("line") = e.line() ? py::object(py::int_(e.line())) : py::object(py::none());
        PyErr_SetObject(g_errorType, error.ptr());
    }
}

}  // namespace

void bindErrors(py::module_& m)
{
    py::exec(R"(
class Error(RuntimeError):
    """An error of towgeom: bad input, an option out of its domain, a failed write, ...

    Attributes:
        code: the error's name, as the command-line tool prints it in brackets
            ("non_numeric", "invalid_argument", "cancelled", ...).
        message: the sentence without the file and line.
        file: the file the error is in, or None.
        tow: the tow the error is about (its name), or None.
        line: the 1-based line in that file, or None.
    """
    code = "internal"
    message = ""
    file = None
    line = None
    tow = None
)", m.attr("__dict__"));
    m.attr("Error").attr("__module__") = "towgeom";
    g_errorType = m.attr("Error").ptr();
    Py_INCREF(g_errorType);
    py::register_exception_translator(&translateError);
}

}  // namespace towgeom::python
