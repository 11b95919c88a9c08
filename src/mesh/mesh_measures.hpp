// Volumes and checks of triangle meshes over a global node list, without copying them (the
// resolve reports' figures). closedVolume() does not check the mesh: resolve checks every tow
// with surfaceFigures() (bad edges and boundary loops); the public enclosedVolume() checks and
// measures any TriangleMesh with CGAL.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// The signed volume bounded by @p triangles (a closed surface; outward orientation gives a
/// positive volume), by the divergence theorem.
double signedVolume(const std::vector<Point3>& nodes, const std::vector<std::array<std::size_t, 3>>& triangles);


/// The number of connected pieces of @p triangles (triangles joined through shared nodes).
std::size_t connectedPieces(const std::vector<std::array<std::size_t, 3>>& triangles);

/// The boundary edges of @p triangles (used by one triangle only) chained into loops of nodes,
/// each loop in the direction its triangles run along it.
std::vector<std::vector<std::size_t>> boundaryLoops(const std::vector<std::array<std::size_t, 3>>& triangles);

/// The signed volume of @p triangles with every boundary loop closed by a fan around its
/// centroid (as closedSurface() does); @p loopCount, if given, gets the number of loops.
double closedVolume(const std::vector<Point3>& nodes, const std::vector<std::array<std::size_t, 3>>& triangles,
                    std::size_t* loopCount = nullptr);

/// What resolve reports and checks of one tow's mesh, from one pass over its edges.
struct SurfaceFigures {
    double volume = 0.0;            ///< closedVolume()
    double area = 0.0;              ///< the triangles' area
    std::size_t boundaryLoops = 0;  ///< boundary loops
    /// Edges that make the mesh no oriented 2-manifold: used by more than two triangles, twice in
    /// the same direction, or joining a node to itself.
    std::size_t badEdges = 0;
};

/// The SurfaceFigures of @p triangles over @p nodes.
SurfaceFigures surfaceFigures(const std::vector<Point3>& nodes, const std::vector<std::array<std::size_t, 3>>& triangles);

/// The winding number of the closed surface @p triangles over @p nodes around @p p: the sum of
/// the triangles' solid angles at @p p over 4 pi (1 inside an outward-oriented surface, 0 outside).
double windingNumber(const std::vector<Point3>& nodes, const std::vector<std::array<std::size_t, 3>>& triangles, const Point3& p);

/// The area of triangle @p t over @p nodes.
double triangleArea(const std::vector<Point3>& nodes, const std::array<std::size_t, 3>& t);

/// The smallest of the three angles of triangle @p t over @p nodes, in degrees.
double smallestAngle(const std::vector<Point3>& nodes, const std::array<std::size_t, 3>& t);

/// Why a tow's mesh that should be closed (@p caps; else a tube open at its two ends) is not:
/// a sentence with its @p badEdges (SurfaceFigures::badEdges) and @p boundaryLoops.
std::string notClosedMessage(bool caps, std::size_t badEdges, std::size_t boundaryLoops);

}  // namespace detail
TOWGEOM_END_NAMESPACE
