#include "mesh/textile_mesher.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <utility>

#include "cell/axis.hpp"
#include "cell/cell_faces.hpp"
#include "cell/face_crossings.hpp"
#include "cell/tow_cuts.hpp"
#include "core/elapsed.hpp"
#include "core/parallel.hpp"
#include "intersect/intersection_loop_data.hpp"
#include "core/progress_report.hpp"
#include "mesh/crossing_spots.hpp"
#include "mesh/end_caps.hpp"
#include "mesh/loop_nodes.hpp"
#include "mesh/mesh_measures.hpp"
#include "mesh/parametric_mesher.hpp"
#include "mesh/textile_mesh_finish.hpp"
#include "mesh/thin_loops.hpp"
#include "region/meeting_loops.hpp"
#include "region/tow_ranks.hpp"
#include "region/triple_points.hpp"
#include "region/winding_loops.hpp"
#include "surface/fibre_directions.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

using Clock = std::chrono::steady_clock;
using Triangle = std::array<std::size_t, 3>;
using TowPair = std::pair<std::size_t, std::size_t>;

using detail::msSince;

/// @p p with v moved into the period [vMin, vMax) by whole periods.
UV inPeriod(UV p, const ParameterRange& r)
{
    p.v = r.vMin + std::fmod(p.v - r.vMin, r.vPeriod());
    if (p.v < r.vMin) p.v += r.vPeriod();
    if (p.v >= r.vMax) p.v = r.vMin;
    return p;
}

/// Where an intersection loop lies with respect to a cell.
enum class CellSide { Inside, Outside, Across };

/// Inside: every point of @p loop at least @p margin inside @p cell; Outside: every point outside
/// the box and no chord of it through the box shrunk by @p margin (a straight loop's few points
/// may all lie outside while it passes through); else Across.
CellSide cellSide(const IntersectionLoop& loop, const Cell& cell, double margin)
{
    Cell inner = cell;
    inner.min = {cell.min.x + margin, cell.min.y + margin, cell.min.z + margin};
    inner.max = {cell.max.x - margin, cell.max.y - margin, cell.max.z - margin};
    const bool thick = inner.min.x < inner.max.x && inner.min.y < inner.max.y && inner.min.z < inner.max.z;
    bool allIn = true, allOut = true, through = false;
    const std::vector<LoopPoint>& points = loop.points();
    for (std::size_t k = 0; k < points.size(); ++k) {
        const Point3& q = points[k].point;
        allIn = allIn && thick && inCellBox(inner, q);
        allOut = allOut && !inCellBox(cell, q);
        if (!through && thick && (k + 1 < points.size() || loop.closed()))
            through = segmentMeetsBox(q, points[(k + 1) % points.size()].point, inner);
    }
    return allIn ? CellSide::Inside : allOut && !through ? CellSide::Outside : CellSide::Across;
}

/// Drops the triangles of tow @p t's mesh that lie beyond the cell's cuts (by their (u,v) centroids).
void keepInCell(ParametricMesh& mesh, const CellCuts& cuts, std::size_t t)
{
    std::size_t kept = 0;
    for (std::size_t k = 0; k < mesh.triangles.size(); ++k)
        if (cuts.keeps(t, mesh.centroids[k])) {
            mesh.triangles[kept] = mesh.triangles[k];
            mesh.centroids[kept] = mesh.centroids[k];
            ++kept;
        }
    mesh.triangles.resize(kept);
    mesh.centroids.resize(kept);
}

/// The meshes of tow @p tow could not be made with the loops of @p pairs on it.
struct TowMeshFailure {
    std::size_t tow = 0;
    std::string message;
    std::set<TowPair> pairs;  ///< the tow pairs with resolved loops on that tow
};

/// Every tow that failed in one meshing stage, in tow order.
struct TowMeshFailures {
    std::vector<TowMeshFailure> tows;
};

/// The failures of the tows meshed in parallel, kept per tow so that what is reported does not
/// depend on the threads' timing.
class TowFailures {
public:
    TowFailures(const std::vector<IntersectionLoop>& loops, const std::vector<detail::SharedLoop>& shared, std::size_t tows)
        : loops_(loops), shared_(shared), failures_(tows)
    {
    }
    /// Runs @p body for tow @p tow; a failure is kept as a TowMeshFailure naming the tow's pairs.
    template <class Body>
    void run(std::size_t tow, Body&& body)
    {
        std::string message;
        try {
            body();
            return;
        } catch (const std::bad_alloc&) {
            throw;  // out of memory is not this tow's geometry
        } catch (const Error& e) {
            if (e.code() == ErrorCode::Cancelled) throw;
            message = e.message();  // without the "tow 'NAME'" context, which the caller adds
        } catch (const std::exception& e) {
            message = e.what();
        }
        {
            auto f = std::make_unique<TowMeshFailure>(TowMeshFailure{tow, message, {}});
            for (const detail::SharedLoop& s : shared_) {
                const IntersectionLoop& l = loops_[s.loop];
                if (l.towA() == tow || l.towB() == tow) f->pairs.emplace(l.towA(), l.towB());
            }
            failures_[tow] = std::move(f);
        }
    }
    /// A failure of tow @p tow that costs only the tow pairs @p pairs.
    void fail(std::size_t tow, const std::string& message, std::set<TowPair> pairs)
    {
        if (!failures_[tow]) failures_[tow] = std::make_unique<TowMeshFailure>(TowMeshFailure{tow, message, {}});
        failures_[tow]->pairs.insert(pairs.begin(), pairs.end());
    }
    /// Throws every failure so far (TowMeshFailures), if any.
    void throwAll() const
    {
        TowMeshFailures all;
        for (const auto& f : failures_)
            if (f) all.tows.push_back(*f);
        if (!all.tows.empty()) throw all;
    }

private:
    const std::vector<IntersectionLoop>& loops_;
    const std::vector<detail::SharedLoop>& shared_;
    std::vector<std::unique_ptr<TowMeshFailure>> failures_;
};

