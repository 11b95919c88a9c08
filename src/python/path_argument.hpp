// File paths from Python: str or any os.PathLike (pathlib.Path), as the library's std::string.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

namespace towgeom::python {

/// A path argument: what os.fspath() gives for a str or an os.PathLike.
struct Path {
    std::string text;
};

}  // namespace towgeom::python

namespace pybind11::detail {

template <>
struct type_caster<towgeom::python::Path> {
    PYBIND11_TYPE_CASTER(towgeom::python::Path, const_name("Union[str, os.PathLike]"));

    bool load(handle source, bool)
    {
        PyObject* text = PyOS_FSPath(source.ptr());
        if (!text) {
            PyErr_Clear();
            return false;
        }
        const auto owned = reinterpret_steal<object>(text);
        if (!PyUnicode_Check(text)) return false;  // bytes paths: not supported
        value.text = owned.cast<std::string>();
        return true;
    }

    static handle cast(const towgeom::python::Path& path, return_value_policy, handle) { return str(path.text).release(); }
};

}  // namespace pybind11::detail
