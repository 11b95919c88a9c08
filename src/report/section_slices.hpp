// Cross-section areas of a closed tow mesh, cut by the planes of the tow's input sections.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// The plane of one input section and how far from its centre a cut counts.
struct SectionPlane {
    Point3 centre;    ///< the section points' centroid
    Vector3 normal;   ///< unit normal of the section polygon (Newell)
    double reach = 0.0;  ///< twice the section's largest distance from its centre
};

/// The plane of each section of @p sections (points per section).
std::vector<SectionPlane> sectionPlanes(const std::vector<std::vector<Point3>>& sections);

/// The area of the cut of the closed, outward-oriented mesh @p triangles (over @p nodes) by
/// @p plane, counting only the cut's segments within plane.reach of its centre: by the
/// divergence theorem in the plane, each triangle crossing it gives a segment oriented along
/// normal x (the triangle's normal), so no chaining of segments is needed.
double sectionArea(const std::vector<Point3>& nodes, const std::vector<std::array<std::size_t, 3>>& triangles, const SectionPlane& plane);

}  // namespace detail
TOWGEOM_END_NAMESPACE
