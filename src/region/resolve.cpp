#include "towgeom/resolve.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iterator>
#include <map>
#include <memory>
#include <optional>
#include <mutex>
#include <set>
#include <tuple>
#include <sstream>

#include "core/glob_match.hpp"
#include "core/parallel.hpp"
#include "core/progress_report.hpp"
#include "intersect/textile_frame.hpp"
#include "mesh/end_caps.hpp"
#include "mesh/loop_nodes.hpp"
#include "mesh/mesh_measures.hpp"
#include "mesh/parametric_mesher.hpp"
#include "region/connected_region.hpp"
#include "region/triple_points.hpp"
#include "region/winding_loops.hpp"
#include "surface/fibre_directions.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

using Clock = std::chrono::steady_clock;
using Triangle = std::array<std::size_t, 3>;

double msSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

bool matchesAny(const std::string& name, const std::vector<std::string>& patterns)
{
    return std::any_of(patterns.begin(), patterns.end(),
                       [&](const std::string& p) { return detail::globMatch(p, name); });
}

double triangleArea(const std::vector<Point3>& nodes, const Triangle& t)
{
    return 0.5 * norm(cross(nodes[t[1]] - nodes[t[0]], nodes[t[2]] - nodes[t[0]]));
}

double smallestAngle(const std::vector<Point3>& nodes, const Triangle& t)
{
    double best = 180.0;
    for (int k = 0; k < 3; ++k) {
        const Vector3 a = nodes[t[(k + 1) % 3]] - nodes[t[k]], b = nodes[t[(k + 2) % 3]] - nodes[t[k]];
        const double c = dot(a, b) / (norm(a) * norm(b));
        best = std::min(best, std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / 3.14159265358979323846);
    }
    return best;
}

Triangle reversed(const Triangle& t) { return {t[0], t[2], t[1]}; }

/// @p p with v moved into the period [vMin, vMax) by whole periods.
UV inPeriod(UV p, const ParameterRange& r)
{
    p.v = r.vMin + std::fmod(p.v - r.vMin, r.vPeriod());
    if (p.v < r.vMin) p.v += r.vPeriod();
    if (p.v >= r.vMax) p.v = r.vMin;
    return p;
}

void checkOptions(const ResolveOptions& o)
{
    const MeshOptions& m = o.mesh;
    const auto nonNegative = [](double x) { return x >= 0.0 && std::isfinite(x); };
    if (!nonNegative(m.edgeLength)) throw Error(ErrorCode::InvalidArgument, "mesh edge length must be >= 0 and finite");
    if (!(m.relativeEdgeLength > 0.0 && std::isfinite(m.relativeEdgeLength)))
        throw Error(ErrorCode::InvalidArgument, "relative mesh edge length must be > 0 and finite");
    if (!(m.minAngle > 0.0 && m.minAngle <= 30.0))
        throw Error(ErrorCode::InvalidArgument, "minimum angle must lie in (0, 30] degrees");
    if (!nonNegative(m.loopSpacing)) throw Error(ErrorCode::InvalidArgument, "loop spacing must be >= 0 and finite");
    if (m.maxTriangles == 0) throw Error(ErrorCode::InvalidArgument, "the triangle limit must be at least 1");
}

/// Reports stage @p what to the Progress and the deprecated callback of @p options, then throws
/// Error(Cancelled) if cancelled.
void say(const ResolveOptions& options, const std::string& what)
{
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"  // ResolveOptions::progress, until 0.3
    detail::reportStage(options.monitor, options.progress, what, 0, 0);
#pragma GCC diagnostic pop
}

/// Triangles the mesher makes per equilateral triangle of side h in the same area: it keeps
/// every edge below h in 3D, so its triangles are smaller (2.55 on the bundled twill, 2.97 on a
/// straight tube, for h from 0.02 to 0.1 of their size).
constexpr double kTrianglesPerEquilateral = 3.0;
/// Extra triangles per unit of loop length / loop spacing when the loop spacing s is below h
/// (both tows, both sides of the loop, graded from s to h): 17 to 19 on the bundled twill at
/// h = 0.1, s = 0.01 to 0.003.
constexpr double kTrianglesPerLoopNode = 20.0;

/// Refuses (ErrorCode::TooLarge) meshes whose estimated triangle count is over the limit: the
/// tows' area in triangles of side h, plus the refinement along loops of length
/// @p loopLength at a spacing below h.
void checkMeshSize(const MeshOptions& m, double area, double h, double loopLength, double spacing)
{
    const double equilateral = std::sqrt(3.0) / 4.0 * h * h;
    double estimate = kTrianglesPerEquilateral * area / equilateral;
    std::ostringstream how;
    how.precision(3);
    how << kTrianglesPerEquilateral << " x the tows' area " << area << " / (sqrt(3)/4 h^2) at mesh size h = " << h;
    if (spacing < h && loopLength > 0.0) {
        estimate += kTrianglesPerLoopNode * loopLength * (1.0 / spacing - 1.0 / h);
        how << ", plus " << kTrianglesPerLoopNode << " x the loops' length " << loopLength << " x (1/s - 1/h) at loop spacing s = "
            << spacing;
    }
    if (!(estimate > static_cast<double>(m.maxTriangles))) return;
    std::ostringstream message;
    message.precision(3);
    message << "the meshes would have about " << estimate << " triangles (" << how.str() << "), over the limit of "
            << m.maxTriangles << " (MeshOptions::maxTriangles); refused before meshing";
    throw Error(ErrorCode::TooLarge, message.str());
}

}  // namespace

double MeshQuality::fractionAtLeast(double degrees) const
{
    if (triangles == 0) return 1.0;
    std::size_t below = 0;
    for (std::size_t b = 0; b < histogram.size(); ++b)
        if (5.0 * static_cast<double>(b + 1) <= degrees) below += histogram[b];
    return 1.0 - static_cast<double>(below) / static_cast<double>(triangles);
}

