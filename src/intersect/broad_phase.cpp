#include "intersect/broad_phase.hpp"

#include <CGAL/Bbox_3.h>
#include <CGAL/box_intersection_d.h>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include <algorithm>
#include <map>
#include <set>

#include "surface/tow_surface_impl.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

using Box = CGAL::Box_intersection_d::Box_with_handle_d<double, 3, std::size_t, CGAL::Box_intersection_d::ID_EXPLICIT>;

/// One u-span of one tow: [uMin, uMax] and the box of the control points that act on it.
struct Span {
    std::size_t tow;
    double uMin, uMax;
};

/// The spans of a surface open in u (degree p, flat knots t_1..t_{n+p+1}): span [t_k, t_k+1]
/// for k = p+1..n is moved by poles k-p..k only, so their box holds that part of the surface.
void addSpans(const Geom_BSplineSurface& s, std::size_t tow, double margin, std::vector<Span>& spans,
              std::vector<Box>& boxes)
{
    const int p = s.UDegree();
    const int n = s.NbUPoles();
    TColStd_Array1OfReal flat(1, n + p + 1);
    s.UKnotSequence(flat);
    const TColgp_Array2OfPnt& poles = s.Poles();
    for (int k = p + 1; k <= n; ++k) {
        if (!(flat(k) < flat(k + 1))) continue;
        CGAL::Bbox_3 box;
        for (int i = k - p; i <= k; ++i)
            for (int j = poles.LowerCol(); j <= poles.UpperCol(); ++j) {
                const gp_Pnt& q = poles(i, j);
                box += CGAL::Bbox_3(q.X(), q.Y(), q.Z(), q.X(), q.Y(), q.Z());
            }
        box = CGAL::Bbox_3(box.xmin() - margin, box.ymin() - margin, box.zmin() - margin, box.xmax() + margin,
                           box.ymax() + margin, box.zmax() + margin);
        boxes.emplace_back(box, spans.size());
        spans.push_back({tow, flat(k), flat(k + 1)});
    }
}

/// Groups sorted span indices of one tow into runs of consecutive spans; returns the run of
/// each span index.
std::map<std::size_t, std::size_t> runsOf(const std::set<std::size_t>& spanIds, std::vector<std::pair<std::size_t, std::size_t>>& runs)
{
    std::map<std::size_t, std::size_t> runOf;
    for (std::size_t id : spanIds) {
        if (runs.empty() || id != runs.back().second + 1)
            runs.push_back({id, id});
        else
            runs.back().second = id;
        runOf[id] = runs.size() - 1;
    }
    return runOf;
}

}  // namespace

std::vector<CandidatePair> broadPhase(const std::vector<TowSurface>& tows, double margin)
{
    std::vector<Span> spans;
    std::vector<Box> boxes;
    std::vector<std::size_t> firstSpan(tows.size() + 1, 0);
    for (std::size_t t = 0; t < tows.size(); ++t) {
        firstSpan[t] = spans.size();
        addSpans(*tows[t].impl().surface, t, margin, spans, boxes);
    }
    firstSpan[tows.size()] = spans.size();

    // Overlapping spans of different tows, grouped by tow pair.
    std::map<std::pair<std::size_t, std::size_t>, std::vector<std::pair<std::size_t, std::size_t>>> hits;
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& x, const Box& y) {
        std::size_t i = x.handle(), j = y.handle();
        if (spans[i].tow == spans[j].tow) return;
        if (spans[i].tow > spans[j].tow) std::swap(i, j);
        hits[{spans[i].tow, spans[j].tow}].emplace_back(i, j);
    });

    std::vector<CandidatePair> result;
    for (const auto& [towPair, spanPairs] : hits) {
        std::set<std::size_t> idsA, idsB;
        for (const auto& [i, j] : spanPairs) {
            idsA.insert(i);
            idsB.insert(j);
        }
        std::vector<std::pair<std::size_t, std::size_t>> runsA, runsB;
        const auto runOfA = runsOf(idsA, runsA);
        const auto runOfB = runsOf(idsB, runsB);
        std::set<std::pair<std::size_t, std::size_t>> runPairs;
        for (const auto& [i, j] : spanPairs) runPairs.insert({runOfA.at(i), runOfB.at(j)});

        const auto window = [&](const std::pair<std::size_t, std::size_t>& run, std::size_t tow) {
            const std::size_t first = std::max(run.first, firstSpan[tow] + 1) - 1;
            const std::size_t last = std::min(run.second + 1, firstSpan[tow + 1] - 1);
            return UWindow{spans[first].uMin, spans[last].uMax};
        };
        CandidatePair c;
        c.a = towPair.first;
        c.b = towPair.second;
        c.spanPairs = spanPairs.size();
        for (const auto& [ra, rb] : runPairs) c.windows.push_back({window(runsA[ra], c.a), window(runsB[rb], c.b)});
        result.push_back(std::move(c));
    }
    return result;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
