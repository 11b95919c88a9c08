// The shrink baseline: each interpenetrating pair's tow(s) shrunk locally about their sections'
// centroids, by bisection on the reduction, until the refitted pair has no intersection curve.
#include "towgeom/shrink_tows.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "core/elapsed.hpp"
#include "core/progress_report.hpp"
#include "region/tow_ranks.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

using detail::kPi;

/// A tow's sections as TowSurface::sections() gives them, their centroids and the length along
/// the polyline of centroids at each.
struct TowSections {
    std::vector<std::vector<Point3>> points;
    std::vector<Point3> centroid;
    std::vector<double> along;
};

TowSections sectionsOf(const TowSurface& tow)
{
    TowSections s;
    s.points = tow.sections();
    for (const auto& section : s.points) {
        Point3 c;
        for (const Point3& p : section) c = c + p;
        s.centroid.push_back((1.0 / static_cast<double>(section.size())) * c);
        s.along.push_back(s.along.empty() ? 0.0 : s.along.back() + distance(s.centroid[s.centroid.size() - 2], s.centroid.back()));
    }
    return s;
}

/// The length along the tow at parameter @p u (linear between sections).
double alongAt(const TowSurface& tow, const TowSections& s, double u)
{
    const std::vector<double>& us = tow.sectionParameters();
    if (u <= us.front()) return s.along.front();
    if (u >= us.back()) return s.along.back();
    const std::size_t i = static_cast<std::size_t>(std::upper_bound(us.begin(), us.end(), u) - us.begin()) - 1;
    const double t = (u - us[i]) / (us[i + 1] - us[i]);
    return s.along[i] + t * (s.along[i + 1] - s.along[i]);
}

/// Per section, the weight of the shrink for a pair whose curves span [from, to] along the tow:
/// 1 there, cos^2 down to 0 over @p blend on both sides.
std::vector<double> weights(const TowSections& s, double from, double to, double blend)
{
    std::vector<double> w;
    for (double x : s.along) {
        const double d = x < from ? from - x : x > to ? x - to : 0.0;
        const double c = d >= blend ? 0.0 : std::cos(0.5 * kPi * d / blend);
        w.push_back(c * c);
    }
    return w;
}

/// The stack of @p tow with its sections scaled about their centroids by @p scale.
TowStack scaledStack(const TowSurface& tow, const TowSections& s, const std::vector<double>& scale)
{
    TowStack stack;
    stack.name = tow.name();
    stack.source = tow.name() + " (shrunk)";
    for (std::size_t i = 0; i < s.points.size(); ++i) {
        std::vector<Point3>& out = stack.sections.emplace_back();
        for (const Point3& p : s.points[i]) out.push_back(s.centroid[i] + scale[i] * (p - s.centroid[i]));
    }
    return stack;
}

void checkOptions(const ShrinkOptions& o)
{
    if (!(o.blendLength >= 0.0 && std::isfinite(o.blendLength)))
        throw Error(ErrorCode::InvalidArgument, "ShrinkOptions::blendLength must be >= 0 and finite");
    if (!(o.tolerance > 0.0 && o.tolerance < 0.5)) throw Error(ErrorCode::InvalidArgument, "ShrinkOptions::tolerance must lie in (0, 0.5)");
    if (!(o.minScale > 0.0 && o.minScale < 1.0)) throw Error(ErrorCode::InvalidArgument, "ShrinkOptions::minScale must lie in (0, 1)");
    if (!(o.margin >= 0.0 && o.margin < 1.0)) throw Error(ErrorCode::InvalidArgument, "ShrinkOptions::margin must lie in [0, 1)");
}

}  // namespace

