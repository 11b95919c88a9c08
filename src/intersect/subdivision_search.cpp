// CGAL first: OpenCASCADE (through the headers below) defines a macro named Handle.
#include <CGAL/Bbox_3.h>
#include <CGAL/box_intersection_d.h>

#include "intersect/subdivision_search.hpp"

#include <algorithm>
#include <memory>
#include <utility>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

using Box = CGAL::Box_intersection_d::Box_with_handle_d<double, 3, std::size_t, CGAL::Box_intersection_d::ID_EXPLICIT>;

bool longerAlongU(const BezierPatch& p);

/// A patch of the subdivision. Its halves are made once, on first use, and shared by every
/// patch of the other tow it meets: a patch is halved the same way whichever it meets.
struct Node {
    BoundedPatch bounded;
    mutable std::unique_ptr<std::pair<Node, Node>> halves;

    const BezierPatch& patch() const { return bounded.patch; }
    const PatchBounds& bounds() const { return bounded.bounds; }
    const NormalCone& normals() const { return bounded.normals(); }
    const std::pair<Node, Node>& halved() const
    {
        if (!halves) {
            auto [first, second] = halve(patch(), longerAlongU(patch()));
            halves = std::make_unique<std::pair<Node, Node>>(Node{detail::bounded(std::move(first)), nullptr},
                                                             Node{detail::bounded(std::move(second)), nullptr});
        }
        return *halves;
    }
};

/// The leaf of @p a and @p b; its guess is the closest pair of control points (near the surface
/// when the patches are small), at their Greville parameters.
Leaf leafOf(const Node& a, const Node& b)
{
    const BezierPatch &pa = a.patch(), &pb = b.patch();
    std::size_t bestA = 0, bestB = 0;
    double best = 1e300;
    for (std::size_t i = 0; i < pa.poles.size(); ++i)
        for (std::size_t j = 0; j < pb.poles.size(); ++j) {
            const Vector3 d = pa.poles[i] - pb.poles[j];
            const double dd = dot(d, d);
            if (dd < best) {
                best = dd;
                bestA = i;
                bestB = j;
            }
        }
    const auto param = [](const BezierPatch& p, std::size_t k, double& u, double& v) {
        const int cols = p.degreeV + 1;
        const double i = static_cast<double>(static_cast<int>(k) / cols), j = static_cast<double>(static_cast<int>(k) % cols);
        u = p.u0 + (p.u1 - p.u0) * (p.degreeU > 0 ? i / p.degreeU : 0.5);
        v = p.v0 + (p.v1 - p.v0) * (p.degreeV > 0 ? j / p.degreeV : 0.5);
    };
    Seed s;
    param(pa, bestA, s.guess.ua, s.guess.va);
    param(pb, bestB, s.guess.ub, s.guess.vb);
    s.guess.point = 0.5 * (pa.poles[bestA] + pb.poles[bestB]);
    s.facetSize = std::min(a.bounds().diameter, b.bounds().diameter);
    return {s, pa.u0, pa.u1, pa.v0, pa.v1, pb.u0, pb.u1, pb.v0, pb.v1};
}

/// The direction to halve @p p in: the longer of its control polygons' mean lengths along u (over
/// its degreeV + 1 rows) and along v (over its degreeU + 1 columns).
bool longerAlongU(const BezierPatch& p)
{
    double lu = 0.0, lv = 0.0;
    for (int i = 0; i <= p.degreeU; ++i)
        for (int j = 0; j <= p.degreeV; ++j) {
            if (i < p.degreeU) lu += distance(p.pole(i + 1, j), p.pole(i, j));
            if (j < p.degreeV) lv += distance(p.pole(i, j + 1), p.pole(i, j));
        }
    return lu / (p.degreeV + 1) >= lv / (p.degreeU + 1);
}

class Search {
public:
    Search(const SubdivisionLimits& limits, const std::function<bool(const Leaf&)>& settle) : limits_(limits), settle_(settle) {}

    void pair(const Node& a, const Node& b)
    {
        if (stats_.exhausted) return;
        if (++stats_.examined > limits_.budget) {
            stats_.exhausted = true;
            return;
        }
        if (separated(a.patch(), a.bounds(), b.patch(), b.bounds(), limits_.overlap)) return;
        const double size = std::max(a.bounds().diameter, b.bounds().diameter);
        const bool smallest = size <= limits_.smallest;
        if (smallest || (size <= limits_.seedSize && conesApart(a.normals(), b.normals()))) {
            ++stats_.offered;
            if (settle_(leafOf(a, b))) return;
            if (smallest) {
                ++stats_.unsettled;
                return;
            }
        }
        // Halve the larger patch.
        if (a.bounds().diameter >= b.bounds().diameter) {
            const auto& [h1, h2] = a.halved();
            pair(h1, b);
            pair(h2, b);
        } else {
            const auto& [h1, h2] = b.halved();
            pair(a, h1);
            pair(a, h2);
        }
    }

