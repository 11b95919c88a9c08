// Which tow gives way: the tows meshed once (meshTows, no region swapped), then connected twice
// (connectRegions) with two rankings, warps first and wefts first, without meshing again.
//   rank_study REPORT.json FILE.stw...
#include <towgeom/towgeom.hpp>

#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv)
{
    if (argc < 3) {
        std::cerr << "usage: rank_study REPORT.json FILE.stw...\n";
        return 2;
    }
    try {
        std::vector<towgeom::TowSurface> tows;
        for (int k = 2; k < argc; ++k) tows.push_back(towgeom::TowSurface::fit(towgeom::readStackFile(argv[k])));
        const towgeom::IntersectionReport loops = towgeom::readIntersectionReport(argv[1], tows);
        towgeom::ResolveOptions options;
        options.mesh.relativeEdgeLength = 0.2;
        const towgeom::ResolveResult meshed = towgeom::meshTows(tows, loops, options);  // once
        std::cout << meshed.mesh.loops.size() << " loops meshed, " << meshed.quality.triangles << " triangles\n";
        for (const char* first : {"warp*", "weft*"}) {
            options.primaryPatterns = {first};
            const towgeom::ResolveResult r = towgeom::connectRegions(tows, meshed, options);
            double removed = 0.0;
            for (const towgeom::ConnectedRegion& g : r.mesh.regions) removed += g.volumeRemoved;
            std::cout << first << " first: " << r.mesh.regions.size() << " regions, overlap volume " << removed << "\n";
            for (std::size_t t = 0; t < tows.size(); ++t)
                std::cout << "  " << tows[t].name() << " keeps " << 100.0 * r.tows[t].volumeAfter / r.tows[t].volumeBefore
                          << " % of its volume\n";
        }
        return 0;
    } catch (const towgeom::Error& e) {
        std::cerr << e.what() << " [" << towgeom::errorCodeName(e.code()) << "]\n";
        return 2;
    }
}
