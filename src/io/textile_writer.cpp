// writeTextile(): the generator's output, all-or-nothing.
#include "towgeom/textile_io.hpp"

#include <filesystem>
#include <iomanip>
#include <limits>

#include <nlohmann/json.hpp>

#include "io/output_files.hpp"
#include "towgeom/error.hpp"
#include "towgeom/stack_reader.hpp"
#include "towgeom/stl_writer.hpp"
#include "towgeom/vtk_writer.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

void writeTextile(const Textile& textile, const std::string& directory, const TextileOutput& output)
{
    namespace fs = std::filesystem;
    const auto path = [&](const std::string& file) { return (fs::path(directory) / file).string(); };

    detail::OutputFiles files;
    files.makeDirectory(directory);
    const std::vector<TowStack> stacks = textile.stacks();
    for (const TowStack& s : stacks) {
        writeStack(files.open(path(s.name + ".stw")), s);
        if (!output.facetedVtk && !output.facetedStl) continue;
        const TriangleMesh mesh = facetedTube(s, true);
        if (output.facetedVtk)
            writeVtk(mesh, files.open(path(s.name + ".faceted.vtk")), "towgeom faceted yarn " + s.name);
        if (output.facetedStl) try {
                writeStl(mesh, files.open(path(s.name + ".faceted.stl")));
            } catch (const Error& e) {
                throw Error(e.code(), e.message(), path(s.name + ".faceted.stl"));
            }
    }
    const WeaveOptions& o = textile.options;
    using Json = nlohmann::ordered_json;
    Json j;
    j["weave"] = weaveKindName(o.kind);
    j["parameters"] = {{"warps", o.warps},
                       {"wefts", o.wefts},
                       {"float_over", static_cast<std::size_t>(o.floatOver)},
                       {"float_under", static_cast<std::size_t>(o.floatUnder)},
                       {"step", static_cast<std::size_t>(o.step)},
                       {"layers", o.layers},
                       {"spacing", o.spacing},
                       {"width", o.width},
                       {"height", o.height},
                       {"crimp", o.crimp},
                       {"overlap", o.overlap},
                       {"section", sectionShapeName(o.shape)},
                       {"points_per_section", o.pointsPerSection}};
    Json yarns = Json::array();
    for (std::size_t k = 0; k < stacks.size(); ++k)
        yarns.push_back({{"name", stacks[k].name},
                         {"role", yarnRoleName(textile.yarns[k].role)},
                         {"file", stacks[k].name + ".stw"},
                         {"sections", stacks[k].sectionCount()},
                         {"points", stacks[k].pointsPerSection()}});
    j["yarns"] = std::move(yarns);
    Json crossings = Json::array();
    for (const Crossing& c : textile.crossings)
        crossings.push_back({{"warp", textile.yarns[c.warp].name},
                             {"weft", textile.yarns[c.weft].name},
                             {"x", c.position.x},
                             {"y", c.position.y},
                             {"warp_over", c.warpOver}});
    j["crossings"] = std::move(crossings);
    if (const std::optional<Cell> cell = textile.unitCell())  // for towgeom resolve --cell textile.json
        j["cell"] = {{"min", {cell->min.x, cell->min.y, cell->min.z}}, {"max", {cell->max.x, cell->max.y, cell->max.z}}, {"periodic", true}};
    files.open(path("textile.json")) << j.dump(-1, ' ', false, Json::error_handler_t::replace);
    files.commit();
}

TOWGEOM_END_NAMESPACE
