// The dihedral angles of a volume mesh's tetrahedra.
#include <algorithm>
#include <cmath>

#include "towgeom/error.hpp"
#include "towgeom/volume_mesh.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

/// The dihedral angle (degrees) at edge (a, b) of the tetrahedron with the other corners c, d:
/// the angle between c and d seen across the edge, their components normal to it.
double dihedral(const Point3& a, const Point3& b, const Point3& c, const Point3& d)
{
    const Vector3 e = b - a;
    const double ee = dot(e, e);
    const Vector3 u = (c - a) - (dot(c - a, e) / ee) * e;
    const Vector3 w = (d - a) - (dot(d - a, e) / ee) * e;
    const double cosine = dot(u, w) / (norm(u) * norm(w));
    return std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / 3.14159265358979323846;
}

}  // namespace

TetrahedronQuality tetrahedronQuality(const VolumeMesh& volumes)
{
    TetrahedronQuality q;
    q.minDihedral = volumes.tetrahedra.empty() ? 0.0 : 180.0;
    constexpr double kBins[] = {5.0, 10.0, 20.0, 30.0, 40.0, 50.0, 60.0};
    for (const auto& t : volumes.tetrahedra) {
        for (std::size_t n : t)
            if (n >= volumes.nodes.size()) throw Error(ErrorCode::InvalidArgument, "a tetrahedron names a node out of range");
        const Point3* p[4] = {&volumes.nodes[t[0]], &volumes.nodes[t[1]], &volumes.nodes[t[2]], &volumes.nodes[t[3]]};
        double lo = 180.0, hi = 0.0;
        constexpr int kEdges[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2}, {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
        for (const auto& e : kEdges) {
            const double angle = dihedral(*p[e[0]], *p[e[1]], *p[e[2]], *p[e[3]]);
            lo = std::min(lo, std::isfinite(angle) ? angle : 0.0);
            hi = std::max(hi, std::isfinite(angle) ? angle : 180.0);
        }
        q.minDihedral = std::min(q.minDihedral, lo);
        q.maxDihedral = std::max(q.maxDihedral, hi);
        const std::size_t bin = static_cast<std::size_t>(std::upper_bound(std::begin(kBins), std::end(kBins), lo) - std::begin(kBins));
        ++q.histogram[bin];
    }
    return q;
}

TOWGEOM_END_NAMESPACE
