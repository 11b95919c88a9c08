// The Python module towgeom._towgeom (the package towgeom re-exports it): the library's stages
// on NumPy arrays.
#include <pybind11/pybind11.h>

#include <string>

#include "bindings.hpp"
#include "towgeom/version.hpp"

namespace towgeom::python {

void applyKeywords(py::object options, const py::kwargs& keywords, std::initializer_list<const char*> nested)
{
    for (const auto& [key, value] : keywords) {
        const std::string name = py::str(key);
        bool set = false;
        if (py::hasattr(options, name.c_str())) {
            options.attr(name.c_str()) = value;
            set = true;
        }
        for (auto inner = nested.begin(); !set && inner != nested.end(); ++inner) {
            py::object part = options.attr(*inner);
            if (!py::hasattr(part, name.c_str())) continue;
            part.attr(name.c_str()) = value;
            set = true;
        }
        if (set) continue;
        std::string where = std::string(py::str(options.get_type().attr("__name__")));
        for (const char* inner : nested) where += std::string(", ") + inner + ".*";
        throw py::type_error("unknown option '" + name + "' (looked in " + where + ")");
    }
}

}  // namespace towgeom::python

PYBIND11_MODULE(_towgeom, m)
{
    namespace tp = towgeom::python;
    m.doc() = "towgeom: exact geometry for composite tows (the C++ library's stages on NumPy arrays).";
    m.attr("__version__") = TOWGEOM_VERSION_STRING;
    tp::bindErrors(m);
    tp::bindSurfaces(m);
    tp::bindIntersections(m);
    tp::bindMeshes(m);
    tp::bindResolve(m);
    tp::bindVolumes(m);
    tp::bindExports(m);
    tp::bindGenerate(m);
    tp::bindPlacement(m);
}
