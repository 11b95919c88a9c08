#include "region/meeting_loops.hpp"

#include <algorithm>
#include <set>
#include <string>
#include <utility>

#include "region/connected_region.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {
using TowPair = std::pair<std::size_t, std::size_t>;
}  // namespace

void dropMeetingLoops(const std::vector<TowSurface>& tows, const std::vector<IntersectionLoop>& loops,
                      std::vector<SharedLoop>& shared, const std::vector<CrossingLoops>& crossing,
                      std::vector<UnresolvedPair>& unresolved)
{
    std::set<TowPair> dropped;
    const auto pairOf = [&](std::size_t k) { return TowPair{loops[shared[k].loop].towA(), loops[shared[k].loop].towB()}; };
    const auto names = [&](TowPair p) { return "tows '" + tows[p.first].name() + "' and '" + tows[p.second].name() + "'"; };
    const auto drop = [&](TowPair p, TowPair q, std::size_t t, const std::string& how, const std::string& why) {
        const TowPair later = std::max(p, q), kept = std::min(p, q);
        dropped.insert(later);
        unresolved.push_back({later.first, later.second, UnresolvedPair::Reason::LoopsMeet,
                              "a loop of " + names(later) + " " + how + " a loop of " + names(kept) + " on tow '" + tows[t].name() +
                                  "': three tows overlap there, and " + why});
    };
    for (const CrossingLoops& c : crossing) {
        const TowPair p = pairOf(c.first), q = pairOf(c.second);
        if (!dropped.count(p) && !dropped.count(q))
            drop(p, q, c.tow, "crosses",
                 "the loops do not meet in a point of the three tows' surfaces there (the third pair has no resolved loop "
                 "through it, or the point was not found)");
    }
    const auto sideOn = [&](std::size_t k, std::size_t tow) { return loops[shared[k].loop].towA() == tow ? LoopSide::A : LoopSide::B; };
    const auto meetOn = [&](std::size_t a, std::size_t b, std::size_t tow) {
        return loopsMeet(loopPolygon(shared[a], sideOn(a, tow)), loopPolygon(shared[b], sideOn(b, tow)),
                                 tows[tow].parameterRange().vPeriod());
    };
    // A resolved loop of the third pair (s1, s2) there: one that meets loop @p i of (t, s1) on s1
    // or loop @p j of (t, s2) on s2.
    const auto thirdThere = [&](TowPair third, std::size_t i, std::size_t s1, std::size_t j, std::size_t s2) {
        for (std::size_t m = 0; m < shared.size(); ++m)
            if (pairOf(m) == third && (meetOn(m, i, s1) || meetOn(m, j, s2))) return true;
        return false;
    };
    for (bool changed = true; changed;) {
        changed = false;
        for (std::size_t t = 0; t < tows.size(); ++t) {
            std::vector<std::size_t> on;  // the loops on tow t
            for (std::size_t k = 0; k < shared.size(); ++k)
                if (loops[shared[k].loop].towA() == t || loops[shared[k].loop].towB() == t) on.push_back(k);
            for (std::size_t i = 0; i < on.size(); ++i)
                for (std::size_t j = i + 1; j < on.size(); ++j) {
                    const TowPair p = pairOf(on[i]), q = pairOf(on[j]);
                    if (p == q || dropped.count(p) || dropped.count(q)) continue;
                    const std::size_t s1 = p.first == t ? p.second : p.first, s2 = q.first == t ? q.second : q.first;
                    const TowPair third = std::minmax(s1, s2);
                    if (!meetOn(on[i], on[j], t)) continue;
                    if (dropped.count(third) == 0 && thirdThere(third, on[i], s1, on[j], s2)) continue;
                    drop(p, q, t, "meets", names(third) + " have no loop resolved there");
                    changed = true;
                }
        }
    }
    shared.erase(std::remove_if(shared.begin(), shared.end(),
                                [&](const SharedLoop& s) {
                                    return dropped.count({loops[s.loop].towA(), loops[s.loop].towB()}) > 0;
                                }),
                 shared.end());
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
