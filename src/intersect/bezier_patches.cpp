#include "intersect/bezier_patches.hpp"

#include <GeomConvert_BSplineSurfaceToBezierSurface.hxx>
#include <Geom_BezierSurface.hxx>
#include <TColGeom_Array2OfBezierSurface.hxx>
#include <TColStd_Array1OfReal.hxx>

#include <algorithm>
#include <cmath>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

std::vector<BezierPatch> bezierPatches(const Handle(Geom_BSplineSurface)& surface, double uMin, double uMax)
{
    std::vector<BezierPatch> patches;
    if (surface->IsURational() || surface->IsVRational()) return patches;
    double u1, u2, v1, v2;
    surface->Bounds(u1, u2, v1, v2);
    GeomConvert_BSplineSurfaceToBezierSurface convert(surface, std::max(u1, uMin), std::min(u2, uMax), v1, v2, 1e-12);
    const int nu = convert.NbUPatches(), nv = convert.NbVPatches();
    TColGeom_Array2OfBezierSurface bezier(1, nu, 1, nv);
    convert.Patches(bezier);
    TColStd_Array1OfReal uk(1, nu + 1), vk(1, nv + 1);
    convert.UKnots(uk);
    convert.VKnots(vk);
    patches.reserve(static_cast<std::size_t>(nu * nv));
    for (int i = 1; i <= nu; ++i)
        for (int j = 1; j <= nv; ++j) {
            const Handle(Geom_BezierSurface)& s = bezier(i, j);
            BezierPatch p;
            p.degreeU = s->UDegree();
            p.degreeV = s->VDegree();
            p.u0 = uk(i);
            p.u1 = uk(i + 1);
            p.v0 = vk(j);
            p.v1 = vk(j + 1);
            for (int a = 1; a <= s->NbUPoles(); ++a)
                for (int b = 1; b <= s->NbVPoles(); ++b) {
                    const gp_Pnt q = s->Pole(a, b);
                    p.poles.push_back({q.X(), q.Y(), q.Z()});
                }
            patches.push_back(std::move(p));
        }
    return patches;
}

namespace {

/// de Casteljau at 1/2 of the control polygon @p c (n + 1 points, stride @p step in @p poles):
/// the first half's polygon into @p left, the second's into @p right (same positions).
void splitPolygon(const std::vector<Point3>& poles, std::size_t first, std::size_t step, int n, std::vector<Point3>& left,
                  std::vector<Point3>& right)
{
    std::vector<Point3> work(static_cast<std::size_t>(n + 1));
    for (int k = 0; k <= n; ++k) work[static_cast<std::size_t>(k)] = poles[first + static_cast<std::size_t>(k) * step];
    for (int r = 0; r <= n; ++r) {
        left[first + static_cast<std::size_t>(r) * step] = work[0];
        right[first + static_cast<std::size_t>(n - r) * step] = work[static_cast<std::size_t>(n - r)];
        for (int k = 0; k < n - r; ++k)
            work[static_cast<std::size_t>(k)] = 0.5 * (work[static_cast<std::size_t>(k)] + work[static_cast<std::size_t>(k + 1)]);
    }
}

}  // namespace

std::pair<BezierPatch, BezierPatch> halve(const BezierPatch& p, bool alongU)
{
    BezierPatch left = p, right = p;
    const int rows = p.degreeU + 1, cols = p.degreeV + 1;
    if (alongU) {
        for (int j = 0; j < cols; ++j)
            splitPolygon(p.poles, static_cast<std::size_t>(j), static_cast<std::size_t>(cols), p.degreeU, left.poles, right.poles);
        left.u1 = right.u0 = 0.5 * (p.u0 + p.u1);
    } else {
        for (int i = 0; i < rows; ++i)
            splitPolygon(p.poles, static_cast<std::size_t>(i * cols), 1, p.degreeV, left.poles, right.poles);
        left.v1 = right.v0 = 0.5 * (p.v0 + p.v1);
    }
    return {std::move(left), std::move(right)};
}

namespace {

/// The smallest cone about the normalised mean of @p w that holds every vector of @p w; invalid
/// when one of them is (nearly) zero or at 90 degrees or more from that axis. @p lengths holds
/// the vectors' lengths.
NormalCone coneOf(const std::vector<Vector3>& w, const std::vector<double>& lengths)
{
    NormalCone cone;
    const double longest = lengths.empty() ? 0.0 : *std::max_element(lengths.begin(), lengths.end());
    if (!(longest > 0.0)) return cone;
    // A vector near zero: the hull may hold the origin, a normal may vanish.
    for (double n : lengths)
        if (!(n > 1e-12 * longest)) return cone;
    Vector3 sum;
    for (std::size_t k = 0; k < w.size(); ++k) sum = sum + (1.0 / lengths[k]) * w[k];
    const double s = norm(sum);
    if (!(s > 0.0)) return cone;
    cone.axis = (1.0 / s) * sum;
    double cosMin = 1.0;
    for (std::size_t k = 0; k < w.size(); ++k) cosMin = std::min(cosMin, dot(cone.axis, w[k]) / lengths[k]);
    if (!(cosMin > 1e-9)) return cone;
    cone.halfAngle = std::acos(std::min(1.0, cosMin));
    cone.valid = true;
    return cone;
}

}  // namespace

