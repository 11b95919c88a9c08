// The detect and resolve reports as JSON (nlohmann-json, keys in the order written).
#include <algorithm>
#include <ostream>

#include <nlohmann/json.hpp>

#include "export/volume_mesh_checks.hpp"

#include "core/parallel.hpp"
#include "towgeom/error.hpp"
#include "towgeom/report.hpp"
#include "towgeom/volume_mesh.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

using OrderedJson = nlohmann::ordered_json;

/// The name of tow @p t, checked against @p tows.
const std::string& towName(const std::vector<TowSurface>& tows, std::size_t t)
{
    if (t >= tows.size())
        throw Error(ErrorCode::InvalidArgument,
                    "tow index " + std::to_string(t) + " is not one of the " + std::to_string(tows.size()) + " tows given");
    return tows[t].name();
}

/// "loops": per loop its tows, closedness, length, enclosed areas, distance and points.
OrderedJson loopsJson(const IntersectionReport& report, const std::vector<TowSurface>& tows, double spacing, std::size_t threads)
{
    for (const IntersectionLoop& l : report.loops) {
        towName(tows, l.towA());
        towName(tows, l.towB());
    }
    // The per-loop figures (areas cost a quadrature each) on all threads, then the JSON.
    struct LoopFigures {
        double areaA = 0.0, areaB = 0.0;
        std::vector<LoopPoint> points;
    };
    std::vector<LoopFigures> figures(report.loops.size());
    detail::parallelFor(report.loops.size(), detail::workerCount(threads), [&](std::size_t k) {
        const IntersectionLoop& l = report.loops[k];
        figures[k] = {l.enclosedArea(LoopSide::A), l.enclosedArea(LoopSide::B), spacing > 0.0 ? l.resample(spacing) : l.points()};
    });
    OrderedJson loops = OrderedJson::array();
    for (std::size_t k = 0; k < report.loops.size(); ++k) {
        const IntersectionLoop& l = report.loops[k];
        OrderedJson j;
        j["tow_a"] = tows[l.towA()].name();
        j["tow_b"] = tows[l.towB()].name();
        j["closed"] = l.closed();
        if (!l.closed()) j["open_reason"] = l.openReason();
        j["length"] = l.length();
        j["area_a"] = figures[k].areaA;
        j["area_b"] = figures[k].areaB;
        j["max_distance"] = std::max(l.maxDistance(LoopSide::A), l.maxDistance(LoopSide::B));
        const std::vector<LoopPoint>& pts = figures[k].points;
        j["point_count"] = pts.size();
        OrderedJson points = OrderedJson::array();
        for (const LoopPoint& p : pts) points.push_back({p.point.x, p.point.y, p.point.z});
        j["points"] = std::move(points);
        loops.push_back(std::move(j));
    }
    return loops;
}

/// "findings": pairs that meet without an intersection curve.
OrderedJson findingsJson(const IntersectionReport& report, const std::vector<TowSurface>& tows)
{
    OrderedJson findings = OrderedJson::array();
    for (const PairFinding& f : report.findings) {
        const char* kind = f.kind == PairFinding::Kind::Nested       ? "nested"
                           : f.kind == PairFinding::Kind::Contact    ? "contact"
                           : f.kind == PairFinding::Kind::Incomplete ? "incomplete"
                                                                     : "touching";
        findings.push_back({{"tow_a", towName(tows, f.towA)}, {"tow_b", towName(tows, f.towB)}, {"kind", kind}, {"message", f.message}});
    }
    return findings;
}

void putTime(OrderedJson& timings, const char* key, double ms)
{
    if (ms >= 0.0) timings[key] = ms;
}

/// @p j on @p out, compact, with a final newline; an invalid UTF-8 byte in a name or message
/// (names come from file names) becomes U+FFFD instead of an exception.
void dump(const OrderedJson& j, std::ostream& out)
{
    out << j.dump(-1, ' ', false, OrderedJson::error_handler_t::replace) << "\n";
    if (!out) throw Error(ErrorCode::WriteFailed, "could not write the report");
}

/// The report code of a skipped loop's reason.
const char* skipCode(SkippedLoop::Reason r)
{
    switch (r) {
    case SkippedLoop::Reason::OpenCurve: return "open_curve";
    case SkippedLoop::Reason::AroundBothTows: return "around_both_tows";
    case SkippedLoop::Reason::AroundTowWithoutCaps: return "around_tow_without_caps";
    case SkippedLoop::Reason::BandsDoNotAlternate: return "bands_do_not_alternate";
    case SkippedLoop::Reason::CrossesCap: return "crosses_cap";
    case SkippedLoop::Reason::OutsideCell: return "outside_cell";
    case SkippedLoop::Reason::Contact: return "contact";
    }
    return "open_curve";
}

}  // namespace

