/// @file course_coverage.hpp
/// @brief courseCoverage(): how much of a tool surface a course plan's tows cover once, twice or
/// more, or not at all, on a tessellation of the surface, and its VTK field.
#pragma once

#include <array>
#include <cstddef>
#include <iosfwd>
#include <vector>

#include "towgeom/fibre_courses.hpp"
#include "towgeom/nurbs_offset.hpp"
#include "towgeom/placement_surface.hpp"
#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// @addtogroup placement
/// @{

/// A tool surface's tessellation with the number of tows covering each triangle.
struct CourseCoverage {
    std::vector<Point3> nodes;                          ///< the tessellation's nodes, S(u,v) on a regular (u,v) grid
    std::vector<std::array<std::size_t, 3>> triangles;  ///< two per grid cell
    std::vector<std::size_t> count;  ///< per triangle, the tows whose band holds its centroid
    std::vector<double> area;        ///< per triangle, its area (flat)
    double totalArea = 0.0;  ///< the tessellation's area (the surface's, to the chords' error)
    /// Fractions of totalArea covered by no tow, by one, and by two or more: they add to 1.
    double uncovered = 0.0;
    double once = 0.0;    ///< see uncovered
    double several = 0.0; ///< see uncovered
};

/// Covers @p surface's (u,v) box with @p cells x @p cells grid cells, two triangles each, and
/// counts per triangle the tows of @p plan whose band holds the triangle's centroid in (u,v)
/// (across a periodic seam, any copy of it): the band's outline is its right edge's (u,v) cubic
/// and its left edge's back, 256 points each, closed across the tow's ends. An edge wholly off
/// the face (empty) is taken as the other's mirror image about the centreline in (u,v), so the
/// band runs on to the boundary. At an end the face's boundary cut (TowPath::startBoundary,
/// endBoundary) both edges run on straight past it in (u,v), by half the distance between their
/// ends in space, so that the band reaches a boundary bulging out between them all across rather
/// than stopping at the chord (a hole narrower than that is bridged). Accurate to about one cell
/// along each band's border.
/// @throws towgeom::Error (InvalidArgument) for fewer than 2 or more than 4000 cells, or an edge
///         whose points repeat.
TOWGEOM_EXPORT CourseCoverage courseCoverage(const NurbsSurface& surface, const CoursePlan& plan, std::size_t cells = 200);

/// As the other overload, on the face @p tool: where it is trimmed (PlacementSurface::trim) the
/// triangles whose centroid lies off it (OpenCASCADE's face classifier) are left out, so the
/// fractions and totalArea are the face's (its edges to about one cell).
/// @throws towgeom::Error as the other overload.
TOWGEOM_EXPORT CourseCoverage courseCoverage(const PlacementSurface& tool, const CoursePlan& plan, std::size_t cells = 200);

/// Writes @p coverage as a legacy VTK unstructured grid of triangles (ParaView) with cell data
/// "coverage" (the count) and "area". @throws towgeom::Error (WriteFailed) when the stream fails.
TOWGEOM_EXPORT void writeCourseCoverageVtk(const CourseCoverage& coverage, std::ostream& out);

/// @}

TOWGEOM_END_NAMESPACE
