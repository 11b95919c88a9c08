#include "towgeom/tow_intersection.hpp"

#include <Standard_Failure.hxx>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <memory>
#include <mutex>
#include <vector>

#include "core/elapsed.hpp"
#include "core/parallel.hpp"
#include "core/progress_report.hpp"
#include "core/section_geometry.hpp"
#include "intersect/broad_phase.hpp"
#include "intersect/cap_crossing.hpp"
#include "intersect/containment.hpp"
#include "intersect/intersection_loop_data.hpp"
#include "intersect/loop_tracing.hpp"
#include "intersect/seed_search.hpp"
#include "intersect/subdivision_search.hpp"
#include "intersect/surface_walk.hpp"
#include "intersect/textile_frame.hpp"
#include "surface/tow_surface_impl.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

using Clock = std::chrono::steady_clock;

using detail::msSince;

struct PairResult {
    std::vector<IntersectionLoop> loops;
    std::vector<PairFinding> findings;
    std::size_t seeds = 0;
    std::size_t walks = 0;
    detail::SubdivisionStats subdivision;
};

/// The mean width, relative to the tow size, below which a closed curve is a line contact.
constexpr double kContactWidth = 1e-4;
/// Patch pairs whose normal cones exclude a closed loop are walked from once both patches are
/// this small (relative to the tow size; about the facets' size around a tow).
constexpr double kSeedPatchSize = 0.05;
/// Patch pairs this small (relative to the tow size) are walked from whatever their normals: a
/// loop under 1e-3 of the tow size long is the smallest the subdivision promises to find.
constexpr double kSmallestPatch = 2.5e-4;
/// Patch pairs examined at most per tow pair: past it the search is reported incomplete.
constexpr std::size_t kSubdivisionBudget = 200000;

