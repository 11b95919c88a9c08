// The bounds behind the subdivision search (intersect/bezier_patches.hpp), against OpenCASCADE's
// own evaluation of the same patches: halving reproduces the patch, the normal cone holds every
// normal, and the separation and cone tests say no only when they must.
#include <catch2/catch.hpp>

#include <Geom_BezierSurface.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <gp_Vec.hxx>

#include <cmath>
#include <random>

#include "intersect/bezier_patches.hpp"

using namespace towgeom;
using namespace towgeom::detail;

namespace {

/// A random bicubic patch over [0,1]^2: a wavy sheet (z up to 0.3) with jittered control points.
BezierPatch randomPatch(std::mt19937& rng)
{
    std::uniform_real_distribution<double> jitter(-0.1, 0.1);
    BezierPatch p;
    p.degreeU = 3;
    p.degreeV = 3;
    p.u0 = 0.0;
    p.u1 = 1.0;
    p.v0 = 0.0;
    p.v1 = 1.0;
    for (int i = 0; i <= 3; ++i)
        for (int j = 0; j <= 3; ++j) p.poles.push_back({i / 3.0 + jitter(rng), j / 3.0 + jitter(rng), 3.0 * jitter(rng)});
    return p;
}

Handle(Geom_BezierSurface) occt(const BezierPatch& p)
{
    TColgp_Array2OfPnt poles(1, p.degreeU + 1, 1, p.degreeV + 1);
    for (int i = 0; i <= p.degreeU; ++i)
        for (int j = 0; j <= p.degreeV; ++j) poles(i + 1, j + 1) = gp_Pnt(p.pole(i, j).x, p.pole(i, j).y, p.pole(i, j).z);
    return new Geom_BezierSurface(poles);
}

}  // namespace

TEST_CASE("Bezier patches: halves reproduce the patch, the cone holds every normal", "[intersection][subdivision]")
{
    std::mt19937 rng(38);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int k = 0; k < 100; ++k) {
        const BezierPatch p = randomPatch(rng);
        const Handle(Geom_BezierSurface) whole = occt(p);
        for (const bool alongU : {true, false}) {
            const auto [left, right] = halve(p, alongU);
            const Handle(Geom_BezierSurface) l = occt(left), r = occt(right);
            for (int n = 0; n < 20; ++n) {
                const double s = unit(rng), t = unit(rng);
                const gp_Pnt a = l->Value(s, t), b = r->Value(s, t);
                const gp_Pnt wa = alongU ? whole->Value(0.5 * s, t) : whole->Value(s, 0.5 * t);
                const gp_Pnt wb = alongU ? whole->Value(0.5 + 0.5 * s, t) : whole->Value(s, 0.5 + 0.5 * t);
                CHECK(a.Distance(wa) < 1e-12);
                CHECK(b.Distance(wb) < 1e-12);
            }
        }
        const NormalCone cone = normalCone(p);
        if (!cone.valid) continue;
        for (int n = 0; n < 50; ++n) {
            gp_Pnt x;
            gp_Vec du, dv;
            whole->D1(unit(rng), unit(rng), x, du, dv);
            const gp_Vec normal = du.Crossed(dv);
            const double c = (normal.X() * cone.axis.x + normal.Y() * cone.axis.y + normal.Z() * cone.axis.z) / normal.Magnitude();
            CHECK(std::acos(std::min(1.0, c)) <= cone.halfAngle + 1e-12);
        }
    }
}

TEST_CASE("Bezier patches: separation and cone tests", "[intersection][subdivision]")
{
    std::mt19937 rng(7);
    const BezierPatch p = randomPatch(rng);
    // The same patch lifted by more than its thickness is apart; lifted by less, it is not.
    const PatchBounds bp = boundsOf(p);
    const double thickness = bp.box.max.z - bp.box.min.z;
    BezierPatch high = p, low = p;
    for (Point3& q : high.poles) q.z += thickness + 0.01;
    for (Point3& q : low.poles) q.z += 0.5 * thickness;
    CHECK(separated(p, bp, high, boundsOf(high), 0.0));
    CHECK_FALSE(separated(p, bp, low, boundsOf(low), 0.0));
    // The overlap tolerance: hulls overlapping by 0.005 each way are apart with a tolerance of 0.01 only.
    BezierPatch flatA, flatB;
    flatA.degreeU = flatA.degreeV = flatB.degreeU = flatB.degreeV = 1;
    flatA.poles = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}};
    flatB.poles = flatA.poles;
    flatB.poles[0].z = 0.005;   // B crosses A's plane: 0.005 above it at one corner,
    flatB.poles[3].z = -0.005;  // 0.005 below at the other
    CHECK_FALSE(separated(flatA, boundsOf(flatA), flatB, boundsOf(flatB), 0.001));
    CHECK(separated(flatA, boundsOf(flatA), flatB, boundsOf(flatB), 0.01));
    // Cones: parallel and antiparallel axes are never apart; perpendicular narrow cones are.
    NormalCone up{{0, 0, 1}, 0.1, true}, down{{0, 0, -1}, 0.1, true}, side{{1, 0, 0}, 0.1, true}, wide{{1, 0, 0}, 1.5, true};
    CHECK_FALSE(conesApart(up, up));
    CHECK_FALSE(conesApart(up, down));
    CHECK(conesApart(up, side));
    CHECK_FALSE(conesApart(up, wide));
    CHECK_FALSE(conesApart(up, NormalCone{}));  // invalid: may hold any direction
}
