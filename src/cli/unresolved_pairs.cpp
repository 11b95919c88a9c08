#include "cli/unresolved_pairs.hpp"

#include <algorithm>
#include <cstring>
#include <iostream>

namespace towgeom::cli {

namespace {

/// The findings of @p report (pairs that meet without a curve) as unresolved pairs.
void addFindings(const IntersectionReport& report, std::vector<UnresolvedEntry>& pairs)
{
    for (const PairFinding& f : report.findings) {
        if (f.kind == PairFinding::Kind::Contact) continue;  // nothing to resolve: a note (reportContacts)
        const bool nested = f.kind == PairFinding::Kind::Nested;
        pairs.push_back({f.towA, f.towB, nested ? reason::kNested : reason::kIdenticalOrTouching,
                         nested ? f.message + " (a complete overlap: no intersection curve)" : f.message});
    }
}

/// Adds @p p unless the same pair already has an entry with the same reason.
void addOnce(std::vector<UnresolvedEntry>& pairs, UnresolvedEntry p)
{
    const bool seen = std::any_of(pairs.begin(), pairs.end(), [&](const UnresolvedEntry& q) {
        return q.towA == p.towA && q.towB == p.towB && std::strcmp(q.reason, p.reason) == 0;
    });
    if (!seen) pairs.push_back(std::move(p));
}

void sortByPair(std::vector<UnresolvedEntry>& pairs)
{
    std::stable_sort(pairs.begin(), pairs.end(), [](const UnresolvedEntry& a, const UnresolvedEntry& b) {
        return std::make_pair(a.towA, a.towB) < std::make_pair(b.towA, b.towB);
    });
}

}  // namespace

std::vector<UnresolvedEntry> unresolvedPairs(const IntersectionReport& report)
{
    std::vector<UnresolvedEntry> pairs;
    for (const IntersectionLoop& l : report.loops)
        if (!l.closed()) addOnce(pairs, {l.towA(), l.towB(), reason::kOpenCurve, "open intersection curve: " + l.openReason()});
    addFindings(report, pairs);
    sortByPair(pairs);
    return pairs;
}

std::vector<UnresolvedEntry> unresolvedPairs(const ResolveResult& result)
{
    std::vector<UnresolvedEntry> pairs;
    for (const SkippedLoop& s : result.skippedLoops) {
        const IntersectionLoop& l = result.intersections.loops[s.loop];
        if (s.reason == SkippedLoop::Reason::OpenCurve)
            addOnce(pairs, {l.towA(), l.towB(), reason::kOpenCurve, "open intersection curve: " + l.openReason()});
        else
            addOnce(pairs, {l.towA(), l.towB(), reason::kWindsAround, s.message});
    }
    for (const towgeom::UnresolvedPair& u : result.unresolved) {
        using Why = towgeom::UnresolvedPair::Reason;
        const char* code = u.reason == Why::LoopsMeet ? reason::kLoopsMeet : u.reason == Why::RegionFailed ? reason::kRegionFailed : reason::kMeshFailed;
        addOnce(pairs, {u.towA, u.towB, code, u.message});
    }
    addFindings(result.intersections, pairs);
    sortByPair(pairs);
    return pairs;
}

void writeUnresolvedJson(detail::JsonWriter& json, const std::vector<UnresolvedEntry>& pairs, const std::vector<TowSurface>& tows)
{
    json.key("unresolved").beginArray();
    for (const UnresolvedEntry& p : pairs) {
        json.beginObject().key("tow_a").value(tows[p.towA].name()).key("tow_b").value(tows[p.towB].name());
        json.key("reason").value(p.reason).key("message").value(p.message).endObject();
    }
    json.endArray();
}

void reportContacts(const char* command, const IntersectionReport& report, const std::vector<TowSurface>& tows)
{
    for (const PairFinding& f : report.findings)
        if (f.kind == PairFinding::Kind::Contact)
            std::cerr << "towgeom " << command << ": note: tows '" << tows[f.towA].name() << "' and '" << tows[f.towB].name()
                      << "': " << f.message << " [contact]\n";
}

void reportUnresolved(const char* command, const std::vector<UnresolvedEntry>& pairs, const std::vector<TowSurface>& tows)
{
    for (const UnresolvedEntry& p : pairs)
        std::cerr << "towgeom " << command << ": unresolved tow pair '" << tows[p.towA].name() << "' and '"
                  << tows[p.towB].name() << "': " << p.message << " [" << p.reason << "]\n";
}

bool exitsUnresolved(const std::vector<UnresolvedEntry>& pairs, bool allowOpen)
{
    return std::any_of(pairs.begin(), pairs.end(),
                       [&](const UnresolvedEntry& p) { return !allowOpen || std::strcmp(p.reason, reason::kOpenCurve) != 0; });
}

}  // namespace towgeom::cli
