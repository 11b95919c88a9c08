// Cross-section areas of a closed tow mesh, cut by the planes of the tow's input sections.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// The plane of one input section, and the section's polygon in it.
struct SectionPlane {
    Point3 centre;    ///< the section points' centroid (moved a hair inwards at the tow's ends)
    Vector3 normal;   ///< unit normal of the section polygon (Newell)
    Vector3 e1, e2;   ///< an orthonormal basis of the plane
    std::vector<std::array<double, 2>> polygon;  ///< the section's points in (e1, e2) about centre
    double tolerance = 0.0;  ///< 5 % of the section's largest distance from its centre
};

/// The plane of each section of @p sections (points per section).
std::vector<SectionPlane> sectionPlanes(const std::vector<std::vector<Point3>>& sections);

/// The area of the cut of the closed, outward-oriented mesh @p triangles (over @p nodes) by
/// @p plane. Each triangle crossing the plane gives a segment oriented along normal x (its
/// normal); the segments are chained into closed contours through the mesh edges they cross,
/// and a contour counts when most of its points lie inside the section's polygon (or within
/// plane.tolerance of it): another pass of the same tow through the plane does not. The area is
/// the counted contours' signed area (divergence theorem in the plane).
double sectionArea(const std::vector<Point3>& nodes, const std::vector<std::array<std::size_t, 3>>& triangles, const SectionPlane& plane);

}  // namespace detail
TOWGEOM_END_NAMESPACE
