// classifyKnotSpans(): every knot-span element of the resolved twill's tows valid, invalid or
// trimmed. Checked independently: the elements' kept areas against the surface's own area
// (TowSurface::area(), OCCT quadrature per knot span) and against the loops' enclosed areas
// (the intersection stage's integrals); whole elements against the loops' exact points.
#include <catch2/catch.hpp>

#include <towgeom/error.hpp>
#include <towgeom/knot_span_classification.hpp>
#include <towgeom/resolve.hpp>

#include <cmath>
#include <sstream>

#include "synthetic_tows.hpp"

using namespace towgeom;

namespace {

/// Winding number of the closed polyline @p poly (v unwrapped) about @p p, in (u,v).
int winding(const std::vector<UV>& poly, UV p)
{
    double angle = 0.0;
    for (std::size_t k = 0; k < poly.size(); ++k) {
        const UV& a = poly[k];
        const UV& b = poly[(k + 1) % poly.size()];
        angle += std::atan2((a.u - p.u) * (b.v - p.v) - (a.v - p.v) * (b.u - p.u), (a.u - p.u) * (b.u - p.u) + (a.v - p.v) * (b.v - p.v));
    }
    return static_cast<int>(std::lround(angle / (2.0 * 3.14159265358979323846)));
}

}  // namespace

TEST_CASE("knot-span classification of the resolved twill: areas add up, whole elements agree with the loops", "[iga][knot_spans]")
{
    const std::vector<TowSurface> tows = testing::fittedTwill22();
    for (const ResolutionMethod method : {ResolutionMethod::Connect, ResolutionMethod::Symmetric}) {
        ResolveOptions o;
        o.method = method;
        const ResolveResult res = resolveTextile(tows, o);
        for (std::size_t t = 0; t < tows.size(); ++t) {
            INFO("tow " << tows[t].name() << (method == ResolutionMethod::Symmetric ? ", symmetric" : ", connect"));
            const KnotSpanClassification c = classifyKnotSpans(tows, res.mesh, t);
            REQUIRE(c.elements.size() == (tows[t].controlPointCount(true) - 3) * tows[t].controlPointCount(false));
            // 1. Against the surface's own area and the loops' enclosed areas: what the tow loses is
            // the inside of each loop where it gives way (to the loops' chords: 1e-3).
            double removed = 0.0;
            std::vector<std::vector<UV>> removing;
            for (const ConnectedRegion& r : res.mesh.regions) {
                if (r.secondary != t && !(r.primary == t && r.surface == SharedSurface::Middle)) continue;
                const IntersectionLoop& l = res.intersections.loops[r.loop];
                const LoopSide side = l.towA() == t ? LoopSide::A : LoopSide::B;
                removed += l.enclosedArea(side);
                std::vector<UV>& poly = removing.emplace_back();
                for (const LoopPoint& p : l.points()) poly.push_back(side == LoopSide::A ? p.onA : p.onB);
            }
            const double area = tows[t].area();
            const double kept = c.keptArea();
            if (removing.empty()) {
                CHECK(std::abs(kept - area) <= 1e-9 * area);
                CHECK(c.count(ElementClass::Valid) == c.elements.size());
            } else {
                CHECK(std::abs(kept - (area - removed)) <= 1e-3 * area);
                CHECK(c.count(ElementClass::Trimmed) > 0);
            }
            // 2. Whole elements: valid ones lie outside every loop where the tow gives way, invalid
            // ones inside one (their centres, against the loops' exact points, periodic in v).
            const double period = tows[t].parameterRange().vPeriod();
            for (const KnotSpanElement& e : c.elements) {
                if (e.kind == ElementClass::Trimmed) {
                    CHECK(e.keptArea > 0.0);
                    CHECK(e.keptArea < e.area);
                    for (const auto& curve : e.trimmingCurves)
                        for (const UV& p : curve) {
                            CHECK(p.u >= e.uMin - 1e-12);
                            CHECK(p.u <= e.uMax + 1e-12);
                            CHECK(p.v >= e.vMin - 1e-12);
                            CHECK(p.v <= e.vMax + 1e-12);
                        }
                    continue;
                }
                CHECK(e.trimmingCurves.empty());
                bool inside = false;
                for (const std::vector<UV>& poly : removing)
                    for (int shift = -1; shift <= 1; ++shift)
                        inside = inside || winding(poly, {0.5 * (e.uMin + e.uMax), 0.5 * (e.vMin + e.vMax) + shift * period}) != 0;
                CHECK(inside == (e.kind == ElementClass::Invalid));
                CHECK(e.keptArea == (e.kind == ElementClass::Valid ? e.area : 0.0));
            }
        }
    }
}

