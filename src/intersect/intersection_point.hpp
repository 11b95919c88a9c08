// A point of the intersection of two tow surfaces, with its parameters on both, and the Newton
// corrector that puts a guess exactly on the intersection curve.
#pragma once

#include <GeomAdaptor_Surface.hxx>
#include <Geom_BSplineSurface.hxx>

#include <array>

#include "surface/cap_chart.hpp"
#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// A point on two surfaces: (ua, va) on A, (ub, vb) on B. v may be unwrapped (beyond the period).
struct PointOn2 {
    double ua = 0.0, va = 0.0, ub = 0.0, vb = 0.0;
    Point3 point;  ///< the mean of S_A(ua, va) and S_B(ub, vb) after refinement
    double gap = 0.0;  ///< |S_A(ua, va) - S_B(ub, vb)|
};

/// The fourth equation that makes "on both surfaces" (three equations, four unknowns) a point.
struct PointCondition {
    enum class Kind {
        Plane,  ///< (S_A - origin) . normal = 0: the point where the curve crosses a plane
        FixVA,  ///< va = value (where the curve crosses a v-iso line of A, e.g. the seam)
        FixVB,  ///< vb = value
        FixUA,  ///< ua = value (where the curve crosses a section of A, e.g. its end)
        FixUB   ///< ub = value
    };
    Kind kind = Kind::Plane;
    Point3 origin;    ///< Plane only
    Vector3 normal;   ///< Plane only (need not be unit)
    double value = 0.0;  ///< Fix* only
};

/// The two surfaces and their u domains (points beyond a tow's end are refused). The adaptors
/// evaluate through OCCT's per-span polynomial cache (much faster than the B-spline's own D1 for
/// points close together); they make a SurfacePair for one thread at a time.
struct SurfacePair {
    Handle(Geom_BSplineSurface) a;
    Handle(Geom_BSplineSurface) b;
    Handle(GeomAdaptor_Surface) evalA;
    Handle(GeomAdaptor_Surface) evalB;
    double uMinA = 0.0, uMaxA = 1.0, uMinB = 0.0, uMaxB = 1.0;
    /// When set, a u beyond a tow's end is a point on its end cap (cap_chart.hpp): the pair is
    /// the two closed tows, and refinement may cross the rim. Null: the tubes only.
    const TowCaps* capsA = nullptr;
    const TowCaps* capsB = nullptr;
};

/// The unit tangent of the intersection curve at @p x: the normalised cross product of the two
/// surface normals, (0,0,0) where the surfaces are tangent.
Vector3 intersectionTangent(const SurfacePair& s, const PointOn2& x);

/// Newton's method on S_A(ua,va) = S_B(ub,vb) plus @p condition, from @p x. On success @p x is
/// the refined point (gap <= @p tolerance) and true is returned; false when the iteration does
/// not converge within a few steps, becomes singular (tangent surfaces) or leaves a tow's ends.
bool refineOnIntersection(const SurfacePair& s, PointOn2& x, const PointCondition& condition, double tolerance);

/// A point on three surfaces A, B and C: its (u,v) on each (v may be unwrapped).
struct PointOn3 {
    std::array<double, 6> uv{};  ///< ua, va, ub, vb, uc, vc
    Point3 point;                ///< the mean of S_A, S_B and S_C after refinement
    double gap = 0.0;            ///< the largest distance between two of the three surface points
};

/// Newton's method on S_A(ua,va) = S_B(ub,vb) = S_C(uc,vc) (six equations, six unknowns) from
/// @p x: the triple point where three tows' surfaces meet, where the intersection curves of the
/// three pairs cross. @p ab and @p ac are the pairs (A, B) and (A, C) (the same A). On success
/// @p x is the refined point (gap <= @p tolerance) and true is returned; false when the
/// iteration does not converge, becomes singular (two of the curves tangent there) or leaves a
/// tow's ends.
bool refineTriplePoint(const SurfacePair& ab, const SurfacePair& ac, PointOn3& x, double tolerance);

/// For a guess @p m between two curve points @p a and @p b (their (u,v) mixed): where the chord
/// lies on a tow's end cap (an end on the cap, or both ends on its rim), that tow's (u,v) of
/// @p m are taken from its 3D point by the cap's chart instead (mixed (u,v) of two rim points
/// would lie on the rim, not on the cap between them). No change without caps. Returns the
/// chord's turn about the cap's centre, as a fraction of a period (0 when not on a cap).
double capGuess(const SurfacePair& s, const PointOn2& a, const PointOn2& b, PointOn2& m);

/// refineOnIntersection() with the plane through x.point normal to the curve's tangent: the
/// intersection point nearest a good guess.
bool refineNearest(const SurfacePair& s, PointOn2& x, double tolerance);

}  // namespace detail
TOWGEOM_END_NAMESPACE
