// The meshing stage alone: one tow meshed with a constraint of the host's own (a ring around the
// middle of its surface), closed by its caps, written as VTK with each triangle's fibre direction
// (its x component as an integer field in thousandths, to colour by in ParaView).
//   mesh_one_tow FILE.stw OUT.vtk
#include <towgeom/towgeom.hpp>

#include <cmath>
#include <fstream>
#include <iostream>

int main(int argc, char** argv)
{
    if (argc != 3) {
        std::cerr << "usage: mesh_one_tow FILE.stw OUT.vtk\n";
        return 2;
    }
    try {
        const towgeom::TowSurface tow = towgeom::TowSurface::fit(towgeom::readStackFile(argv[1]));
        const towgeom::ParameterRange r = tow.parameterRange();
        towgeom::MeshConstraint ring;
        ring.closed = true;
        for (int k = 0; k < 24; ++k) {
            const double a = k * 3.14159265358979323846 / 12.0;
            ring.points.push_back({0.5 * (r.uMin + r.uMax) + 0.05 * (r.uMax - r.uMin) * std::cos(a),
                                   r.vMin + 0.5 * r.vPeriod() + 0.1 * r.vPeriod() * std::sin(a)});
        }
        const towgeom::SurfaceMesh m = towgeom::ParametricMesher(tow).mesh({ring});
        towgeom::TriangleMesh out;
        out.vertices = m.nodes;
        out.triangles = m.triangles;
        std::vector<long> fibreX, face;
        for (std::size_t k = 0; k < m.triangles.size(); ++k) {
            fibreX.push_back(std::lround(1000.0 * m.fibreDirection[k].x));
            face.push_back(static_cast<long>(m.face[k]));
        }
        std::ofstream file(argv[2]);
        towgeom::writeVtk(out, file, "towgeom mesh of " + tow.name(), {{"fibre_x_milli", fibreX}, {"face", face}});
        if (!file.flush()) throw towgeom::Error(towgeom::ErrorCode::WriteFailed, "cannot write", argv[2]);
        std::cout << tow.name() << ": " << m.nodes.size() << " nodes, " << m.triangles.size() << " triangles, ring of "
                  << m.constraintNodes[0].size() << " nodes, volume " << towgeom::enclosedVolume(out) << '\n';
        return 0;
    } catch (const towgeom::Error& e) {
        std::cerr << e.what() << " [" << towgeom::errorCodeName(e.code()) << "]\n";
        return 2;
    }
}
