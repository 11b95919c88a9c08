// Tow pairs that meet but are not resolved: open curves, loops around a tow, complete overlaps
// (one tow inside another, identical or touching tows), and (resolve) pairs left out because a
// tow could not be meshed with their loops. detect and resolve name each on stderr whatever
// --quiet says, resolve lists them in report.json, and both exit 3 for them.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/json_writer.hpp"
#include "towgeom/resolve.hpp"
#include "towgeom/tow_intersection.hpp"

namespace towgeom::cli {

/// Why a tow pair is not resolved: the "reason" code of report.json and of the stderr line.
namespace reason {
constexpr const char* kOpenCurve = "open_curve";           ///< a curve runs into a tow's end
constexpr const char* kWindsAround = "winds_around";       ///< a loop goes around a tow (resolve only)
constexpr const char* kNested = "nested";                  ///< one tow lies inside the other
constexpr const char* kIdenticalOrTouching = "identical_or_touching";  ///< surfaces coincide or touch, no curve
constexpr const char* kMeshFailed = "mesh_failed";  ///< a tow could not be meshed with the pair's loops (resolve only)
constexpr const char* kLoopsMeet = "loops_meet";    ///< the pair's loop meets another pair's on a tow (resolve only)
constexpr const char* kRegionFailed = "region_failed";  ///< a tow was not closed after the swap (resolve only)
}  // namespace reason

/// One tow pair that meets without a resolvable intersection loop: an entry of report.json's
/// "unresolved" (towgeom::UnresolvedPair holds only the library's own mesh_failed pairs).
struct UnresolvedEntry {
    std::size_t towA = 0, towB = 0;  ///< tow indices, towA < towB
    const char* reason = "";         ///< one of the reason codes
    std::string message;             ///< a sentence naming what was found
};

/// detect: every pair with an open curve (once per pair) or with a finding (nested,
/// identical_or_touching), ordered by pair.
std::vector<UnresolvedEntry> unresolvedPairs(const IntersectionReport& report);

/// resolve: every pair with a skipped loop (open_curve, winds_around; once per pair and reason),
/// left out by the mesher (mesh_failed) or with a finding, ordered by pair.
std::vector<UnresolvedEntry> unresolvedPairs(const ResolveResult& result);

/// Writes key "unresolved" and the array: per pair tow_a, tow_b, reason, message.
void writeUnresolvedJson(detail::JsonWriter& json, const std::vector<UnresolvedEntry>& pairs,
                         const std::vector<TowSurface>& tows);

/// One stderr note per pair whose surfaces only touch along a line (PairFinding::Kind::Contact):
/// not unresolved (nothing interpenetrates), but never silent.
void reportContacts(const char* command, const IntersectionReport& report, const std::vector<TowSurface>& tows);

/// One stderr line per pair, `towgeom COMMAND: unresolved tow pair 'a' and 'b': message [reason]`.
void reportUnresolved(const char* command, const std::vector<UnresolvedEntry>& pairs, const std::vector<TowSurface>& tows);

/// True when a pair makes the command exit 3: any pair but an open curve, which only does
/// without --allow-open (@p allowOpen false).
bool exitsUnresolved(const std::vector<UnresolvedEntry>& pairs, bool allowOpen);

}  // namespace towgeom::cli
