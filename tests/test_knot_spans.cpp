// classifyKnotSpans(): every knot-span element of the resolved twill's tows valid, invalid or
// trimmed. Checked independently: the elements' kept areas against the surface's own area
// (TowSurface::area(), OCCT quadrature per knot span), against Green's theorem on the kept
// triangles' boundary (1e-9) and against the loops' enclosed areas (the intersection stage's
// integrals, 1e-3: the mesh trims by the loops' chords); whole elements against the loops' exact
// points.
#include <catch2/catch.hpp>

#include <towgeom/bezier_extraction.hpp>
#include <towgeom/error.hpp>
#include <towgeom/knot_span_classification.hpp>
#include <towgeom/resolve.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <sstream>

#include "occt_reference.hpp"
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


/// The area tow @p t keeps of its own surface in @p resolved, computed without the
/// classification: the whole surface's area (TowSurface::area()) plus, by Green's theorem, the
/// integral of F dv along the boundary of what it loses, with F(u,v) = the integral of
/// |S_u x S_v|(s,v) ds from a knot u0 to u. That boundary is the edges of the tow's own kept side
/// triangles (the header's selection) used once and not on the tube's ends, oriented as their
/// triangles run them; each closed chain of them may take its own u0 (the knot below it) as long
/// as it does not wind around the tow (both checked: every node has as many edges in as out,
/// each chain's v turns add up to 0). Every edge is cut at the knot lines (the Bézier
/// extraction's, not the classification's) and F's integral at the u-knots, so each piece's
/// integrand is smooth and 12-point Gauss-Legendre converges to ~1e-11 (it is a square root, not
/// a polynomial).
double keptAreaByGreen(const std::vector<TowSurface>& tows, const ResolveResult& resolved, std::size_t t)
{
    const TowSurface& tow = tows[t];
    const TowMesh& mesh = resolved.mesh.tows[t];
    const double period = tow.parameterRange().vPeriod();
    const ParameterRange range = tow.parameterRange();
    // The distinct knots.
    const BezierSurface bezier = extractBezier(tow);
    std::vector<double> uKnots = bezier.uKnots, vKnots = bezier.vKnots;
    for (std::vector<double>* k : {&uKnots, &vKnots}) {
        std::sort(k->begin(), k->end());
        k->erase(std::unique(k->begin(), k->end()), k->end());
    }
    const std::vector<std::array<double, 2>> gauss = testing::gaussLegendre01(12);
    const auto density = [&](double u, double v) {
        const SurfaceDerivatives d = tow.derivatives(u, v);
        return norm(cross(d.du, d.dv));
    };
    const auto F = [&](double u0, double u, double v) {  // u0 a knot, u0 <= u
        double sum = 0.0;
        for (std::size_t k = 0; k + 1 < uKnots.size(); ++k) {
            const double lo = std::max(uKnots[k], u0), hi = std::min(uKnots[k + 1], u);
            if (hi <= lo) continue;
            for (const auto& [x, w] : gauss) sum += w * (hi - lo) * density(lo + x * (hi - lo), v);
        }
        return sum;
    };
    // The own kept side triangles and their edges used once.
    const std::map<std::size_t, UV> uv(mesh.parameters.begin(), mesh.parameters.end());
    std::map<std::pair<std::size_t, std::size_t>, int> uses;
    std::vector<std::array<std::size_t, 3>> own;
    double orientation = 0.0;  // the triangles' (u,v) area, signed
    for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
        if (mesh.face[k] != TowFace::Side) continue;
        if (mesh.region[k] >= 0) {
            const ConnectedRegion& r = resolved.mesh.regions[static_cast<std::size_t>(mesh.region[k])];
            if (r.secondary == t || r.surface == SharedSurface::Middle) continue;
        }
        const auto& tri = mesh.triangles[k];
        if (!uv.count(tri[0]) || !uv.count(tri[1]) || !uv.count(tri[2])) continue;
        own.push_back(tri);
        UV p[3] = {uv.at(tri[0]), uv.at(tri[1]), uv.at(tri[2])};
        for (UV& q : p) q.v -= period * std::round((q.v - p[0].v) / period);
        orientation += (p[1].u - p[0].u) * (p[2].v - p[0].v) - (p[1].v - p[0].v) * (p[2].u - p[0].u);
        for (std::size_t m = 0; m < 3; ++m) ++uses[std::minmax(tri[m], tri[(m + 1) % 3])];
    }
    const double uEnd = 1e-12 * (range.uMax - range.uMin);
    const auto atEnd = [&](const UV& p, double end) { return std::abs(p.u - end) <= uEnd; };
    std::vector<std::array<std::size_t, 2>> boundary;
    std::map<std::size_t, std::size_t> chain;  // union-find over the boundary's nodes
    const std::function<std::size_t(std::size_t)> root = [&](std::size_t n) {
        auto it = chain.emplace(n, n).first;
        return it->second == n ? n : (it->second = root(it->second));
    };
    for (const auto& tri : own)
        for (std::size_t m = 0; m < 3; ++m) {
            const std::size_t a = tri[m], b = tri[(m + 1) % 3];
            if (uses[std::minmax(a, b)] != 1) continue;
            const UV pa = uv.at(a), pb = uv.at(b);
            if ((atEnd(pa, range.uMin) && atEnd(pb, range.uMin)) || (atEnd(pa, range.uMax) && atEnd(pb, range.uMax))) continue;
            boundary.push_back({a, b});
            chain[root(a)] = root(b);
        }
    // Closed chains: as many edges into each node as out of it.
    std::map<std::size_t, int> balance;
    for (const auto& [a, b] : boundary) {
        ++balance[a];
        --balance[b];
    }
    for (const auto& [n, inOut] : balance) REQUIRE(inOut == 0);
    // Per chain: its knot below, and its winding in v (must be 0).
    std::map<std::size_t, double> u0, winding;
    for (const auto& [a, b] : boundary) {
        const std::size_t r = root(a);
        const double lo = std::min(uv.at(a).u, uv.at(b).u);
        const auto above = std::upper_bound(uKnots.begin(), uKnots.end(), lo);
        const double knot = above == uKnots.begin() ? uKnots.front() : *std::prev(above);
        u0[r] = u0.count(r) ? std::min(u0[r], knot) : knot;
        const double dv = uv.at(b).v - uv.at(a).v;
        winding[r] += dv - period * std::round(dv / period);
    }
    for (const auto& [r, w] : winding) REQUIRE(std::abs(w) <= 1e-9 * period);
    double boundaryIntegral = 0.0;  // of F dv, the edges oriented as their triangles run them
    for (const auto& [a, b] : boundary) {
        const UV pa = uv.at(a);
        UV pb = uv.at(b);
        pb.v -= period * std::round((pb.v - pa.v) / period);
        std::vector<double> cuts{0.0, 1.0};
        for (const double k : uKnots)
            if (pb.u != pa.u) cuts.push_back((k - pa.u) / (pb.u - pa.u));
        for (int shift = -2; shift <= 2; ++shift)
            for (const double k : vKnots)
                if (pb.v != pa.v) cuts.push_back((k + shift * period - pa.v) / (pb.v - pa.v));
        std::sort(cuts.begin(), cuts.end());
        for (std::size_t q = 0; q + 1 < cuts.size(); ++q) {
            const double t0 = std::max(cuts[q], 0.0), t1 = std::min(cuts[q + 1], 1.0);
            if (t1 <= t0) continue;
            for (const auto& [x, w] : gauss) {
                const double s = t0 + x * (t1 - t0);
                boundaryIntegral += w * (t1 - t0) * F(u0[root(a)], pa.u + s * (pb.u - pa.u), pa.v + s * (pb.v - pa.v)) * (pb.v - pa.v);
            }
        }
    }
    return tow.area() + (orientation > 0.0 ? boundaryIntegral : -boundaryIntegral);
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
            // The kept area by Green's theorem on the kept triangles' boundary (no element cut):
            // the elements' kept parts add up to it within 1e-9.
            const double green = keptAreaByGreen(tows, res, t);
            CHECK(std::abs(kept - green) <= 1e-9 * area);
            if (removing.empty()) {
                CHECK(std::abs(kept - area) <= 1e-9 * area);
                CHECK(c.count(ElementClass::Valid) == c.elements.size());
            } else {
                CHECK(area - green > 0.01 * area);  // the check above compares something
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
    o.cell->cut = CellCut::Parametric;  // cuts along the tows' sections
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