PairResult intersectCandidate(const std::vector<TowSurface>& tows, const std::vector<detail::SurfaceGrid>& grids,
                              const detail::CandidatePair& c, const IntersectionOptions& o)
{
    const TowSurface& a = tows[c.a];
    const TowSurface& b = tows[c.b];
    const double size = std::min(a.towSize(), b.towSize());
    detail::TraceTolerances tol;
    tol.point = o.tolerance > 0.0 ? o.tolerance : o.relativeTolerance * size;
    tol.chordal = o.chordalTolerance > 0.0 ? o.chordalTolerance : o.relativeChordalTolerance * size;
    tol.closing = std::max(100.0 * tol.point, 1e-3 * tol.chordal);
    const detail::SurfacePair surfaces = detail::surfacePairOf(a, b);
    const detail::SurfaceWalker walker(surfaces, tol.point);

    PairResult result;
    std::vector<detail::TracedCurve> curves;
    std::vector<detail::CurveProximity> proximity;  // of each curve, while the seeds are tried
    const auto near = [&](const Point3& p, double within) {
        return std::any_of(proximity.begin(), proximity.end(),
                           [&](const detail::CurveProximity& c) { return c.within(p, within); });
    };
    // Walks from a start guess unless a curve walked already passes there; true when a curve
    // passes there now.
    const auto settle = [&](const detail::Seed& s) {
        // Cheap pre-check before Newton: the guess lies within a facet's size of the curve it
        // comes from. The smaller facet is used so that a second loop near the first (a
        // thin tow through a coarse one) is never skipped, only refined for nothing.
        if (near(s.guess.point, s.facetSize)) return true;
        detail::PointOn2 start = s.guess;
        if (!detail::refineNearest(surfaces, start, tol.point)) return false;
        if (near(start.point, 2.0 * tol.chordal + tol.closing)) return true;
        ++result.walks;
        detail::TracedCurve t = detail::traceCurve(surfaces, walker, start, tol);
        if (t.points.size() < 2) return false;
        if (near(t.points[t.points.size() / 2].point, 2.0 * tol.chordal + tol.closing)) return true;
        curves.push_back(std::move(t));
        proximity.clear();  // the curves may have moved
        for (const detail::TracedCurve& c : curves) proximity.emplace_back(c);
        return true;
    };
    // A leaf of the subdivision is settled only by a curve through it: one found already within
    // the smaller patch's size of the guess, or one through the point Newton reaches from it if
    // that lies on both patches (their (u, v) grown by a quarter). A point elsewhere is walked if
    // it is on no curve yet, and the leaf is halved further all the same.
    const double periodA = a.parameterRange().vPeriod(), periodB = b.parameterRange().vPeriod();
    const auto within = [](double x, double lo, double hi, double period) {
        const double grow = 0.25 * (hi - lo), mid = 0.5 * (lo + hi);
        if (period > 0.0) x = mid + std::remainder(x - mid, period);
        return x >= lo - grow && x <= hi + grow;
    };
    const auto settleLeaf = [&](const detail::Leaf& leaf) {
        const detail::Seed& s = leaf.seed;
        if (near(s.guess.point, s.facetSize)) return true;
        detail::PointOn2 start = s.guess;
        if (!detail::refineNearest(surfaces, start, tol.point)) return false;
        const bool inLeaf = within(start.ua, leaf.ua0, leaf.ua1, 0.0) && within(start.va, leaf.va0, leaf.va1, periodA) &&
                            within(start.ub, leaf.ub0, leaf.ub1, 0.0) && within(start.vb, leaf.vb0, leaf.vb1, periodB);
        detail::Seed at = s;
        at.guess = start;
        at.facetSize = 0.0;  // refined: on a curve if within its tolerance
        return settle(at) && inLeaf;
    };
    // The facets' crossings first (cheap, and they find every deep overlap), then the patch
    // subdivision, which finds what they miss and mostly meets curves walked already.
    for (const detail::WindowPair& w : c.windows) {
        const std::vector<detail::Seed> seeds = detail::findSeeds(grids[c.a], grids[c.b], w);
        result.seeds += seeds.size();
        for (const detail::Seed& s : seeds) settle(s);
    }
    detail::SubdivisionLimits limits;
    limits.overlap = tol.point;
    limits.seedSize = kSeedPatchSize * size;
    limits.smallest = kSmallestPatch * size;
    limits.budget = kSubdivisionBudget;
    result.subdivision = detail::searchPatchPairs(surfaces.a, surfaces.b, c.windows, limits, settleLeaf);
    detail::joinOpenCurves(surfaces, curves, tol);
    // Tows are closed solids: curves into a tow's end continue across its cap.
    detail::closeAcrossCaps(a, b, curves, tol);
    const detail::SurfacePair closedPair = detail::closedPairOf(a, b);
    for (detail::TracedCurve& t : curves) detail::consolidateCurve(closedPair, t, tol);
    detail::dropDuplicateCurves(curves, tol);
    // A closed curve that encloses (almost) nothing: it runs out along a line where the surfaces
    // touch and back. Thinner on average than 1e-4 of the tow size, it is a contact, not an
    // interpenetration.
    const auto isSliver = [&](const IntersectionLoop& loop) {
        if (!loop.closed() || loop.windsAround(LoopSide::A) || loop.windsAround(LoopSide::B)) return false;
        const double thin = 0.5 * loop.length() * kContactWidth * size;
        // Cheap first: no surface the curve bounds has less area than the curve's vector area
        // (|integral of n dA| <= area), which is the polyline's within 2 x chordal x length.
        // (A loop crossing itself in (u, v) has signed areas that may cancel below it: such a
        // loop is taken as no sliver here.)
        std::vector<Point3> polyline;
        for (const LoopPoint& p : loop.points()) polyline.push_back(p.point);
        if (norm(detail::vectorArea(polyline)) > thin + 2.0 * tol.chordal * loop.length()) return false;
        return !(loop.enclosedArea(LoopSide::A) > thin) || !(loop.enclosedArea(LoopSide::B) > thin);
    };
    const ParameterRange ra = a.parameterRange(), rb = b.parameterRange();
    const auto onTubes = [&](const detail::TracedCurve& t) {
        return std::all_of(t.points.begin(), t.points.end(), [&](const detail::PointOn2& p) {
            return p.ua >= ra.uMin && p.ua <= ra.uMax && p.ub >= rb.uMin && p.ub <= rb.uMax;
        });
    };
    std::vector<IntersectionLoop> loops;
    std::vector<char> sliver, drop(curves.size(), 0);
    for (const detail::TracedCurve& t : curves) {
        loops.push_back(detail::makeLoop(c.a, c.b, a, b, t.points, t.closed, t.openReason, tol.point));
        sliver.push_back(isSliver(loops.back()));
    }
    // Where the surfaces are nearly tangent a walk with coarse steps can turn back and retrace
    // its way: a sliver is walked again with OCCT's own, finer step. What that gives is kept
    // unless it runs along a loop kept already (then the sliver was that loop, traced badly).
    std::unique_ptr<detail::SurfaceWalker> fine;  // made when a coarse walk needs it
    std::deque<detail::TracedCurve> retraced;      // stable addresses for proximity
    proximity.clear();
    for (std::size_t k = 0; k < curves.size(); ++k)
        if (!sliver[k]) proximity.emplace_back(curves[k]);
    const auto alongKept = [&](const detail::TracedCurve& t) {
        return std::any_of(proximity.begin(), proximity.end(), [&](const detail::CurveProximity& p) {
            return std::all_of(t.points.begin(), t.points.end(),
                               [&](const detail::PointOn2& q) { return p.within(q.point, 2.0 * tol.chordal + tol.closing); });
        });
    };
    for (std::size_t k = 0; k < curves.size(); ++k) {
        if (!sliver[k] || !onTubes(curves[k])) continue;
        if (!fine) fine = std::make_unique<detail::SurfaceWalker>(surfaces, tol.point, detail::kFineWalkStep);
        ++result.walks;
        detail::TracedCurve again = detail::traceCurve(surfaces, *fine, curves[k].points[curves[k].points.size() / 2], tol);
        if (!again.closed) continue;
        detail::consolidateCurve(closedPair, again, tol);
        IntersectionLoop loop = detail::makeLoop(c.a, c.b, a, b, again.points, true, "", tol.point);
        if (isSliver(loop)) continue;
        sliver[k] = 0;
        if (alongKept(again)) {
            drop[k] = 1;
            continue;
        }
        loops[k] = std::move(loop);
        retraced.push_back(std::move(again));
        proximity.emplace_back(retraced.back());
    }
    std::size_t slivers = 0;
    for (std::size_t k = 0; k < loops.size(); ++k) {
        if (drop[k]) continue;
        if (sliver[k]) {
            ++slivers;
            continue;
        }
        result.loops.push_back(std::move(loops[k]));
    }
    if (slivers > 0)
        result.findings.push_back({c.a, c.b, PairFinding::Kind::Contact,
                                   std::to_string(slivers) + " closed intersection curve(s) enclose no area (thinner than 1e-4 "
                                   "of the tow size): the surfaces touch along a line there"});
    // A search stopped at its budget where the surfaces touch or coincide with no curve (e.g.
    // identical tows) is the Touching finding below (one finding per pair); otherwise a loop may
    // be missing.
    const bool touchingOnly = result.loops.empty() && slivers == 0 && result.seeds > 0;
    if (result.subdivision.exhausted && !touchingOnly)
        result.findings.push_back({c.a, c.b, PairFinding::Kind::Incomplete,
                                   "the search for intersection loops between tows '" + a.name() + "' and '" + b.name() +
                                       "' stopped after " + std::to_string(kSubdivisionBudget) +
                                       " patch pairs (the surfaces nearly touch over a wide area): a loop may be missing"});
    if (result.loops.empty() && slivers == 0) {
        // No curve: say why, if the tows meet at all (their surfaces touch or coincide: facets
        // cross, yet no transversal curve; or one tow lies inside the other).
        if (result.seeds > 0)
            result.findings.push_back({c.a, c.b, PairFinding::Kind::Touching,
                                       "the surfaces touch or coincide (their facets cross) but do not cross each other "
                                       "along a curve: no interpenetration loop"});
        else if (result.subdivision.exhausted)
            ;  // Incomplete above: the surfaces meet closely, not one inside the other
        else if (detail::pointOfInsideOther(b, a))
            result.findings.push_back({c.a, c.b, PairFinding::Kind::Nested, "tow '" + b.name() + "' lies inside tow '" + a.name() + "'"});
        else if (detail::pointOfInsideOther(a, b))
            result.findings.push_back({c.a, c.b, PairFinding::Kind::Nested, "tow '" + a.name() + "' lies inside tow '" + b.name() + "'"});
    }
    return result;
}

}  // namespace