ShrinkResult shrinkTows(const std::vector<TowSurface>& tows, const IntersectionReport& report, const ResolveOptions& options)
{
    checkOptions(options.shrink);
    for (const IntersectionLoop& l : report.loops)
        if (l.towA() >= tows.size() || l.towB() >= tows.size() || l.towA() >= l.towB())
            throw Error(ErrorCode::InvalidArgument, "an intersection curve is not between two of the tows (the report of other tows?)");
    const ShrinkOptions& o = options.shrink;
    const std::vector<std::size_t> rank = detail::towRanks(tows, options.primaryPatterns);
    ShrinkResult result;
    result.tows = tows;
    std::vector<TowSections> sections;
    for (const TowSurface& t : tows) sections.push_back(sectionsOf(t));
    std::vector<std::vector<double>> scale(tows.size());
    for (std::size_t t = 0; t < tows.size(); ++t) scale[t].assign(sections[t].points.size(), 1.0);
    // Each pair's span along each of its tows.
    std::map<std::pair<std::size_t, std::size_t>, std::array<std::pair<double, double>, 2>> spans;
    for (const IntersectionLoop& l : report.loops) {
        auto [it, added] = spans.try_emplace({l.towA(), l.towB()});
        for (int side = 0; side < 2; ++side) {
            const std::size_t t = side == 0 ? l.towA() : l.towB();
            auto& [from, to] = it->second[static_cast<std::size_t>(side)];
            if (added) {
                from = 1e300;
                to = -1e300;
            }
            for (const LoopPoint& p : l.points()) {
                const double x = alongAt(tows[t], sections[t], side == 0 ? p.onA.u : p.onB.u);
                from = std::min(from, x);
                to = std::max(to, x);
            }
        }
    }
    FitOptions fit;
    IntersectionOptions io = options.intersection;
    io.threads = 1;
    io.monitor = nullptr;
    std::size_t done = 0;
    for (const auto& [pair, span] : spans) {
        detail::throwIfCancelled(options.monitor);
        detail::sayStage(options, "shrinking tow pair " + std::to_string(++done) + " of " + std::to_string(spans.size()));
        const std::size_t a = pair.first, b = pair.second;  // (not a structured binding: the lambdas below capture them)
        const std::size_t secondary = rank[a] < rank[b] ? b : a;
        // The tows shrunk for this pair, with their weights.
        std::vector<std::pair<std::size_t, std::vector<double>>> shrunk;
        for (int side = 0; side < 2; ++side) {
            const std::size_t t = side == 0 ? a : b;
            if (!o.both && t != secondary) continue;
            const double blend = o.blendLength > 0.0 ? o.blendLength : tows[t].towSize();
            shrunk.emplace_back(t, weights(sections[t], span[static_cast<std::size_t>(side)].first, span[static_cast<std::size_t>(side)].second, blend));
        }
        // The pair with reduction f: true when it no longer interpenetrates; @p out gets the
        // trial tows and their scales.
        std::map<std::size_t, std::pair<TowSurface, std::vector<double>>> trial;
        const auto separated = [&](double f) {
            trial.clear();
            for (const auto& [t, w] : shrunk) {
                std::vector<double> s = scale[t];
                for (std::size_t i = 0; i < s.size(); ++i) s[i] = std::min(s[i], 1.0 - f * w[i]);
                if (s == scale[t]) continue;  // unchanged: the tow as it is, not a refit
                FitOptions byMode = fit;
                byMode.mode = tows[t].mode();
                trial.insert_or_assign(t, std::make_pair(TowSurface::fit(scaledStack(tows[t], sections[t], s), byMode), s));
                ++result.fits;
            }
            const TowSurface& ta = trial.count(a) ? trial.at(a).first : result.tows[a];
            const TowSurface& tb = trial.count(b) ? trial.at(b).first : result.tows[b];
            // Separated: no curve, and neither tow inside the other (a tow shrunk into the other
            // is not separated) nor touching it.
            const IntersectionReport pair = intersectTows({ta, tb}, io);
            return pair.loops.empty() && pair.findings.empty();
        };
        const auto keep = [&]() {
            for (auto& [t, entry] : trial) {
                result.tows[t] = entry.first;
                scale[t] = entry.second;
            }
        };
        if (separated(0.0)) continue;  // shrinking for earlier pairs separated it already
        double lo = 0.0, hi = 1.0 - o.minScale;
        if (!separated(hi)) {  // shrinking cannot separate it (e.g. the secondary's centre is inside the primary): left as it is
            result.notSeparated.push_back({a, b, UnresolvedPair::Reason::NotSeparated,
                                           "tows '" + tows[a].name() + "' and '" + tows[b].name() +
                                               "' still interpenetrate (or one lies inside the other) with their sections scaled to " +
                                               std::to_string(o.minScale) + ": not shrunk for this pair, the rank rule resolves it"});
            continue;
        }
        while (hi - lo > o.tolerance) {
            const double mid = 0.5 * (lo + hi);
            (separated(mid) ? hi : lo) = mid;
        }
        // A margin keeps a gap the meshes' chords do not close.
        if (!separated(std::min(hi + o.margin, 1.0 - o.minScale))) separated(hi);
        keep();
    }
    for (std::size_t t = 0; t < tows.size(); ++t) {
        ShrunkTow f;
        f.sectionScale = scale[t];
        f.volumeBefore = tows[t].volume();
        f.volumeAfter = result.tows[t].volume();
        f.stack = scaledStack(tows[t], sections[t], scale[t]);
        result.figures.push_back(std::move(f));
    }
    return result;
}

TOWGEOM_END_NAMESPACE
