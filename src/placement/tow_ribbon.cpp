// A tow on a surface as a stack of flat sections along its centreline.
#include "towgeom/tow_ribbon.hpp"

#include <algorithm>

#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

TowStack towRibbon(const NurbsSurface& surface, const CurveOnSurface& centreline, const CrossSection& section, std::size_t points,
                   const std::string& name)
{
    const std::size_t n = centreline.uv.size();
    if (n < TowStack::kMinSections || centreline.points.size() != n)
        throw Error(ErrorCode::InvalidArgument, "towRibbon: at least " + std::to_string(TowStack::kMinSections) +
                                                    " centreline points, each with its (u,v)", name);
    if (points < TowStack::kMinPointsPerSection)
        throw Error(ErrorCode::InvalidArgument, "towRibbon: at least " + std::to_string(TowStack::kMinPointsPerSection) + " points per section",
                    name);
    const std::vector<Point2> shape = section.sample(points);
    double lowest = 0.0;  // the section's lowest y rests on the surface
    for (const Point2& q : shape) lowest = std::min(lowest, q.y);
    TowStack stack;
    stack.name = name;
    stack.source = "towRibbon";
    for (std::size_t i = 0; i < n; ++i) {
        const Vector3 normal = surface.normal(centreline.uv[i].u, centreline.uv[i].v);
        if (i > 0 && distance(centreline.points[i], centreline.points[i - 1]) == 0.0)
            throw Error(ErrorCode::InvalidArgument, "towRibbon: two consecutive centreline points coincide", name);
        Vector3 t = centreline.points[i + 1 < n ? i + 1 : i] - centreline.points[i > 0 ? i - 1 : i];
        t = t - dot(t, normal) * normal;
        if (!(norm(t) > 0.0)) throw Error(ErrorCode::InvalidArgument, "towRibbon: two consecutive centreline points coincide", name);
        Vector3 across = cross(normal, (1.0 / norm(t)) * t);
        across = (1.0 / norm(across)) * across;
        const Point3 centre = centreline.points[i] - lowest * normal;
        std::vector<Point3>& out = stack.sections.emplace_back();
        for (const Point2& q : shape) out.push_back(centre + q.x * across + q.y * normal);
    }
    return stack;
}

TOWGEOM_END_NAMESPACE
