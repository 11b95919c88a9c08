#include "mesh/crossing_triangles.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <tuple>

#include "core/parallel.hpp"
#include "core/triangle_crossings.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using CornerIndices = std::array<std::size_t, 3>;
using TriangleBox = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;

/// A tow's triangles as points: shared nodes and its own.
struct TowNodes {
    const std::vector<Point3>& shared;
    std::size_t ownFrom;
    const TowTriangles& tow;
    const Point3& node(std::size_t n) const { return n < ownFrom ? shared[n] : (*tow.own)[n - ownFrom]; }
    K::Point_3 point(std::size_t n) const
    {
        const Point3& p = node(n);
        return {p.x, p.y, p.z};
    }
    const CornerIndices& triangle(std::size_t k) const { return (*tow.triangles)[k]; }
    K::Triangle_3 geometry(std::size_t k) const
    {
        const CornerIndices& t = triangle(k);
        return {point(t[0]), point(t[1]), point(t[2])};
    }
    CGAL::Bbox_3 box(std::size_t k) const
    {
        const CornerIndices& t = triangle(k);
        return point(t[0]).bbox() + point(t[1]).bbox() + point(t[2]).bbox();
    }
};

/// Whether triangle @p i of @p a and triangle @p j of @p b meet beyond the shared nodes they
/// have in common (see crossingTriangles()).
bool cross(const TowNodes& a, std::size_t i, const TowNodes& b, std::size_t j)
{
    const CornerIndices &s = a.triangle(i), &t = b.triangle(j);
    return trianglesCross(s, {a.point(s[0]), a.point(s[1]), a.point(s[2])}, t, {b.point(t[0]), b.point(t[1]), b.point(t[2])}, a.ownFrom);
}

/// The box of every node a tow's triangles use.
CGAL::Bbox_3 boxOf(const TowNodes& tow)
{
    CGAL::Bbox_3 b;
    for (const CornerIndices& t : *tow.tow.triangles)
        for (std::size_t n : t) b += tow.point(n).bbox();
    return b;
}

/// The box common to @p a and @p b (which overlap).
CGAL::Bbox_3 overlapOf(const CGAL::Bbox_3& a, const CGAL::Bbox_3& b)
{
    return {std::max(a.xmin(), b.xmin()), std::max(a.ymin(), b.ymin()), std::max(a.zmin(), b.zmin()),
            std::min(a.xmax(), b.xmax()), std::min(a.ymax(), b.ymax()), std::min(a.zmax(), b.zmax())};
}

/// The boxes of @p tow's triangles that meet @p within.
std::vector<TriangleBox> boxesWithin(const TowNodes& tow, const CGAL::Bbox_3& within)
{
    std::vector<TriangleBox> out;
    for (std::size_t k = 0; k < tow.tow.triangles->size(); ++k) {
        const CGAL::Bbox_3 b = tow.box(k);
        if (CGAL::do_overlap(b, within)) out.emplace_back(b, k);
    }
    return out;
}

/// Cells of a grid over a box, each marked when a triangle's box touches it.
class OccupancyGrid {
public:
    OccupancyGrid(const CGAL::Bbox_3& box, double cell) : box_(box), cell_(cell)
    {
        for (int d = 0; d < 3; ++d) n_[d] = std::max(1, static_cast<int>(std::ceil((box.max(d) - box.min(d)) / cell)));
        marked_.assign(static_cast<std::size_t>(n_[0]) * static_cast<std::size_t>(n_[1]) * static_cast<std::size_t>(n_[2]), false);
    }
    void mark(const CGAL::Bbox_3& b)
    {
        visit(b, [&](std::size_t k) {
            marked_[k] = true;
            return false;
        });
    }
    bool touches(const CGAL::Bbox_3& b) const { return visit(b, [&](std::size_t k) { return bool(marked_[k]); }); }

private:
    /// Calls @p f on every cell @p b touches until it returns true; returns whether it did.
    template <class F>
    bool visit(const CGAL::Bbox_3& b, F&& f) const
    {
        int lo[3], hi[3];
        for (int d = 0; d < 3; ++d) {
            lo[d] = std::clamp(static_cast<int>(std::floor((b.min(d) - box_.min(d)) / cell_)), 0, n_[d] - 1);
            hi[d] = std::clamp(static_cast<int>(std::floor((b.max(d) - box_.min(d)) / cell_)), 0, n_[d] - 1);
        }
        for (int i = lo[0]; i <= hi[0]; ++i)
            for (int j = lo[1]; j <= hi[1]; ++j)
                for (int k = lo[2]; k <= hi[2]; ++k)
                    if (f((static_cast<std::size_t>(i) * static_cast<std::size_t>(n_[1]) + static_cast<std::size_t>(j)) *
                              static_cast<std::size_t>(n_[2]) +
                          static_cast<std::size_t>(k)))
                        return true;
        return false;
    }
    CGAL::Bbox_3 box_;
    double cell_;
    int n_[3];
    std::vector<bool> marked_;
};

