// Knot-span classification: the tow's own kept side triangles in (u,v) cut by each element's box
// (CGAL), the surface area integrated over every piece (collapsed Gauss-Legendre on triangles,
// OCCT's exact derivatives).
#include "towgeom/knot_span_classification.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>
#include <GeomAdaptor_Surface.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>
#include <math.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <ostream>

#include "surface/tow_surface_impl.hpp"
#include "towgeom/error.hpp"
#include "towgeom/vtk_writer.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using P2 = Kernel::Point_2;
using CornerIndices = std::array<std::size_t, 3>;

constexpr int kGauss = 12;  // Gauss-Legendre points per direction: ~1e-9 relative or better on a tow's elements

/// Gauss-Legendre points and weights on [0, 1] (OCCT's math::GaussPoints on [-1, 1]).
struct GaussRule {
    std::array<double, kGauss> x{}, w{};
    GaussRule()
    {
        math_Vector points(1, kGauss), weights(1, kGauss);
        math::GaussPoints(kGauss, points);
        math::GaussWeights(kGauss, weights);
        for (int i = 0; i < kGauss; ++i) {
            x[static_cast<std::size_t>(i)] = 0.5 * (points(i + 1) + 1.0);
            w[static_cast<std::size_t>(i)] = 0.5 * weights(i + 1);
        }
    }
};

/// |S_u x S_v| at (u, v).
double areaDensity(const GeomAdaptor_Surface& s, double u, double v)
{
    gp_Pnt p;
    gp_Vec su, sv;
    s.D1(u, v, p, su, sv);
    return su.Crossed(sv).Magnitude();
}

/// The surface area over the (u,v) triangle a, b, c: Gauss-Legendre on the square collapsed onto
/// the triangle (Duffy).
double triangleIntegral(const GeomAdaptor_Surface& s, const GaussRule& g, const P2& a, const P2& b, const P2& c)
{
    const double twiceArea = std::abs((b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x()));
    if (twiceArea == 0.0) return 0.0;
    double sum = 0.0;
    for (std::size_t i = 0; i < kGauss; ++i)
        for (std::size_t j = 0; j < kGauss; ++j) {
            const double xi = g.x[i], eta = g.x[j];
            const double u = (1.0 - xi) * a.x() + xi * (1.0 - eta) * b.x() + xi * eta * c.x();
            const double v = (1.0 - xi) * a.y() + xi * (1.0 - eta) * b.y() + xi * eta * c.y();
            sum += g.w[i] * g.w[j] * xi * areaDensity(s, u, v);
        }
    return sum * twiceArea;
}

/// The surface area over the (u,v) box [u0, u1] x [v0, v1]: tensor Gauss-Legendre.
double boxIntegral(const GeomAdaptor_Surface& s, const GaussRule& g, double u0, double u1, double v0, double v1)
{
    double sum = 0.0;
    for (std::size_t i = 0; i < kGauss; ++i)
        for (std::size_t j = 0; j < kGauss; ++j)
            sum += g.w[i] * g.w[j] * areaDensity(s, u0 + g.x[i] * (u1 - u0), v0 + g.x[j] * (v1 - v0));
    return sum * (u1 - u0) * (v1 - v0);
}

/// The surface area over the convex (u,v) polygon @p p (a fan from its first corner).
double polygonIntegral(const GeomAdaptor_Surface& s, const GaussRule& g, const std::vector<P2>& p)
{
    double sum = 0.0;
    for (std::size_t k = 1; k + 1 < p.size(); ++k) sum += triangleIntegral(s, g, p[0], p[k], p[k + 1]);
    return sum;
}

/// The part of triangle @p t inside box @p box, as a convex polygon (empty when only an edge or
/// a point, or nothing, is shared): CGAL's triangle / iso-rectangle intersection.
std::vector<P2> clip(const Kernel::Triangle_2& t, const Kernel::Iso_rectangle_2& box)
{
    const auto x = CGAL::intersection(t, box);
    if (!x) return {};
    if (const Kernel::Triangle_2* tri = boost::get<Kernel::Triangle_2>(&*x)) return {tri->vertex(0), tri->vertex(1), tri->vertex(2)};
    if (const std::vector<P2>* poly = boost::get<std::vector<P2>>(&*x)) return *poly;
    return {};
}

