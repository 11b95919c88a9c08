// Fibre directions of the tetrahedra: each tow's mean direction at its sections, interpolated
// along its centreline to the point nearest each tetrahedron's centroid (CGAL's AABB tree finds
// the nearest segment: a million tetrahedra against a few hundred segments).
#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/parallel.hpp"
#include "surface/fibre_directions.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"
#include "towgeom/volume_mesh.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Segment = Kernel::Segment_3;
using SegmentIterator = std::vector<Segment>::const_iterator;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_segment_primitive<Kernel, SegmentIterator>>>;

/// A tow's centreline: its sections' centroids and the mean fibre direction at each.
struct Centreline {
    std::vector<Point3> centre;
    std::vector<Vector3> direction;
    std::vector<Segment> segments;  // centre[i] to centre[i + 1]
    std::unique_ptr<Tree> tree;
};

Centreline centrelineOf(const TowSurface& tow)
{
    Centreline c;
    const std::vector<double>& us = tow.sectionParameters();
    const ParameterRange r = tow.parameterRange();
    constexpr int kAround = 16;
    std::vector<UV> at;
    for (double u : us)
        for (int k = 0; k < kAround; ++k) at.push_back({u, r.vMin + r.vPeriod() * k / kAround});
    const std::vector<Vector3> d = detail::fibreDirections(tow, at);
    for (std::size_t i = 0; i < us.size(); ++i) {
        Vector3 sum;
        for (int k = 0; k < kAround; ++k) sum = sum + d[i * kAround + static_cast<std::size_t>(k)];
        const double n = norm(sum);
        c.direction.push_back(n > 0.0 ? (1.0 / n) * sum : sum);
        Point3 centre;
        for (const Point3& p : tow.sections()[i]) centre = centre + p;
        c.centre.push_back((1.0 / static_cast<double>(tow.sections()[i].size())) * centre);
    }
    for (std::size_t i = 0; i + 1 < c.centre.size(); ++i)
        c.segments.emplace_back(Kernel::Point_3(c.centre[i].x, c.centre[i].y, c.centre[i].z),
                                Kernel::Point_3(c.centre[i + 1].x, c.centre[i + 1].y, c.centre[i + 1].z));
    return c;
}

/// The tree over @p c's segments, made once @p c is in its place (it holds iterators into them).
void buildTree(Centreline& c)
{
    if (c.segments.empty()) return;
    c.tree = std::make_unique<Tree>(c.segments.cbegin(), c.segments.cend());
    c.tree->build();
    c.tree->accelerate_distance_queries();
}

/// The direction at the point of @p c's polyline nearest @p p.
Vector3 directionAt(const Centreline& c, const Point3& p)
{
    if (!c.tree) return c.direction.empty() ? Vector3{} : c.direction.front();
    const auto [nearest, segment] = c.tree->closest_point_and_primitive(Kernel::Point_3(p.x, p.y, p.z));
    const std::size_t i = static_cast<std::size_t>(segment - c.segments.cbegin());
    const Vector3 e = c.centre[i + 1] - c.centre[i];
    const double ee = dot(e, e);
    const Point3 q{nearest.x(), nearest.y(), nearest.z()};
    const double s = ee > 0.0 ? std::clamp(dot(q - c.centre[i], e) / ee, 0.0, 1.0) : 0.0;
    const Vector3 mix = (1.0 - s) * c.direction[i] + s * c.direction[i + 1];
    const double n = norm(mix);
    return n > 0.0 ? (1.0 / n) * mix : c.direction[i];
}

}  // namespace

void addFibreDirections(VolumeMesh& volumes, const std::vector<TowSurface>& tows, std::size_t threads)
{
    std::vector<char> used(tows.size(), 0);
    for (std::size_t k = 0; k < volumes.tetrahedra.size(); ++k) {
        const std::size_t t = k < volumes.tow.size() ? volumes.tow[k] : tows.size() + 1;
        if (t == tows.size() && volumes.withMatrix) continue;  // the matrix: no fibres (the zero vector)
        if (t >= tows.size())
            throw Error(ErrorCode::InvalidArgument, "tetrahedron " + std::to_string(k) + " names tow " + std::to_string(t) + " of " +
                                                        std::to_string(tows.size()) + " given");
        used[t] = 1;
    }
    // The centrelines of the tows that have tetrahedra, each tree built before the queries
    // (CGAL builds on first use otherwise), then the tetrahedra in blocks on every thread.
    threads = detail::workerCount(threads);
    std::vector<Centreline> lines(tows.size());
    detail::parallelFor(tows.size(), threads, [&](std::size_t t) {
        if (!used[t]) return;
        lines[t] = centrelineOf(tows[t]);
        buildTree(lines[t]);
    });
    std::vector<Vector3> out(volumes.tetrahedra.size());
    constexpr std::size_t kBlock = 4096;
    detail::parallelFor((out.size() + kBlock - 1) / kBlock, threads, [&](std::size_t b) {
        for (std::size_t k = b * kBlock; k < std::min(out.size(), (b + 1) * kBlock); ++k) {
            const std::size_t t = volumes.tow[k];
            if (t >= tows.size()) continue;  // the matrix
            Point3 centroid;
            for (std::size_t n : volumes.tetrahedra[k]) centroid = centroid + volumes.nodes[n];
            out[k] = directionAt(lines[t], 0.25 * centroid);
        }
    });
    volumes.fibreDirection = std::move(out);
}

TOWGEOM_END_NAMESPACE