/// Keeps only the boxes of @p a and @p b (all within @p both) that share a grid cell with a box
/// of the other: where two tows' surfaces cross within a box most of their triangles are far
/// apart. Cells of about the boxes' mean size, at most 128 along a side of @p both.
void keepNear(std::vector<TriangleBox>& a, std::vector<TriangleBox>& b, const CGAL::Bbox_3& both)
{
    double extent = 0.0;
    for (const std::vector<TriangleBox>* v : {&a, &b})
        for (const TriangleBox& x : *v) {
            const CGAL::Bbox_3& y = x.bbox();
            extent += std::max({y.xmax() - y.xmin(), y.ymax() - y.ymin(), y.zmax() - y.zmin()});
        }
    extent /= static_cast<double>(a.size() + b.size());
    const double side = std::max({both.xmax() - both.xmin(), both.ymax() - both.ymin(), both.zmax() - both.zmin()});
    const double cell = std::max({extent, side / 128.0, 1e-300});
    const auto filter = [&](std::vector<TriangleBox>& kept, const std::vector<TriangleBox>& other) {
        OccupancyGrid grid(both, cell);
        for (const TriangleBox& x : other) grid.mark(x.bbox());
        kept.erase(std::remove_if(kept.begin(), kept.end(), [&](const TriangleBox& x) { return !grid.touches(x.bbox()); }), kept.end());
    };
    filter(a, b);
    filter(b, a);
}

}  // namespace

std::vector<CrossingTriangles> crossingTriangles(const std::vector<Point3>& shared, std::size_t ownFrom,
                                                 const std::vector<TowTriangles>& tows,
                                                 const std::set<std::pair<std::size_t, std::size_t>>& ignored, std::size_t threads)
{
    std::vector<TowNodes> at;
    at.reserve(tows.size());
    for (const TowTriangles& t : tows) at.push_back({shared, ownFrom, t});
    std::vector<CGAL::Bbox_3> towBox(tows.size());
    parallelFor(tows.size(), threads, [&](std::size_t t) { towBox[t] = boxOf(at[t]); });
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    for (std::size_t a = 0; a < tows.size(); ++a)
        for (std::size_t b = a + 1; b < tows.size(); ++b)
            if (!tows[a].triangles->empty() && !tows[b].triangles->empty() && !ignored.count({a, b}) &&
                CGAL::do_overlap(towBox[a], towBox[b]))
                pairs.emplace_back(a, b);
    std::vector<CrossingTriangles> out;
    std::mutex outMutex;
    parallelFor(pairs.size(), threads, [&](std::size_t k) {
        const std::size_t a = pairs[k].first, b = pairs[k].second;  // (a lambda below uses them)
        const CGAL::Bbox_3 both = overlapOf(towBox[a], towBox[b]);
        std::vector<TriangleBox> ba = boxesWithin(at[a], both), bb = boxesWithin(at[b], both);
        if (ba.empty() || bb.empty()) return;
        keepNear(ba, bb, both);
        std::vector<CrossingTriangles> found;
        CGAL::box_intersection_d(ba.begin(), ba.end(), bb.begin(), bb.end(), [&](const TriangleBox& x, const TriangleBox& y) {
            if (cross(at[a], x.info(), at[b], y.info())) found.push_back({a, x.info(), b, y.info()});
        });
        if (found.empty()) return;
        std::lock_guard<std::mutex> lock(outMutex);
        out.insert(out.end(), found.begin(), found.end());
    });
    std::sort(out.begin(), out.end(), [](const CrossingTriangles& x, const CrossingTriangles& y) {
        return std::tie(x.towA, x.triangleA, x.towB, x.triangleB) < std::tie(y.towA, y.triangleA, y.towB, y.triangleB);
    });
    return out;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
