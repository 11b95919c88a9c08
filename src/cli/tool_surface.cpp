// --face N or --face NAME for the fibre-placement commands.
#include "cli/tool_surface.hpp"

#include <algorithm>
#include <cctype>

namespace towgeom::cli {

PlacementSurface readToolSurface(const Args& args, const std::string& file)
{
    const auto face = args.value("face");
    if (!face) return readPlacementSurface(file, 0);
    if (face->empty()) throw UsageError("--face takes an index or a name, not an empty string");
    const bool index = !face->empty() && std::all_of(face->begin(), face->end(), [](unsigned char c) { return std::isdigit(c) != 0; });
    if (index) return readPlacementSurface(file, args.whole("face", 0, 0, 1e6, "0 to 1000000 (or a face's name)"));
    return readPlacementSurface(file, *face);
}

}  // namespace towgeom::cli
