/// @file method_comparison.hpp
/// @brief compareMethods(): one textile resolved by several methods (connect, symmetric,
/// shrink) on one intersection and one set of meshes, as figures a report shows side by side;
/// writeReportHtml() and writeReportCsv() write that report.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

#include "towgeom/resolve.hpp"
#include "towgeom/textile_mesh.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// @defgroup comparison Comparing resolution methods
/// @brief compareMethods(): several methods side by side; the self-contained HTML report.
/// @{

/// One tow resolved by one method.
struct TowMethodFigures {
    /// TowResolution::role(); for ResolutionMethod::Shrink "shrunk" or "unchanged".
    std::string role;
    double volumeBefore = 0.0;    ///< TowResolution::volumeBefore
    double volumeAfter = 0.0;     ///< TowResolution::volumeAfter
    double area = 0.0;            ///< TowResolution::area
    std::size_t triangles = 0;    ///< of its final mesh
    double largestSectionChange = 0.0;  ///< ResolutionMethod::Shrink: ShrunkTow::largestSectionChange(); else 0
    /// At each input section: the area of the final mesh's cross-section in that section's plane
    /// (through its centroid, normal to its polygon): the cut's closed contours that lie mostly
    /// inside the input section's polygon (so another pass of the same tow through the plane is
    /// not counted).
    std::vector<double> sectionArea;
    /// The relative volume change in percent: 100 (after - before) / before.
    double volumeChangePercent() const { return volumeBefore > 0.0 ? 100.0 * (volumeAfter - volumeBefore) / volumeBefore : 0.0; }
};

/// One method's result.
struct MethodFigures {
    ResolutionMethod method = ResolutionMethod::Connect;  ///< which method
    std::vector<TowMethodFigures> tows;  ///< per input tow
    std::size_t regions = 0;             ///< connected regions (shared surfaces)
    std::size_t unresolvedPairs = 0;     ///< ResolveResult::unresolved
    MeshQuality quality;                 ///< of its final meshes
    double milliseconds = 0.0;           ///< the method's own stages (regions; shrinking and meshing for Shrink)
};

/// An intersection loop as the report lists it.
struct LoopRow {
    std::size_t towA = 0;             ///< IntersectionLoop::towA()
    std::size_t towB = 0;             ///< IntersectionLoop::towB()
    bool closed = true;               ///< IntersectionLoop::closed()
    double length = 0.0;              ///< IntersectionLoop::length()
    double areaA = 0.0;               ///< IntersectionLoop::enclosedArea() on tow A
    double areaB = 0.0;               ///< IntersectionLoop::enclosedArea() on tow B
};

/// A connected region of the first method, as the report lists it.
struct RegionRow {
    std::size_t primary = 0;     ///< ConnectedRegion::primary
    std::size_t secondary = 0;   ///< ConnectedRegion::secondary
    std::size_t triangles = 0;   ///< its triangles
    double area = 0.0;           ///< ConnectedRegion::area
    double volumeRemoved = 0.0;  ///< ConnectedRegion::volumeRemoved
    SharedSurface surface = SharedSurface::Primary;  ///< ConnectedRegion::surface
};

/// What compareMethods() measured: everything the report shows, as plain values.
struct MethodComparison {
    std::vector<std::string> towNames;  ///< the tows, in input order
    /// Per tow, at each input section: the length along the polyline of the sections' centroids.
    std::vector<std::vector<double>> stations;
    /// Per tow, at each input section: the cross-section area of the tow's own closed mesh before
    /// resolution (measured as TowMethodFigures::sectionArea, so the two compare).
    std::vector<std::vector<double>> sectionAreaBefore;
    std::vector<MethodFigures> methods;  ///< in the order asked for
    std::vector<LoopRow> loops;          ///< every loop found
    std::vector<RegionRow> regions;      ///< the first method's regions
    double intersectMilliseconds = 0.0;  ///< intersectTows()
    double meshMilliseconds = 0.0;       ///< meshTows(), shared by connect and symmetric
};

/// Resolves @p tows with each of @p methods on one intersectTows() and (for Connect and
/// Symmetric) one meshTows(), and measures each: per tow the volumes, area, triangles and the
/// cross-section areas along it (the tows' meshes cut by the planes of the input sections);
/// the loops and the first method's regions. @p options is used as given except for its method.
/// If @p results is given it gets each method's ResolveResult, in the same order (to write the
/// meshes of one of them).
///
/// @code
/// const towgeom::MethodComparison c = towgeom::compareMethods(
///     tows, {towgeom::ResolutionMethod::Connect, towgeom::ResolutionMethod::Symmetric, towgeom::ResolutionMethod::Shrink});
/// for (std::size_t m = 0; m < c.methods.size(); ++m)
///     for (std::size_t t = 0; t < c.towNames.size(); ++t)
///         std::cout << c.towNames[t] << ": " << c.methods[m].tows[t].volumeChangePercent() << " %\n";
/// std::ofstream html("report.html");
/// towgeom::writeReportHtml(c, results.front().mesh, html);
/// @endcode
///
/// @throws towgeom::Error as resolveTextile(); (InvalidArgument) for no method or one twice.
TOWGEOM_EXPORT MethodComparison compareMethods(const std::vector<TowSurface>& tows, const std::vector<ResolutionMethod>& methods,
                                               const ResolveOptions& options = {}, std::vector<ResolveResult>* results = nullptr);

/// "connect", "symmetric" or "shrink".
TOWGEOM_EXPORT const char* resolutionMethodName(ResolutionMethod method) noexcept;

/// Writes @p comparison as one self-contained HTML page (no network needed: Chart.js and
/// three.js are inlined, from the pinned npm packages in the source tree): the table of tows
/// per method (role, volume before and after, change in %, area, triangles, largest section
/// change), the regions and the loops; plots of the volume change per tow per method side by
/// side, of each tow's section area along it before and after each method, and of the mesh
/// quality (smallest-angle histogram); and a 3D view of @p view (rotate, zoom, colour by tow
/// or by region, a toggle per tow).
/// @throws towgeom::Error (InvalidArgument) when @p view's tows are not @p comparison's;
/// (WriteFailed) when @p out fails.
TOWGEOM_EXPORT void writeReportHtml(const MethodComparison& comparison, const TextileMesh& view, std::ostream& out);

/// Writes the table of tows as CSV (one row per tow and method: tow, method, role,
/// volume_before, volume_after, volume_change_percent, area, triangles, largest_section_change).
/// @throws towgeom::Error (WriteFailed) when @p out fails.
TOWGEOM_EXPORT void writeReportCsv(const MethodComparison& comparison, std::ostream& out);

/// @}

TOWGEOM_END_NAMESPACE