/// The distinct knots of a B-spline direction.
std::vector<double> distinctKnots(const TColStd_Array1OfReal& knots)
{
    std::vector<double> k;
    for (int i = knots.Lower(); i <= knots.Upper(); ++i) k.push_back(knots(i));
    return k;
}

/// The spans [k[i], k[i+1]] of @p knots that hold [lo, hi] (by index).
std::pair<std::size_t, std::size_t> spanRange(const std::vector<double>& knots, double lo, double hi)
{
    const std::size_t spans = knots.size() - 1;
    std::size_t first = static_cast<std::size_t>(std::upper_bound(knots.begin(), knots.end(), lo) - knots.begin());
    first = first == 0 ? 0 : first - 1;
    std::size_t last = static_cast<std::size_t>(std::lower_bound(knots.begin(), knots.end(), hi) - knots.begin());
    last = last == 0 ? 0 : last - 1;
    return {std::min(first, spans - 1), std::min(last, spans - 1)};
}

}  // namespace

double KnotSpanClassification::keptArea() const
{
    double sum = 0.0;
    for (const KnotSpanElement& e : elements) sum += e.keptArea;
    return sum;
}

std::size_t KnotSpanClassification::count(ElementClass kind) const
{
    return static_cast<std::size_t>(std::count_if(elements.begin(), elements.end(), [&](const KnotSpanElement& e) { return e.kind == kind; }));
}

