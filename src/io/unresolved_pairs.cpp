// The tow pairs that meet but were not resolved, as the reports list them.
#include <algorithm>
#include <utility>

#include "intersect/intersection_loop_data.hpp"
#include "towgeom/error.hpp"
#include "towgeom/report.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

/// The findings of @p report (pairs that meet without a curve) as unresolved pairs.
void addFindings(const IntersectionReport& report, std::vector<UnresolvedPairEntry>& pairs)
{
    for (const PairFinding& f : report.findings) {
        if (f.kind == PairFinding::Kind::Contact) continue;  // nothing interpenetrates: not unresolved
        if (f.kind == PairFinding::Kind::Incomplete) {
            pairs.push_back({f.towA, f.towB, "search_incomplete", f.message});
            continue;
        }
        const bool nested = f.kind == PairFinding::Kind::Nested;
        pairs.push_back({f.towA, f.towB, nested ? "nested" : "identical_or_touching",
                         nested ? f.message + " (a complete overlap: no intersection curve)" : f.message});
    }
}

/// Adds @p p unless the same pair already has an entry with the same code.
void addOnce(std::vector<UnresolvedPairEntry>& pairs, UnresolvedPairEntry p)
{
    const bool seen = std::any_of(pairs.begin(), pairs.end(), [&](const UnresolvedPairEntry& q) {
        return q.towA == p.towA && q.towB == p.towB && q.code == p.code;
    });
    if (!seen) pairs.push_back(std::move(p));
}

void sortByPair(std::vector<UnresolvedPairEntry>& pairs)
{
    std::stable_sort(pairs.begin(), pairs.end(), [](const UnresolvedPairEntry& a, const UnresolvedPairEntry& b) {
        return std::make_pair(a.towA, a.towB) < std::make_pair(b.towA, b.towB);
    });
}

const char* codeOf(UnresolvedPair::Reason r)
{
    switch (r) {
    case UnresolvedPair::Reason::MeshFailed: return "mesh_failed";
    case UnresolvedPair::Reason::LoopsMeet: return "loops_meet";
    case UnresolvedPair::Reason::RegionFailed: return "region_failed";
    case UnresolvedPair::Reason::NotSeparated: return "not_separated";
    }
    return "mesh_failed";
}

}  // namespace

std::vector<UnresolvedPairEntry> unresolvedPairs(const IntersectionReport& report)
{
    std::vector<UnresolvedPairEntry> pairs;
    for (const IntersectionLoop& l : report.loops)
        if (!l.closed()) addOnce(pairs, {l.towA(), l.towB(), "open_curve", "open intersection curve: " + l.openReason()});
    addFindings(report, pairs);
    sortByPair(pairs);
    return pairs;
}

std::vector<UnresolvedPairEntry> unresolvedPairs(const ResolveResult& result)
{
    std::vector<UnresolvedPairEntry> pairs;
    for (const SkippedLoop& s : result.skippedLoops) {
        if (s.loop >= result.intersections.loops.size())
            throw Error(ErrorCode::InvalidArgument, "skipped loop " + std::to_string(s.loop) + " is not in the result's report");
        const IntersectionLoop& l = result.intersections.loops[s.loop];
        if (s.reason == SkippedLoop::Reason::OutsideCell) continue;  // clipped away, not unresolved
        if (s.reason == SkippedLoop::Reason::Contact) continue;      // the tows touch there: not unresolved
        if (s.reason == SkippedLoop::Reason::OpenCurve)
            addOnce(pairs, {l.towA(), l.towB(), "open_curve", "open intersection curve: " + l.openReason()});
        else if (s.reason == SkippedLoop::Reason::CrossesCap)
            addOnce(pairs, {l.towA(), l.towB(), "crosses_cap", s.message});
        else
            addOnce(pairs, {l.towA(), l.towB(), "winds_around", s.message});
    }
    for (const UnresolvedPair& u : result.unresolved) addOnce(pairs, {u.towA, u.towB, codeOf(u.reason), u.message});
    addFindings(result.intersections, pairs);
    sortByPair(pairs);
    return pairs;
}

TOWGEOM_END_NAMESPACE
