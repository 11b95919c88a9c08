#include "mesh/thin_loops.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "towgeom/error.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

/// Whether the loop's node polygon on tow @p side is a simple polygon in (u,v) (v unwrapped).
bool simpleOn(const SharedLoop& shared, LoopSide side)
{
    std::vector<K::Point_2> polygon;
    polygon.reserve(shared.points.size());
    for (const UV& p : loopPolygon(shared, side)) polygon.emplace_back(p.u, p.v);
    return polygon.size() < 3 || CGAL::is_simple_2(polygon.begin(), polygon.end(), K());
}

/// The diagonal of the box of @p loop's points.
double extentOf(const IntersectionLoop& loop)
{
    BoundingBox box;
    for (const LoopPoint& p : loop.points()) box.add(p.point);
    return box.diagonal();
}

/// The largest angle (radians, up to pi/2) at which the two surfaces meet at @p loop's points;
/// NaN where a surface's normal is undefined.
double largestAngle(const IntersectionLoop& loop)
{
    double largest = 0.0;
    try {
        for (const LoopPoint& p : loop.points()) {
            const double c = std::abs(dot(loop.surfaceA().normal(p.onA.u, p.onA.v), loop.surfaceB().normal(p.onB.u, p.onB.v)));
            largest = std::max(largest, std::acos(std::min(1.0, c)));
        }
    } catch (const Error&) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    return largest;
}

}  // namespace

std::string thinLoopContact(const IntersectionLoop& loop, const SharedLoop& shared, double meshSize)
{
    if (!loop.closed() || loop.windsAround(LoopSide::A) || loop.windsAround(LoopSide::B) || loop.crossesCap(LoopSide::A) ||
        loop.crossesCap(LoopSide::B))
        return {};
    if (simpleOn(shared, LoopSide::A) && simpleOn(shared, LoopSide::B)) return {};
    const double angle = largestAngle(loop);
    const double depth = 0.5 * extentOf(loop) * std::tan(angle);
    if (!(depth < kContactDepth * meshSize)) return {};
    // Relative figures: the mesh stage may work in a frame scaled from the user's units.
    std::ostringstream why;
    why.precision(2);
    why << "the loop of tows '" << loop.surfaceA().name() << "' and '" << loop.surfaceB().name() << "' is thinner than its "
        << "nodes can follow (its node polygon crosses itself; the surfaces meet at up to " << angle * 180.0 / 3.14159265358979323846
        << " degrees along it): a contact, its overlap at most " << depth / meshSize
        << " of the mesh size deep, less than the meshes' chord deviation";
    return why.str();
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