NormalCone normalCone(const BezierPatch& p)
{
    // Reused buffers: the subdivision asks for many cones, each of (degree + 1)^2 degree^2 vectors.
    thread_local std::vector<Vector3> du, dv, normals;
    thread_local std::vector<double> lengths;
    du.clear();
    dv.clear();
    normals.clear();
    lengths.clear();
    for (int i = 0; i <= p.degreeU; ++i)
        for (int j = 0; j <= p.degreeV; ++j) {
            if (i < p.degreeU) du.push_back(p.pole(i + 1, j) - p.pole(i, j));
            if (j < p.degreeV) dv.push_back(p.pole(i, j + 1) - p.pole(i, j));
        }
    for (const Vector3& x : du)
        for (const Vector3& y : dv) {
            normals.push_back(cross(x, y));
            lengths.push_back(norm(normals.back()));
        }
    return coneOf(normals, lengths);
}

PatchBounds boundsOf(const BezierPatch& p)
{
    PatchBounds b;
    // std::min and max, not BoundingBox::add's fmin and fmax: poles are finite, and this is hot.
    Point3 lo = p.poles.front(), hi = lo;
    for (const Point3& q : p.poles) {
        lo = {std::min(lo.x, q.x), std::min(lo.y, q.y), std::min(lo.z, q.z)};
        hi = {std::max(hi.x, q.x), std::max(hi.y, q.y), std::max(hi.z, q.z)};
    }
    b.box.add(lo);
    b.box.add(hi);
    b.diameter = b.box.diagonal();
    // Any direction gives a valid slab; the net's normal gives a thin one when the patch is small.
    const Vector3 n = cross(p.pole(p.degreeU, p.degreeV) - p.pole(0, 0), p.pole(0, p.degreeV) - p.pole(p.degreeU, 0));
    const double len = norm(n);
    b.slabNormal = len > 0.0 ? (1.0 / len) * n : Vector3{0.0, 0.0, 1.0};
    b.slabLow = 1e300;
    b.slabHigh = -1e300;
    for (const Point3& q : p.poles) {
        const double d = dot(q, b.slabNormal);
        b.slabLow = std::min(b.slabLow, d);
        b.slabHigh = std::max(b.slabHigh, d);
    }
    return b;
}

namespace {

/// Whether @p other's control points all lie beyond the slab of @p own (by more than -overlap).
bool outsideSlab(const PatchBounds& own, const BezierPatch& other, double overlap)
{
    double lo = 1e300, hi = -1e300;
    for (const Point3& q : other.poles) {
        const double d = dot(q, own.slabNormal);
        lo = std::min(lo, d);
        hi = std::max(hi, d);
    }
    return hi < own.slabLow + overlap || lo > own.slabHigh - overlap;
}

}  // namespace

BoundedPatch bounded(BezierPatch p)
{
    BoundedPatch b;
    b.patch = std::move(p);
    b.bounds = boundsOf(b.patch);
    return b;
}

void addBoundedPatches(const Handle(Geom_BSplineSurface)& surface, double uMin, double uMax, std::vector<BoundedPatch>& out)
{
    for (BezierPatch& p : bezierPatches(surface, uMin, uMax)) out.push_back(bounded(std::move(p)));
}

bool separated(const BezierPatch& a, const PatchBounds& ba, const BezierPatch& b, const PatchBounds& bb, double overlap)
{
    const BoundingBox &x = ba.box, &y = bb.box;
    if (x.max.x < y.min.x + overlap || y.max.x < x.min.x + overlap || x.max.y < y.min.y + overlap ||
        y.max.y < x.min.y + overlap || x.max.z < y.min.z + overlap || y.max.z < x.min.z + overlap)
        return true;
    return outsideSlab(ba, b, overlap) || outsideSlab(bb, a, overlap);
}

bool conesApart(const NormalCone& a, const NormalCone& b)
{
    if (!a.valid || !b.valid) return false;
    const double c = std::min(1.0, std::fabs(dot(a.axis, b.axis)));
    return std::acos(c) > a.halfAngle + b.halfAngle;
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
