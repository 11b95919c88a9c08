/// @file intersection_report_json.hpp
/// @brief An IntersectionReport written as JSON and read back exactly, so that one intersection
/// serves many meshes (resolveTextile() with a report), in another run or another program.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "towgeom/tow_intersection.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// @defgroup report_json Intersection reports as JSON
/// @brief intersectTows() once, its loops kept in a file, meshes made from them later.
///
/// The format (`"format": "towgeom-intersections"`, `"version": 1`) holds the names of the tows
/// the report is for, in order, and per loop its tows (indices into that list), whether it is
/// closed (or why not), its point tolerance and its points, each as
/// `[x, y, z, uA, vA, uB, vB, s]`: the 3D point, its (u,v) on tow A and on tow B, and the arc
/// length s from the first point. Numbers are written to round-trip exactly: the points, their
/// (u,v), arc lengths, tolerances, open reasons, the pair findings (touching, nested, contact, incomplete)
/// and the counts of the search read back bit for bit, so a report read back gives the same
/// meshes as the one written. IntersectionLoop::maxDistance() is recomputed from the points
/// (it may differ in the last bits); timings are written but not read back.
///
/// @code
/// const towgeom::IntersectionReport found = towgeom::intersectTows(tows);
/// towgeom::writeIntersectionReport(found, tows, "loops.json");
/// // ... later, or in another program with the same tows:
/// const towgeom::IntersectionReport loops = towgeom::readIntersectionReport("loops.json", tows);
/// const towgeom::ResolveResult r = towgeom::resolveTextile(tows, loops);
/// @endcode
/// @{

/// Writes @p report, computed for @p tows, as JSON to @p out.
/// @throws towgeom::Error (InvalidArgument) if a loop of @p report is not between two of @p tows
/// (an index out of range, or tows of other names at its indices), a loop's tolerance is over
/// 1e-2 of the tows' size, or a tow name is not UTF-8.
TOWGEOM_EXPORT void writeIntersectionReport(const IntersectionReport& report, const std::vector<TowSurface>& tows, std::ostream& out);

/// Writes @p report, computed for @p tows, as JSON to the file @p path: complete or not at all
/// (written to a temporary file beside it, then renamed).
/// @throws towgeom::Error (WriteFailed) if the file cannot be written; (InvalidArgument) as above.
TOWGEOM_EXPORT void writeIntersectionReport(const IntersectionReport& report, const std::vector<TowSurface>& tows, const std::string& path);

/// Reads a report written by writeIntersectionReport() for @p tows: the loops become loops of
/// these tows (their points checked to lie on both surfaces). @p sourceName names the input in
/// errors.
/// @throws towgeom::Error (MalformedReport) naming @p sourceName and the loop or point when the
/// input is not JSON, not this format or version, has a missing or wrong-typed field, a
/// non-finite or out-of-range number, a closed loop of fewer than 3 points, a u off a tow's
/// range or a v more than 100 periods off, arc lengths that are not the distances of the points
/// (to 1e-9), a loop of no length, a tolerance over 1e-2 of the tows' size, a loop given twice,
/// or is for other tows: other names, another count or order, or points off the tows' surfaces
/// (farther than 1000 x the loop's tolerance plus 1e-6 of the tow's size).
TOWGEOM_EXPORT IntersectionReport readIntersectionReport(std::istream& in, const std::vector<TowSurface>& tows,
                                          const std::string& sourceName = "<stream>");

/// readIntersectionReport() from the file @p path.
/// @throws towgeom::Error (FileNotFound, FileUnreadable) if @p path cannot be read; as above.
TOWGEOM_EXPORT IntersectionReport readIntersectionReport(const std::string& path, const std::vector<TowSurface>& tows);

/// @}

TOWGEOM_END_NAMESPACE
