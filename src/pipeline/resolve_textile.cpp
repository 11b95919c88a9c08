// The pipeline's orchestration: resolveTextile() as its stages chained (intersectTows(),
// meshTows(), connectRegions()), and meshTows()'s checks, mesh sizes and normalised frame.
#include "towgeom/connect_regions.hpp"
#include "towgeom/mesh_tows.hpp"
#include "towgeom/resolve.hpp"
#include "towgeom/surface_fold.hpp"
#include "towgeom/shrink_tows.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "cell/cell_faces.hpp"
#include "core/elapsed.hpp"
#include "core/parallel.hpp"
#include "core/progress_report.hpp"
#include "pipeline/resolve_checks.hpp"
#include "intersect/textile_frame.hpp"
#include "mesh/curvature_size.hpp"
#include "mesh/textile_mesher.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

using Clock = std::chrono::steady_clock;

using detail::msSince;

void checkOptions(const ResolveOptions& o)
{
    const MeshOptions& m = o.mesh;
    const auto nonNegative = [](double x) { return x >= 0.0 && std::isfinite(x); };
    if (!nonNegative(m.edgeLength)) throw Error(ErrorCode::InvalidArgument, "mesh edge length must be >= 0 and finite");
    if (!(m.relativeEdgeLength > 0.0 && std::isfinite(m.relativeEdgeLength)))
        throw Error(ErrorCode::InvalidArgument, "relative mesh edge length must be > 0 and finite");
    if (!(m.minAngle > 0.0 && m.minAngle <= 30.0))
        throw Error(ErrorCode::InvalidArgument, "minimum angle must lie in (0, 30] degrees");
    if (!nonNegative(m.chordDeviation) || !nonNegative(m.relativeChordDeviation))
        throw Error(ErrorCode::InvalidArgument, "chord deviation (absolute and relative) must be >= 0 and finite");
    if (!nonNegative(m.minEdgeLength) || !nonNegative(m.relativeMinEdgeLength))
        throw Error(ErrorCode::InvalidArgument, "smallest edge length (absolute and relative) must be >= 0 and finite");
    if (!nonNegative(m.loopSpacing)) throw Error(ErrorCode::InvalidArgument, "loop spacing must be >= 0 and finite");
    if (m.maxTriangles == 0) throw Error(ErrorCode::InvalidArgument, "the triangle limit must be at least 1");
    if (o.cell) {
        o.cell->validate();
        if (!m.caps) throw Error(ErrorCode::InvalidArgument, "a cell needs closed tows: the end caps (MeshOptions::caps) cannot be off");
    }
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
    how << kTrianglesPerEquilateral << " x the area to mesh (tows, and a cell's faces) " << area << " / (sqrt(3)/4 h^2) at mesh size h = " << h;
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
void resultToUser(ResolveResult& result, const IntersectionReport& report, const detail::Frame& frame, const ResolveOptions& options)
{
    result.intersections = report;
    for (Point3& p : result.mesh.nodes) p = frame.toUser(p);
    if (result.mesh.cell && options.cell) {
        // The user's box, and the nodes on its faces exactly on their planes.
        CellMesh& cell = *result.mesh.cell;
        cell.box = *options.cell;
        for (std::size_t f = 0; f < 6; ++f) {
            const double at = cell.box.plane(static_cast<CellFace>(f));
            for (std::size_t n : cell.faceNodes[f]) {
                Point3& p = result.mesh.nodes[n];
                (f < 2 ? p.x : f < 4 ? p.y : p.z) = at;
            }
        }
    }
    const double s = frame.scale;
    for (TowResolution& t : result.tows) {
        t.volumeBefore /= s * s * s;
        t.volumeAfter /= s * s * s;
        t.area /= s * s;
    }
}

/// The mesh sizes of the mesh stage, checked against MeshOptions::maxTriangles before the loops
/// are known; check() repeats the check with the loops' refinement.
struct MeshSizePlan {
    std::vector<double> towH;  ///< per tow, the user's units
    /// Per tow, its size graded by curvature (MeshOptions::chordDeviation), the user's units;
    /// null for a tow meshed at towH everywhere.
    std::vector<std::shared_ptr<const detail::CurvatureSize>> graded;
    double area = 0.0;         ///< the tows' (faceted) area, and a cell's faces
    double h = 1.0;            ///< the tows' mesh sizes averaged as the triangle count sees them
    double spacing = 1.0;      ///< the loop spacing

    MeshSizePlan(const std::vector<TowSurface>& tows, const MeshOptions& mesh, const std::optional<Cell>& cell, std::size_t threads)
        : towH(meshSizes(tows, mesh)), graded(tows.size())
    {
        detail::parallelFor(tows.size(), detail::workerCount(threads), [&](std::size_t t) { graded[t] = detail::curvatureSizeFor(tows[t], mesh, towH[t]); });
        // In the user's units, for the message; h area-weighted in 1/h^2 (a graded tow's
        // (h / size)^2 averaged over its area).
        double perH2 = 0.0;
        for (std::size_t t = 0; t < tows.size(); ++t) {
            const double a = facetedArea(tows[t], mesh.caps);
            area += a;
            perH2 += a * (graded[t] ? graded[t]->densityOverLargest() : 1.0) / (towH[t] * towH[t]);
        }
        if (cell) {  // the box's faces counted at the finest tow's size: an upper bound (graded coarser away from the caps)
            const double dx = cell->max.x - cell->min.x, dy = cell->max.y - cell->min.y, dz = cell->max.z - cell->min.z;
            const double a = 2.0 * (dx * dy + dy * dz + dz * dx);
            const double faceH = detail::cellFaceSize(*cell, towH);
            area += a;
            perH2 += a / (faceH * faceH);
        }
        h = perH2 > 0.0 ? std::sqrt(area / perH2) : 1.0;
        spacing = mesh.loopSpacing > 0.0 ? mesh.loopSpacing : h;
        checkMeshSize(mesh, area, h, 0.0, spacing);
    }
};

/// TowResolution::fold of every tow (inside the cell, if any): findFold() on @p options.threads
/// threads.
void findFolds(const std::vector<TowSurface>& tows, const ResolveOptions& options, ResolveResult& result)
{
    detail::sayStage(options, "looking for folds in " + std::to_string(tows.size()) + " tows' surfaces");
    FoldSearchOptions search;
    if (options.cell) {  // a fold outside the cell is clipped away
        search.within.add(options.cell->min);
        search.within.add(options.cell->max);
    }
    detail::parallelFor(tows.size(), detail::workerCount(options.threads), [&](std::size_t t) { result.tows[t].fold = findFold(tows[t], search); });
}

/// meshTows() with @p report for @p tows, both checked, the sizes planned. Computed in the
/// textile's normalised frame (as intersectTows()), so that the meshes do not depend on the
/// user's units; the result is in the user's units.
ResolveResult meshWithPlan(const std::vector<TowSurface>& tows, const IntersectionReport& report, const ResolveOptions& options,
                           const MeshSizePlan& plan)
{
    const detail::Frame frame = detail::textileFrame(tows);
    ResolveOptions o = options;
    std::vector<double> towHInFrame;
    for (double x : plan.towH) towHInFrame.push_back(frame.lengthToFrame(x));
    o.mesh.loopSpacing = frame.lengthToFrame(options.mesh.loopSpacing);
    o.intersection = detail::optionsInFrame(options.intersection, frame);
    if (options.cell && options.cell->cutsMeshes()) {
        o.cell.reset();  // connectRegions() clips the resolved meshes
    } else if (options.cell) {
        o.cell->min = frame.toFrame(options.cell->min);
        o.cell->max = frame.toFrame(options.cell->max);
    }
    const std::vector<TowSurface> moved = detail::towsInFrame(tows, frame);
    const IntersectionReport reportInFrame = detail::reportToFrame(report, moved, frame);
    // The loops that will be meshed refine the mesh along them: checked with them now.
    double loopLength = 0.0;
    for (const IntersectionLoop& l : reportInFrame.loops)
        if (l.closed() && (options.mesh.caps || (!l.windsAround(LoopSide::A) && !l.windsAround(LoopSide::B)))) loopLength += l.length();
    checkMeshSize(options.mesh, plan.area, plan.h, frame.lengthToUser(loopLength), plan.spacing);
    if (!plan.towH.empty()) {  // in the user's units
        const auto [lo, hi] = std::minmax_element(plan.towH.begin(), plan.towH.end());
        detail::sayStage(options, "meshing " + std::to_string(tows.size()) + " tows at h = " + std::to_string(*lo) +
                                      (*hi > *lo * (1.0 + 1e-6) ? " to " + std::to_string(*hi) : std::string()));
    }
    std::vector<detail::TowSizeField> sizeAt(tows.size());
    for (std::size_t t = 0; t < tows.size(); ++t)
        if (const auto graded = plan.graded[t])
            sizeAt[t] = [graded, scale = frame.lengthToFrame(1.0)](const UV& at) { return scale * graded->at(at); };
    ResolveResult result = detail::meshTowsInFrame(moved, towHInFrame, o, reportInFrame, sizeAt);
    resultToUser(result, report, frame, options);
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"  // ResolveResult::skipped, until 0.3
    for (const SkippedLoop& s : result.skippedLoops) result.skipped.emplace_back(s.loop, s.message);
#pragma GCC diagnostic pop
    for (std::size_t t = 0; t < tows.size(); ++t) result.tows[t].meshSize = plan.towH[t];
    findFolds(tows, options, result);
    return result;
}

/// The checks of every entry point that takes a report.
void checkWithReport(const std::vector<TowSurface>& tows, const IntersectionReport& report, const ResolveOptions& options)
{
    checkOptions(options);
    detail::checkIntersectionOptions(options.intersection);
    detail::checkReportTows(tows, report);
}

/// ResolutionMethod::Shrink: the tows shrunk apart (shrinkTows()), intersected again and meshed
/// each on its own (what is left of a pair not separated is resolved by the rank rule).
ResolveResult resolveShrunk(const std::vector<TowSurface>& tows, const IntersectionReport& report, const ResolveOptions& options)
{
    const Clock::time_point t0 = Clock::now();
    ShrinkResult s = shrinkTows(tows, report, options);
    IntersectionOptions io = options.intersection;
    io.threads = options.threads;
    if (!io.monitor) io.monitor = options.monitor;
    detail::sayStage(options, "intersecting the shrunk tows");
    const IntersectionReport after = intersectTows(s.tows, io);
    const double shrinkMs = msSince(t0);
    ResolveOptions o = options;
    o.method = ResolutionMethod::Connect;
    ResolveResult result = connectRegions(s.tows, meshWithPlan(s.tows, after, o, MeshSizePlan(s.tows, o.mesh, o.cell, o.threads)), o);
    result.method = ResolutionMethod::Shrink;
    for (std::size_t t = 0; t < tows.size(); ++t) {
        TowResolution& r = result.tows[t];
        const ShrunkTow& f = s.figures[t];
        // The input tow's volume at the shrunk mesh's resolution (before any swap of what the
        // rank rule still resolved), so the loss counts both the shrink and that swap.
        r.volumeBefore = f.volumeAfter > 0.0 ? f.volumeBefore * (r.volumeBefore / f.volumeAfter) : r.volumeBefore;
    }
    result.shrunk = std::move(s.figures);
    result.unresolved.insert(result.unresolved.end(), s.notSeparated.begin(), s.notSeparated.end());
    result.timings.intersect += shrinkMs;
    return result;
}

}  // namespace

