// CGAL first: OpenCASCADE (through seed_search.hpp) defines a macro named Handle.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>  // do_intersect

#include "intersect/seed_search.hpp"

#include <algorithm>
#include <cmath>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;
using Box = CGAL::Box_intersection_d::Box_with_handle_d<double, 3, std::size_t, CGAL::Box_intersection_d::ID_EXPLICIT>;

/// A facet with the (u, v) of its corners (v unwrapped across the seam).
struct Facet {
    Triangle triangle;
    UV uv[3];
};

/// The rows of @p g's grid that window @p w covers: [first, last].
std::pair<std::size_t, std::size_t> rowsOf(const SurfaceGrid& g, const UWindow& w)
{
    const std::size_t m = g.u.size();
    const auto lo = std::upper_bound(g.u.begin(), g.u.end(), w.uMin);
    const std::size_t first = lo == g.u.begin() ? 0 : static_cast<std::size_t>(lo - g.u.begin()) - 1;
    std::size_t last = first;
    while (last + 1 < m && g.u[last] < w.uMax) ++last;
    return {first, last};
}

/// The box of the grid points of rows [first, last] (the box of the facets between them).
CGAL::Bbox_3 boxOfRows(const SurfaceGrid& g, std::pair<std::size_t, std::size_t> rows)
{
    const std::size_t n = g.v.size();
    CGAL::Bbox_3 box;
    for (std::size_t k = rows.first * n; k < (rows.second + 1) * n && k < g.points.size(); ++k) {
        const Point3& q = g.points[k];
        box += CGAL::Bbox_3(q.x, q.y, q.z, q.x, q.y, q.z);
    }
    return box;
}

/// The facets between rows [first, last] of @p g that reach into @p other (the other window's
/// box): most of a window, the far side of each tow, drops out before any triangle is made.
std::vector<Facet> facetsIn(const SurfaceGrid& g, std::pair<std::size_t, std::size_t> rows, const CGAL::Bbox_3& other)
{
    std::vector<Facet> facets;
    const std::size_t n = g.v.size();
    const auto reaches = [&](const Point3& p, const Point3& q, const Point3& r) {
        return std::max({p.x, q.x, r.x}) >= other.xmin() && std::min({p.x, q.x, r.x}) <= other.xmax() &&
               std::max({p.y, q.y, r.y}) >= other.ymin() && std::min({p.y, q.y, r.y}) <= other.ymax() &&
               std::max({p.z, q.z, r.z}) >= other.zmin() && std::min({p.z, q.z, r.z}) <= other.zmax();
    };
    const auto pt = [](const Point3& q) { return Point(q.x, q.y, q.z); };
    for (std::size_t i = rows.first; i < rows.second; ++i)
        for (std::size_t j = 0; j < n; ++j) {
            const std::size_t jn = (j + 1) % n;
            const double vj = g.v[j], vn = j + 1 < n ? g.v[jn] : g.v[0] + g.period;
            const Point3 &p00 = g.points[i * n + j], &p10 = g.points[(i + 1) * n + j], &p11 = g.points[(i + 1) * n + jn],
                         &p01 = g.points[i * n + jn];
            if (reaches(p00, p10, p11))
                facets.push_back({Triangle(pt(p00), pt(p10), pt(p11)), {{g.u[i], vj}, {g.u[i + 1], vj}, {g.u[i + 1], vn}}});
            if (reaches(p00, p11, p01))
                facets.push_back({Triangle(pt(p00), pt(p11), pt(p01)), {{g.u[i], vj}, {g.u[i + 1], vn}, {g.u[i], vn}}});
        }
    return facets;
}

/// (u, v) of the point of @p f's plane nearest @p p, by barycentric interpolation.
UV interpolate(const Facet& f, const Point& p)
{
    const Kernel::Vector_3 e1 = f.triangle[1] - f.triangle[0], e2 = f.triangle[2] - f.triangle[0], d = p - f.triangle[0];
    const double a = e1 * e1, b = e1 * e2, c = e2 * e2, r1 = d * e1, r2 = d * e2;
    const double det = a * c - b * b;
    double s = 1.0 / 3.0, t = 1.0 / 3.0;
    if (det > 0.0) {
        s = std::clamp((c * r1 - b * r2) / det, 0.0, 1.0);
        t = std::clamp((a * r2 - b * r1) / det, 0.0, 1.0 - s);
    }
    const double w0 = 1.0 - s - t;
    return {w0 * f.uv[0].u + s * f.uv[1].u + t * f.uv[2].u, w0 * f.uv[0].v + s * f.uv[1].v + t * f.uv[2].v};
}