namespace {

using TowPair = std::pair<std::size_t, std::size_t>;

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

/// Each tow's rank (0 first): tows whose name matches a primary pattern, then the others, each
/// in input order. A tow gives way to every tow ranked above it.
std::vector<std::size_t> towRanks(const std::vector<TowSurface>& tows, const std::vector<std::string>& primaryPatterns)
{
    std::vector<std::size_t> order(tows.size());
    for (std::size_t t = 0; t < tows.size(); ++t) order[t] = t;
    std::stable_partition(order.begin(), order.end(), [&](std::size_t t) { return matchesAny(tows[t].name(), primaryPatterns); });
    std::vector<std::size_t> rank(tows.size());
    for (std::size_t r = 0; r < order.size(); ++r) rank[order[r]] = r;
    return rank;
}

/// Loops of different tow pairs that meet on a tow: three tows overlap there. The rank rule
/// resolves them when they meet only in triple points (nodes of the three loops) or lie one inside
/// the other, and the third pair has loops resolved too. Otherwise the later pair (by tow indices)
/// is left out (LoopsMeet), its loops removed from @p shared; pairs that relied on it follow.
void dropMeetingLoops(const std::vector<TowSurface>& tows, const std::vector<IntersectionLoop>& loops,
                      std::vector<detail::SharedLoop>& shared, const std::vector<detail::CrossingLoops>& crossing,
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
    for (const detail::CrossingLoops& c : crossing) {
        const TowPair p = pairOf(c.first), q = pairOf(c.second);
        if (!dropped.count(p) && !dropped.count(q))
            drop(p, q, c.tow, "crosses",
                 "the loops do not meet in a point of the three tows' surfaces there (the third pair has no resolved loop "
                 "through it, or the point was not found)");
    }
    const auto sideOn = [&](std::size_t k, std::size_t tow) { return loops[shared[k].loop].towA() == tow ? LoopSide::A : LoopSide::B; };
    const auto meetOn = [&](std::size_t a, std::size_t b, std::size_t tow) {
        return detail::loopsMeet(detail::loopPolygon(shared[a], sideOn(a, tow)), detail::loopPolygon(shared[b], sideOn(b, tow)),
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
                                [&](const detail::SharedLoop& s) {
                                    return dropped.count({loops[s.loop].towA(), loops[s.loop].towB()}) > 0;
                                }),
                 shared.end());
}

/// Stages 2 and 3 of resolveTextile() on tows already in a normalised frame, with options in the
/// frame's units (the mesh size set): @p result holds the intersections; loops of the tow pairs
/// in @p excluded are left out.
/// @throws TowMeshFailure when a tow's mesh cannot be made or is not a tube.
void meshAndConnect(const std::vector<TowSurface>& tows, const std::vector<double>& towH, const ResolveOptions& options,
                    const std::set<TowPair>& excluded, ResolveResult& result)
{
    const std::size_t threads = detail::workerCount(options.threads);
    const std::vector<IntersectionLoop>& loops = result.intersections.loops;

    // 2. Shared loop nodes and each tow's constraints: loop spacing the finer of the two tows'
    // mesh sizes unless given.
    Clock::time_point t0 = Clock::now();
    const auto spacingOf = [&](const IntersectionLoop& l) {
        return options.mesh.loopSpacing > 0.0 ? options.mesh.loopSpacing : std::min(towH[l.towA()], towH[l.towB()]);
    };
    std::vector<Point3> nodes;
    // Loops that wind around a tow (it passes through the other tow, or ends inside it) cut it
    // into bands alternately inside and outside the other; a pair whose loops disagree on which
    // side is inside is left out (before anything else depends on its loops).
    std::map<TowPair, detail::WindingBands> bands;  // (t, o) -> the bands of t
    std::set<TowPair> disagree;
    {
        std::map<TowPair, std::vector<std::size_t>> winding;  // (t, o) -> the loops winding around t
        for (std::size_t i = 0; i < loops.size(); ++i) {
            const IntersectionLoop& l = loops[i];
            if (!options.mesh.caps || !l.closed() || excluded.count({l.towA(), l.towB()}) ||
                (l.windsAround(LoopSide::A) && l.windsAround(LoopSide::B)))
                continue;
            if (l.windsAround(LoopSide::A)) winding[{l.towA(), l.towB()}].push_back(i);
            if (l.windsAround(LoopSide::B)) winding[{l.towB(), l.towA()}].push_back(i);
        }
        for (const auto& [to, list] : winding) {
            std::optional<detail::WindingBands> b = detail::windingBands(tows, to.first, to.second, loops, list);
            if (b)
                bands.emplace(to, std::move(*b));
            else
                disagree.insert(std::minmax(to.first, to.second));
        }
        for (const TowPair& p : disagree) {
            bands.erase(p);
            bands.erase({p.second, p.first});
        }
    }
    std::vector<detail::SharedLoop> shared;
    for (std::size_t i = 0; i < loops.size(); ++i) {
        const IntersectionLoop& l = loops[i];
        using Why = SkippedLoop::Reason;
        if (!l.closed())
            result.skippedLoops.push_back({i, Why::OpenCurve, "open curve: " + l.openReason()});
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
        else if (!excluded.count({l.towA(), l.towB()}))
            shared.push_back(detail::shareLoopNodes(l, i, spacingOf(l), nodes));
    }
    // Lobes of a figure-8 (one pair's loops touching where the surfaces are tangent) meet in one
    // node; loops of different pairs that cross meet in triple points, or the later pair is left
    // out.
    for (std::size_t i = 0; i < shared.size(); ++i)
        for (std::size_t j = i + 1; j < shared.size(); ++j) {
            const IntersectionLoop& li = loops[shared[i].loop];
            const IntersectionLoop& lj = loops[shared[j].loop];
            if (li.towA() != lj.towA() || li.towB() != lj.towB()) continue;
            const double within = kTouchingLoops * std::min(tows[li.towA()].towSize(), tows[li.towB()].towSize());
            detail::joinTouchingLoops(shared[i], li, shared[j], lj, within, nodes);
        }
    const detail::TripleJoin triples = detail::joinAtTriplePoints(tows, loops, shared, nodes);
    dropMeetingLoops(tows, loops, shared, triples.crossing, result.unresolved);
    constexpr std::size_t kLocal = std::size_t(1) << 60;  // marks a tow's own new nodes
    // Round 1 meshes every tow. Refinement never splits a constraint; where a triangle needs a
    // split of a loop chord or seam edge to meet the bounds, the split becomes an exact loop node
    // (both tows) or a seam station (both sides), and the next round puts it into the tows
    // concerned and refines around it. The last round's requests are not taken: its meshes are
    // consistent, a few triangles stay over the bounds (reported).
    constexpr int kMaxRounds = 6;
    // loop node -> its shared loop(s): a figure-8's touching node belongs to both lobes
    std::multimap<std::size_t, std::size_t> sharedOf;
    for (std::size_t k = 0; k < shared.size(); ++k)
        for (std::size_t n : shared[k].nodes) sharedOf.emplace(n, k);
    std::vector<std::unique_ptr<detail::ParametricMesher>> meshers(tows.size());
    std::vector<detail::MeshRequests> requests(tows.size());
    const auto constraintsOf = [&](std::size_t t) {
        std::vector<detail::LoopConstraint> c;
        for (const detail::SharedLoop& s : shared) {
            const IntersectionLoop& l = loops[s.loop];
            for (const LoopSide side : {LoopSide::A, LoopSide::B})
                if ((side == LoopSide::A ? l.towA() : l.towB()) == t) {
                    auto pieces = detail::constraintsOn(s, l, side);
                    c.insert(c.end(), pieces.begin(), pieces.end());
                }
        }
        return c;
    };
    std::vector<std::vector<double>> seamU(tows.size());
    TowFailures failures(loops, shared, tows.size());
    std::mutex meshedMutex;
    std::size_t meshed = 0;
    detail::parallelFor(tows.size(), threads, [&](std::size_t t) {
        failures.run(t, [&] {
            detail::throwIfCancelled(options.monitor);  // inside: TowFailures must pass it on
            meshers[t] = std::make_unique<detail::ParametricMesher>(tows[t], detail::MeshSizes{towH[t], options.mesh.minAngle, {}});
            meshers[t]->mesh(constraintsOf(t), {}, requests[t]);
        });
        if (!options.monitor) return;
        std::lock_guard<std::mutex> lock(meshedMutex);
        options.monitor->update("meshing tows", ++meshed, tows.size());
    });
    failures.throwAll();
    int round = 1;
    for (; round < kMaxRounds; ++round) {
        // Every split asked for (by either tow) becomes an exact loop node; seam stations are
        // copied to both sides by the tow itself.
        std::vector<std::vector<detail::ChordSplit>> splits(tows.size());
        std::vector<std::vector<double>> newSeamU(tows.size());
        std::set<std::pair<std::size_t, std::size_t>> chords;
        for (std::size_t t = 0; t < tows.size(); ++t) {
            newSeamU[t] = requests[t].seamU;
            seamU[t].insert(seamU[t].end(), requests[t].seamU.begin(), requests[t].seamU.end());
            for (const detail::MeshRequests::OnLoop& q : requests[t].onLoop)
                chords.emplace(std::min(q.a, q.b), std::max(q.a, q.b));
        }
        for (const auto& [a, b] : chords) {
            // The loop this chord belongs to: of the loops through node a, the one where b follows.
            std::size_t k = shared.size();
            const auto range = sharedOf.equal_range(a);
            for (auto it = range.first; it != range.second && k == shared.size(); ++it)
                if (detail::splitChord(loops[shared[it->second].loop], shared[it->second], a, b, 0.5, nodes)) k = it->second;
            if (k == shared.size()) continue;
            detail::SharedLoop& s = shared[k];
            const std::size_t node = nodes.size() - 1;
            sharedOf.emplace(node, k);
            const LoopPoint& p = s.points[static_cast<std::size_t>(std::find(s.nodes.begin(), s.nodes.end(), node) - s.nodes.begin())];
            const IntersectionLoop& l = loops[s.loop];
            splits[l.towA()].push_back({a, b, node, p.onA});
            splits[l.towB()].push_back({a, b, node, p.onB});
        }
        std::vector<std::size_t> busy;
        for (std::size_t t = 0; t < tows.size(); ++t)
            if (!splits[t].empty() || !newSeamU[t].empty()) busy.push_back(t);
        if (busy.empty()) break;
        for (std::size_t t : busy) requests[t] = {};
        detail::parallelFor(busy.size(), threads, [&](std::size_t k) {
            detail::throwIfCancelled(options.monitor);
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
    result.meshRounds = static_cast<std::size_t>(round);
    // The final meshes, and the tows' own nodes evaluated on their surfaces.
    std::vector<detail::ParametricMesh> meshes(tows.size());
    std::vector<std::vector<Point3>> ownNodes(tows.size());
    std::vector<std::vector<Vector3>> fibre(tows.size());  // per mesher triangle (then caps)
    detail::parallelFor(tows.size(), threads, [&](std::size_t t) {
        detail::throwIfCancelled(options.monitor);
        meshes[t] = meshers[t]->result(kLocal);
        meshers[t].reset();
        ownNodes[t].reserve(meshes[t].newNodes.size());
        for (const UV& p : meshes[t].newNodes) ownNodes[t].push_back(tows[t].point(p.u, p.v));
        fibre[t] = detail::fibreDirections(tows[t], meshes[t].centroids);
    });
    // Per tow, the (u,v) of every node on its own surface: its own nodes and its loops' nodes.
    // (Sorted by node once all are in; a node in several loops, as a triple point, keeps one.)
    std::vector<std::vector<std::pair<std::size_t, UV>>> uvOn(tows.size());
    for (const detail::SharedLoop& s : shared) {
        const IntersectionLoop& l = loops[s.loop];
        for (std::size_t k = 0; k < s.nodes.size(); ++k) {
            uvOn[l.towA()].emplace_back(s.nodes[k], inPeriod(s.points[k].onA, tows[l.towA()].parameterRange()));
            uvOn[l.towB()].emplace_back(s.nodes[k], inPeriod(s.points[k].onB, tows[l.towB()].parameterRange()));
        }
    }
    for (std::size_t t = 0; t < tows.size(); ++t) {
        const std::size_t base = nodes.size();
        for (std::size_t k = 0; k < meshes[t].newNodes.size(); ++k)
            uvOn[t].emplace_back(base + k, inPeriod(meshes[t].newNodes[k], tows[t].parameterRange()));
        nodes.insert(nodes.end(), ownNodes[t].begin(), ownNodes[t].end());
        for (Triangle& tri : meshes[t].triangles)
            for (std::size_t& n : tri)
                if (n >= kLocal) n = base + (n - kLocal);
        result.quality.facesOverBounds += meshes[t].badFaces;
    }
    // Every tow's own mesh is a tube (the mesher's rectangle closed across the seam); closed by
    // its end caps before the regions are made, so that a cap inside another tow is shared too.
    std::vector<std::vector<TowFace>> faceOf(tows.size());
    for (std::size_t t = 0; t < tows.size(); ++t) faceOf[t].assign(meshes[t].triangles.size(), TowFace::Side);
    if (options.mesh.caps) detail::closeEnds(tows, towH, options.mesh.minAngle, threads, meshes, faceOf, nodes);
    for (std::size_t t = 0; t < tows.size(); ++t) detail::appendCapDirections(tows[t], faceOf[t], fibre[t]);
    result.timings.mesh = msSince(t0);

    // 3. Connected regions, by rank: every tow minus the tows ranked above it. A triangle of tow
    // t lies inside tow o when it is inside an odd number of the loops of (t, o) on t (a loop
    // nested in one of the same pair bounds an island). It is removed when it lies inside a tow
    // ranked above t; otherwise, inside lower-ranked tows, it is also a triangle of the highest
    // ranked of them (the surface between t and that tow): a region of its pair's loop around it.
    t0 = Clock::now();
    say(options, "connecting " + std::to_string(shared.size()) + " regions");
    result.mesh.nodes = std::move(nodes);
    const std::vector<Point3>& N = result.mesh.nodes;
    result.tows.resize(tows.size());
    const std::vector<std::size_t> rank = towRanks(tows, options.primaryPatterns);
    const auto period = [&](std::size_t t) { return tows[t].parameterRange().vPeriod(); };
    const auto pairOf = [&](std::size_t k) { return TowPair{loops[shared[k].loop].towA(), loops[shared[k].loop].towB()}; };
    // The nesting depth of each loop among its pair's loops; the loops directly inside one of
    // even depth are the holes of its region.
    std::vector<std::size_t> depth(shared.size(), 0);
    std::vector<std::vector<std::size_t>> inside(shared.size());  // the pair's loops inside each loop
    for (std::size_t a = 0; a < shared.size(); ++a)
        for (std::size_t b = 0; b < shared.size(); ++b) {
            if (a == b || pairOf(a) != pairOf(b)) continue;
            // On a tow around which neither loop winds (a loop around a tow bounds no inside there).
            const IntersectionLoop& la = loops[shared[a].loop];
            const IntersectionLoop& lb = loops[shared[b].loop];
            const bool onA = !la.windsAround(LoopSide::A) && !lb.windsAround(LoopSide::A);
            if (!onA && (la.windsAround(LoopSide::B) || lb.windsAround(LoopSide::B))) continue;
            const LoopSide side = onA ? LoopSide::A : LoopSide::B;
            const UV first = onA ? shared[b].points.front().onA : shared[b].points.front().onB;
            if (detail::insideLoop(detail::loopPolygon(shared[a], side), first, period(onA ? pairOf(a).first : pairOf(a).second))) {
                ++depth[b];
                inside[a].push_back(b);
            }
        }
    // Per tow, (triangle, loop) for every loop whose inside holds the triangle, by triangle.
    std::vector<std::vector<std::pair<std::size_t, std::size_t>>> hits(tows.size());
    detail::parallelFor(tows.size(), threads, [&](std::size_t t) {
        detail::throwIfCancelled(options.monitor);
        for (std::size_t k = 0; k < shared.size(); ++k)
            for (const LoopSide side : {LoopSide::A, LoopSide::B}) {
                const IntersectionLoop& l = loops[shared[k].loop];
                if ((side == LoopSide::A ? l.towA() : l.towB()) != t || l.windsAround(side)) continue;  // bands: below
                for (std::size_t tri : detail::trianglesInside(meshes[t], detail::loopPolygon(shared[k], side), period(t)))
                    hits[t].emplace_back(tri, k);
            }
        std::sort(hits[t].begin(), hits[t].end());
    });
    // One region per loop of even depth, primary the higher-ranked tow of its pair.
    std::vector<long> regionOf(shared.size(), -1);
    std::vector<ConnectedRegion> regions;
    std::vector<std::vector<Triangle>> lens;  // per region: both tows' surfaces inside the loop
    for (std::size_t k = 0; k < shared.size(); ++k) {
        if (depth[k] % 2 == 1) continue;  // a hole of the region around it
        const auto [a, b] = pairOf(k);
        ConnectedRegion r;
        r.primary = rank[a] < rank[b] ? a : b;
        r.secondary = rank[a] < rank[b] ? b : a;
        r.loop = shared[k].loop;
        for (std::size_t h : inside[k])
            if (depth[h] == depth[k] + 1) r.holes.push_back(shared[h].loop);
        r.loopNodes = shared[k].nodes;
        regionOf[k] = static_cast<long>(regions.size());
        regions.push_back(std::move(r));
        lens.emplace_back();
    }
    // The bands of each tow cut by loops winding around it: per tow, the other tow, its bands
    // and their loops' node polygons on this tow, in band order.
    struct TowBands {
        std::size_t other = 0;
        const detail::WindingBands* bands = nullptr;
        std::vector<std::size_t> loops;               // shared indices, in band order
        std::vector<detail::WindingPolygon> polygons;  // each loop's node polygon on the tow
    };
    std::vector<std::vector<TowBands>> bandsOn(tows.size());
    {
        std::map<std::size_t, std::size_t> sharedOfLoop;
        for (std::size_t k = 0; k < shared.size(); ++k) sharedOfLoop[shared[k].loop] = k;
        for (const auto& [to, b] : bands) {
            if (!std::all_of(b.loops.begin(), b.loops.end(), [&](std::size_t l) { return sharedOfLoop.count(l) > 0; }))
                continue;  // the pair was left out
            TowBands tb{to.second, &b, {}, {}};
            for (const std::size_t l : b.loops) {
                const std::size_t k = sharedOfLoop.at(l);
                tb.loops.push_back(k);
                tb.polygons.emplace_back(detail::loopPolygon(shared[k], loops[l].towA() == to.first ? LoopSide::A : LoopSide::B));
            }
            bandsOn[to.first].push_back(std::move(tb));
        }
    }
    std::map<TowPair, std::size_t> windingRegionLoop;  // pair -> its first loop around a tow
    for (std::size_t k = 0; k < shared.size(); ++k) {
        const IntersectionLoop& l = loops[shared[k].loop];
        if ((l.windsAround(LoopSide::A) || l.windsAround(LoopSide::B)) && regionOf[k] >= 0) windingRegionLoop.try_emplace(pairOf(k), k);
    }
    std::vector<std::vector<char>> removed(tows.size());
    std::vector<std::vector<long>> region(tows.size());
    // Per tow, the triangles of lower-ranked tows' surfaces it gets: (triangle, region, fibre
    // direction of the surface it lies on).
    std::vector<std::vector<std::tuple<Triangle, long, Vector3>>> inserted(tows.size());
    for (std::size_t t = 0; t < tows.size(); ++t) {
        removed[t].assign(meshes[t].triangles.size(), 0);
        region[t].assign(meshes[t].triangles.size(), -1);
        const auto& h = hits[t];
        const double uMin = tows[t].parameterRange().uMin;
        std::size_t next = 0;  // into hits, sorted by triangle
        for (std::size_t tri = 0; tri < meshes[t].triangles.size(); ++tri) {
            const std::size_t first = next;
            while (next < h.size() && h[next].first == tri) ++next;
            if (first == next && bandsOn[t].empty()) {  // inside no loop: skip ahead
                tri = next < h.size() ? h[next].first - 1 : meshes[t].triangles.size();
                continue;
            }
            // The tows it lies inside, each with its pair's deepest loop around it.
            std::map<std::size_t, std::pair<std::size_t, std::size_t>> in;  // tow -> (loops around it, deepest)
            for (std::size_t q = first; q < next; ++q) {
                const std::size_t k = h[q].second;
                const auto [a, b] = pairOf(k);
                auto& [count, deepest] = in.try_emplace(a == t ? b : a, 0, k).first->second;
                ++count;
                if (depth[k] > depth[deepest]) deepest = k;
            }
            // Bands: inside the other tow when an odd number of its winding loops lie between the
            // tow's start and the triangle, unless the start is inside; caps in the end bands.
            for (const TowBands& b : bandsOn[t]) {
                const std::size_t n = b.loops.size();
                std::size_t passed = 0;
                if (faceOf[t][tri] == TowFace::End)
                    passed = n;
                else if (faceOf[t][tri] == TowFace::Side)
                    passed = detail::loopsBefore(b.polygons, meshes[t].centroids[tri], uMin, period(t));
                if (b.bands->startInside == (passed % 2 == 1)) continue;  // outside o there
                const std::size_t bounding = b.loops[passed > 0 ? std::min(passed, n) - 1 : 0];
                auto [it, added] = in.try_emplace(b.other, 1, bounding);
                if (!added) {
                    ++it->second.first;
                    if (it->second.first % 2 == 1 && regionOf[it->second.second] < 0) it->second.second = bounding;
                }
            }
            // Inside by parity but its deepest loop is a hole (a loop nested in a loop around a
            // tow, whose nesting was taken on the other tow): the pair's band region.
            for (auto& [o, c] : in)
                if (c.first % 2 == 1 && regionOf[c.second] < 0)
                    if (const auto w = windingRegionLoop.find(std::minmax(t, o)); w != windingRegionLoop.end()) c.second = w->second;
            std::size_t top = tows.size();  // the highest-ranked tow it lies inside
            for (const auto& [o, c] : in)
                if (c.first % 2 == 1 && (top == tows.size() || rank[o] < rank[top])) top = o;
            for (const auto& [o, c] : in)
                if (c.first % 2 == 1 && regionOf[c.second] >= 0) lens[static_cast<std::size_t>(regionOf[c.second])].push_back(meshes[t].triangles[tri]);
            if (top == tows.size()) continue;
            if (rank[top] < rank[t]) {
                removed[t][tri] = 1;
            } else {
                const long id = regionOf[in[top].second];
                if (id < 0) {
                    failures.run(t, [&] { throw Error(ErrorCode::Internal, "a triangle inside an odd number of loops has no region"); });
                    continue;
                }
                const Triangle& triangle = meshes[t].triangles[tri];
                region[t][tri] = id;
                ConnectedRegion& r = regions[static_cast<std::size_t>(id)];
                r.triangles.push_back(tri);
                r.area += triangleArea(N, triangle);
                inserted[top].emplace_back(reversed(triangle), id, fibre[t][tri]);
            }
        }
    }
    failures.throwAll();
    // A tow through another (or ending inside it): its loops bound one overlap together, whose
    // volume goes to the pair's first region that kept triangles.
    for (const auto& [to, b] : bands) {
        if (to.first > to.second && bands.count({to.second, to.first})) continue;  // once per pair
        const TowPair pair = std::minmax(to.first, to.second);
        std::vector<Triangle> all;
        long keep = -1;
        for (std::size_t k = 0; k < shared.size(); ++k) {
            if (pairOf(k) != pair || regionOf[k] < 0) continue;
            const std::size_t g = static_cast<std::size_t>(regionOf[k]);
            all.insert(all.end(), lens[g].begin(), lens[g].end());
            lens[g].clear();
            if (keep < 0 && !regions[g].triangles.empty()) keep = regionOf[k];
        }
        if (keep >= 0) lens[static_cast<std::size_t>(keep)] = std::move(all);
    }
    // Regions that kept triangles (a loop's surface may lie wholly inside a higher-ranked tow),
    // renumbered in loop order.
    std::vector<long> renumbered(regions.size(), -1);
    for (std::size_t g = 0; g < regions.size(); ++g) {
        ConnectedRegion& r = regions[g];
        if (r.triangles.empty()) continue;
        std::set<std::size_t> regionNodes;
        for (std::size_t k : r.triangles) {
            const Triangle& tri = meshes[r.primary].triangles[k];
            regionNodes.insert(tri.begin(), tri.end());
        }
        r.nodes.assign(regionNodes.begin(), regionNodes.end());
        // The loop's nodes around this region: where a higher-ranked tow covers part of the
        // loop, its nodes there belong to no triangle of the region.
        std::vector<std::size_t> around;
        for (std::size_t n : r.loopNodes)
            if (regionNodes.count(n)) around.push_back(n);
        r.loopNodes = std::move(around);
        // Both tows' surfaces inside the loop bound the two tows' overlap there, facing out of
        // it: its volume.
        r.volumeRemoved = std::abs(detail::signedVolume(N, lens[g]));
        result.tows[r.primary].primaryAnywhere = true;
        result.tows[r.secondary].secondaryAnywhere = true;
        renumbered[g] = static_cast<long>(result.mesh.regions.size());
        result.mesh.regions.push_back(std::move(r));
    }
    for (auto& ids : region)
        for (long& id : ids)
            if (id >= 0) id = renumbered[static_cast<std::size_t>(id)];
    for (auto& list : inserted)
        for (auto& entry : list) std::get<1>(entry) = renumbered[static_cast<std::size_t>(std::get<1>(entry))];
    result.mesh.tows.resize(tows.size());
    std::vector<std::vector<std::size_t>> placeOf(tows.size());  // mesher's triangle -> its place in the tow's mesh
    for (std::size_t t = 0; t < tows.size(); ++t) {
        TowMesh& m = result.mesh.tows[t];
        m.name = tows[t].name();
        placeOf[t].assign(meshes[t].triangles.size(), SIZE_MAX);
        for (std::size_t k = 0; k < meshes[t].triangles.size(); ++k) {
            if (removed[t][k]) continue;
            placeOf[t][k] = m.triangles.size();
            m.triangles.push_back(meshes[t].triangles[k]);
            m.region.push_back(region[t][k]);
            m.face.push_back(faceOf[t][k]);
            m.fibreDirection.push_back(fibre[t][k]);
        }
        for (const auto& [tri, id, direction] : inserted[t]) {  // another tow's surface (or cap): this tow's side
            m.triangles.push_back(tri);
            m.region.push_back(id);
            m.face.push_back(TowFace::Side);
            m.fibreDirection.push_back(direction);
        }
    }
    // Each tow's nodes on its own surface, with their (u,v).
    detail::parallelFor(tows.size(), threads, [&](std::size_t t) {
        TowMesh& m = result.mesh.tows[t];
        std::vector<std::size_t> used;
        used.reserve(3 * m.triangles.size());
        for (const Triangle& tri : m.triangles) used.insert(used.end(), tri.begin(), tri.end());
        std::sort(used.begin(), used.end());
        used.erase(std::unique(used.begin(), used.end()), used.end());
        std::vector<std::pair<std::size_t, UV>>& on = uvOn[t];
        std::stable_sort(on.begin(), on.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        auto at = on.begin();
        for (std::size_t n : used) {
            while (at != on.end() && at->first < n) ++at;
            if (at != on.end() && at->first == n) m.parameters.push_back(*at);
        }
        on = {};
    });
    // A region's triangles by their place in the primary's final mesh (it keeps them all).
    for (ConnectedRegion& r : result.mesh.regions)
        for (std::size_t& k : r.triangles) k = placeOf[r.primary][k];
    // Every tow must still be closed (a tube open at its two ends without caps), oriented and
    // 2-manifold; anything else is a defect, never written out.
    const std::size_t ends = options.mesh.caps ? 0 : 2;
    std::vector<std::size_t> badEdges(tows.size(), 0);
    detail::parallelFor(tows.size(), threads, [&](std::size_t t) {
        TowResolution& r = result.tows[t];
        r.volumeBefore = detail::closedVolume(N, meshes[t].triangles);
        r.volumeAfter = detail::closedVolume(N, result.mesh.tows[t].triangles, &r.boundaryLoops);
        badEdges[t] = detail::nonManifoldEdges(result.mesh.tows[t].triangles);
        r.pieces = detail::connectedPieces(result.mesh.tows[t].triangles);
        for (const Triangle& tri : result.mesh.tows[t].triangles) r.area += triangleArea(N, tri);
    });
    for (std::size_t t = 0; t < tows.size(); ++t)
        if (badEdges[t] != 0 || result.tows[t].boundaryLoops != ends)
            failures.run(t, [&] {
                throw Error(ErrorCode::Internal,
                            std::string(options.mesh.caps ? "the mesh is not a closed surface (" : "the mesh is not a tube open at its two ends (") +
                                std::to_string(badEdges[t]) + " edges not shared by exactly two triangles the opposite way round, " +
                                std::to_string(result.tows[t].boundaryLoops) + " boundary loops)",
                            "tow '" + tows[t].name() + "'");
            });
    failures.throwAll();
    // Quality over distinct triangles: a secondary's copies of a region's triangles are skipped.
    result.quality.histogram.assign(12, 0);
    result.quality.minAngle = 180.0;
    for (std::size_t t = 0; t < tows.size(); ++t) {
        const TowMesh& m = result.mesh.tows[t];
        for (std::size_t k = 0; k < m.triangles.size(); ++k) {
            if (m.region[k] >= 0 && result.mesh.regions[static_cast<std::size_t>(m.region[k])].secondary == t) continue;
            const double a = smallestAngle(N, m.triangles[k]);
            result.quality.minAngle = std::min(result.quality.minAngle, a);
            ++result.quality.histogram[std::min<std::size_t>(11, static_cast<std::size_t>(a / 5.0))];
            ++result.quality.triangles;
        }
    }
    // The secondary's nodes inside its removed triangles are used by no triangle now: drop them
    // and number the rest consecutively.
    {
        std::vector<std::size_t> renumber(N.size(), SIZE_MAX);
        std::vector<Point3> kept;
        const auto use = [&](std::size_t& n) {
            if (renumber[n] == SIZE_MAX) {
                renumber[n] = kept.size();
                kept.push_back(N[n]);
            }
            n = renumber[n];
        };
        for (TowMesh& m : result.mesh.tows)
            for (Triangle& tri : m.triangles)
                for (std::size_t& n : tri) use(n);
        for (TowMesh& m : result.mesh.tows) {  // every node listed is one of the tow's triangles'
            for (auto& entry : m.parameters) entry.first = renumber[entry.first];
            std::sort(m.parameters.begin(), m.parameters.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        }
        for (ConnectedRegion& g : result.mesh.regions) {
            for (std::size_t& n : g.nodes) use(n);
            for (std::size_t& n : g.loopNodes) use(n);
            std::sort(g.nodes.begin(), g.nodes.end());  // sorted by the new numbers
        }
        // Triple points whose three pairs were resolved: a node of all three tows' meshes.
        std::map<std::size_t, std::set<std::size_t>> towsAt;  // triple node -> the tows using it
        for (const TriplePoint& p : triples.points)
            if (renumber[p.node] != SIZE_MAX) towsAt[renumber[p.node]];
        for (std::size_t t = 0; t < tows.size() && !towsAt.empty(); ++t)
            for (const Triangle& tri : result.mesh.tows[t].triangles)
                for (std::size_t n : tri)
                    if (const auto it = towsAt.find(n); it != towsAt.end()) it->second.insert(t);
        for (TriplePoint p : triples.points) {
            if (renumber[p.node] == SIZE_MAX) continue;
            const std::set<std::size_t>& at = towsAt[renumber[p.node]];
            if (!at.count(p.tows[0]) || !at.count(p.tows[1]) || !at.count(p.tows[2])) continue;
            p.node = renumber[p.node];
            result.mesh.triplePoints.push_back(p);
        }
        result.mesh.nodes = std::move(kept);
    }
    result.timings.regions = msSince(t0);
}

/// Meshes and connects tows already in a normalised frame with the loops of @p report (on those
/// tows), options in the frame's units (the mesh size set); @p checkLoopRefinement is given the
/// loops' length (frame units) before meshing. A tow whose mesh fails costs only the tow pairs
/// with loops on it: they are left unresolved (named in the result) and the rest is meshed again
/// without them.
ResolveResult resolveInFrame(const std::vector<TowSurface>& tows, const std::vector<double>& towH, const ResolveOptions& options,
                             const IntersectionReport& report, const std::function<void(double)>& checkLoopRefinement)
{
    double loopLength = 0.0;  // of the loops that will be meshed
    for (const IntersectionLoop& l : report.loops)
        if (l.closed() && (options.mesh.caps || (!l.windsAround(LoopSide::A) && !l.windsAround(LoopSide::B)))) loopLength += l.length();
    checkLoopRefinement(loopLength);
    std::set<TowPair> excluded;
    std::vector<UnresolvedPair> unresolved;
    for (;;) {
        ResolveResult attempt;
        attempt.intersections = report;
        try {
            meshAndConnect(tows, towH, options, excluded, attempt);
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
            say(options, "meshing again without the " + std::to_string(left) + " tow pair(s) on " +
                                 std::to_string(failed.tows.size()) + " tow(s) whose mesh failed");
            continue;
        }
        attempt.unresolved.insert(attempt.unresolved.end(), unresolved.begin(), unresolved.end());
        return attempt;
    }
}

/// The area of a (planar) polygon: half the norm of Newell's normal.
double polygonArea(const std::vector<Point3>& polygon)
{
    Vector3 n;
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k) n = n + cross(polygon[k] - polygon[0], polygon[k + 1] - polygon[0]);
    return 0.5 * norm(n);
}

/// The lateral area of @p tow's input polygons joined by flat quads (two triangles each), plus
/// its end polygons with @p caps: within a few percent of the surface's area at a cost of M x N,
/// for the size estimate (the exact area() integrates every knot span: 0.06 s for a tow of
/// 400 x 64).
double facetedArea(const TowSurface& tow, bool caps)
{
    const auto& s = tow.sections();
    double area = caps ? polygonArea(s.front()) + polygonArea(s.back()) : 0.0;
    for (std::size_t i = 0; i + 1 < s.size(); ++i)
        for (std::size_t j = 0; j < s[i].size(); ++j) {
            const std::size_t k = (j + 1) % s[i].size();
            area += 0.5 * norm(cross(s[i + 1][j] - s[i][j], s[i + 1][k] - s[i][j])) +
                    0.5 * norm(cross(s[i + 1][k] - s[i][j], s[i][k] - s[i][j]));
        }
    return area;
}

/// The mesh size of each tow in the user's units: relativeEdgeLength x its own size, or the
/// edge length given, at most a quarter of the tow's circumference (at least 4 edges around).
std::vector<double> meshSizes(const std::vector<TowSurface>& tows, const MeshOptions& mesh)
{
    std::vector<double> h;
    for (const TowSurface& t : tows) {
        const double around = 3.14159265358979323846 * t.towSize();
        if (mesh.edgeLength > 0.0) {
            h.push_back(std::min(mesh.edgeLength, around / 4.0));
            continue;
        }
        h.push_back(mesh.relativeEdgeLength * t.towSize());
        if (h.back() > around / 4.0)
            throw Error(ErrorCode::InvalidArgument,
                        "relative mesh size " + std::to_string(mesh.relativeEdgeLength) + " is too coarse: tow '" + t.name() +
                            "' needs at least 4 edges around (relative mesh size at most pi / 4)");
    }
    return h;
}

/// @p result, computed on tows moved into @p frame, in the user's units; @p report (the user's)
/// replaces the loops in the frame.
void resultToUser(ResolveResult& result, const IntersectionReport& report, const detail::Frame& frame)
{
    result.intersections = report;
    for (Point3& p : result.mesh.nodes) p = frame.toUser(p);
    const double s = frame.scale;
    for (TowResolution& t : result.tows) {
        t.volumeBefore /= s * s * s;
        t.volumeAfter /= s * s * s;
        t.area /= s * s;
    }
    for (ConnectedRegion& r : result.mesh.regions) {
        r.area /= s * s;
        r.volumeRemoved /= s * s * s;
    }
}

/// The mesh sizes of resolveTextile(), checked against MeshOptions::maxTriangles before the
/// loops are known; check() repeats the check with the loops' refinement.
struct MeshSizePlan {
    std::vector<double> towH;  ///< per tow, the user's units
    double area = 0.0;         ///< the tows' (faceted) area
    double h = 1.0;            ///< the tows' mesh sizes averaged as the triangle count sees them
    double spacing = 1.0;      ///< the loop spacing

    MeshSizePlan(const std::vector<TowSurface>& tows, const MeshOptions& mesh) : towH(meshSizes(tows, mesh))
    {
        // In the user's units, for the message; h area-weighted in 1/h^2.
        double perH2 = 0.0;
        for (std::size_t t = 0; t < tows.size(); ++t) {
            const double a = facetedArea(tows[t], mesh.caps);
            area += a;
            perH2 += a / (towH[t] * towH[t]);
        }
        h = perH2 > 0.0 ? std::sqrt(area / perH2) : 1.0;
        spacing = mesh.loopSpacing > 0.0 ? mesh.loopSpacing : h;
        checkMeshSize(mesh, area, h, 0.0, spacing);
    }
};

/// resolveTextile() with @p report for @p tows, both checked, the sizes planned.
ResolveResult resolveWithReport(const std::vector<TowSurface>& tows, const IntersectionReport& report,
                                const ResolveOptions& options, const MeshSizePlan& plan)
{
    // Computed in the textile's normalised frame (as intersectTows()), so that the meshes do not
    // depend on the user's units; the results go back to the user's units.
    const detail::Frame frame = detail::textileFrame(tows);
    ResolveOptions o = options;
    std::vector<double> towHInFrame;
    for (double x : plan.towH) towHInFrame.push_back(frame.lengthToFrame(x));
    o.mesh.loopSpacing = frame.lengthToFrame(options.mesh.loopSpacing);
    o.intersection = detail::optionsInFrame(options.intersection, frame);
    const std::vector<TowSurface> moved = detail::towsInFrame(tows, frame);
    ResolveResult result = resolveInFrame(moved, towHInFrame, o, detail::reportToFrame(report, moved, frame), [&](double loopLength) {
        checkMeshSize(options.mesh, plan.area, plan.h, frame.lengthToUser(loopLength), plan.spacing);
        if (!plan.towH.empty()) {  // in the user's units
            const auto [lo, hi] = std::minmax_element(plan.towH.begin(), plan.towH.end());
            say(options, "meshing " + std::to_string(tows.size()) + " tows at h = " + std::to_string(*lo) +
                             (*hi > *lo * (1.0 + 1e-6) ? " to " + std::to_string(*hi) : std::string()));
        }
    });
    resultToUser(result, report, frame);
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"  // ResolveResult::skipped, until 0.3
    for (const SkippedLoop& s : result.skippedLoops) result.skipped.emplace_back(s.loop, s.message);
#pragma GCC diagnostic pop
    for (std::size_t t = 0; t < tows.size(); ++t) result.tows[t].meshSize = plan.towH[t];
    return result;
}

}  // namespace

ResolveResult resolveTextile(const std::vector<TowSurface>& tows, const IntersectionReport& report, const ResolveOptions& options)
{
    checkOptions(options);
    detail::checkIntersectionOptions(options.intersection);
    detail::checkReportTows(tows, report);
    return resolveWithReport(tows, report, options, MeshSizePlan(tows, options.mesh));
}

ResolveResult resolveTextile(const std::vector<TowSurface>& tows, const ResolveOptions& options)
{
    checkOptions(options);
    detail::checkIntersectionOptions(options.intersection);
    // A mesh too large for memory is refused now, before intersecting.
    const MeshSizePlan plan(tows, options.mesh);
    const Clock::time_point t0 = Clock::now();
    IntersectionOptions io = options.intersection;
    io.threads = options.threads;
    say(options, "intersecting " + std::to_string(tows.size()) + " tows");
    if (!io.monitor) io.monitor = options.monitor;
    const IntersectionReport report = intersectTows(tows, io);
    const double intersectMs = msSince(t0);
    ResolveResult result = resolveWithReport(tows, report, options, plan);
    result.timings.intersect = intersectMs;
    return result;
}

TOWGEOM_END_NAMESPACE
