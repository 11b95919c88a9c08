// --face N or --face NAME for the fibre-placement commands.
#include "cli/tool_surface.hpp"

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

namespace towgeom::cli {

PlacementSurface readToolSurface(const Args& args, const std::string& file)
{
    const auto face = args.value("face");
    if (!face) return readPlacementSurface(file, 0);
    if (face->empty()) throw UsageError("--face takes an index or a name, not an empty string");
    // Several faces, joined into one surface: "N,M,..." or "all".
    const bool list = face->find(',') != std::string::npos && std::all_of(face->begin(), face->end(), [](unsigned char c) {
        return std::isdigit(c) != 0 || c == ',';
    });
    if (*face == "all" || list) {
        std::vector<std::size_t> faces;
        if (*face == "all") {
            const std::size_t count = readPlacementSurface(file, 0).faceCount;
            for (std::size_t k = 0; k < std::max<std::size_t>(count, 1); ++k) faces.push_back(k);
        } else {
            std::size_t at = 0;
            while (at <= face->size()) {
                const std::size_t comma = std::min(face->find(',', at), face->size());
                const std::string item = face->substr(at, comma - at);
                if (item.empty() || item.size() > 7) throw UsageError("--face takes a list of face indices 'N,M,...', not '" + *face + "'");
                faces.push_back(static_cast<std::size_t>(std::stoul(item)));
                at = comma + 1;
            }
        }
        return readPlacementSurface(file, faces);
    }
    const bool index = !face->empty() && std::all_of(face->begin(), face->end(), [](unsigned char c) { return std::isdigit(c) != 0; });
    if (index) return readPlacementSurface(file, args.whole("face", 0, 0, 1e6, "0 to 1000000 (or a face's name)"));
    return readPlacementSurface(file, *face);
}

}  // namespace towgeom::cli
