// The parts of the Python module towgeom._towgeom, one function per stage (module.cpp calls them).
#pragma once

#include <pybind11/pybind11.h>

#include <initializer_list>
#include <string>

#include "towgeom/error.hpp"

namespace towgeom::python {

namespace py = pybind11;

void bindErrors(py::module_& m);        // errors.cpp: towgeom.Error
void bindSurfaces(py::module_& m);      // bind_surfaces.cpp: stacks and TowSurface
void bindIntersections(py::module_& m); // bind_intersections.cpp: intersect_tows and its report
void bindCell(py::module_& m);          // bind_resolve.cpp: Cell (before the meshes, which name it)
void bindMeshes(py::module_& m);        // bind_meshes.cpp: TextileMesh and its writers
void bindResolve(py::module_& m);       // bind_resolve.cpp: resolve_textile, its options and result
void bindVolumes(py::module_& m);       // bind_meshes.cpp: mesh_volumes, write_vtu (after bindResolve)
void bindGenerate(py::module_& m);      // bind_generate.cpp: generate_weave
void bindExports(py::module_& m);       // bind_exports.cpp: per-tow VTK/STL, volume writers, STEP (after bindVolumes)
void bindPlacement(py::module_& m);     // bind_placement.cpp: tool surfaces, references, lay_courses

/// Sets each keyword argument on @p options (an instance of a bound options class), looking
/// first at @p options itself, then at each of @p nested (attribute names of sub-options, in
/// order); an unknown keyword raises TypeError listing where it was looked for.
void applyKeywords(py::object options, const py::kwargs& keywords, std::initializer_list<const char*> nested = {});

/// The value of enum E whose name (@p nameOf, e.g. fitModeName) is @p name ('-' and '_' alike);
/// towgeom.Error (invalid_argument) listing the names otherwise.
template <class E>
E enumNamed(const std::string& name, std::initializer_list<E> values, const char* (*nameOf)(E) noexcept, const char* what)
{
    auto same = [](const std::string& a, const std::string& b) {
        if (a.size() != b.size()) return false;
        for (std::size_t k = 0; k < a.size(); ++k)
            if (a[k] != b[k] && !((a[k] == '-' || a[k] == '_') && (b[k] == '-' || b[k] == '_'))) return false;
        return true;
    };
    std::string names;
    for (E value : values) {
        if (same(name, nameOf(value))) return value;
        names += (names.empty() ? "" : ", ") + std::string(nameOf(value));
    }
    throw Error(ErrorCode::InvalidArgument, std::string(what) + " '" + name + "': use one of " + names);
}

}  // namespace towgeom::python
