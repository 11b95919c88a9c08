#include "cli/loop_json.hpp"

#include <algorithm>

#include "core/parallel.hpp"

namespace towgeom::cli {

void writeLoopsJson(detail::JsonWriter& json, const IntersectionReport& report, const std::vector<TowSurface>& tows,
                    double spacing, std::size_t threads)
{
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
    json.key("loops").beginArray();
    for (std::size_t k = 0; k < report.loops.size(); ++k) {
        const IntersectionLoop& l = report.loops[k];
        json.beginObject();
        json.key("tow_a").value(tows[l.towA()].name());
        json.key("tow_b").value(tows[l.towB()].name());
        json.key("closed").value(l.closed());
        if (!l.closed()) json.key("open_reason").value(l.openReason());
        json.key("length").value(l.length());
        json.key("area_a").value(figures[k].areaA);
        json.key("area_b").value(figures[k].areaB);
        json.key("max_distance").value(std::max(l.maxDistance(LoopSide::A), l.maxDistance(LoopSide::B)));
        const std::vector<LoopPoint>& pts = figures[k].points;
        json.key("point_count").value(pts.size());
        json.key("points").beginArray();
        for (const LoopPoint& p : pts) json.beginArray().value(p.point.x).value(p.point.y).value(p.point.z).endArray();
        json.endArray();
        json.endObject();
    }
    json.endArray();
}

void writeFindingsJson(detail::JsonWriter& json, const IntersectionReport& report, const std::vector<TowSurface>& tows)
{
    json.key("findings").beginArray();
    for (const PairFinding& f : report.findings) {
        const char* kind = f.kind == PairFinding::Kind::Nested ? "nested" : f.kind == PairFinding::Kind::Contact ? "contact" : "touching";
        json.beginObject().key("tow_a").value(tows[f.towA].name()).key("tow_b").value(tows[f.towB].name());
        json.key("kind").value(kind).key("message").value(f.message).endObject();
    }
    json.endArray();
}

}  // namespace towgeom::cli
