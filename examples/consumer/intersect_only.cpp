// The intersection stage alone: every interpenetration of the tows given, one line per loop,
// and the exact loops kept in a JSON report for later meshing (mesh_size_study).
//   intersect_only REPORT.json FILE.stw...
#include <towgeom/towgeom.hpp>

#include <iostream>
#include <vector>

int main(int argc, char** argv)
{
    if (argc < 3) {
        std::cerr << "usage: intersect_only REPORT.json FILE.stw...\n";
        return 2;
    }
    try {
        std::vector<towgeom::TowSurface> tows;
        for (int k = 2; k < argc; ++k) tows.push_back(towgeom::TowSurface::fit(towgeom::readStackFile(argv[k])));
        const towgeom::IntersectionReport report = towgeom::intersectTows(tows);
        for (const towgeom::IntersectionLoop& l : report.loops)
            std::cout << tows[l.towA()].name() << ' ' << tows[l.towB()].name() << (l.closed() ? " closed" : " open")
                      << " length " << l.length() << '\n';
        towgeom::writeIntersectionReport(report, tows, argv[1]);
        std::cout << report.loops.size() << " loops\n";
        return 0;
    } catch (const towgeom::Error& e) {
        std::cerr << e.what() << " [" << towgeom::errorCodeName(e.code()) << "]\n";
        return 2;
    }
}