KnotSpanClassification classifyKnotSpans(const std::vector<TowSurface>& tows, const TextileMesh& resolved, std::size_t t)
{
    if (t >= tows.size() || resolved.tows.size() != tows.size())
        throw Error(ErrorCode::InvalidArgument, "classifyKnotSpans(): tow " + std::to_string(t) + " of " + std::to_string(tows.size()) +
                                                    " tows, the mesh has " + std::to_string(resolved.tows.size()));
    const TowSurface& tow = tows[t];
    const TowMesh& mesh = resolved.tows[t];
    if (mesh.name != tow.name()) throw Error(ErrorCode::InvalidArgument, "classifyKnotSpans(): the mesh's tow is '" + mesh.name + "'", "tow '" + tow.name() + "'");
    const Handle(Geom_BSplineSurface)& surface = tow.impl().surface;
    const GeomAdaptor_Surface s(surface);
    const GaussRule gauss;
    const std::vector<double> uKnots = distinctKnots(surface->UKnots()), vKnots = distinctKnots(surface->VKnots());
    const double period = tow.parameterRange().vPeriod();
    const double v0 = vKnots.front();
    KnotSpanClassification out;
    out.tow = tow.name();
    const std::size_t nu = uKnots.size() - 1, nv = vKnots.size() - 1;
    for (std::size_t i = 0; i < nu; ++i)
        for (std::size_t j = 0; j < nv; ++j) {
            KnotSpanElement e;
            e.uSpan = i;
            e.vSpan = j;
            e.uMin = uKnots[i];
            e.uMax = uKnots[i + 1];
            e.vMin = vKnots[j];
            e.vMax = vKnots[j + 1];
            e.area = boxIntegral(s, gauss, e.uMin, e.uMax, e.vMin, e.vMax);
            out.elements.push_back(std::move(e));
        }
    // The tow's own kept side triangles in (u,v), v unwrapped from the first corner.
    std::map<std::size_t, UV> uv(mesh.parameters.begin(), mesh.parameters.end());
    std::vector<std::array<UV, 3>> own;
    std::vector<CornerIndices> ownNodes;
    for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
        if (k < mesh.face.size() && mesh.face[k] != TowFace::Side) continue;
        const long id = k < mesh.region.size() ? mesh.region[k] : -1;
        if (id >= 0 && static_cast<std::size_t>(id) < resolved.regions.size()) {
            const ConnectedRegion& r = resolved.regions[static_cast<std::size_t>(id)];
            if (r.secondary == t || r.surface == SharedSurface::Middle) continue;  // another tow's surface, or the mid-surface
        }
        std::array<UV, 3> c{};
        bool onSurface = true;
        for (std::size_t m = 0; m < 3 && onSurface; ++m) {
            const auto it = uv.find(mesh.triangles[k][m]);
            if (it == uv.end()) onSurface = false;
            else c[m] = it->second;
        }
        if (!onSurface) continue;
        for (std::size_t m = 1; m < 3; ++m) c[m].v -= period * std::round((c[m].v - c[0].v) / period);
        own.push_back(c);
        ownNodes.push_back(mesh.triangles[k]);
    }
    // The trimming curves: edges of the own kept triangles used once (not along the tube's ends),
    // oriented as their triangle runs them (the kept side on the left), cut by each element.
    std::vector<std::vector<std::array<UV, 2>>> pieces(out.elements.size());  // per element, unchained
    std::map<std::pair<std::size_t, std::size_t>, int> uses;
    for (const CornerIndices& tri : ownNodes)
        for (std::size_t m = 0; m < 3; ++m) ++uses[std::minmax(tri[m], tri[(m + 1) % 3])];
    const ParameterRange range = tow.parameterRange();
    const double uEnd = 1e-12 * (range.uMax - range.uMin);
    for (std::size_t k = 0; k < own.size(); ++k)
        for (std::size_t m = 0; m < 3; ++m) {
            if (uses[std::minmax(ownNodes[k][m], ownNodes[k][(m + 1) % 3])] != 1) continue;
            const UV a = own[k][m], b = own[k][(m + 1) % 3];
            const bool atEnd = (std::abs(a.u - range.uMin) <= uEnd && std::abs(b.u - range.uMin) <= uEnd) ||
                               (std::abs(a.u - range.uMax) <= uEnd && std::abs(b.u - range.uMax) <= uEnd);
            if (atEnd) continue;
            for (int shift = -2; shift <= 2; ++shift) {
                const double dv = shift * period;
                const Kernel::Segment_2 seg(P2(a.u, a.v + dv), P2(b.u, b.v + dv));
                const double vLo = std::min(a.v, b.v) + dv, vHi = std::max(a.v, b.v) + dv;
                if (vHi < v0 || vLo > v0 + period) continue;
                const auto [i0, i1] = spanRange(uKnots, std::min(a.u, b.u), std::max(a.u, b.u));
                const auto [j0, j1] = spanRange(vKnots, std::max(vLo, v0), std::min(vHi, v0 + period));
                for (std::size_t i = i0; i <= i1; ++i)
                    for (std::size_t j = j0; j <= j1; ++j) {
                        KnotSpanElement& e = out.elements[i * nv + j];
                        const auto x = CGAL::intersection(seg, Kernel::Iso_rectangle_2(P2(e.uMin, e.vMin), P2(e.uMax, e.vMax)));
                        const Kernel::Segment_2* inside = x ? boost::get<Kernel::Segment_2>(&*x) : nullptr;
                        if (!inside) continue;
                        P2 p0 = inside->source(), p1 = inside->target();
                        // Not a cut: a piece of negligible length, or one along the element's
                        // own edge (a boundary on a knot line, e.g. a cell face at a section).
                        const double du = e.uMax - e.uMin, dvE = e.vMax - e.vMin;
                        const double eps = 1e-12 * (du + dvE);
                        if (std::sqrt(CGAL::to_double(inside->squared_length())) <= eps) continue;
                        const auto onSide = [&](double a, double b, double side) { return std::abs(a - side) <= eps && std::abs(b - side) <= eps; };
                        if (onSide(p0.x(), p1.x(), e.uMin) || onSide(p0.x(), p1.x(), e.uMax) || onSide(p0.y(), p1.y(), e.vMin) ||
                            onSide(p0.y(), p1.y(), e.vMax))
                            continue;
                        if ((p1 - p0) * (seg.target() - seg.source()) < 0.0) std::swap(p0, p1);  // along the edge
                        pieces[i * nv + j].push_back({UV{p0.x(), p0.y()}, UV{p1.x(), p1.y()}});
                    }
            }
        }
    // Each triangle against each element it meets (its copies a period apart too): an element no
    // trimming curve crosses is kept whole as soon as one triangle covers part of it; in the
    // others the kept pieces are integrated.
    std::vector<double> covered(out.elements.size(), 0.0);  // the (u,v) area the kept triangles cover
    const auto boxArea = [&](const KnotSpanElement& e) { return (e.uMax - e.uMin) * (e.vMax - e.vMin); };
    for (std::size_t k = 0; k < own.size(); ++k) {
        const std::array<UV, 3>& c = own[k];
        const double uLo = std::min({c[0].u, c[1].u, c[2].u}), uHi = std::max({c[0].u, c[1].u, c[2].u});
        const double vLo = std::min({c[0].v, c[1].v, c[2].v}), vHi = std::max({c[0].v, c[1].v, c[2].v});
        for (int shift = -2; shift <= 2; ++shift) {
            const double dv = shift * period;
            if (vHi + dv <= v0 || vLo + dv >= v0 + period) continue;
            const Kernel::Triangle_2 tri(P2(c[0].u, c[0].v + dv), P2(c[1].u, c[1].v + dv), P2(c[2].u, c[2].v + dv));
            const auto [i0, i1] = spanRange(uKnots, uLo, uHi);
            const auto [j0, j1] = spanRange(vKnots, std::max(vLo + dv, v0), std::min(vHi + dv, v0 + period));
            for (std::size_t i = i0; i <= i1; ++i)
                for (std::size_t j = j0; j <= j1; ++j) {
                    const std::size_t id = i * nv + j;
                    if (pieces[id].empty() && covered[id] > 0.5 * boxArea(out.elements[id])) continue;  // whole, decided
                    KnotSpanElement& e = out.elements[id];
                    const std::vector<P2> piece = clip(tri, Kernel::Iso_rectangle_2(P2(e.uMin, e.vMin), P2(e.uMax, e.vMax)));
                    if (piece.size() < 3) continue;
                    double twice = 0.0;  // the piece's (u,v) area by the shoelace formula, either orientation
                    for (std::size_t q = 0; q < piece.size(); ++q) {
                        const P2& a = piece[q];
                        const P2& b = piece[(q + 1) % piece.size()];
                        twice += a.x() * b.y() - a.y() * b.x();
                    }
                    covered[id] += 0.5 * std::abs(twice);
                    if (!pieces[id].empty()) e.keptArea += polygonIntegral(s, gauss, piece);
                }
        }
    }
    // Each element's pieces chained into polylines (a piece joins where another ends, either
    // way round), so a curve runs from where it enters the element to where it leaves.
    for (std::size_t k = 0; k < out.elements.size(); ++k) {
        KnotSpanElement& e = out.elements[k];
        std::vector<std::array<UV, 2>>& left = pieces[k];
        const double eps = 1e-11 * ((e.uMax - e.uMin) + (e.vMax - e.vMin));
        const auto same = [&](const UV& a, const UV& b) { return std::abs(a.u - b.u) <= eps && std::abs(a.v - b.v) <= eps; };
        while (!left.empty()) {
            std::vector<UV> curve{left.back()[0], left.back()[1]};
            left.pop_back();
            for (bool grown = true; grown;) {
                grown = false;
                for (std::size_t q = 0; q < left.size(); ++q) {
                    if (same(left[q][0], curve.back())) curve.push_back(left[q][1]);
                    else if (same(left[q][1], curve.front())) curve.insert(curve.begin(), left[q][0]);
                    else continue;
                    left.erase(left.begin() + static_cast<std::ptrdiff_t>(q));
                    grown = true;
                    break;
                }
            }
            e.trimmingCurves.push_back(std::move(curve));
        }
    }
    // A trimming curve through it makes an element trimmed; one without is kept whole or not
    // at all (its measured kept area is then its area or 0 to the quadrature, ~1e-8).
    for (std::size_t k = 0; k < out.elements.size(); ++k) {
        KnotSpanElement& e = out.elements[k];
        const double ratio = e.area > 0.0 ? e.keptArea / e.area : 0.0;
        if (!e.trimmingCurves.empty() && ratio > 1e-12 && ratio < 1.0 - 1e-12) {
            e.kind = ElementClass::Trimmed;
            continue;
        }
        // Whole: without a curve, kept if a triangle covers part of it; with one that keeps all
        // or nothing (a curve grazing it), by its kept area.
        // (Slivers of triangles rounding past a knot line cover next to nothing: not kept.)
        const bool kept = e.trimmingCurves.empty() ? covered[k] > 0.5 * boxArea(e) : ratio >= 0.5;
        e.trimmingCurves.clear();
        e.kind = kept ? ElementClass::Valid : ElementClass::Invalid;
        e.keptArea = kept ? e.area : 0.0;
    }
    return out;
}

