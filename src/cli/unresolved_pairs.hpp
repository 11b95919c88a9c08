// Tow pairs that meet but are not resolved: open curves, loops around a tow, complete overlaps
// (one tow inside another, identical or touching tows), and (resolve) pairs left out because a
// tow could not be meshed with their loops. detect, resolve and export name each on stderr
// whatever --quiet says, resolve lists them in report.json, and all three exit 3 for them.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "towgeom/report.hpp"
#include "towgeom/resolve.hpp"
#include "towgeom/tow_intersection.hpp"

namespace towgeom::cli {

/// One stderr note per pair whose surfaces only touch along a line (PairFinding::Kind::Contact):
/// not unresolved (nothing interpenetrates), but never silent.
void reportContacts(const char* command, const IntersectionReport& report, const std::vector<TowSurface>& tows);

/// The same for resolve's result, and one note per loop it took for a contact
/// (SkippedLoop::Reason::Contact: the tows nearly touch along a loop too thin to bound a region).
void reportContacts(const char* command, const ResolveResult& result, const std::vector<TowSurface>& tows);

/// One stderr line per pair, `towgeom COMMAND: unresolved tow pair 'a' and 'b': message [reason]`.
void reportUnresolved(const char* command, const std::vector<UnresolvedPairEntry>& pairs, const std::vector<TowSurface>& tows);

/// True when a pair makes the command exit 3: any pair but an open curve, which only does
/// without --allow-open (@p allowOpen false).
bool exitsUnresolved(const std::vector<UnresolvedPairEntry>& pairs, bool allowOpen);

}  // namespace towgeom::cli