/// Two loops of one tow pair closer than this (relative to the tow size) touch: a figure-8.
constexpr double kTouchingLoops = 1e-3;

/// One attempt of meshTowsInFrame(): loops of the tow pairs in @p excluded are left out.
/// @throws TowMeshFailures when a tow's mesh cannot be made or is not a tube.
void meshTextile(const std::vector<TowSurface>& tows, const std::vector<double>& towH, const std::vector<TowSizeField>& sizeAt,
                 const ResolveOptions& options, const std::set<TowPair>& excluded, ResolveResult& result)
{
    const std::size_t threads = workerCount(options.threads);
    const std::vector<IntersectionLoop>& loops = result.intersections.loops;

    // Shared loop nodes and each tow's constraints: loop spacing the finer of the two tows'
    // mesh sizes unless given.
    Clock::time_point t0 = Clock::now();
    const auto spacingOf = [&](const IntersectionLoop& l) {
        return options.mesh.loopSpacing > 0.0 ? options.mesh.loopSpacing : std::min(towH[l.towA()], towH[l.towB()]);
    };
    std::vector<Point3> nodes;
    // Loops that wind around a tow (it passes through the other tow, or ends inside it) cut it
    // into bands alternately inside and outside the other; a pair whose loops disagree on which
    // side is inside is left out (before anything else depends on its loops).
    std::set<TowPair> disagree;
    {
        std::map<TowPair, std::vector<std::size_t>> winding;  // (t, o) -> the loops winding around t
        for (std::size_t i = 0; i < loops.size(); ++i) {
            const IntersectionLoop& l = loops[i];
            if (!options.mesh.caps || !l.closed() || excluded.count({l.towA(), l.towB()}) ||
                (l.windsAround(LoopSide::A) && l.windsAround(LoopSide::B)))
                continue;
            if (options.cell && cellSide(l, *options.cell, 0.25 * std::min(towH[l.towA()], towH[l.towB()])) != CellSide::Inside)
                continue;  // clipped away (outside), or refused below (across a face)
            if (l.windsAround(LoopSide::A)) winding[{l.towA(), l.towB()}].push_back(i);
            if (l.windsAround(LoopSide::B)) winding[{l.towB(), l.towA()}].push_back(i);
        }
        for (const auto& [to, list] : winding)
            if (!windingBands(tows, to.first, to.second, loops, list)) disagree.insert(std::minmax(to.first, to.second));
    }
    // A loop across a face of the cell is resolved inside it: with the rank rule (the caps on the
    // face split by it too), a loop on the tubes that winds around neither tow (with a periodic
    // cell, each crossing of a max face is one of the min face's moved: crossCellFaces()).
    // With the symmetric method the region of such a loop keeps the higher-ranked tow's surface
    // (connectRegions() notes it), as the caps on the face are split by rank.
    const auto acrossRefusal = [&](const IntersectionLoop& l) -> std::string {
        if (l.windsAround(LoopSide::A) || l.windsAround(LoopSide::B))
            return "a loop that goes around a tow must not cross the cell's faces";
        // Across an end cap only outside the box (tows overlapping along their length, cut by
        // the cell inside both): no chord on a cap (both ends on one cap of a tow or its rim, one
        // beyond it) may meet the box. (A straight loop's chord may run from one cap's rim to
        // the other's: that is not on a cap.)
        const ParameterRange ra = l.surfaceA().parameterRange(), rb = l.surfaceB().parameterRange();
        const auto end = [](double u, const ParameterRange& r) { return u <= r.uMin ? -1 : u >= r.uMax ? 1 : 0; };
        const auto onCap = [&](const UV& p, const UV& q, const ParameterRange& r) {
            const int e = end(p.u, r);
            return e != 0 && e == end(q.u, r) && (p.u < r.uMin || p.u > r.uMax || q.u < r.uMin || q.u > r.uMax);
        };
        const std::vector<LoopPoint>& points = l.points();
        for (std::size_t k = 0; k < points.size(); ++k) {
            const LoopPoint& p = points[k];
            const LoopPoint& q = points[(k + 1) % points.size()];
            if ((onCap(p.onA, q.onA, ra) || onCap(p.onB, q.onB, rb)) && segmentMeetsBox(p.point, q.point, *options.cell))
                return "a loop that runs across a tow's end cap inside the cell must not cross the cell's faces";
        }
        return {};
    };
    const auto acrossSupported = [&](const IntersectionLoop& l) { return acrossRefusal(l).empty(); };
    std::set<std::size_t> acrossLoops;  // loops across a face, resolved inside the cell
    std::vector<SharedLoop> shared;
    std::set<TowPair> loopFailed;
    for (std::size_t i = 0; i < loops.size(); ++i) {
        const IntersectionLoop& l = loops[i];
        using Why = SkippedLoop::Reason;
        const CellSide inCell = options.cell ? cellSide(l, *options.cell, 0.25 * std::min(towH[l.towA()], towH[l.towB()])) : CellSide::Inside;
        if (inCell == CellSide::Outside)
            result.skippedLoops.push_back({i, Why::OutsideCell, "the loop of tows '" + l.surfaceA().name() + "' and '" +
                                                                    l.surfaceB().name() + "' lies outside the cell"});
        else if (inCell == CellSide::Across && l.closed() && !acrossSupported(l))
            throw Error(ErrorCode::InvalidArgument, "an intersection loop of tows '" + l.surfaceA().name() + "' and '" +
                                                        l.surfaceB().name() +
                                                        "' crosses (or comes within a quarter of the mesh size of) a face of the "
                                                        "cell: " + acrossRefusal(l));
        else if (!l.closed())
            result.skippedLoops.push_back({i, Why::OpenCurve, "open curve: " + l.openReason()});
        else if ((l.crossesCap(LoopSide::A) || l.crossesCap(LoopSide::B)) && !options.mesh.caps)
            result.skippedLoops.push_back({i, Why::CrossesCap, detail::crossesCapMessage(l)});
        else if (l.windsAround(LoopSide::A) && l.windsAround(LoopSide::B))
            result.skippedLoops.push_back({i, Why::AroundBothTows, "the loop goes around both tows '" + l.surfaceA().name() +
                                                                       "' and '" + l.surfaceB().name() + "'"});
        else if ((l.windsAround(LoopSide::A) || l.windsAround(LoopSide::B)) && !options.mesh.caps)
            result.skippedLoops.push_back({i, Why::AroundTowWithoutCaps,
                                           "the loop goes around tow '" +
                                               (l.windsAround(LoopSide::A) ? l.surfaceA() : l.surfaceB()).name() +
                                               "' (one tow passes through the other; resolved only with end caps)"});
        else if (disagree.count({l.towA(), l.towB()}))
            result.skippedLoops.push_back({i, Why::BandsDoNotAlternate,
                                           "the loops of tows '" + l.surfaceA().name() + "' and '" + l.surfaceB().name() +
                                               "' go around one of them but do not cut it into bands alternately inside and "
                                               "outside the other"});
        else if (!excluded.count({l.towA(), l.towB()})) {
            if (inCell == CellSide::Across) acrossLoops.insert(i);
            try {
                SharedLoop placed = shareLoopNodes(l, i, spacingOf(l), nodes);
                // Its pieces on both tows, checked here (they throw where a piece leaves a tow's
                // rectangle), so that such a loop costs its own pair only.
                constraintsOn(placed, l, LoopSide::A);
                constraintsOn(placed, l, LoopSide::B);
                // A loop whose sides come closer than its nodes follow, a sliver: a contact.
                const std::string thin = thinLoopContact(l, placed, std::min(towH[l.towA()], towH[l.towB()]));
                if (!thin.empty() && inCell == CellSide::Inside)
                    result.skippedLoops.push_back({i, Why::Contact, thin});
                else
                    shared.push_back(std::move(placed));
            } catch (const Error& e) {
                if (e.code() == ErrorCode::Cancelled) throw;
                if (loopFailed.emplace(l.towA(), l.towB()).second)
                    result.unresolved.push_back({l.towA(), l.towB(), UnresolvedPair::Reason::MeshFailed,
                                                 "the loop nodes of tows '" + l.surfaceA().name() + "' and '" + l.surfaceB().name() +
                                                     "' could not be placed: " + e.message()});
            }
        }
    }
    // A pair one of whose loops got no nodes is left out whole.
    shared.erase(std::remove_if(shared.begin(), shared.end(),
                                [&](const SharedLoop& s) { return loopFailed.count({loops[s.loop].towA(), loops[s.loop].towB()}) > 0; }),
                 shared.end());
    // Lobes of a figure-8 (one pair's loops touching where the surfaces are tangent) meet in one
    // node; loops of different pairs that cross meet in triple points, or the later pair is left
    // out.
    for (std::size_t i = 0; i < shared.size(); ++i)
        for (std::size_t j = i + 1; j < shared.size(); ++j) {
            const IntersectionLoop& li = loops[shared[i].loop];
            const IntersectionLoop& lj = loops[shared[j].loop];
            if (li.towA() != lj.towA() || li.towB() != lj.towB()) continue;
            const double within = kTouchingLoops * std::min(tows[li.towA()].towSize(), tows[li.towB()].towSize());
            joinTouchingLoops(shared[i], li, shared[j], lj, within, nodes);
        }
    const TripleJoin triples = joinAtTriplePoints(tows, loops, shared, nodes);
    dropMeetingLoops(tows, loops, shared, triples.crossing, result.unresolved);
    // A loop across a face of the cell must be resolved: else the two tows' caps overlap there.
    if (!acrossLoops.empty()) {
        std::set<std::size_t> kept;
        for (const SharedLoop& s : shared) kept.insert(s.loop);
        for (const std::size_t i : acrossLoops)
            if (!kept.count(i)) {
                const IntersectionLoop& l = loops[i];
                std::string why;
                for (const UnresolvedPair& u : result.unresolved)
                    if (std::minmax(u.towA, u.towB) == std::minmax(l.towA(), l.towB())) why = ": " + u.message;
                throw Error(ErrorCode::InvalidArgument, "an intersection loop of tows '" + l.surfaceA().name() + "' and '" +
                                                            l.surfaceB().name() + "' crosses a face of the cell but could not be resolved" +
                                                            why + " (the cell's faces must not cut an unresolved overlap)");
            }
    }
    // Where loops cross the cell's faces: nodes of the loops and of both tows' cuts there.
    std::vector<FaceCrossing> crossings;
    const auto isAcross = [&](std::size_t k) { return acrossLoops.count(shared[k].loop) > 0; };
    if (!acrossLoops.empty())
        crossings = crossCellFaces(
            tows, loops, shared, isAcross, [&](std::size_t k) { return 0.25 * spacingOf(loops[shared[k].loop]); }, *options.cell, nodes);
    // A loop whose chords only graze the box (no node of it inside) lies outside as meshed.
    if (!acrossLoops.empty())
        shared.erase(std::remove_if(shared.begin(), shared.end(),
                                    [&](const SharedLoop& s) {
                                        if (!acrossLoops.count(s.loop) ||
                                            std::any_of(s.nodes.begin(), s.nodes.end(), [&](std::size_t n) { return inCellBox(*options.cell, nodes[n]); }))
                                            return false;
                                        const IntersectionLoop& l = loops[s.loop];
                                        result.skippedLoops.push_back({s.loop, SkippedLoop::Reason::OutsideCell,
                                                                       "the loop of tows '" + l.surfaceA().name() + "' and '" +
                                                                           l.surfaceB().name() + "' lies outside the cell"});
                                        return true;
                                    }),
                     shared.end());
    // The cell's cuts of the tows: constraints of their meshes, the parts beyond them dropped.
    std::optional<CellCuts> cuts;
    if (options.cell) cuts = cutTows(tows, *options.cell, towH, nodes, crossings, sizeAt);
    constexpr std::size_t kLocal = std::size_t(1) << 60;  // marks a tow's own new nodes
    // Round 1 meshes every tow. Refinement never splits a constraint; where a triangle needs a
    // split of a loop chord or seam edge to meet the bounds, the split becomes an exact loop node
    // (both tows) or a seam station (both sides), and the next round puts it into the tows
    // concerned and refines around it. The last round's requests are not taken: its meshes are
    // consistent, a few triangles stay over the bounds (reported).
    constexpr int kMaxRounds = 6;
    // Refinements around crossings of two tows' meshes: each halves the size there (so the sag
    // falls to a quarter); a crossing left after the last is counted.
    constexpr std::size_t kFewCrossings = 16;  // plus 1 % of the smaller mesh's triangles
    constexpr int kContactPasses = 4;
    // loop node -> its shared loop(s): a figure-8's touching node belongs to both lobes
    std::multimap<std::size_t, std::size_t> sharedOf;
    for (std::size_t k = 0; k < shared.size(); ++k)
        for (std::size_t n : shared[k].nodes) sharedOf.emplace(n, k);
    std::vector<std::unique_ptr<ParametricMesher>> meshers(tows.size());
    std::vector<MeshRequests> requests(tows.size());
    const auto constraintsOf = [&](std::size_t t) {
        std::vector<LoopConstraint> c;
        for (const SharedLoop& s : shared) {
            const IntersectionLoop& l = loops[s.loop];
            for (const LoopSide side : {LoopSide::A, LoopSide::B})
                if ((side == LoopSide::A ? l.towA() : l.towB()) == t) {
                    auto pieces = constraintsOn(s, l, side);
                    if (acrossLoops.count(s.loop)) pieces = clipLoopPieces(pieces, *options.cell, nodes);  // its pieces inside
                    c.insert(c.end(), pieces.begin(), pieces.end());
                }
        }
        if (cuts)
            for (int end = 0; end < 2; ++end)
                if (cuts->cuts[t][static_cast<std::size_t>(end)]) c.push_back(cuts->constraint(t, end, tows[t].parameterRange()));
        return c;
    };
    std::vector<std::vector<double>> seamU(tows.size());
    TowFailures failures(loops, shared, tows.size());
    std::mutex meshedMutex;
    std::size_t meshed = 0;
    parallelFor(tows.size(), threads, [&](std::size_t t) {
        failures.run(t, [&] {
            throwIfCancelled(options.monitor);  // inside: TowFailures must pass it on
            MeshSizes sizes{towH[t], options.mesh.minAngle, {}, {}};
            if (t < sizeAt.size() && sizeAt[t]) sizes.sizeAt = sizeAt[t];
            if (cuts) {
                // Only what the cell keeps is meshed; nothing of a tow outside it.
                sizes.uSpan = cuts->keptSpan(t, tows[t].parameterRange());
                if (!sizes.uSpan) return;
            }
            meshers[t] = std::make_unique<ParametricMesher>(tows[t], sizes);
            meshers[t]->mesh(constraintsOf(t), {}, requests[t]);
        });
        if (!options.monitor) return;
        std::lock_guard<std::mutex> lock(meshedMutex);
        options.monitor->update("meshing tows", ++meshed, tows.size());
    });
    failures.throwAll();
    // The rounds: every split asked for is put into the tows concerned until none is asked for
    // (or kMaxRounds). Returns the tows changed.
    const auto runRounds = [&] {
        std::set<std::size_t> changed;
        int round = 1;
        for (; round < kMaxRounds; ++round) {
            // Every split asked for (by either tow) becomes an exact loop node; seam stations are
            // copied to both sides by the tow itself.
            std::vector<std::vector<ChordSplit>> splits(tows.size());
            std::vector<std::vector<double>> newSeamU(tows.size());
            std::set<std::pair<std::size_t, std::size_t>> chords;
            for (std::size_t t = 0; t < tows.size(); ++t) {
                newSeamU[t] = requests[t].seamU;
                seamU[t].insert(seamU[t].end(), requests[t].seamU.begin(), requests[t].seamU.end());
                for (const MeshRequests::OnLoop& q : requests[t].onLoop)
                    chords.emplace(std::min(q.a, q.b), std::max(q.a, q.b));
            }
            for (const auto& [a, b] : chords) {
                // The loop this chord belongs to: of the loops through node a, the one where b follows.
                std::size_t k = shared.size();
                const auto range = sharedOf.equal_range(a);
                for (auto it = range.first; it != range.second && k == shared.size(); ++it)
                    if (splitChord(loops[shared[it->second].loop], shared[it->second], a, b, 0.5, nodes)) k = it->second;
                if (k == shared.size()) continue;
                SharedLoop& s = shared[k];
                const std::size_t node = nodes.size() - 1;
                sharedOf.emplace(node, k);
                const LoopPoint& p = s.points[static_cast<std::size_t>(std::find(s.nodes.begin(), s.nodes.end(), node) - s.nodes.begin())];
                const IntersectionLoop& l = loops[s.loop];
                // A node on a tow's cap is not in its tube's mesh: the cap takes it when meshed.
                const auto onTube = [](const TowSurface& t, const UV& uv) {
                    const ParameterRange r = t.parameterRange();
                    return uv.u >= r.uMin && uv.u <= r.uMax;
                };
                if (onTube(tows[l.towA()], p.onA)) splits[l.towA()].push_back({a, b, node, p.onA});
                if (onTube(tows[l.towB()], p.onB)) splits[l.towB()].push_back({a, b, node, p.onB});
            }
            std::vector<std::size_t> busy;
            for (std::size_t t = 0; t < tows.size(); ++t)
                if (meshers[t] && (!splits[t].empty() || !newSeamU[t].empty())) busy.push_back(t);
            if (busy.empty()) break;
            changed.insert(busy.begin(), busy.end());
            for (std::size_t t : busy) requests[t] = {};
            parallelFor(busy.size(), threads, [&](std::size_t k) {
                throwIfCancelled(options.monitor);
                const std::size_t t = busy[k];
                failures.run(t, [&] {
                    if (!meshers[t]->split(splits[t], newSeamU[t], requests[t])) {
                        requests[t] = {};
                        meshers[t]->mesh(constraintsOf(t), seamU[t], requests[t]);
                    }
                });
            });
            failures.throwAll();
        }
        result.meshRounds = std::max(result.meshRounds, static_cast<std::size_t>(round));
        return changed;
    };
    runRounds();
    // The final meshes, and the tows' own nodes evaluated on their surfaces. Where two tows'
    // meshes cross (a chord's sag deeper than the gap between the surfaces: next to a loop where
    // they meet at a shallow angle, or where they nearly touch), both are refined around the
    // crossing and the rounds run again, up to kContactPasses times.
    std::vector<ParametricMesh> meshes(tows.size());
    std::vector<std::vector<Point3>> ownNodes(tows.size());
    // Pairs left unresolved pass through each other: their crossings are not the chords' sag.
    std::set<TowPair> ignored(excluded);
    for (const UnresolvedPair& u : result.unresolved) ignored.insert(std::minmax(u.towA, u.towB));
    for (const SkippedLoop& k : result.skippedLoops)
        if (k.reason != SkippedLoop::Reason::OutsideCell && k.reason != SkippedLoop::Reason::Contact)
            ignored.insert(std::minmax(loops[k.loop].towA(), loops[k.loop].towB()));
    // So do tows that coincide, lie one inside the other, or whose search for loops stopped (a
    // contact along a line stays: its meshes must not cross either).
    for (const PairFinding& f : result.intersections.findings)
        if (f.kind != PairFinding::Kind::Contact) ignored.insert(std::minmax(f.towA, f.towB));
    std::map<TowPair, std::size_t> lastCrossings;  // each pair's crossing triangle pairs in the last pass
    std::set<std::size_t> stale;  // tows whose mesh changed since it was taken
    for (std::size_t t = 0; t < tows.size(); ++t)
        if (meshers[t]) stale.insert(t);  // (none outside the cell)
    // The caps as they would be made now, checked with the tubes: a loop that dips onto a cap
    // meets the other tow's tube there at a shallow angle too.
    std::vector<CapMesh> caps(options.mesh.caps ? tows.size() : 0);
    std::vector<std::vector<CapConstraint>> capPaths(tows.size());
    std::vector<std::array<bool, 2>> cutEnds(tows.size(), {false, false});
    if (cuts)
        for (std::size_t t = 0; t < tows.size(); ++t) cutEnds[t] = {cuts->cuts[t][0].has_value(), cuts->cuts[t][1].has_value()};
    for (int pass = 0;; ++pass) {
        if (!caps.empty()) {
            // (They change as loop chords are split: a changed cap is tested again.)
            std::vector<std::vector<CapConstraint>> paths = capConstraintsOfTows(shared, loops, tows.size());
            for (std::size_t t = 0; t < tows.size(); ++t)
                if (meshers[t] && paths[t] != capPaths[t]) stale.insert(t);
            capPaths = std::move(paths);
        }
        const std::vector<std::size_t> todo(stale.begin(), stale.end());
        parallelFor(todo.size(), threads, [&](std::size_t k) {
            throwIfCancelled(options.monitor);
            const std::size_t t = todo[k];
            meshes[t] = meshers[t]->result(kLocal);
            if (cuts) keepInCell(meshes[t], *cuts, t);
            ownNodes[t].clear();
            ownNodes[t].reserve(meshes[t].newNodes.size());
            for (const UV& p : meshes[t].newNodes) ownNodes[t].push_back(tows[t].point(p.u, p.v));
            if (caps.empty()) return;
            const NodeAt at = [&](std::size_t n) -> const Point3& { return n < kLocal ? nodes[n] : ownNodes[t][n - kLocal]; };
            caps[t] = provisionalCaps(tows[t], towH[t], options.mesh.minAngle, meshes[t].triangles, at, capPaths[t],
                                      kLocal + ownNodes[t].size(), cuts ? &cuts->cutNode : nullptr, &cutEnds[t]);
        });
        // A pair is refined while its crossings are few (the chords' sag along a loop or a near
        // contact) and fall from pass to pass; many, or not falling, the tows pass through each
        // other there (a loop missing): counted, left as they are.
        const auto refinePair = [&](const TowPair& p, std::size_t count) {
            const std::size_t fewer = std::min(meshes[p.first].triangles.size(), meshes[p.second].triangles.size());
            const auto last = lastCrossings.find(p);
            return count <= kFewCrossings + fewer / 100 && (last == lastCrossings.end() || count < last->second);
        };
        // After the first pass only pairs with a tow changed are tested again; the others keep
        // their count (they were not refined).
        std::set<TowPair> untested(ignored);
        std::map<TowPair, std::size_t> kept;
        if (pass > 0)
            for (std::size_t a = 0; a < tows.size(); ++a)
                for (std::size_t b = a + 1; b < tows.size(); ++b)
                    if (!stale.count(a) && !stale.count(b)) {
                        untested.insert({a, b});
                        if (const auto it = lastCrossings.find({a, b}); it != lastCrossings.end()) kept.insert(*it);
                    }
        const CrossingSpots crossing = crossingSpots(nodes, meshes, ownNodes, kLocal, caps, untested, refinePair, threads);
        lastCrossings = crossing.crossingPairs;
        lastCrossings.insert(kept.begin(), kept.end());
        result.crossingTrianglePairs = 0;
        for (const auto& [pair, count] : lastCrossings) result.crossingTrianglePairs += count;
        if (pass == kContactPasses || std::all_of(crossing.spots.begin(), crossing.spots.end(), [](const auto& v) { return v.empty(); })) break;
        stale.clear();
        for (std::size_t t = 0; t < tows.size(); ++t)
            if (!crossing.spots[t].empty()) stale.insert(t);
        const std::vector<std::size_t> refined(stale.begin(), stale.end());
        parallelFor(refined.size(), threads, [&](std::size_t k) {
            throwIfCancelled(options.monitor);
            const std::size_t t = refined[k];
            failures.run(t, [&] {
                requests[t] = {};
                meshers[t]->refineAround(crossing.spots[t], requests[t]);
            });
        });
        failures.throwAll();
        const std::set<std::size_t> changed = runRounds();
        stale.insert(changed.begin(), changed.end());
    }
    std::vector<std::vector<Vector3>> fibre(tows.size());  // per mesher triangle (then caps)
    parallelFor(tows.size(), threads, [&](std::size_t t) {
        if (!meshers[t]) return;
        meshers[t].reset();
        fibre[t] = fibreDirections(tows[t], meshes[t].centroids);
    });
    // Per tow, the (u,v) of every node on its own surface: its own nodes and its loops' nodes.
    // (Sorted by node once all are in; a node in several loops, as a triple point, keeps one.)
    std::vector<std::vector<std::pair<std::size_t, UV>>> uvOn(tows.size());
    for (const SharedLoop& s : shared) {
        const IntersectionLoop& l = loops[s.loop];
        for (std::size_t k = 0; k < s.nodes.size(); ++k) {
            uvOn[l.towA()].emplace_back(s.nodes[k], inPeriod(s.points[k].onA, tows[l.towA()].parameterRange()));
            uvOn[l.towB()].emplace_back(s.nodes[k], inPeriod(s.points[k].onB, tows[l.towB()].parameterRange()));
        }
    }
    if (cuts)
        for (std::size_t t = 0; t < tows.size(); ++t)
            for (const auto& cut : cuts->cuts[t])
                if (cut)
                    for (std::size_t k = 0; k < cut->nodes.size(); ++k) uvOn[t].emplace_back(cut->nodes[k], cut->uv[k]);
    for (std::size_t t = 0; t < tows.size(); ++t) {
        const std::size_t base = nodes.size();
        for (std::size_t k = 0; k < meshes[t].newNodes.size(); ++k)
            uvOn[t].emplace_back(base + k, inPeriod(meshes[t].newNodes[k], tows[t].parameterRange()));
        nodes.insert(nodes.end(), ownNodes[t].begin(), ownNodes[t].end());
        for (Triangle& tri : meshes[t].triangles)
            for (std::size_t& n : tri)
                if (n >= kLocal) n = base + (n - kLocal);
        for (SharpCorner& c : meshes[t].sharpCorners) {
            if (c.node >= kLocal) c.node = base + (c.node - kLocal);
            for (Triangle& tri : c.triangles)
                for (std::size_t& n : tri)
                    if (n >= kLocal) n = base + (n - kLocal);
        }
        result.quality.facesOverBounds += meshes[t].badFaces;
    }
    // Every tow's own mesh is a tube (the mesher's rectangle closed across the seam); closed by
    // its end caps before the regions are made, so that a cap inside another tow is shared too.
    std::vector<std::vector<TowFace>> faceOf(tows.size());
    for (std::size_t t = 0; t < tows.size(); ++t) faceOf[t].assign(meshes[t].triangles.size(), TowFace::Side);
    if (options.mesh.caps) {
        capPaths = capConstraintsOfTows(shared, loops, tows.size());  // loop pieces on each tow's caps
        std::vector<std::string> capFailed(tows.size());
        closeEnds(tows, towH, options.mesh.minAngle, threads, meshes, faceOf, nodes, capPaths, &capFailed,
                  cuts ? &cuts->cutNode : nullptr, &cutEnds);
        // A cap that could not be meshed with loop pieces on it costs the pairs of those loops.
        for (std::size_t t = 0; t < tows.size(); ++t) {
            if (capFailed[t].empty()) continue;
            std::set<TowPair> pairs;
            for (const SharedLoop& s : shared) {
                const IntersectionLoop& l = loops[s.loop];
                if ((l.towA() == t && l.crossesCap(LoopSide::A)) || (l.towB() == t && l.crossesCap(LoopSide::B))) pairs.emplace(l.towA(), l.towB());
            }
            if (pairs.empty())  // no loop across that cap: every pair with loops on the tow
                failures.run(t, [&] { throw Error(ErrorCode::Internal, capFailed[t]); });
            else
                failures.fail(t, capFailed[t], pairs);
        }
        failures.throwAll();
    }
    for (std::size_t t = 0; t < tows.size(); ++t) appendCapDirections(tows[t], faceOf[t], fibre[t]);
    // The cell's faces meshed around the cuts: each tow's caps there, the rest the matrix's.
    std::optional<CellFaces> cellFaces;
    if (cuts) {
        cellFaces = meshCellFaces(tows, *options.cell, *cuts, cellFaceSize(*options.cell, towH), options.mesh.minAngle, nodes,
                                  towRanks(tows, options.primaryPatterns));
        for (std::size_t t = 0; t < tows.size(); ++t)
            for (int end = 0; end < 2; ++end) {
                const auto& cut = cuts->cuts[t][static_cast<std::size_t>(end)];
                if (!cut) continue;
                const Vector3 along = meanFibreDirection(tows[t], cut->uv);
                for (const Triangle& tri : cellFaces->caps[t][static_cast<std::size_t>(end)]) {
                    meshes[t].triangles.push_back(tri);
                    faceOf[t].push_back(end == 0 ? TowFace::Start : TowFace::End);
                    fibre[t].push_back(along);
                }
            }
    }

    // The stage's result: every tow's own closed mesh over the global nodes, each of its nodes on
    // its surface with its (u,v) there, and the loops it was made with.
    TextileMesh& out = result.mesh;
    out.nodes = std::move(nodes);
    out.tows.resize(tows.size());
    parallelFor(tows.size(), threads, [&](std::size_t t) {
        TowMesh& m = out.tows[t];
        m.name = tows[t].name();
        m.triangles = std::move(meshes[t].triangles);
        m.region.assign(m.triangles.size(), -1);
        m.face = std::move(faceOf[t]);
        m.fibreDirection = std::move(fibre[t]);
        std::vector<std::pair<std::size_t, UV>>& on = uvOn[t];
        std::stable_sort(on.begin(), on.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        on.erase(std::unique(on.begin(), on.end(), [](const auto& a, const auto& b) { return a.first == b.first; }), on.end());
        m.parameters = std::move(on);
    });
    for (const SharedLoop& s : shared) out.loops.push_back({s.loop, s.nodes});
    for (std::size_t t = 0; t < tows.size(); ++t)
        for (SharpCorner& c : meshes[t].sharpCorners) {
            c.tow = t;
            out.sharpCorners.push_back(std::move(c));
        }
    if (cellFaces) {
        out.cell = std::move(cellFaces->mesh);
        for (std::size_t t = 0; t < tows.size(); ++t)
            for (int end = 0; end < 2; ++end)
                if (const auto& cut = cuts->cuts[t][static_cast<std::size_t>(end)]) out.tows[t].cutAt[static_cast<std::size_t>(end)] = cut->face;
    }
    out.triplePoints = triples.points;
    keepResolvedTriplePoints(out, loops);  // not those of a pair left out since (LoopsMeet)
    keepUsedNodes(out);
    // Every tow's own mesh must be closed (a tube open at its two ends without caps), oriented
    // and 2-manifold before any region is made of it.
    const std::size_t ends = options.mesh.caps ? 0 : 2;
    result.tows.resize(tows.size());
    std::vector<std::size_t> badEdges(tows.size(), 0);
    parallelFor(tows.size(), threads, [&](std::size_t t) {
        TowResolution& r = result.tows[t];
        const auto& triangles = out.tows[t].triangles;
        const SurfaceFigures f = surfaceFigures(out.nodes, triangles);
        r.volumeBefore = r.volumeAfter = f.volume;
        r.area = f.area;
        r.boundaryLoops = f.boundaryLoops;
        badEdges[t] = f.badEdges;
        r.pieces = connectedPieces(triangles);
        r.meshSize = towH[t];
    });
    for (std::size_t t = 0; t < tows.size(); ++t)
        if (badEdges[t] != 0 || result.tows[t].boundaryLoops != ends)
            failures.run(t, [&] { throw Error(ErrorCode::Internal, notClosedMessage(options.mesh.caps, badEdges[t], result.tows[t].boundaryLoops)); });
    failures.throwAll();
    const std::size_t overBounds = result.quality.facesOverBounds;
    result.quality = meshQuality(out, surfaceAngleBound(options.mesh.minAngle));
    result.quality.facesOverBounds = overBounds;
    result.timings.mesh = msSince(t0);
}

}  // namespace