void writeKnotSpansJson(const KnotSpanClassification& c, std::ostream& out)
{
    using Json = nlohmann::ordered_json;
    static const char* names[] = {"valid", "invalid", "trimmed"};
    Json elements = Json::array();
    for (const KnotSpanElement& e : c.elements) {
        Json curves = Json::array();
        for (const std::vector<UV>& curve : e.trimmingCurves) {
            Json points = Json::array();
            for (const UV& p : curve) points.push_back({p.u, p.v});
            curves.push_back(std::move(points));
        }
        elements.push_back({{"u_span", e.uSpan},
                            {"v_span", e.vSpan},
                            {"u", {e.uMin, e.uMax}},
                            {"v", {e.vMin, e.vMax}},
                            {"class", names[static_cast<int>(e.kind)]},
                            {"area", e.area},
                            {"kept_area", e.keptArea},
                            {"trimming_curves", std::move(curves)}});
    }
    const Json j = {{"tow", c.tow},
                    {"valid", c.count(ElementClass::Valid)},
                    {"invalid", c.count(ElementClass::Invalid)},
                    {"trimmed", c.count(ElementClass::Trimmed)},
                    {"kept_area", c.keptArea()},
                    {"elements", std::move(elements)}};
    out << j.dump(-1, ' ', false, Json::error_handler_t::replace) << "\n";
    if (!out) throw Error(ErrorCode::WriteFailed, "could not write the knot-span classification", "tow '" + c.tow + "'");
}

