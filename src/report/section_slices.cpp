#include "report/section_slices.hpp"

#include <algorithm>
#include <cmath>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

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
        p.normal = length > 0.0 ? (1.0 / length) * n : n;
        for (const Point3& x : s) p.reach = std::max(p.reach, 2.0 * distance(x, p.centre));
        planes.push_back(p);
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
    double twice = 0.0;
    for (const auto& t : triangles) {
        std::array<double, 3> d{};
        for (std::size_t k = 0; k < 3; ++k) d[k] = dot(nodes[t[k]] - plane.centre, plane.normal);
        // A node on the plane counts as above it, so every crossing is counted once.
        const auto above = [&](std::size_t k) { return d[k] >= 0.0; };
        if (above(0) == above(1) && above(1) == above(2)) continue;
        std::array<Point3, 2> ends;
        std::size_t found = 0;
        for (std::size_t k = 0; k < 3 && found < 2; ++k) {
            const std::size_t j = (k + 1) % 3;
            if (above(k) == above(j)) continue;
            const double s = d[k] / (d[k] - d[j]);
            ends[found++] = nodes[t[k]] + s * (nodes[t[j]] - nodes[t[k]]);
        }
        if (found != 2) continue;
        if (distance(ends[0], plane.centre) > plane.reach || distance(ends[1], plane.centre) > plane.reach) continue;
        // Oriented along normal x n_triangle: counter-clockwise about the normal around the
        // inside of an outward-oriented closed mesh.
        const Vector3 nt = cross(nodes[t[1]] - nodes[t[0]], nodes[t[2]] - nodes[t[0]]);
        const Vector3 along = cross(plane.normal, nt);
        if (dot(ends[1] - ends[0], along) < 0.0) std::swap(ends[0], ends[1]);
        twice += dot(cross(ends[0] - plane.centre, ends[1] - plane.centre), plane.normal);
    }
    return 0.5 * twice;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
