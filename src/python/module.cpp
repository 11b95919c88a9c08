// The Python module towgeom._towgeom (the package towgeom re-exports it): the library's stages
// on NumPy arrays.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

#include "bindings.hpp"
#include "towgeom/version.hpp"

namespace towgeom::python {

void applyKeywords(py::object options, const py::kwargs& keywords, std::initializer_list<const char*> nested)
{
    for (const auto& [key, value] : keywords) {
        const std::string name = py::str(key);
        // Data attributes only (properties of the bound class): a method's name is no option.
        const auto isOption = [&](const py::object& target) {
            return py::hasattr(target, name.c_str()) && py::isinstance(py::getattr(target.get_type(), name.c_str(), py::none()),
                                                                        py::module_::import("builtins").attr("property"));
        };
        const auto assign = [&](py::object target) {
            try {
                target.attr(name.c_str()) = value;
            } catch (py::error_already_set& e) {
                if (!e.matches(PyExc_TypeError)) throw;
                const py::object current = target.attr(name.c_str());
                throw py::type_error("option '" + name + "': " + std::string(py::str(py::repr(value))) + " is not a value it takes (" +
                                     std::string(py::str(current.get_type().attr("__name__"))) + ", e.g. its default " +
                                     std::string(py::str(py::repr(current))) + ")");
            }
        };
        bool set = false;
        if (isOption(options)) {
            assign(options);
            set = true;
        }
        for (auto inner = nested.begin(); !set && inner != nested.end(); ++inner) {
            py::object part = options.attr(*inner);
            if (!isOption(part)) continue;
            assign(part);
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
    namespace py = pybind11;
    // NumPy's C API set up now, on the importing thread: pybind11 does it once, lazily, inside
    // a function-level static whose import of numpy releases the GIL; two threads making their
    // first array at once would otherwise deadlock.
    py::module_::import("numpy");
    (void)py::dtype::of<double>();
    m.doc() = "towgeom: exact geometry for composite tows (the C++ library's stages on NumPy arrays).";
    m.attr("__version__") = TOWGEOM_VERSION_STRING;
    tp::bindErrors(m);
    tp::bindSurfaces(m);
    tp::bindIntersections(m);
    tp::bindCell(m);
    tp::bindMeshes(m);
    tp::bindResolve(m);
    tp::bindVolumes(m);
    tp::bindExports(m);
    tp::bindGenerate(m);
    tp::bindPlacement(m);
}
