// The mid-surface of a connected region: each node of the primary's surface inside the loop moved
// halfway to the secondary's surface along their common normal. The ray's first hit on the
// secondary's faceted surface (CGAL's AABB tree; else its nearest point) seeds Newton's method
// on the secondary's exact B-spline surface (OCCT), so the midpoint is that of the two exact
// surfaces.
#include "region/mid_surface.hpp"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <GeomAdaptor_Surface.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <cmath>

#include "surface/occt_convert.hpp"
#include "surface/tow_surface_impl.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangle3 = Kernel::Triangle_3;
using TriangleIterator = std::vector<Triangle3>::const_iterator;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_triangle_primitive<Kernel, TriangleIterator>>>;
using NodeUV = std::pair<std::size_t, UV>;

Kernel::Point_3 cgal(const Point3& p) { return {p.x, p.y, p.z}; }

const UV* uvOf(const std::vector<NodeUV>& parameters, std::size_t node)
{
    const auto it = std::lower_bound(parameters.begin(), parameters.end(), node,
                                     [](const NodeUV& e, std::size_t n) { return e.first < n; });
    return it != parameters.end() && it->first == node ? &it->second : nullptr;
}

double vNear(double v, double near, double period) { return v - period * std::round((v - near) / period); }

/// Barycentric coordinates of @p x (in the triangle's plane) in triangle @p a, @p b, @p c.
std::array<double, 3> barycentric(const gp_XYZ& x, const gp_XYZ& a, const gp_XYZ& b, const gp_XYZ& c)
{
    const gp_XYZ e1 = b - a, e2 = c - a, r = x - a;
    const double d11 = e1.Dot(e1), d12 = e1.Dot(e2), d22 = e2.Dot(e2), r1 = r.Dot(e1), r2 = r.Dot(e2);
    const double det = d11 * d22 - d12 * d12;
    if (det <= 0.0) return {1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0};
    const double s = (d22 * r1 - d12 * r2) / det, t = (d11 * r2 - d12 * r1) / det;
    return {1.0 - s - t, s, t};
}

/// Newton's method on S(u, v) = p + t d for (u, v, t), from their values in; true when the
/// residual fell to @p tolerance.
bool onSurfaceAlong(const GeomAdaptor_Surface& surface, const ParameterRange& range, const gp_XYZ& p, const gp_XYZ& d,
                    double tolerance, double& u, double& v, double& t)
{
    for (int iteration = 0; iteration < 30; ++iteration) {
        u = std::clamp(u, range.uMin, range.uMax);
        gp_Pnt s;
        gp_Vec su, sv;
        surface.D1(u, v, s, su, sv);
        const gp_Vec r(s.XYZ() - p - t * d);  // residual
        if (r.Magnitude() <= tolerance) return true;
        // su du + sv dv - d dt = -r, by Cramer's rule.
        const gp_Vec e(d.Reversed());
        const double det = su.Dot(sv.Crossed(e));
        if (std::abs(det) < 1e-300) return false;
        u += -r.Dot(sv.Crossed(e)) / det;
        v += -su.Dot(r.Crossed(e)) / det;
        t += -su.Dot(sv.Crossed(r)) / det;
    }
    return false;
}

}  // namespace

