#include "surface/fibre_directions.hpp"

#include <GeomAdaptor_Surface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "surface/occt_guard.hpp"
#include "surface/tow_surface_impl.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

std::vector<Vector3> fibreDirections(const TowSurface& tow, const std::vector<UV>& at)
{
    return guarded(tow.name(), "fibre directions", [&] {
        // Patch by patch (u knot span, then v), so that the adaptor's cache of one patch's
        // polynomial is rebuilt once per patch, not at nearly every point of a mesh's
        // (unordered) triangles.
        const Handle(Geom_BSplineSurface)& bs = tow.impl().surface;
        std::vector<double> uKnots;
        for (int k = 1; k <= bs->NbUKnots(); ++k) uKnots.push_back(bs->UKnot(k));
        std::vector<std::pair<std::size_t, double>> key(at.size());
        for (std::size_t k = 0; k < at.size(); ++k)
            key[k] = {static_cast<std::size_t>(std::upper_bound(uKnots.begin(), uKnots.end(), at[k].u) - uKnots.begin()), at[k].v};
        std::vector<std::size_t> order(at.size());
        std::iota(order.begin(), order.end(), std::size_t(0));
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key[a] < key[b]; });
        GeomAdaptor_Surface surface(tow.impl().surface);
        std::vector<Vector3> out(at.size());
        gp_Pnt p;
        gp_Vec du, dv;
        for (std::size_t k : order) {
            surface.D1(at[k].u, at[k].v, p, du, dv);
            const double n = du.Magnitude();
            out[k] = n > 0.0 ? Vector3{du.X() / n, du.Y() / n, du.Z() / n} : Vector3{};
        }
        return out;
    });
}

Vector3 meanFibreDirection(const TowSurface& tow, const std::vector<UV>& at)
{
    Vector3 sum;
    for (const Vector3& d : fibreDirections(tow, at)) sum = sum + d;
    const double n = norm(sum);
    return n > 0.0 ? (1.0 / n) * sum : sum;
}

void appendCapDirections(const TowSurface& tow, const std::vector<TowFace>& face, std::vector<Vector3>& fibre)
{
    if (fibre.size() >= face.size()) return;
    const ParameterRange r = tow.parameterRange();
    const auto along = [&](double u) {
        std::vector<UV> section;
        for (int k = 0; k < 16; ++k) section.push_back({u, r.vMin + r.vPeriod() * k / 16.0});
        return meanFibreDirection(tow, section);
    };
    const Vector3 start = along(r.uMin), end = along(r.uMax);
    for (std::size_t k = fibre.size(); k < face.size(); ++k) fibre.push_back(face[k] == TowFace::Start ? start : end);
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