void writeKnotSpansVtk(const KnotSpanClassification& c, const TowSurface& tow, std::ostream& out)
{
    constexpr std::size_t kGrid = 4;
    TriangleMesh m;
    std::vector<long> kind, element;
    for (std::size_t k = 0; k < c.elements.size(); ++k) {
        const KnotSpanElement& e = c.elements[k];
        const std::size_t first = m.vertices.size();
        for (std::size_t b = 0; b <= kGrid; ++b)
            for (std::size_t a = 0; a <= kGrid; ++a)
                m.vertices.push_back(tow.point(e.uMin + (e.uMax - e.uMin) * static_cast<double>(a) / kGrid,
                                               e.vMin + (e.vMax - e.vMin) * static_cast<double>(b) / kGrid));
        for (std::size_t b = 0; b < kGrid; ++b)
            for (std::size_t a = 0; a < kGrid; ++a) {
                const std::size_t p = first + b * (kGrid + 1) + a;
                m.triangles.push_back({p, p + 1, p + kGrid + 2});
                m.triangles.push_back({p, p + kGrid + 2, p + kGrid + 1});
                for (int twice = 0; twice < 2; ++twice) {
                    kind.push_back(static_cast<long>(e.kind));
                    element.push_back(static_cast<long>(k));
                }
            }
    }
    writeVtk(m, out, "towgeom knot-span elements of tow " + c.tow, {{"class", kind}, {"element", element}});
}

TOWGEOM_END_NAMESPACE
