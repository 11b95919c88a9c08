// compareMethods(): one intersection, one set of meshes, every method asked for, measured alike.
#include "towgeom/method_comparison.hpp"

#include <algorithm>
#include <chrono>

#include "core/elapsed.hpp"
#include "core/parallel.hpp"
#include "core/progress_report.hpp"
#include "pipeline/resolve_checks.hpp"
#include "report/section_slices.hpp"
#include "towgeom/connect_regions.hpp"
#include "towgeom/error.hpp"
#include "towgeom/mesh_tows.hpp"
#include "towgeom/tow_intersection.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

using Clock = std::chrono::steady_clock;

using detail::msSince;

/// Each tow's cross-section areas at its input sections' planes, in @p mesh.
std::vector<std::vector<double>> sectionAreas(const std::vector<std::vector<detail::SectionPlane>>& planes, const TextileMesh& mesh,
                                              std::size_t threads)
{
    std::vector<std::vector<double>> areas(planes.size());
    detail::parallelFor(planes.size(), threads, [&](std::size_t t) {
        for (const detail::SectionPlane& p : planes[t]) areas[t].push_back(detail::sectionArea(mesh.nodes, mesh.tows[t].triangles, p));
    });
    return areas;
}

}  // namespace

const char* resolutionMethodName(ResolutionMethod method) noexcept
{
    switch (method) {
    case ResolutionMethod::Connect: return "connect";
    case ResolutionMethod::Symmetric: return "symmetric";
    case ResolutionMethod::Shrink: return "shrink";
    }
    return "connect";
}

MethodComparison compareMethods(const std::vector<TowSurface>& tows, const std::vector<ResolutionMethod>& methods,
                                const ResolveOptions& options, std::vector<ResolveResult>* results)
{
    if (methods.empty()) throw Error(ErrorCode::InvalidArgument, "compareMethods() needs at least one method");
    for (std::size_t i = 0; i < methods.size(); ++i)
        if (std::count(methods.begin(), methods.end(), methods[i]) > 1)
            throw Error(ErrorCode::InvalidArgument, std::string("method '") + resolutionMethodName(methods[i]) + "' is asked for twice");
    detail::checkBeforeIntersecting(tows, options);
    const std::size_t threads = detail::workerCount(options.threads);
    MethodComparison c;
    std::vector<std::vector<detail::SectionPlane>> planes;
    for (const TowSurface& t : tows) {
        c.towNames.push_back(t.name());
        planes.push_back(detail::sectionPlanes(t.sections()));
        std::vector<double>& along = c.stations.emplace_back();
        for (std::size_t i = 0; i < planes.back().size(); ++i)
            along.push_back(i == 0 ? 0.0 : along.back() + distance(planes.back()[i - 1].centre, planes.back()[i].centre));
    }
    Clock::time_point t0 = Clock::now();
    IntersectionOptions io = options.intersection;
    io.threads = options.threads;
    if (!io.monitor) io.monitor = options.monitor;
    detail::sayStage(options, "intersecting " + std::to_string(tows.size()) + " tows");
    const IntersectionReport report = intersectTows(tows, io);
    c.intersectMilliseconds = msSince(t0);
    for (const IntersectionLoop& l : report.loops)
        c.loops.push_back({l.towA(), l.towB(), l.closed(), l.length(), l.enclosedArea(LoopSide::A), l.enclosedArea(LoopSide::B)});
    t0 = Clock::now();
    const ResolveResult meshed = meshTows(tows, report, options);
    c.meshMilliseconds = msSince(t0);
    c.sectionAreaBefore = sectionAreas(planes, meshed.mesh, threads);
    for (const ResolutionMethod method : methods) {
        detail::throwIfCancelled(options.monitor);
        detail::sayStage(options, std::string("resolving by ") + resolutionMethodName(method));
        ResolveOptions o = options;
        o.method = method;
        t0 = Clock::now();
        ResolveResult r = method == ResolutionMethod::Shrink ? resolveTextile(tows, report, o) : connectRegions(tows, meshed, o);
        MethodFigures f;
        f.method = method;
        f.milliseconds = msSince(t0);
        r.timings.intersect += c.intersectMilliseconds;  // the shared intersection (and meshing) in each result
        if (method != ResolutionMethod::Shrink) r.timings.mesh = c.meshMilliseconds;
        f.regions = r.mesh.regions.size();
        f.unresolvedPairs = r.unresolved.size();
        f.quality = r.quality;
        const std::vector<std::vector<double>> areas = sectionAreas(planes, r.mesh, threads);
        for (std::size_t t = 0; t < tows.size(); ++t) {
            const TowResolution& tr = r.tows[t];
            TowMethodFigures tf;
            tf.role = tr.role();
            tf.volumeBefore = tr.volumeBefore;
            tf.volumeAfter = tr.volumeAfter;
            tf.area = tr.area;
            tf.triangles = r.mesh.tows[t].triangles.size();
            if (t < r.shrunk.size()) {
                tf.largestSectionChange = r.shrunk[t].largestSectionChange();
                tf.role = tf.largestSectionChange > 0.0 ? "shrunk" : "unchanged";
            }
            tf.sectionArea = areas[t];
            f.tows.push_back(std::move(tf));
        }
        if (c.methods.empty())
            for (const ConnectedRegion& g : r.mesh.regions)
                c.regions.push_back({g.primary, g.secondary, g.triangles.size(), g.area, g.volumeRemoved, g.surface});
        c.methods.push_back(std::move(f));
        if (results) results->push_back(std::move(r));
    }
    return c;
}

TOWGEOM_END_NAMESPACE
