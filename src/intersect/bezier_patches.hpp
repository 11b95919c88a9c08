// A tow's tube as Bezier patches (OpenCASCADE's conversion of its B-spline surface), halved by
// de Casteljau, with the bounds that prove where two patches cannot meet: the box and slab of
// their control points (the convex hull holds the patch), and the cone that holds every normal.
#pragma once

#include <Geom_BSplineSurface.hxx>

#include <utility>
#include <vector>

#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// A polynomial patch of a tow's surface: (degreeU + 1) x (degreeV + 1) control points, row i
/// the u index. [u0, u1] x [v0, v1] is its part of the tow's (u, v) space.
struct BezierPatch {
    int degreeU = 0;
    int degreeV = 0;
    std::vector<Point3> poles;
    double u0 = 0.0, u1 = 0.0, v0 = 0.0, v1 = 0.0;

    const Point3& pole(int i, int j) const { return poles[static_cast<std::size_t>(i * (degreeV + 1) + j)]; }
};

/// The Bezier patches of @p surface (non-rational) between u = @p uMin and @p uMax (knots), one
/// per knot span pair, rows of u. Empty for a rational surface (its normals are not bounded by
/// the cone below).
std::vector<BezierPatch> bezierPatches(const Handle(Geom_BSplineSurface)& surface, double uMin, double uMax);

/// @p p split at the middle of its u range (@p alongU) or of its v range.
std::pair<BezierPatch, BezierPatch> halve(const BezierPatch& p, bool alongU);

/// A cone of directions: every unit vector within halfAngle of axis. Not valid when the
/// directions it must hold span a half-space or more (a normal may vanish there).
struct NormalCone {
    Vector3 axis;
    double halfAngle = 0.0;
    bool valid = false;
};

/// The cone that holds the normal (S_u x S_v) of @p p everywhere: S_u is a convex combination
/// of the differences of the control points along u, S_v of those along v, so S_u x S_v is a
/// convex combination of their pairwise cross products; the cone holds them all.
NormalCone normalCone(const BezierPatch& p);

/// Where a patch lies: the box and a slab of its control points (their convex hull holds it).
struct PatchBounds {
    BoundingBox box;       ///< of the control points
    double diameter = 0.0;  ///< of the box
    Vector3 slabNormal;    ///< a normal of the control net (its corner diagonals' cross product)
    double slabLow = 0.0, slabHigh = 0.0;  ///< the control points' extent along slabNormal
};

/// The bounds of @p p.
PatchBounds boundsOf(const BezierPatch& p);

/// A patch with its bounds, and its normal cone once asked for.
struct BoundedPatch {
    BezierPatch patch;
    PatchBounds bounds;
    mutable NormalCone cone;      ///< valid once coneKnown
    mutable bool coneKnown = false;

    /// The normal cone, computed on first use.
    const NormalCone& normals() const
    {
        if (!coneKnown) {
            cone = normalCone(patch);
            coneKnown = true;
        }
        return cone;
    }
};

/// @p p with its bounds.
BoundedPatch bounded(BezierPatch p);

/// The Bezier patches of @p surface between @p uMin and @p uMax with their bounds (see
/// bezierPatches()), appended to @p out.
void addBoundedPatches(const Handle(Geom_BSplineSurface)& surface, double uMin, double uMax, std::vector<BoundedPatch>& out);

/// Whether the patches' control-point hulls are apart by more than -@p overlap (an overlap of the
/// hulls shallower than @p overlap does not count): their boxes, or either's slab, separate them.
bool separated(const BezierPatch& a, const PatchBounds& ba, const BezierPatch& b, const PatchBounds& bb, double overlap);

/// Whether no normal of one patch is parallel to one of the other (Sinha, Klassen and Wang): then
/// their intersection holds no closed loop, and every branch of it reaches a patch's boundary.
bool conesApart(const NormalCone& a, const NormalCone& b);

}  // namespace detail
TOWGEOM_END_NAMESPACE
