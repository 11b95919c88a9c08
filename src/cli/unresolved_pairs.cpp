#include "cli/unresolved_pairs.hpp"

#include <algorithm>
#include <iostream>

namespace towgeom::cli {

void reportContacts(const char* command, const IntersectionReport& report, const std::vector<TowSurface>& tows)
{
    for (const PairFinding& f : report.findings)
        if (f.kind == PairFinding::Kind::Contact)
            std::cerr << "towgeom " << command << ": note: tows '" << tows[f.towA].name() << "' and '" << tows[f.towB].name()
                      << "': " << f.message << " [contact]\n";
}

void reportContacts(const char* command, const ResolveResult& result, const std::vector<TowSurface>& tows)
{
    reportContacts(command, result.intersections, tows);
    for (const SkippedLoop& s : result.skippedLoops)
        if (s.reason == SkippedLoop::Reason::Contact) std::cerr << "towgeom " << command << ": note: " << s.message << " [contact]\n";
}

void reportUnresolved(const char* command, const std::vector<UnresolvedPairEntry>& pairs, const std::vector<TowSurface>& tows)
{
    for (const UnresolvedPairEntry& p : pairs)
        std::cerr << "towgeom " << command << ": unresolved tow pair '" << tows[p.towA].name() << "' and '"
                  << tows[p.towB].name() << "': " << p.message << " [" << p.code << "]\n";
}

bool exitsUnresolved(const std::vector<UnresolvedPairEntry>& pairs, bool allowOpen)
{
    return std::any_of(pairs.begin(), pairs.end(),
                       [&](const UnresolvedPairEntry& p) { return !allowOpen || (p.code != "open_curve" && p.code != "crosses_cap"); });
}

}  // namespace towgeom::cli
