// generate_weave(): textiles of known geometry and controllable interpenetration.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>

#include "bindings.hpp"
#include "towgeom/weave.hpp"

namespace towgeom::python {

namespace {

void bindWeaveOptions(py::module_& m)
{
    py::class_<WeaveOptions>(m, "WeaveOptions", "Parameters of generate_weave() (keyword arguments set the same names); lengths in your units.")
        .def(py::init([](const py::kwargs& keywords) {
            py::object options = py::cast(WeaveOptions{});
            applyKeywords(options, keywords);
            return options.cast<WeaveOptions>();
        }))
        .def_property("kind", [](const WeaveOptions& o) { return weaveKindName(o.kind); },
                      [](WeaveOptions& o, const std::string& name) {
                          o.kind = enumNamed(name, {WeaveKind::Plain, WeaveKind::Twill, WeaveKind::Satin, WeaveKind::Basket, WeaveKind::Orthogonal},
                                             &weaveKindName, "weave kind");
                      }, "'plain', 'twill', 'satin', 'basket' or 'orthogonal'.")
        .def_readwrite("warps", &WeaveOptions::warps)
        .def_readwrite("wefts", &WeaveOptions::wefts)
        .def_readwrite("float_over", &WeaveOptions::floatOver, "Twill n (warp over n wefts); satin harness n; basket group n.")
        .def_readwrite("float_under", &WeaveOptions::floatUnder, "Twill m (warp under m wefts).")
        .def_readwrite("step", &WeaveOptions::step)
        .def_readwrite("layers", &WeaveOptions::layers, "Orthogonal weaves: warp layers.")
        .def_readwrite("spacing", &WeaveOptions::spacing, "Distance between neighbouring yarns' centre lines.")
        .def_readwrite("width", &WeaveOptions::width)
        .def_readwrite("height", &WeaveOptions::height)
        .def_readwrite("crimp", &WeaveOptions::crimp)
        .def_readwrite("overlap", &WeaveOptions::overlap, "Interpenetration at every crossing as a fraction of the yarn height.")
        .def_property("shape", [](const WeaveOptions& o) { return sectionShapeName(o.shape); },
                      [](WeaveOptions& o, const std::string& name) {
                          o.shape = enumNamed(name, {SectionShape::Circle, SectionShape::Ellipse, SectionShape::Racetrack, SectionShape::Lenticular,
                                                     SectionShape::Hermite},
                                              &sectionShapeName, "section shape");
                      }, "'circle', 'ellipse', 'racetrack', 'lenticular' or 'hermite'.")
        .def_readwrite("sections_per_yarn", &WeaveOptions::sectionsPerYarn)
        .def_readwrite("points_per_section", &WeaveOptions::pointsPerSection)
        .def("validate", &WeaveOptions::validate);
}

}  // namespace

void bindGenerate(py::module_& m)
{
    bindWeaveOptions(m);
    py::class_<Textile>(m, "Textile", "A generated textile: its yarns as stacks.")
        .def_property_readonly("options", [](const Textile& t) { return t.options; }, "A copy of the options that made it.")
        .def_property_readonly("names", [](const Textile& t) {
            py::list out;
            for (const GeneratedYarn& y : t.yarns) out.append(y.name);
            return out;
        })
        .def_property_readonly("roles", [](const Textile& t) {
            py::list out;
            for (const GeneratedYarn& y : t.yarns) out.append(yarnRoleName(y.role));
            return out;
        })
        .def("unit_cell", &Textile::unitCell, "The weave's periodic unit cell (a Cell), or None where it has none.")
        .def("stacks", &Textile::stacks, "Every yarn as a Stack (options.points_per_section points per section).");
    m.def("generate_weave", [](std::optional<WeaveOptions> options, const py::kwargs& keywords) {
            py::object chosen = py::cast(options.value_or(WeaveOptions{}));
            applyKeywords(chosen, keywords);
            const WeaveOptions o = chosen.cast<WeaveOptions>();
            py::gil_scoped_release released;
            return generateWeave(o);
        }, py::arg("options") = py::none(),
        "A textile from WeaveOptions and/or keyword arguments, e.g. generate_weave(kind='twill', warps=4, wefts=4, overlap=0.1).");
}

}  // namespace towgeom::python
