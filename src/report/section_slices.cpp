#include "report/section_slices.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Edge = std::pair<std::size_t, std::size_t>;

/// One piece of the cut: from the crossing of mesh edge @c from to that of @c to.
struct Piece {
    Edge from, to;
    Point3 a, b;
};

double segmentDistance(const std::array<double, 2>& p, const std::array<double, 2>& a, const std::array<double, 2>& b)
{
    const double ex = b[0] - a[0], ey = b[1] - a[1];
    const double l2 = ex * ex + ey * ey;
    const double t = l2 > 0.0 ? std::clamp(((p[0] - a[0]) * ex + (p[1] - a[1]) * ey) / l2, 0.0, 1.0) : 0.0;
    return std::hypot(p[0] - a[0] - t * ex, p[1] - a[1] - t * ey);
}

}  // namespace

std::vector<SectionPlane> sectionPlanes(const std::vector<std::vector<Point3>>& sections)
{
    std::vector<SectionPlane> planes;
    for (const std::vector<Point3>& s : sections) {
        SectionPlane p;
        for (const Point3& x : s) p.centre = p.centre + x;
        p.centre = (1.0 / static_cast<double>(s.size())) * p.centre;
        Vector3 n;
        for (std::size_t k = 0; k < s.size(); ++k) n = n + cross(s[k] - p.centre, s[(k + 1) % s.size()] - p.centre);
        const double length = norm(n);
        p.normal = length > 0.0 ? (1.0 / length) * n : Vector3{0.0, 0.0, 1.0};
        // e1: the axis least aligned with the normal, made orthogonal to it.
        const Vector3 axis = std::abs(p.normal.x) < 0.6 ? Vector3{1.0, 0.0, 0.0} : Vector3{0.0, 1.0, 0.0};
        p.e1 = axis - dot(axis, p.normal) * p.normal;
        p.e1 = (1.0 / norm(p.e1)) * p.e1;
        p.e2 = cross(p.normal, p.e1);
        double radius = 0.0;
        for (const Point3& x : s) {
            p.polygon.push_back({dot(x - p.centre, p.e1), dot(x - p.centre, p.e2)});
            radius = std::max(radius, distance(x, p.centre));
        }
        p.tolerance = 0.05 * radius;
        planes.push_back(std::move(p));
    }
    // The end sections' planes hold the caps: moved a hair inwards, so the cut is the tube's.
    if (planes.size() >= 2) {
        SectionPlane& first = planes.front();
        SectionPlane& last = planes.back();
        first.centre = first.centre + 1e-4 * (planes[1].centre - first.centre);
        last.centre = last.centre + 1e-4 * (planes[planes.size() - 2].centre - last.centre);
    }
    return planes;
}

double sectionArea(const std::vector<Point3>& nodes, const std::vector<std::array<std::size_t, 3>>& triangles, const SectionPlane& plane)
{
    // The pieces, each from one mesh edge's crossing to another's, oriented counter-clockwise
    // about the normal around the inside; an edge's crossing is computed from its lower node,
    // so both triangles on the edge give the same point.
    std::map<Edge, std::size_t> startingAt;
    std::vector<Piece> pieces;
    const auto side = [&](std::size_t n) { return dot(nodes[n] - plane.centre, plane.normal); };
    for (const auto& t : triangles) {
        const std::array<double, 3> d{side(t[0]), side(t[1]), side(t[2])};
        const auto above = [&](std::size_t k) { return d[k] >= 0.0; };  // a node on the plane counts as above
        if (above(0) == above(1) && above(1) == above(2)) continue;
        std::array<Edge, 2> edges;
        std::array<Point3, 2> ends;
        std::size_t found = 0;
        for (std::size_t k = 0; k < 3 && found < 2; ++k) {
            const std::size_t j = (k + 1) % 3;
            if (above(k) == above(j)) continue;
            const std::size_t lo = t[k] < t[j] ? k : j, hi = lo == k ? j : k;
            const double s = d[lo] / (d[lo] - d[hi]);
            edges[found] = {t[lo], t[hi]};
            ends[found++] = nodes[t[lo]] + s * (nodes[t[hi]] - nodes[t[lo]]);
        }
        if (found != 2) continue;
        const Vector3 along = cross(plane.normal, cross(nodes[t[1]] - nodes[t[0]], nodes[t[2]] - nodes[t[0]]));
        Piece p{edges[0], edges[1], ends[0], ends[1]};
        if (dot(ends[1] - ends[0], along) < 0.0) p = {edges[1], edges[0], ends[1], ends[0]};
        startingAt.emplace(p.from, pieces.size());
        pieces.push_back(p);
    }
    // Chain the pieces into contours; count those lying mostly in the section's polygon.
    const auto inPlane = [&](const Point3& x) {
        return std::array<double, 2>{dot(x - plane.centre, plane.e1), dot(x - plane.centre, plane.e2)};
    };
    std::vector<Kernel::Point_2> polygon;
    for (const auto& q : plane.polygon) polygon.emplace_back(q[0], q[1]);
    const auto nearSection = [&](const Point3& x) {
        const std::array<double, 2> q = inPlane(x);
        if (CGAL::bounded_side_2(polygon.begin(), polygon.end(), Kernel::Point_2(q[0], q[1]), Kernel()) != CGAL::ON_UNBOUNDED_SIDE) return true;
        for (std::size_t k = 0; k < plane.polygon.size(); ++k)
            if (segmentDistance(q, plane.polygon[k], plane.polygon[(k + 1) % plane.polygon.size()]) <= plane.tolerance) return true;
        return false;
    };
    std::vector<char> used(pieces.size(), 0);
    double twice = 0.0;
    for (std::size_t first = 0; first < pieces.size(); ++first) {
        if (used[first]) continue;
        double contour = 0.0;
        std::size_t points = 0, near = 0;
        for (std::size_t k = first; k < pieces.size() && !used[k];) {
            used[k] = 1;
            const Piece& p = pieces[k];
            contour += dot(cross(p.a - plane.centre, p.b - plane.centre), plane.normal);
            ++points;
            near += nearSection(p.a);
            const auto next = startingAt.find(p.to);
            k = next == startingAt.end() ? pieces.size() : next->second;
        }
        if (2 * near >= points) twice += contour;
    }
    return 0.5 * twice;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
