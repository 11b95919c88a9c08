/// @file report.hpp
/// @brief The JSON reports of `towgeom detect` and `towgeom resolve` as library calls, and the
/// list of tow pairs that meet but were not resolved that both give.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

#include "towgeom/resolve.hpp"
#include "towgeom/tow_intersection.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

struct VolumeMesh;  // volume_mesh.hpp

/// @defgroup reports Reports
/// @brief What the command-line tool writes, for hosts that want the same files: the detect and
/// resolve reports as JSON, and every tow pair that meets but was not resolved.
/// @{

/// A tow pair that meets but was not resolved (their meshes still overlap), once per pair and
/// reason: an entry of the reports' "unresolved" list.
struct UnresolvedPairEntry {
    std::size_t towA = 0;  ///< the lower tow index
    std::size_t towB = 0;  ///< the higher tow index
    /// Why, as the reports' code: `open_curve` (a curve stops: both tows end in one
    /// plane, caps face to face, or the surfaces are tangent), `crosses_cap` (a loop runs across a tow's end cap,
    /// IntersectionLoop::crossesCap(), and the tows are meshed without caps), `winds_around` (a loop goes around a tow without caps, or around
    /// both tows, or a pair's loops around a tow do not cut it into alternating bands), `nested` (one tow inside the other), `identical_or_touching` (surfaces that
    /// coincide or touch, no curve), `search_incomplete` (the search for loops stopped at its budget,
    /// PairFinding::Kind::Incomplete: a loop may be missing), `loops_meet`, `mesh_failed` or `region_failed`
    /// (UnresolvedPair::Reason).
    std::string code;
    std::string message;  ///< a sentence saying what was found
};

/// The pairs intersectTows() found but cannot be resolved: an open curve (once per pair), one
/// tow inside the other, or surfaces that coincide or touch; sorted by pair. Pairs that only
/// touch along a line (PairFinding::Kind::Contact) are not listed: nothing interpenetrates.
TOWGEOM_EXPORT std::vector<UnresolvedPairEntry> unresolvedPairs(const IntersectionReport& report);

/// The pairs of resolveTextile()'s result that were not resolved: a skipped loop (once per pair
/// and reason), a pair left out (ResolveResult::unresolved) or one of the report's findings;
/// sorted by pair.
/// @throws towgeom::Error (InvalidArgument) when a skipped loop is not in the result's report.
TOWGEOM_EXPORT std::vector<UnresolvedPairEntry> unresolvedPairs(const ResolveResult& result);

/// The caller's own stages, in milliseconds, written with the library's in "timings_ms" (a
/// negative value is left out).
struct ReportTimes {
    double read = -1.0;   ///< reading the input files
    double fit = -1.0;    ///< fitting the surfaces
    double volume = -1.0; ///< meshing the tows' volumes (meshVolumes())
    double brep = -1.0;   ///< building the exact solids (trimmedBrep())
    double write = -1.0;  ///< writing the output files
    double total = -1.0;  ///< everything
};

/// What writeDetectReport() writes besides the report.
struct DetectReportOptions {
    /// Each loop's points resampled at this arc length (the tows' units); 0: the loop's own points.
    double spacing = 0.0;
    std::size_t threads = 0;  ///< for the loops' areas (a quadrature each); 0: one per hardware thread
    ReportTimes times;        ///< the caller's stages
};

/// Writes @p report for @p tows as `towgeom detect` prints it: one JSON object with "loops" (per
/// loop tow_a, tow_b, closed, open_reason, length, area_a, area_b, max_distance, point_count,
/// points), "findings", the broad phase's counts (tow_pairs, pairs_tested, window_pairs, seeds,
/// walks) and "timings_ms". Numbers are written to round-trip exactly; names as UTF-8 (an
/// invalid byte becomes U+FFFD). To keep a report for meshing later use writeIntersectionReport().
///
/// @code
/// const towgeom::IntersectionReport r = towgeom::intersectTows(tows);
/// std::ofstream out("loops.json");
/// towgeom::writeDetectReport(r, tows, out);
/// @endcode
/// @throws towgeom::Error (InvalidArgument) when a loop or finding names a tow index not in @p tows
/// (nothing is written then); (WriteFailed) when @p out fails.
TOWGEOM_EXPORT void writeDetectReport(const IntersectionReport& report, const std::vector<TowSurface>& tows, std::ostream& out,
                                      const DetectReportOptions& options = {});

/// What writeResolveReport() writes besides the result.
struct ResolveReportOptions {
    std::size_t threads = 0;  ///< for the loops' areas; 0: one per hardware thread
    ReportTimes times;        ///< the caller's stages
    /// The tows' tetrahedra (meshVolumes() of the result's mesh), if made: "volume_mesh" gives
    /// tetrahedra, nodes, inner_nodes and per tow its tetrahedra and their volume.
    const VolumeMesh* volumes = nullptr;
    /// Why no volume mesh was made although one was asked for (`towgeom resolve --volume` with
    /// tows that still overlap: overlappingPairs()): written as "volume_mesh": {"refused": this}
    /// when volumes is null; empty: no "volume_mesh".
    std::string volumeRefused;
};

/// Writes @p result for @p tows as `towgeom resolve` writes report.json: one JSON object with
/// "tows" (per tow name, role, volume_before, volume_after, area, triangles, boundary_loops,
/// pieces, mesh_size), the detect report's "loops" and "findings", "unresolved" (unresolvedPairs()
/// with tow_a, tow_b, reason, message), "regions" (primary, secondary, triangles, nodes, area,
/// volume_removed), "triple_points" (tows, node, point), "sharp_corners" (TextileMesh::sharpCorners:
/// tow, face "side", "start" or "end", node, point, angle_deg), "skipped" (tow_a, tow_b, code,
/// reason), node_count, "mesh_quality" (min_angle_deg, angle_histogram, fraction_at_least_20,
/// triangles, faces_over_bounds, angle_bound_deg, under_bound, at_sharp_corners,
/// min_angle_away_from_corners_deg: MeshQuality), mesh_rounds and "timings_ms".
///
/// @code
/// const towgeom::ResolveResult r = towgeom::resolveTextile(tows);
/// std::ofstream out("report.json");
/// towgeom::writeResolveReport(r, tows, out);
/// @endcode
/// @throws towgeom::Error (InvalidArgument) when @p result is not of @p tows (tow count, or a
/// tow index out of range; nothing is written then); (WriteFailed) when @p out fails.
TOWGEOM_EXPORT void writeResolveReport(const ResolveResult& result, const std::vector<TowSurface>& tows, std::ostream& out,
                                       const ResolveReportOptions& options = {});

/// @}

TOWGEOM_END_NAMESPACE