void detail::checkBeforeIntersecting(const std::vector<TowSurface>& tows, const ResolveOptions& options)
{
    checkOptions(options);
    detail::checkIntersectionOptions(options.intersection);
    const MeshSizePlan plan(tows, options.mesh, options.cell, options.threads);
}

ResolveResult meshTows(const std::vector<TowSurface>& tows, const IntersectionReport& report, const ResolveOptions& options)
{
    checkWithReport(tows, report, options);
    return meshWithPlan(tows, report, options, MeshSizePlan(tows, options.mesh, options.cell, options.threads));
}

ResolveResult resolveTextile(const std::vector<TowSurface>& tows, const IntersectionReport& report, const ResolveOptions& options)
{
    checkWithReport(tows, report, options);
    if (options.method == ResolutionMethod::Shrink) return resolveShrunk(tows, report, options);
    return connectRegions(tows, meshWithPlan(tows, report, options, MeshSizePlan(tows, options.mesh, options.cell, options.threads)), options);
}

ResolveResult resolveTextile(const std::vector<TowSurface>& tows, const ResolveOptions& options)
{
    checkOptions(options);
    detail::checkIntersectionOptions(options.intersection);
    // A mesh too large for memory is refused now, before intersecting.
    const MeshSizePlan plan(tows, options.mesh, options.cell, options.threads);
    const Clock::time_point t0 = Clock::now();
    IntersectionOptions io = options.intersection;
    io.threads = options.threads;
    detail::sayStage(options, "intersecting " + std::to_string(tows.size()) + " tows");
    if (!io.monitor) io.monitor = options.monitor;
    // With a cell, only the pairs that may overlap inside it (the others' loops would be
    // dropped); not for Shrink, whose shrinking of a pair reaches along the tows into the cell.
    const bool inCell = options.cell && options.method != ResolutionMethod::Shrink;
    const BoundingBox cellBox = options.cell ? BoundingBox{options.cell->min, options.cell->max} : BoundingBox{};
    const IntersectionReport report = detail::intersectTowsIn(tows, io, inCell ? &cellBox : nullptr);
    const double intersectMs = msSince(t0);
    if (options.method == ResolutionMethod::Shrink) {
        ResolveResult result = resolveShrunk(tows, report, options);
        result.timings.intersect += intersectMs;
        return result;
    }
    ResolveResult result = connectRegions(tows, meshWithPlan(tows, report, options, plan), options);
    result.timings.intersect = intersectMs;
    return result;
}

TOWGEOM_END_NAMESPACE