/// A guess of a point of the crossing of two triangles known to intersect: the midpoint of
/// their centroids, within a facet's size of the crossing. (Constructing the crossing itself
/// with inexact constructions is not safe: CGAL's coplanar case crashed on coincident tubes,
/// and Newton's method refines the guess anyway.)
Point crossingGuess(const Triangle& x, const Triangle& y)
{
    return CGAL::midpoint(CGAL::centroid(x), CGAL::centroid(y));
}

double longestEdge(const Triangle& t)
{
    return std::sqrt(std::max({CGAL::squared_distance(t[0], t[1]), CGAL::squared_distance(t[1], t[2]),
                               CGAL::squared_distance(t[2], t[0])}));
}

}  // namespace

SurfaceGrid sampleGrid(const TowSurface& tow)
{
    // The input's own stations, subdivided where the input is coarse: at least kMinAround
    // stations around (chord error below ~2e-3 of the size of a round tow), and steps along the
    // tow no longer than twice those around. Coarse input would otherwise give facets far from
    // the surface, and shallow interpenetrations no facet crossing.
    constexpr std::size_t kMinAround = 48;
    const std::vector<double>& us = tow.sectionParameters();
    const std::vector<double>& vs = tow.pointParameters();
    const ParameterRange r = tow.parameterRange();
    SurfaceGrid g;
    g.period = r.vPeriod();
    const std::size_t perV = (kMinAround + vs.size() - 1) / vs.size();
    for (std::size_t j = 0; j < vs.size(); ++j) {
        const double next = j + 1 < vs.size() ? vs[j + 1] : vs[0] + g.period;
        for (std::size_t k = 0; k < perV; ++k) g.v.push_back(vs[j] + (next - vs[j]) * static_cast<double>(k) / static_cast<double>(perV));
    }
    const double stepAround = M_PI * tow.towSize() / static_cast<double>(g.v.size());
    const auto& sections = tow.sections();
    const auto centre = [&](std::size_t i) {
        Point3 c;
        for (const Point3& p : sections[i]) c = c + p;
        return (1.0 / static_cast<double>(sections[i].size())) * c;
    };
    for (std::size_t i = 0; i + 1 < us.size(); ++i) {
        const double along = distance(centre(i), centre(i + 1));
        const std::size_t perU = std::min<std::size_t>(64, std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(along / (2.0 * stepAround)))));
        for (std::size_t k = 0; k < perU; ++k) g.u.push_back(us[i] + (us[i + 1] - us[i]) * static_cast<double>(k) / static_cast<double>(perU));
    }
    g.u.push_back(us.back());
    g.points.reserve(g.u.size() * g.v.size());
    for (double u : g.u)
        for (double v : g.v) g.points.push_back(tow.point(u, v));
    return g;
}

std::vector<Seed> findSeeds(const SurfaceGrid& a, const SurfaceGrid& b, const WindowPair& window)
{
    const auto rowsA = rowsOf(a, window.a), rowsB = rowsOf(b, window.b);
    const std::vector<Facet> fa = facetsIn(a, rowsA, boxOfRows(b, rowsB)), fb = facetsIn(b, rowsB, boxOfRows(a, rowsA));
    std::vector<Box> ba, bb;
    ba.reserve(fa.size());
    bb.reserve(fb.size());
    for (std::size_t k = 0; k < fa.size(); ++k) ba.emplace_back(fa[k].triangle.bbox(), k);
    for (std::size_t k = 0; k < fb.size(); ++k) bb.emplace_back(fb[k].triangle.bbox(), k);
    std::vector<std::pair<std::size_t, std::size_t>> hits;
    CGAL::box_intersection_d(ba.begin(), ba.end(), bb.begin(), bb.end(), [&](const Box& x, const Box& y) {
        if (CGAL::do_intersect(fa[x.handle()].triangle, fb[y.handle()].triangle)) hits.emplace_back(x.handle(), y.handle());
    });
    std::sort(hits.begin(), hits.end());
    std::vector<Seed> seeds;
    seeds.reserve(hits.size());
    for (const auto& [i, j] : hits) {
        const Point p = crossingGuess(fa[i].triangle, fb[j].triangle);
        const UV ua = interpolate(fa[i], p), ub = interpolate(fb[j], p);
        Seed s;
        s.guess.ua = ua.u;
        s.guess.va = ua.v;
        s.guess.ub = ub.u;
        s.guess.vb = ub.v;
        s.guess.point = {p.x(), p.y(), p.z()};
        s.facetSize = std::min(longestEdge(fa[i].triangle), longestEdge(fb[j].triangle));
        seeds.push_back(s);
    }
    return seeds;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
