// The "loops" and "findings" arrays of detect's and resolve's JSON reports.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/json_writer.hpp"
#include "towgeom/tow_intersection.hpp"

namespace towgeom::cli {

/// Writes key "loops" and the array: per loop tow_a, tow_b, closed, open_reason (when open),
/// length, area_a, area_b, max_distance, point_count, points (spaced by @p spacing if > 0).
/// The per-loop figures are computed on @p threads threads first.
void writeLoopsJson(detail::JsonWriter& json, const IntersectionReport& report, const std::vector<TowSurface>& tows,
                    double spacing, std::size_t threads);

/// Writes key "findings" and the array: per finding tow_a, tow_b, kind (touching, nested), message.
/// (The stderr lines for them: reportUnresolved() in unresolved_pairs.hpp.)
void writeFindingsJson(detail::JsonWriter& json, const IntersectionReport& report, const std::vector<TowSurface>& tows);

}  // namespace towgeom::cli
