// Collision detection between faceted yarns (CGAL box intersection + exact triangle tests) and
// the flattening response that leaves colliding yarns just touching.
#include "towgeom/collision.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangle = Kernel::Triangle_3;
using Box = CGAL::Box_intersection_d::Box_with_handle_d<double, 3, std::size_t, CGAL::Box_intersection_d::ID_EXPLICIT>;

/// A yarn's triangles in CGAL form, with their boxes and the yarn's box.
struct FacetedYarn {
    std::vector<Triangle> triangles;
    std::vector<Box> boxes;
    CGAL::Bbox_3 bbox;
};

FacetedYarn facet(const TowStack& stack)
{
    const TriangleMesh mesh = facetedTube(stack, false);
    FacetedYarn y;
    y.triangles.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles) {
        const auto p = [&](std::size_t k) {
            const Point3& q = mesh.vertices[t[k]];
            return Kernel::Point_3(q.x, q.y, q.z);
        };
        y.triangles.emplace_back(p(0), p(1), p(2));
    }
    y.boxes.reserve(y.triangles.size());
    for (std::size_t k = 0; k < y.triangles.size(); ++k) {
        y.boxes.emplace_back(y.triangles[k].bbox(), k);
        y.bbox += y.triangles[k].bbox();
    }
    return y;
}

/// The colliding triangle pairs of two yarns, found through their boxes.
std::vector<std::pair<std::size_t, std::size_t>> collide(FacetedYarn& a, FacetedYarn& b, std::size_t& tested,
                                                         bool stopAtFirst = false)
{
    std::vector<std::pair<std::size_t, std::size_t>> hits;
    if (!CGAL::do_overlap(a.bbox, b.bbox)) return hits;
    struct Stop {};
    try {
        CGAL::box_intersection_d(a.boxes.begin(), a.boxes.end(), b.boxes.begin(), b.boxes.end(),
                                 [&](const Box& x, const Box& y) {
                                     ++tested;
                                     if (CGAL::do_intersect(a.triangles[x.handle()], b.triangles[y.handle()])) {
                                         hits.emplace_back(x.handle(), y.handle());
                                         if (stopAtFirst) throw Stop{};
                                     }
                                 });
    } catch (const Stop&) {
    }
    std::sort(hits.begin(), hits.end());
    return hits;
}

}  // namespace

std::size_t CollisionReport::trianglePairCount() const
{
    std::size_t n = 0;
    for (const YarnCollision& c : collisions) n += c.triangles.size();
    return n;
}

CollisionReport detectCollisions(const std::vector<TowStack>& stacks, CollisionMethod method)
{
    std::vector<FacetedYarn> yarns;
    yarns.reserve(stacks.size());
    for (const TowStack& s : stacks) yarns.push_back(facet(s));
    CollisionReport report;

    std::vector<std::pair<std::size_t, std::size_t>> candidates;
    if (method == CollisionMethod::Hierarchy) {
        // Broad phase over the yarns' boxes, then boxes of triangles inside each candidate pair.
        std::vector<Box> boxes;
        for (std::size_t k = 0; k < yarns.size(); ++k) boxes.emplace_back(yarns[k].bbox, k);
        CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
            candidates.emplace_back(std::min(a.handle(), b.handle()), std::max(a.handle(), b.handle()));
        });
        std::sort(candidates.begin(), candidates.end());
        for (const auto& [a, b] : candidates) {
            ++report.yarnPairsTested;
            auto hits = collide(yarns[a], yarns[b], report.trianglePairsTested);
            if (!hits.empty()) report.collisions.push_back({a, b, std::move(hits)});
        }
        return report;
    }
    for (std::size_t a = 0; a < yarns.size(); ++a)
        for (std::size_t b = a + 1; b < yarns.size(); ++b) {
            ++report.yarnPairsTested;
            YarnCollision c{a, b, {}};
            for (std::size_t i = 0; i < yarns[a].triangles.size(); ++i)
                for (std::size_t j = 0; j < yarns[b].triangles.size(); ++j) {
                    ++report.trianglePairsTested;
                    if (CGAL::do_intersect(yarns[a].triangles[i], yarns[b].triangles[j])) c.triangles.emplace_back(i, j);
                }
            if (!c.triangles.empty()) report.collisions.push_back(std::move(c));
        }
    return report;
}

