// writeTextile(): the generator's output, all-or-nothing.
#include "towgeom/textile_io.hpp"

#include <filesystem>
#include <iomanip>
#include <limits>

#include "core/json_writer.hpp"
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
    detail::JsonWriter json(files.open(path("textile.json")));
    json.beginObject();
    json.key("weave").value(weaveKindName(o.kind));
    json.key("parameters").beginObject();
    json.key("warps").value(o.warps).key("wefts").value(o.wefts);
    json.key("float_over").value(static_cast<std::size_t>(o.floatOver));
    json.key("float_under").value(static_cast<std::size_t>(o.floatUnder));
    json.key("step").value(static_cast<std::size_t>(o.step)).key("layers").value(o.layers);
    json.key("spacing").value(o.spacing).key("width").value(o.width).key("height").value(o.height);
    json.key("crimp").value(o.crimp).key("overlap").value(o.overlap);
    json.key("section").value(sectionShapeName(o.shape));
    json.key("points_per_section").value(o.pointsPerSection);
    json.endObject();
    json.key("yarns").beginArray();
    for (std::size_t k = 0; k < stacks.size(); ++k) {
        json.beginObject();
        json.key("name").value(stacks[k].name);
        json.key("role").value(yarnRoleName(textile.yarns[k].role));
        json.key("file").value(stacks[k].name + ".stw");
        json.key("sections").value(stacks[k].sectionCount());
        json.key("points").value(stacks[k].pointsPerSection());
        json.endObject();
    }
    json.endArray();
    json.key("crossings").beginArray();
    for (const Crossing& c : textile.crossings) {
        json.beginObject();
        json.key("warp").value(textile.yarns[c.warp].name).key("weft").value(textile.yarns[c.weft].name);
        json.key("x").value(c.position.x).key("y").value(c.position.y);
        json.key("warp_over").value(c.warpOver);
        json.endObject();
    }
    json.endArray().endObject();
    files.commit();
}

TOWGEOM_END_NAMESPACE
