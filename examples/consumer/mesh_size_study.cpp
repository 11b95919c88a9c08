// A mesh-size study over one intersection: the loops read from a report (intersect_only), the
// textile resolved at three mesh sizes without intersecting again.
//   mesh_size_study REPORT.json FILE.stw...
#include <towgeom/towgeom.hpp>

#include <chrono>
#include <iostream>
#include <vector>

int main(int argc, char** argv)
{
    if (argc < 3) {
        std::cerr << "usage: mesh_size_study REPORT.json FILE.stw...\n";
        return 2;
    }
    try {
        std::vector<towgeom::TowSurface> tows;
        for (int k = 2; k < argc; ++k) tows.push_back(towgeom::TowSurface::fit(towgeom::readStackFile(argv[k])));
        const towgeom::IntersectionReport loops = towgeom::readIntersectionReport(argv[1], tows);
        for (double h : {0.3, 0.15, 0.075}) {
            towgeom::ResolveOptions options;
            options.mesh.relativeEdgeLength = h;
            const auto t0 = std::chrono::steady_clock::now();
            const towgeom::ResolveResult r = towgeom::resolveTextile(tows, loops, options);
            const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            std::cout << "h " << h << ": " << r.quality.triangles << " triangles, " << r.mesh.regions.size()
                      << " regions, smallest angle " << r.quality.minAngle << " deg, " << s << " s\n";
        }
        return 0;
    } catch (const towgeom::Error& e) {
        std::cerr << e.what() << " [" << towgeom::errorCodeName(e.code()) << "]\n";
        return 2;
    }
}