std::vector<std::size_t> collisionsPerCrossing(const Textile& textile, const std::vector<TowStack>& stacks,
                                               const CollisionReport& report)
{
    std::vector<std::size_t> counts(textile.crossings.size(), 0);
    std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t>> crossingsOf;
    for (std::size_t c = 0; c < textile.crossings.size(); ++c) {
        const Crossing& x = textile.crossings[c];
        crossingsOf[{std::min(x.warp, x.weft), std::max(x.warp, x.weft)}].push_back(c);
    }
    for (const YarnCollision& collision : report.collisions) {
        const auto it = crossingsOf.find({collision.yarnA, collision.yarnB});
        if (it == crossingsOf.end()) continue;  // yarns that do not cross (e.g. parallel neighbours)
        const TriangleMesh mesh = facetedTube(stacks.at(collision.yarnA), false);
        for (const auto& [triangle, other] : collision.triangles) {
            const auto& t = mesh.triangles[triangle];
            const Point3 centroid = (1.0 / 3.0) * (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]);
            std::size_t best = it->second.front();
            double bestDistance = 1e300;
            for (const std::size_t c : it->second) {
                const Point3& p = textile.crossings[c].position;
                const double d = std::hypot(p.x - centroid.x, p.y - centroid.y);
                if (d < bestDistance) {
                    bestDistance = d;
                    best = c;
                }
            }
            ++counts[best];
        }
    }
    return counts;
}

namespace {

/// The sections of a yarn near a crossing, with the weight of the flattening blend.
struct Window {
    std::size_t first = 0, last = 0;  // section range [first, last] (with one unweighted neighbour each side)
    std::vector<double> weight;       // per section in the range
};

/// Weights 1 within @p flat of the crossing (in plan), tapering as cos^2 to 0 at @p radius.
Window window(const GeneratedYarn& y, const Point3& at, double flat, double radius)
{
    Window w;
    bool found = false;
    for (std::size_t k = 0; k < y.stations.size(); ++k) {
        const Point3 c = y.path.point(y.stations[k]);
        const double d = std::hypot(c.x - at.x, c.y - at.y);
        if (d < radius) {
            if (!found) w.first = k;
            found = true;
            w.last = k;
        }
    }
    if (!found) return w;
    w.first = w.first > 0 ? w.first - 1 : 0;
    w.last = std::min(w.last + 1, y.stations.size() - 1);
    for (std::size_t k = w.first; k <= w.last; ++k) {
        const Point3 c = y.path.point(y.stations[k]);
        const double d = std::hypot(c.x - at.x, c.y - at.y);
        const double x = std::clamp((d - flat) / (radius - flat), 0.0, 1.0);
        const double s = std::cos(0.5 * 3.14159265358979323846 * x);
        w.weight.push_back(s * s);
    }
    return w;
}

const CrossSection& sectionAt(const GeneratedYarn& y, const Point3& p) { return y.sections[y.nearestSection(p)]; }

/// The yarn's sections [first, last] as a stack (with the yarn's current flattening).
TowStack partial(const GeneratedYarn& y, const Window& w, std::size_t points)
{
    const auto from = static_cast<std::ptrdiff_t>(w.first), to = static_cast<std::ptrdiff_t>(w.last) + 1;
    const GeneratedYarn part{y.name, y.role, y.path, {y.stations.begin() + from, y.stations.begin() + to},
                             {y.sections.begin() + from, y.sections.begin() + to}};
    return part.stack(points);
}

TowStack shifted(TowStack s, const Vector3& by)
{
    for (auto& section : s.sections)
        for (Point3& p : section) p = p + by;
    return s;
}

bool collides(const TowStack& a, const TowStack& b)
{
    FacetedYarn fa = facet(a), fb = facet(b);
    std::size_t tested = 0;
    return !collide(fa, fb, tested, true).empty();
}

/// The distance @p a must move along @p direction (unit) to touch @p b, to within @p resolution;
/// 0 when they already collide; capped at @p limit.
double gapAlong(const TowStack& a, const TowStack& b, const Vector3& direction, double resolution, double limit)
{
    if (collides(a, b)) return 0.0;
    double lo = 0.0, hi = resolution;
    while (!collides(shifted(a, hi * direction), b)) {
        lo = hi;
        hi *= 2.0;
        if (hi > limit) return limit;
    }
    while (hi - lo > resolution) {
        const double mid = 0.5 * (lo + hi);
        (collides(shifted(a, mid * direction), b) ? hi : lo) = mid;
    }
    return hi;
}

/// The flattening state of a textile: one factor per crossing; a section's flattening is the
/// smallest that any crossing whose window holds it asks for (1 - (1 - factor) * weight).
class Flattening {
public:
    explicit Flattening(Textile& t) : t_(t), factor_(t.crossings.size(), 1.0), windows_(t.crossings.size())
    {
        const double s = t.options.spacing;
        for (std::size_t c = 0; c < t.crossings.size(); ++c) {
            const Crossing& x = t.crossings[c];
            // Full flattening across the other yarn's width; the taper ends where the next
            // crossing's full zone begins, so neighbouring crossings share only tapers.
            const double warpFlat = std::min(0.5 * sectionAt(t.yarns[x.weft], x.position).width, 0.45 * s);
            const double weftFlat = std::min(0.5 * sectionAt(t.yarns[x.warp], x.position).width, 0.45 * s);
            windows_[c] = {window(t.yarns[x.warp], x.position, warpFlat, s - warpFlat),
                           window(t.yarns[x.weft], x.position, weftFlat, s - weftFlat)};
            byYarn_[x.warp].push_back(c);
            byYarn_[x.weft].push_back(c);
        }
    }