void writeDetectReport(const IntersectionReport& report, const std::vector<TowSurface>& tows, std::ostream& out,
                       const DetectReportOptions& options)
{
    OrderedJson j;
    j["loops"] = loopsJson(report, tows, options.spacing, options.threads);
    j["findings"] = findingsJson(report, tows);
    j["tow_pairs"] = report.towPairs;
    j["pairs_tested"] = report.pairsTested;
    j["window_pairs"] = report.windowPairs;
    j["seeds"] = report.seeds;
    j["walks"] = report.walks;
    OrderedJson timings = OrderedJson::object();
    putTime(timings, "read", options.times.read);
    putTime(timings, "fit", options.times.fit);
    timings["broad_phase"] = report.timings.broadPhase;
    timings["exact"] = report.timings.exact;
    putTime(timings, "total", options.times.total);
    j["timings_ms"] = std::move(timings);
    dump(j, out);
}

void writeResolveReport(const ResolveResult& result, const std::vector<TowSurface>& tows, std::ostream& out,
                        const ResolveReportOptions& options)
{
    const TextileMesh& mesh = result.mesh;
    if (result.tows.size() != tows.size() || mesh.tows.size() != tows.size())
        throw Error(ErrorCode::InvalidArgument, "the result is of " + std::to_string(result.tows.size()) + " tows, not " +
                                                    std::to_string(tows.size()));
    OrderedJson j;
    OrderedJson towList = OrderedJson::array();
    for (std::size_t t = 0; t < tows.size(); ++t) {
        const TowResolution& r = result.tows[t];
        towList.push_back({{"name", tows[t].name()},
                           {"role", r.role()},
                           {"volume_before", r.volumeBefore},
                           {"volume_after", r.volumeAfter},
                           {"area", r.area},
                           {"triangles", mesh.tows[t].triangles.size()},
                           {"boundary_loops", r.boundaryLoops},
                           {"pieces", r.pieces},
                           {"mesh_size", r.meshSize}});
        if (t < result.shrunk.size()) towList.back()["largest_section_change"] = result.shrunk[t].largestSectionChange();
        if (r.fold)
            towList.back()["fold"] = {{"point", {r.fold->at.x, r.fold->at.y, r.fold->at.z}},
                                      {"uv", {r.fold->uv.u, r.fold->uv.v}},
                                      {"crossing_pairs", r.fold->crossingPairs}};
    }
    j["tows"] = std::move(towList);
    j["loops"] = loopsJson(result.intersections, tows, 0.0, options.threads);
    j["findings"] = findingsJson(result.intersections, tows);
    OrderedJson unresolved = OrderedJson::array();
    for (const UnresolvedPairEntry& p : unresolvedPairs(result))
        unresolved.push_back({{"tow_a", towName(tows, p.towA)}, {"tow_b", towName(tows, p.towB)}, {"reason", p.code}, {"message", p.message}});
    j["unresolved"] = std::move(unresolved);
    OrderedJson regions = OrderedJson::array();
    for (const ConnectedRegion& g : mesh.regions)
        regions.push_back({{"primary", towName(tows, g.primary)},
                           {"secondary", towName(tows, g.secondary)},
                           {"triangles", g.triangles.size()},
                           {"nodes", g.nodes.size()},
                           {"area", g.area},
                           {"volume_removed", g.volumeRemoved},
                           {"surface", g.surface == SharedSurface::Middle ? "middle" : "primary"},
                           {"note", g.note}});
    j["regions"] = std::move(regions);
    OrderedJson triple = OrderedJson::array();
    for (const TriplePoint& p : mesh.triplePoints) {
        if (p.node >= mesh.nodes.size()) throw Error(ErrorCode::InvalidArgument, "a triple point's node is out of range");
        const Point3& x = mesh.nodes[p.node];
        triple.push_back({{"tows", {towName(tows, p.tows[0]), towName(tows, p.tows[1]), towName(tows, p.tows[2])}},
                          {"node", p.node},
                          {"point", {x.x, x.y, x.z}}});
    }
    j["triple_points"] = std::move(triple);
    OrderedJson corners = OrderedJson::array();
    for (const SharpCorner& c : mesh.sharpCorners) {
        if (c.node >= mesh.nodes.size()) throw Error(ErrorCode::InvalidArgument, "a sharp corner's node is out of range");
        const Point3& x = mesh.nodes[c.node];
        corners.push_back({{"tow", towName(tows, c.tow)},
                           {"face", c.face == TowFace::Side ? "side" : c.face == TowFace::Start ? "start" : c.face == TowFace::End ? "end" : "cell"},
                           {"node", c.node},
                           {"point", {x.x, x.y, x.z}},
                           {"angle_deg", c.angle}});
    }
    j["sharp_corners"] = std::move(corners);
    OrderedJson skipped = OrderedJson::array();
    for (const SkippedLoop& s : result.skippedLoops) {
        if (s.loop >= result.intersections.loops.size()) throw Error(ErrorCode::InvalidArgument, "a skipped loop is not in the report");
        const IntersectionLoop& l = result.intersections.loops[s.loop];
        skipped.push_back({{"tow_a", towName(tows, l.towA())}, {"tow_b", towName(tows, l.towB())}, {"code", skipCode(s.reason)}, {"reason", s.message}});
    }
    j["skipped"] = std::move(skipped);
    j["node_count"] = mesh.nodes.size();
    const MeshQuality& q = result.quality;
    j["mesh_quality"] = {{"min_angle_deg", q.minAngle},
                         {"angle_histogram", q.histogram},
                         {"fraction_at_least_20", q.fractionAtLeast(20.0)},
                         {"triangles", q.triangles},
                         {"faces_over_bounds", q.facesOverBounds},
                         {"angle_bound_deg", q.angleBound},
                         {"under_bound", q.underBound},
                         {"at_sharp_corners", q.atSharpCorners},
                         {"min_angle_away_from_corners_deg", q.minAngleAwayFromCorners}};
    j["mesh_rounds"] = result.meshRounds;
    j["crossing_triangle_pairs"] = result.crossingTrianglePairs;
    j["method"] = result.method == ResolutionMethod::Symmetric ? "symmetric" : result.method == ResolutionMethod::Shrink ? "shrink" : "connect";
    if (mesh.cell) {
        const Cell& c = mesh.cell->box;
        std::size_t kept = 0;
        for (const TowMesh& m : mesh.tows) kept += m.triangles.empty() ? 0 : 1;
        j["cell"] = {{"min", {c.min.x, c.min.y, c.min.z}},
                     {"max", {c.max.x, c.max.y, c.max.z}},
                     {"periodic", c.periodic},
                     {"cut", c.cutsMeshes() ? "mesh" : "parametric"},
                     {"face_size_growth", c.faceSizeGrowth},
                     {"face_size_max", c.faceSizeMax},
                     {"volume", c.volume()},
                     {"tows_inside", kept},
                     {"matrix_face_triangles", mesh.cell->triangles.size()}};
    }
    if (const VolumeMesh* v = options.volumes) {
        detail::checkVolumeMeshOf(mesh, *v);
        // Per tow, then the matrix (a mesh clipped to a cell).
        std::vector<std::size_t> count(tows.size() + 1, 0);
        std::vector<double> volume(tows.size() + 1, 0.0);
        for (std::size_t k = 0; k < v->tetrahedra.size(); ++k) {
            ++count[v->tow[k]];
            volume[v->tow[k]] += v->tetrahedronVolume(k);
        }
        OrderedJson perTow = OrderedJson::array();
        double towVolume = 0.0;
        for (std::size_t t = 0; t < tows.size(); ++t) {
            perTow.push_back({{"name", tows[t].name()}, {"tetrahedra", count[t]}, {"volume", volume[t]}});
            towVolume += volume[t];
        }
        j["volume_mesh"] = {{"tetrahedra", v->tetrahedra.size()},
                            {"order", v->edgeNodes.empty() ? 1 : 2},
                            {"nodes", v->nodes.size()},
                            {"inner_nodes", v->nodes.size() - v->surfaceNodes},
                            {"growth_rate", v->growthRate},
                            {"max_size", v->maxSize},
                            {"gmsh_ms", 1000.0 * v->gmshSeconds},
                            {"tows", std::move(perTow)}};
        const TetrahedronQuality q = tetrahedronQuality(*v);
        j["volume_mesh"]["quality"] = {{"min_dihedral_deg", q.minDihedral},
                                       {"max_dihedral_deg", q.maxDihedral},
                                       {"min_dihedral_histogram_bins_deg", {0, 5, 10, 20, 30, 40, 50, 60}},
                                       {"min_dihedral_histogram", q.histogram}};
        if (mesh.cell) {
            j["volume_mesh"]["matrix"] = {{"tetrahedra", count[tows.size()]}, {"volume", volume[tows.size()]}};
            j["volume_mesh"]["tow_volume_fraction"] = towVolume / mesh.cell->box.volume();
        }
    } else if (!options.volumeRefused.empty()) {
        j["volume_mesh"] = {{"refused", options.volumeRefused}};
    }
    OrderedJson timings = OrderedJson::object();
    putTime(timings, "read", options.times.read);
    putTime(timings, "fit", options.times.fit);
    timings["intersect"] = result.timings.intersect;
    timings["mesh"] = result.timings.mesh;
    timings["regions"] = result.timings.regions;
    putTime(timings, "volume", options.times.volume);
    putTime(timings, "brep", options.times.brep);
    putTime(timings, "write", options.times.write);
    putTime(timings, "total", options.times.total);
    j["timings_ms"] = std::move(timings);
    dump(j, out);
}

TOWGEOM_END_NAMESPACE