TEST_CASE("knot-span classification written as JSON and VTK", "[iga][knot_spans]")
{
    const std::vector<TowSurface> tows = testing::fittedTwill22();
    const ResolveResult res = resolveTextile(tows);
    const std::size_t weft = 4;  // a secondary
    const KnotSpanClassification c = classifyKnotSpans(tows, res.mesh, weft);
    std::ostringstream json, vtk;
    writeKnotSpansJson(c, json);
    writeKnotSpansVtk(c, tows[weft], vtk);
    CHECK(json.str().find("\"trimmed\":" + std::to_string(c.count(ElementClass::Trimmed))) != std::string::npos);
    CHECK(json.str().find("\"class\":\"invalid\"") != std::string::npos);
    CHECK(vtk.str().find("CELL_DATA " + std::to_string(32 * c.elements.size())) != std::string::npos);
    CHECK_THROWS_AS(classifyKnotSpans(tows, res.mesh, tows.size()), Error);
}

TEST_CASE("knot-span classification of a cell-clipped twill: faces on knot lines trim nothing, curves are whole polylines", "[iga][knot_spans][cell]")
{
    // The cell's faces lie at sections (knots of the tows' u): elements along a face are whole.
    const std::vector<TowSurface> tows = testing::fittedTwill22();
    ResolveOptions o;
    o.cell = Cell{{-0.5, -0.5, -1.0}, {3.5, 3.5, 1.0}};
    const ResolveResult res = resolveTextile(tows, o);
    std::size_t trimmed = 0, invalid = 0;
    for (std::size_t t = 0; t < tows.size(); ++t) {
        INFO("tow " << tows[t].name());
        const KnotSpanClassification c = classifyKnotSpans(tows, res.mesh, t);
        trimmed += c.count(ElementClass::Trimmed);
        invalid += c.count(ElementClass::Invalid);
        for (const KnotSpanElement& e : c.elements) {
            if (e.kind != ElementClass::Trimmed) continue;
            // A trimmed element keeps some of its area, not all.
            CHECK(e.keptArea > 1e-9 * e.area);
            CHECK(e.keptArea < (1.0 - 1e-9) * e.area);
            // Each curve is chained: it is closed inside the element or both its ends lie on the
            // element's edges (where it enters and leaves).
            const double eps = 1e-9 * ((e.uMax - e.uMin) + (e.vMax - e.vMin));
            const auto onEdge = [&](const UV& p) {
                return std::abs(p.u - e.uMin) <= eps || std::abs(p.u - e.uMax) <= eps || std::abs(p.v - e.vMin) <= eps ||
                       std::abs(p.v - e.vMax) <= eps;
            };
            for (const std::vector<UV>& curve : e.trimmingCurves) {
                REQUIRE(curve.size() >= 2);
                const bool closed = std::abs(curve.front().u - curve.back().u) <= eps && std::abs(curve.front().v - curve.back().v) <= eps;
                CHECK((closed || (onEdge(curve.front()) && onEdge(curve.back()))));
            }
        }
    }
    WARN("cell-clipped twill: " << trimmed << " trimmed, " << invalid << " invalid elements over 8 tows");
    CHECK(invalid > 0);  // beyond the faces
    CHECK(trimmed > 0);  // the loops
}