    double factor(std::size_t c) const { return factor_[c]; }

    /// Sets crossing @p c's factor and updates the sections of its two yarns.
    void set(std::size_t c, double f)
    {
        factor_[c] = f;
        refresh(t_.crossings[c].warp);
        refresh(t_.crossings[c].weft);
    }

    /// The two yarns of crossing @p c, restricted to its windows, as they are now.
    std::pair<TowStack, TowStack> local(std::size_t c) const
    {
        const Crossing& x = t_.crossings[c];
        const std::size_t n = t_.options.pointsPerSection;
        return {partial(t_.yarns[x.warp], windows_[c].first, n), partial(t_.yarns[x.weft], windows_[c].second, n)};
    }

    bool empty(std::size_t c) const { return windows_[c].first.weight.empty() || windows_[c].second.weight.empty(); }

private:
    void refresh(std::size_t yarn)
    {
        GeneratedYarn& y = t_.yarns[yarn];
        for (CrossSection& section : y.sections) section.flattening = 1.0;
        for (const std::size_t c : byYarn_[yarn]) {
            const Window& w = t_.crossings[c].warp == yarn ? windows_[c].first : windows_[c].second;
            for (std::size_t k = w.first; k <= w.last && !w.weight.empty(); ++k) {
                double& f = y.sections[k].flattening;
                f = std::min(f, 1.0 - (1.0 - factor_[c]) * w.weight[k - w.first]);
            }
        }
    }

    Textile& t_;
    std::vector<double> factor_;
    std::vector<std::pair<Window, Window>> windows_;
    std::map<std::size_t, std::vector<std::size_t>> byYarn_;
};

bool collidesAt(Flattening& state, std::size_t c, double f)
{
    state.set(c, f);
    const auto [a, b] = state.local(c);
    return collides(a, b);
}

/// Crossing @p c's factor: the largest (to within the tolerance on the gap it can leave) at
/// which its two yarns do not collide near it, the other crossings as they are.
void respond(Flattening& state, std::size_t c, double scale, double tolerance, const std::string& what)
{
    constexpr double kStep = 1.0 / 16.0;
    double hi = 1.0;
    if (!collidesAt(state, c, hi)) return;
    // Step down gently: flattened sections widen, so a large step could make them collide with
    // the other yarn elsewhere.
    double lo = std::min(state.factor(c), 1.0 - kStep);
    while (collidesAt(state, c, lo)) {
        hi = lo;
        lo -= kStep;
        if (lo < kStep / 2)
            throw Error(ErrorCode::Internal, "crossing of " + what + " cannot be separated by flattening");
    }
    while ((hi - lo) * scale > tolerance) {
        const double mid = 0.5 * (lo + hi);
        (collidesAt(state, c, mid) ? hi : lo) = mid;
    }
    state.set(c, lo);
}

}  // namespace

std::vector<CrossingResponse> flattenToTouching(Textile& textile, double tolerance)
{
    if (!(tolerance > 0.0)) throw Error(ErrorCode::InvalidArgument, "the flattening tolerance must be positive");
    Flattening state(textile);
    std::vector<CrossingResponse> out(textile.crossings.size());
    std::vector<double> scale(textile.crossings.size());
    for (std::size_t c = 0; c < textile.crossings.size(); ++c) {
        const Crossing& x = textile.crossings[c];
        out[c].crossing = c;
        scale[c] = 0.5 * (sectionAt(textile.yarns[x.warp], x.position).height +
                          sectionAt(textile.yarns[x.weft], x.position).height);
        if (!state.empty(c)) {
            const auto [a, b] = state.local(c);
            out[c].collided = collides(a, b);
        }
    }
    // Neighbouring crossings share the tapers of their windows, so a crossing flattened later
    // can leave an earlier one floating: relax until every crossing is just touching again.
    constexpr int kPasses = 4;
    for (int pass = 0; pass < kPasses; ++pass) {
        bool changed = false;
        for (std::size_t c = 0; c < textile.crossings.size(); ++c) {
            if (!out[c].collided || state.empty(c)) continue;
            const double before = state.factor(c);
            const Crossing& x = textile.crossings[c];
            respond(state, c, scale[c], tolerance, textile.yarns[x.warp].name + " and " + textile.yarns[x.weft].name);
            changed = changed || std::fabs(state.factor(c) - before) * scale[c] > 0.5 * tolerance;
        }
        if (!changed) break;
    }
    for (std::size_t c = 0; c < textile.crossings.size(); ++c) {
        out[c].flattening = state.factor(c);
        if (state.empty(c)) continue;
        const auto [a, b] = state.local(c);
        const Vector3 down{0.0, 0.0, textile.crossings[c].warpOver ? -1.0 : 1.0};
        out[c].gap = gapAlong(a, b, down, 0.01 * tolerance, textile.options.height);
    }
    return out;
}

TOWGEOM_END_NAMESPACE