    const SubdivisionStats& stats() const { return stats_; }

private:
    const SubdivisionLimits& limits_;
    const std::function<bool(const Leaf&)>& settle_;
    SubdivisionStats stats_;
};

/// The Bezier patches of @p s over the union of @p windows.
std::vector<Node> patchesIn(const Handle(Geom_BSplineSurface)& s, std::vector<UWindow> windows)
{
    std::sort(windows.begin(), windows.end(), [](const UWindow& x, const UWindow& y) { return x.uMin < y.uMin; });
    std::vector<UWindow> merged;
    for (const UWindow& w : windows) {
        if (!merged.empty() && w.uMin <= merged.back().uMax)
            merged.back().uMax = std::max(merged.back().uMax, w.uMax);
        else
            merged.push_back(w);
    }
    std::vector<BoundedPatch> patches;
    for (const UWindow& w : merged)
        if (w.uMax > w.uMin) addBoundedPatches(s, w.uMin, w.uMax, patches);
    std::vector<Node> nodes;
    nodes.reserve(patches.size());
    for (BoundedPatch& p : patches) nodes.push_back(Node{std::move(p), nullptr});
    return nodes;
}

/// The indices of the patches of @p nodes whose boxes meet @p reach.
std::vector<std::size_t> reaching(const std::vector<Node>& nodes, const BoundingBox& reach)
{
    std::vector<std::size_t> picked;
    for (std::size_t k = 0; k < nodes.size(); ++k)
        if (nodes[k].bounds().box.overlaps(reach)) picked.push_back(k);
    return picked;
}

std::vector<Box> boxesOf(const std::vector<Node>& nodes, const std::vector<std::size_t>& picked)
{
    std::vector<Box> boxes;
    boxes.reserve(picked.size());
    for (std::size_t k : picked) {
        const BoundingBox& b = nodes[k].bounds().box;
        boxes.emplace_back(CGAL::Bbox_3(b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z), k);
    }
    return boxes;
}

/// The box of the patches @p picked of @p nodes.
BoundingBox boxOf(const std::vector<Node>& nodes)
{
    BoundingBox box;
    for (const Node& n : nodes) {
        box.add(n.bounds().box.min);
        box.add(n.bounds().box.max);
    }
    return box;
}

}  // namespace

SubdivisionStats searchPatchPairs(const Handle(Geom_BSplineSurface)& sa, const Handle(Geom_BSplineSurface)& sb,
                                  const std::vector<WindowPair>& windows, const SubdivisionLimits& limits,
                                  const std::function<bool(const Leaf&)>& settle)
{
    std::vector<UWindow> wa, wb;
    for (const WindowPair& w : windows) {
        wa.push_back(w.a);
        wb.push_back(w.b);
    }
    const std::vector<Node> a = patchesIn(sa, wa), b = patchesIn(sb, wb);
    // Only the patches reaching the other side's box.
    const std::vector<std::size_t> pa = reaching(a, boxOf(b)), pb = reaching(b, boxOf(a));
    std::vector<Box> ba = boxesOf(a, pa), bb = boxesOf(b, pb);
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    CGAL::box_intersection_d(ba.begin(), ba.end(), bb.begin(), bb.end(),
                             [&](const Box& x, const Box& y) { pairs.emplace_back(x.handle(), y.handle()); });
    std::sort(pairs.begin(), pairs.end());  // the order of the input, not of CGAL's sweep
    Search search(limits, settle);
    // A patch's halves are dropped after its last pair (memory: at most the patches still to meet).
    std::vector<std::size_t> lastOfB(b.size(), 0);
    for (std::size_t k = 0; k < pairs.size(); ++k) lastOfB[pairs[k].second] = k;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        const auto [i, j] = pairs[k];
        search.pair(a[i], b[j]);
        if (k + 1 == pairs.size() || pairs[k + 1].first != i) a[i].halves.reset();  // the pairs come by a's patch
        if (lastOfB[j] == k) b[j].halves.reset();
    }
    return search.stats();
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
