// Reads one tow stack, fits its surface and prints "NAME VOLUME": the smallest real use of towgeom.
#include <towgeom/towgeom.hpp>

#include <iostream>

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::cerr << "usage: fit_volume FILE.stw\n";
        return 2;
    }
    try {
        const towgeom::TowSurface surface = towgeom::TowSurface::fit(towgeom::readStackFile(argv[1]));
        std::cout.precision(10);
        std::cout << surface.name() << ' ' << surface.volume() << '\n';
        return 0;
    } catch (const towgeom::Error& e) {
        std::cerr << e.what() << " [" << towgeom::errorCodeName(e.code()) << "]\n";
        return 2;
    }
}
