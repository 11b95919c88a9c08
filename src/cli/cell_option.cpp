// The --cell option: six numbers or a generator's textile.json.
#include "cli/cell_option.hpp"

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "cli/args.hpp"
#include "towgeom/error.hpp"

namespace towgeom::cli {

namespace {

/// The "cell" of a generator's textile.json (periodic; --periodic changes nothing then).
/// @throws towgeom::Error (FileNotFound, FileUnreadable, InvalidArgument) naming the file.
Cell readCellFile(const std::string& path)
{
    std::ifstream in(path);
    if (!std::filesystem::exists(path)) throw Error(ErrorCode::FileNotFound, "the file given to --cell does not exist", path);
    if (!in) throw Error(ErrorCode::FileUnreadable, "cannot read the file given to --cell", path);
    try {
        nlohmann::json j;
        in >> j;
        if (!j.is_object() || !j.contains("cell"))
            throw Error(ErrorCode::InvalidArgument,
                        "no \"cell\": the generator writes one for a 2D weave with at least a repeat + 2 wefts and warps "
                        "(e.g. 6 x 6 for a 2/2 twill); give --cell X0,Y0,Z0,X1,Y1,Z1 instead",
                        path);
        const nlohmann::json& cell = j["cell"];
        if (!cell.is_object()) throw Error(ErrorCode::InvalidArgument, "\"cell\" must be an object {\"min\", \"max\", \"periodic\"}", path);
        const auto corner = [&](const char* key) {
            if (!cell.contains(key) || !cell[key].is_array() || cell[key].size() != 3 || !cell[key][0].is_number() ||
                !cell[key][1].is_number() || !cell[key][2].is_number())
                throw Error(ErrorCode::InvalidArgument, std::string("\"cell\".\"") + key + "\" must be three numbers", path);
            return Point3{cell[key][0].get<double>(), cell[key][1].get<double>(), cell[key][2].get<double>()};
        };
        Cell c;
        c.min = corner("min");
        c.max = corner("max");
        if (cell.contains("periodic") && !cell["periodic"].is_boolean())
            throw Error(ErrorCode::InvalidArgument, "\"cell\".\"periodic\" must be true or false", path);
        c.periodic = cell.value("periodic", false);
        if (!(c.min.x < c.max.x && c.min.y < c.max.y && c.min.z < c.max.z))
            throw Error(ErrorCode::InvalidArgument, "\"cell\": each minimum must lie below its maximum", path);
        return c;
    } catch (const nlohmann::json::exception& e) {
        throw Error(ErrorCode::InvalidArgument, std::string("not a textile.json with a cell: ") + e.what(), path);
    }
}

}  // namespace

Cell parseCell(const std::string& text, bool periodic)
{
    // A file (textile.json): any text that is not a list of numbers.
    if (text.find(',') == std::string::npos) {
        Cell c = readCellFile(text);
        c.periodic = c.periodic || periodic;
        return c;
    }
    const std::vector<double> v = numberList(text);
    if (v.size() != 6) throw UsageError("--cell takes six numbers XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX, not '" + text + "'");
    Cell c;
    c.min = {v[0], v[1], v[2]};
    c.max = {v[3], v[4], v[5]};
    c.periodic = periodic;
    if (!(c.min.x < c.max.x && c.min.y < c.max.y && c.min.z < c.max.z))
        throw UsageError("--cell: each minimum must lie below its maximum ('" + text + "')");
    return c;
}

}  // namespace towgeom::cli