ResolveResult meshTowsInFrame(const std::vector<TowSurface>& tows, const std::vector<double>& towH, const ResolveOptions& options,
                              const IntersectionReport& report, const std::vector<TowSizeField>& sizeAt)
{
    std::set<TowPair> excluded;
    std::vector<UnresolvedPair> unresolved;
    for (;;) {
        ResolveResult attempt;
        attempt.intersections = report;
        try {
            meshTextile(tows, towH, sizeAt, options, excluded, attempt);
        } catch (const TowMeshFailures& failed) {
            // Every pair with loops on a failed tow is left out; the rest is meshed again.
            std::size_t left = 0;
            for (const TowMeshFailure& f : failed.tows) {
                if (f.pairs.empty()) throw Error(ErrorCode::Internal, f.message, "tow '" + tows[f.tow].name() + "'");
                for (const TowPair& p : f.pairs) {
                    if (!excluded.insert(p).second) continue;
                    ++left;
                    unresolved.push_back({p.first, p.second, UnresolvedPair::Reason::MeshFailed,
                                          "tow '" + tows[f.tow].name() + "' could not be meshed with the loops of tows '" +
                                              tows[p.first].name() + "' and '" + tows[p.second].name() + "': " + f.message});
                }
            }
            // A pair whose loop crosses a face of the cell cannot be left out (its caps would
            // overlap there).
            if (options.cell)
                for (const TowMeshFailure& f : failed.tows)
                    for (const IntersectionLoop& l : report.loops)
                        if (f.pairs.count(std::minmax(l.towA(), l.towB())) && l.closed() &&
                            cellSide(l, *options.cell, 0.25 * std::min(towH[l.towA()], towH[l.towB()])) == CellSide::Across)
                            throw Error(ErrorCode::InvalidArgument, "tow '" + tows[f.tow].name() + "' could not be meshed with the loops of tows '" +
                                                                        l.surfaceA().name() + "' and '" + l.surfaceB().name() + "', one of which crosses a face of the cell (the cell's faces must not cut an unresolved overlap): " + f.message);
            sayStage(options, "meshing again without the " + std::to_string(left) + " tow pair(s) on " +
                                          std::to_string(failed.tows.size()) + " tow(s) whose mesh failed");
            continue;
        }
        attempt.unresolved.insert(attempt.unresolved.end(), unresolved.begin(), unresolved.end());
        return attempt;
    }
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