std::size_t IntersectionReport::openCount() const
{
    return static_cast<std::size_t>(std::count_if(loops.begin(), loops.end(), [](const IntersectionLoop& l) { return !l.closed(); }));
}

namespace detail {

void checkIntersectionOptions(const IntersectionOptions& o)
{
    const auto positive = [](double x) { return x > 0.0 && std::isfinite(x); };
    const auto nonNegative = [](double x) { return x >= 0.0 && std::isfinite(x); };
    if (!nonNegative(o.tolerance)) throw Error(ErrorCode::InvalidArgument, "intersection tolerance must be >= 0 and finite");
    if (!positive(o.relativeTolerance))
        throw Error(ErrorCode::InvalidArgument, "relative intersection tolerance must be > 0 and finite");
    if (!nonNegative(o.chordalTolerance)) throw Error(ErrorCode::InvalidArgument, "chordal tolerance must be >= 0 and finite");
    if (!positive(o.relativeChordalTolerance))
        throw Error(ErrorCode::InvalidArgument, "relative chordal tolerance must be > 0 and finite");
}

IntersectionReport intersectInFrame(const std::vector<TowSurface>& tows, const IntersectionOptions& options, const BoundingBox* region)
{
    IntersectionReport report;
    report.towPairs = tows.size() * (tows.size() - (tows.empty() ? 0 : 1)) / 2;
    const std::size_t threads = detail::workerCount(options.threads);

    const Clock::time_point t0 = Clock::now();
    double margin = 0.0;
    for (const TowSurface& t : tows)
        margin = std::max(margin, options.tolerance > 0.0 ? options.tolerance : options.relativeTolerance * t.towSize());
    std::vector<detail::CandidatePair> candidates;
    try {
        candidates = detail::broadPhase(tows, margin);
    } catch (const Standard_Failure& e) {
        throw Error(ErrorCode::Internal, std::string("OpenCASCADE failed in the broad phase: ") + e.GetMessageString());
    }
    if (region) {
        // Every point of a loop lies on both tows (within the tolerance), so in both boxes: a
        // box holds its tube (the control points' hull) and its end caps, whose chart points are
        // between the rim and its centre, the mean of rim points (surface/cap_chart.hpp).
        std::vector<BoundingBox> boxes;
        for (const TowSurface& t : tows) boxes.push_back(t.boundingBox());
        const auto misses = [&](const detail::CandidatePair& c) {
            const BoundingBox &a = boxes[c.a], &b = boxes[c.b];
            BoundingBox both;
            both.min = {std::max(a.min.x, b.min.x) - margin, std::max(a.min.y, b.min.y) - margin, std::max(a.min.z, b.min.z) - margin};
            both.max = {std::min(a.max.x, b.max.x) + margin, std::min(a.max.y, b.max.y) + margin, std::min(a.max.z, b.max.z) + margin};
            return !both.overlaps(*region);
        };
        candidates.erase(std::remove_if(candidates.begin(), candidates.end(), misses), candidates.end());
    }
    report.timings.broadPhase = msSince(t0);
    report.pairsTested = candidates.size();
    for (const auto& c : candidates) report.windowPairs += c.windows.size();

    const Clock::time_point t1 = Clock::now();
    // Section grids of the tows that take part (in parallel: each costs M x N evaluations).
    std::vector<char> used(tows.size(), 0);
    for (const auto& c : candidates) used[c.a] = used[c.b] = 1;
    std::vector<detail::SurfaceGrid> grids(tows.size());
    detail::parallelFor(tows.size(), threads, [&](std::size_t i) {
        if (used[i]) grids[i] = detail::sampleGrid(tows[i]);
    });

    std::vector<PairResult> results(candidates.size());
    std::mutex progressMutex;
    std::size_t done = 0;
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"  // IntersectionOptions::progress, until 0.3
    const auto& legacy = options.progress;
#pragma GCC diagnostic pop
    if (options.monitor) options.monitor->update("intersecting tow pairs", 0, candidates.size());
    detail::throwIfCancelled(options.monitor);
    detail::parallelFor(candidates.size(), threads, [&](std::size_t i) {
        detail::throwIfCancelled(options.monitor);
        const detail::CandidatePair& c = candidates[i];
        try {
            results[i] = intersectCandidate(tows, grids, c, options);
        } catch (const Standard_Failure& e) {
            throw Error(ErrorCode::Internal,
                        std::string("OpenCASCADE failed intersecting tows '") + tows[c.a].name() + "' and '" +
                            tows[c.b].name() + "': " + e.GetMessageString());
        }
        std::lock_guard<std::mutex> lock(progressMutex);
        detail::reportStage(options.monitor, legacy, "intersecting tow pairs", ++done, candidates.size());
    });
    for (PairResult& r : results) {
        report.seeds += r.seeds;
        report.walks += r.walks;
        for (IntersectionLoop& l : r.loops) report.loops.push_back(std::move(l));
        for (PairFinding& f : r.findings) report.findings.push_back(std::move(f));
    }
    report.timings.exact = msSince(t1);
    return report;
}

Frame textileFrame(const std::vector<TowSurface>& tows)
{
    BoundingBox box;
    double smallest = 0.0;
    for (const TowSurface& t : tows) {
        const BoundingBox b = t.boundingBox();
        box.add(b.min);
        box.add(b.max);
        smallest = smallest > 0.0 ? std::min(smallest, t.towSize()) : t.towSize();
    }
    return Frame::around(box, smallest);
}

std::vector<TowSurface> towsInFrame(const std::vector<TowSurface>& tows, const Frame& frame)
{
    std::vector<TowSurface> moved;
    moved.reserve(tows.size());
    for (const TowSurface& t : tows) moved.push_back(inFrame(t, frame));
    return moved;
}

void reportToUser(IntersectionReport& report, const std::vector<TowSurface>& tows, const Frame& frame)
{
    for (IntersectionLoop& l : report.loops) l = loopToUser(l, tows[l.towA()], tows[l.towB()], frame);
}

IntersectionReport reportToFrame(const IntersectionReport& report, const std::vector<TowSurface>& towsInFrame, const Frame& frame)
{
    IntersectionReport moved = report;
    for (IntersectionLoop& l : moved.loops) l = loopToFrame(l, towsInFrame[l.towA()], towsInFrame[l.towB()], frame);
    return moved;
}

/// Refuses (InvalidArgument) a report that is not one of @p tows: a loop naming a tow index out
/// of range, or tows other than those at its indices.
void checkReportTows(const std::vector<TowSurface>& tows, const IntersectionReport& report)
{
    for (std::size_t k = 0; k < report.loops.size(); ++k) {
        const IntersectionLoop& l = report.loops[k];
        const std::string which = "intersection loop " + std::to_string(k);
        if (l.towA() >= l.towB() || l.towB() >= tows.size())
            throw Error(ErrorCode::InvalidArgument, which + " is between tows " + std::to_string(l.towA()) + " and " +
                                                        std::to_string(l.towB()) + ", not two of the " +
                                                        std::to_string(tows.size()) + " tows given");
        if (l.surfaceA().name() != tows[l.towA()].name() || l.surfaceB().name() != tows[l.towB()].name())
            throw Error(ErrorCode::InvalidArgument, which + " is between tows '" + l.surfaceA().name() + "' and '" +
                                                        l.surfaceB().name() + "', but the tows at its indices are '" +
                                                        tows[l.towA()].name() + "' and '" + tows[l.towB()].name() + "'");
    }
}

IntersectionOptions optionsInFrame(const IntersectionOptions& options, const Frame& frame)
{
    IntersectionOptions o = options;
    o.tolerance = frame.lengthToFrame(options.tolerance);
    o.chordalTolerance = frame.lengthToFrame(options.chordalTolerance);
    return o;
}

}  // namespace detail

