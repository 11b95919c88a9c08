// The face courses are laid on: its box (periodic directions aside) and its trimming curves.
#include "placement/tool_face.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "placement/periodic_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

ToolFace toolFace(const NurbsSurface& surface, std::shared_ptr<const FaceTrim> trim)
{
    return {toolSurface(surface), std::move(trim)};
}

bool onFace(const ToolFace& f, const UV& uv, double slack)
{
    double u0, u1, v0, v1;
    f.surface->Bounds(u0, u1, v0, v1);
    const double du = slack * (u1 - u0), dv = slack * (v1 - v0);
    const bool inU = f.surface->IsUPeriodic() ? std::isfinite(uv.u) : uv.u >= u0 - du && uv.u <= u1 + du;
    const bool inV = f.surface->IsVPeriodic() ? std::isfinite(uv.v) : uv.v >= v0 - dv && uv.v <= v1 + dv;
    if (!inU || !inV) return false;
    if (!f.trim) return true;
    // Just outside the box by the slack: classified where it is clamped to.
    return insideTrim(*f.trim, f.surface, {f.surface->IsUPeriodic() ? uv.u : std::clamp(uv.u, u0, u1), f.surface->IsVPeriodic() ? uv.v : std::clamp(uv.v, v0, v1)});
}

std::string faceSide(const ToolFace& f, const UV& uv, double tolerance)
{
    if (f.trim) {
        const std::string edge = trimSide(*f.trim, f.surface->Value(uv.u, uv.v), tolerance);
        if (!edge.empty()) return edge;
    }
    return boundarySide(f.surface, uv, tolerance);
}

std::string nearestFaceSide(const ToolFace& f, const UV& uv)
{
    if (f.trim) {
        // An edge it lies on, else a side of the box it lies on (a closed face's seam not made
        // periodic), else the nearest edge.
        const gp_Pnt p = f.surface->Value(uv.u, uv.v);
        std::string side = trimSide(*f.trim, p, 1e-9);
        if (side.empty()) side = boundarySide(f.surface, uv, 1e-9);
        return side.empty() ? trimSide(*f.trim, p, std::numeric_limits<double>::infinity()) : side;
    }
    double u0, u1, v0, v1;
    f.surface->Bounds(u0, u1, v0, v1);
    std::string side;
    double best = std::numeric_limits<double>::infinity();
    const auto consider = [&](double gap, const char* name) {
        if (gap < best) best = gap, side = name;
    };
    if (!f.surface->IsUPeriodic()) consider(std::abs(uv.u - u0) / (u1 - u0), "u_min"), consider(std::abs(uv.u - u1) / (u1 - u0), "u_max");
    if (!f.surface->IsVPeriodic()) consider(std::abs(uv.v - v0) / (v1 - v0), "v_min"), consider(std::abs(uv.v - v1) / (v1 - v0), "v_max");
    return side;
}

UV ontoSide(const ToolFace& f, const UV& uv, const std::string& side)
{
    return side.rfind("edge ", 0) == 0 ? uv : onSide(f.surface, uv, side);
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