bool midSurfacePositions(const MidSurfaceRegion& region, const std::vector<Point3>& nodes, std::vector<Point3>& positions,
                         std::string& why)
{
    const TowSurface& a = *region.primary;
    const TowSurface& b = *region.secondary;
    positions.clear();
    std::vector<Triangle3> faceted;
    faceted.reserve(region.secondaryTriangles.size());
    for (const auto& t : region.secondaryTriangles) faceted.emplace_back(cgal(nodes[t[0]]), cgal(nodes[t[1]]), cgal(nodes[t[2]]));
    if (faceted.empty()) {
        why = "the secondary has no triangle inside the loop";
        return false;
    }
    const Tree tree(faceted.begin(), faceted.end());
    const GeomAdaptor_Surface surfaceA(a.impl().surface), surfaceB(b.impl().surface);
    const ParameterRange rangeB = b.parameterRange();
    const double periodB = rangeB.vPeriod();
    const double scaleTolerance = 1e-12 * std::max(a.towSize(), b.towSize());
    for (const std::size_t node : region.movable) {
        const UV* uvA = uvOf(*region.primaryParameters, node);
        if (!uvA) {
            why = "node " + std::to_string(node) + " has no (u,v) on the primary";
            return false;
        }
        gp_Pnt p;
        gp_Vec su, sv;
        surfaceA.D1(uvA->u, uvA->v, p, su, sv);
        gp_Vec inward = -su.Crossed(sv);  // the surface's normals point out of the tow
        if (inward.Magnitude() == 0.0) {
            why = "the primary's surface has no normal at node " + std::to_string(node);
            return false;
        }
        inward.Normalize();
        // The seed: the first hit of the ray along the inward normal on the secondary's
        // triangles inside the loop, else (a deep overlap, where that ray leaves the primary
        // first) the nearest point of those triangles.
        const Kernel::Point_3 from(p.X(), p.Y(), p.Z());
        const Kernel::Ray_3 ray(from, Kernel::Vector_3(inward.X(), inward.Y(), inward.Z()));
        const auto hit = tree.first_intersection(ray);
        const Kernel::Point_3* onRay = hit ? boost::get<Kernel::Point_3>(&hit->first) : nullptr;
        Kernel::Point_3 seed;
        TriangleIterator seedTriangle;
        if (onRay) {
            seed = *onRay;
            seedTriangle = hit->second;
        } else {
            const auto nearest = tree.closest_point_and_primitive(from);
            seed = nearest.first;
            seedTriangle = nearest.second;
        }
        // The seed's (u,v) on the secondary, interpolated over its triangle's nodes.
        const auto& tri = region.secondaryTriangles[static_cast<std::size_t>(seedTriangle - faceted.cbegin())];
        std::array<const UV*, 3> corner{};
        for (int k = 0; k < 3; ++k) {
            corner[static_cast<std::size_t>(k)] = uvOf(*region.secondaryParameters, tri[static_cast<std::size_t>(k)]);
            if (!corner[static_cast<std::size_t>(k)]) {
                why = "a triangle of the secondary inside the loop has a node without (u,v)";
                return false;
            }
        }
        const gp_XYZ hx(seed.x(), seed.y(), seed.z());
        const std::array<double, 3> w = barycentric(hx, toOcct(nodes[tri[0]]).XYZ(), toOcct(nodes[tri[1]]).XYZ(), toOcct(nodes[tri[2]]).XYZ());
        double u = 0.0, v = 0.0;
        for (std::size_t k = 0; k < 3; ++k) {
            u += w[k] * corner[k]->u;
            v += w[k] * vNear(corner[k]->v, corner[0]->v, periodB);
        }
        const double tolerance = std::max(scaleTolerance, 1e-14 * p.XYZ().Modulus());  // rounding far from the origin
        double t = (hx - p.XYZ()).Dot(inward.XYZ());
        // The common normal: the segment p q along the mean of the primary's inward normal at p
        // and the secondary's outward normal at q (q's side of the overlap), so that the
        // construction is the same with the tows' roles swapped. Fixed-point iteration on the
        // direction, Newton's method on q for each direction.
        gp_XYZ d = inward.XYZ();
        if (!onRay && (hx - p.XYZ()).Modulus() > scaleTolerance) {  // towards the nearest point first
            d = (hx - p.XYZ()).Normalized();
            t = (hx - p.XYZ()).Modulus();
        }
        bool converged = false;
        for (int outer = 0; outer < 200 && !converged; ++outer) {  // linear convergence, about 0.3 per step
            if (!onSurfaceAlong(surfaceB, rangeB, p.XYZ(), d, tolerance, u, v, t)) break;
            gp_Pnt q;
            gp_Vec bu, bv;
            surfaceB.D1(u, v, q, bu, bv);
            gp_XYZ outB = bu.Crossed(bv).XYZ();
            if (outB.Modulus() == 0.0) break;
            outB.Normalize();
            gp_XYZ next = inward.XYZ() + outB;
            if (next.Modulus() < 1e-3) break;  // opposite normals: no common direction
            next.Normalize();
            converged = (next - d).Modulus() <= 1e-10;
            // Keep q where it is while the direction turns: t along the new direction.
            t = (q.XYZ() - p.XYZ()).Dot(next);
            d = next;
        }
        if (converged) converged = onSurfaceAlong(surfaceB, rangeB, p.XYZ(), d, tolerance, u, v, t);
        if (!converged || t < 0.0) {
            why = "the secondary's surface along the common normal at node " + std::to_string(node) + " was not found exactly";
            return false;
        }
        positions.push_back(fromOcct(gp_Pnt(p.XYZ() + 0.5 * t * d)));
    }
    return true;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