IntersectionLoop intersectionLoopFromPoints(const std::vector<TowSurface>& tows, std::size_t towA, std::size_t towB,
                                            const std::vector<Point3>& points, bool closed, const IntersectionOptions& options)
{
    detail::checkIntersectionOptions(options);
    if (towA >= towB || towB >= tows.size())
        throw Error(ErrorCode::InvalidArgument, "tows " + std::to_string(towA) + " and " + std::to_string(towB) +
                                                    " are not two of the " + std::to_string(tows.size()) + " tows (towA < towB)");
    if (points.size() < (closed ? 3u : 2u))
        throw Error(ErrorCode::InvalidArgument, std::string("a loop needs at least ") + (closed ? "3" : "2") + " points");
    // In the textile's frame, as intersectTows(): the same tolerances at every scale.
    const detail::Frame frame = detail::textileFrame(tows);
    const TowSurface a = detail::inFrame(tows[towA], frame), b = detail::inFrame(tows[towB], frame);
    const IntersectionOptions o = detail::optionsInFrame(options, frame);
    const double size = std::min(a.towSize(), b.towSize());
    const double tolerance = o.tolerance > 0.0 ? o.tolerance : o.relativeTolerance * size;
    const detail::SurfacePair s = detail::surfacePairOf(a, b);
    const ParameterRange ra = a.parameterRange(), rb = b.parameterRange();
    std::vector<detail::PointOn2> refined;
    for (std::size_t k = 0; k < points.size(); ++k) {
        const std::string which = "point " + std::to_string(k) + " of the loop of tows '" + tows[towA].name() + "' and '" +
                                  tows[towB].name() + "'";
        const Point3& p = points[k];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw Error(ErrorCode::InvalidArgument, which + " is not finite");
        const Point3 q = frame.toFrame(p);
        const bool first = refined.empty();
        const UV onA = first ? a.closestParameters(q) : a.closestParameters(q, {refined.back().ua, refined.back().va});
        const UV onB = first ? b.closestParameters(q) : b.closestParameters(q, {refined.back().ub, refined.back().vb});
        detail::PointOn2 x{onA.u, onA.v, onB.u, onB.v, q, 0.0};
        // v unwrapped along the loop: the period that keeps it next to the previous point's.
        if (!first) {
            x.va += ra.vPeriod() * std::round((refined.back().va - x.va) / ra.vPeriod());
            x.vb += rb.vPeriod() * std::round((refined.back().vb - x.vb) / rb.vPeriod());
        }
        bool onBoth = false;
        try {
            onBoth = detail::refineNearest(s, x, tolerance);
        } catch (const Standard_Failure& e) {
            throw Error(ErrorCode::Internal, which + ": OpenCASCADE failed refining it: " + e.GetMessageString());
        }
        if (!onBoth)
            throw Error(ErrorCode::InvalidArgument, which + " cannot be brought onto both surfaces (Newton's method does not "
                                                            "converge there: not near their intersection, or the surfaces are "
                                                            "tangent)");
        if (distance(x.point, q) > 0.1 * size)
            throw Error(ErrorCode::InvalidArgument, which + " lies " + std::to_string(frame.lengthToUser(distance(x.point, q))) +
                                                        " from the intersection curve, over 0.1 x the tows' size");
        refined.push_back(x);
    }
    const IntersectionLoop loop = detail::makeLoop(towA, towB, a, b, refined, closed, closed ? std::string() : detail::open_reason::kWalkStops,
                                                   tolerance);
    return detail::loopToUser(loop, tows[towA], tows[towB], frame);
}

IntersectionReport intersectTows(const std::vector<TowSurface>& tows, const IntersectionOptions& options)
{
    return detail::intersectTowsIn(tows, options, nullptr);
}

IntersectionReport detail::intersectTowsIn(const std::vector<TowSurface>& tows, const IntersectionOptions& options, const BoundingBox* region)
{
    detail::checkIntersectionOptions(options);
    // Computed in a frame where the tows are about unit size, so that the kernel's absolute
    // tolerances mean the same at every scale; loops go back to the user's tows and units.
    const detail::Frame frame = detail::textileFrame(tows);
    BoundingBox inFrame;
    if (region) {
        inFrame.add(frame.toFrame(region->min));
        inFrame.add(frame.toFrame(region->max));
    }
    IntersectionReport report = detail::intersectInFrame(detail::towsInFrame(tows, frame), detail::optionsInFrame(options, frame),
                                                         region ? &inFrame : nullptr);
    detail::reportToUser(report, tows, frame);
    return report;
}

std::vector<IntersectionLoop> intersectPair(const TowSurface& a, const TowSurface& b, const IntersectionOptions& options)
{
    return intersectTows({a, b}, options).loops;
}

TOWGEOM_END_NAMESPACE
