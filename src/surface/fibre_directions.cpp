#include "surface/fibre_directions.hpp"

#include <GeomAdaptor_Surface.hxx>
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
        // In order of u (then v), so that the adaptor's span cache is rebuilt once per span, not
        // at nearly every point of a mesh's (unordered) triangles.
        std::vector<std::size_t> order(at.size());
        std::iota(order.begin(), order.end(), std::size_t(0));
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return at[a].u < at[b].u || (at[a].u == at[b].u && at[a].v < at[b].v);
        });
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

}  // namespace detail
TOWGEOM_END_NAMESPACE
