/// @file nurbs_offset.hpp
/// @brief Fibre-placement plies (first part): NURBS curves and surfaces offset by a distance
/// keeping their parametrisation (Nguyen et al. 2014), and trivariate NURBS ply solids between a
/// surface and its offset, for isogeometric analysis of laminates.
#pragma once

#include <array>
#include <cstddef>
#include <iosfwd>
#include <vector>

#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// @defgroup placement Fibre placement
/// @brief NURBS offsets with the same parametrisation and trivariate ply solids.
/// @{

/// A NURBS curve: degree p, the full knot vector (non-decreasing, clamped: the first and last
/// knots p + 1 times), poles and their weights (as many as knots - p - 1).
struct TOWGEOM_EXPORT NurbsCurve {
    int degree = 0;                ///< p >= 1
    std::vector<double> knots;     ///< full knot vector, clamped
    std::vector<Point3> poles;     ///< control points
    std::vector<double> weights;   ///< one per pole, > 0
    /// The point at parameter @p t (within the knot range). @throws towgeom::Error
    /// (InvalidArgument) for an ill-formed curve.
    Point3 point(double t) const;
    /// The first derivative at @p t.
    Vector3 derivative(double t) const;
};

/// A NURBS surface: degrees, full clamped knot vectors, poles in rows of constant u index
/// (pole (i, j) at index i * vCount + j) with their weights.
struct TOWGEOM_EXPORT NurbsSurface {
    int uDegree = 0;                ///< degree in u
    int vDegree = 0;                ///< degree in v
    std::vector<double> uKnots;     ///< full knot vector in u, clamped
    std::vector<double> vKnots;     ///< full knot vector in v, clamped
    std::size_t uCount = 0;         ///< poles in u
    std::size_t vCount = 0;         ///< poles in v
    std::vector<Point3> poles;      ///< uCount x vCount, pole (i, j) at i * vCount + j
    std::vector<double> weights;    ///< one per pole, > 0
    /// The point at (@p u, @p v). Where the surface closes smoothly across its u (or v) ends (a
    /// cylinder's, sphere's or torus's angle: end rows equal, the derivative across them
    /// continuous) it is periodic there: u past the knots' range by whole periods is the same
    /// point, as the parameters of fibre-placement curves that cross the seam are.
    /// @throws towgeom::Error (InvalidArgument) for an ill-formed surface.
    Point3 point(double u, double v) const;
    /// The unit normal dS/du x dS/dv / |...| at (@p u, @p v) (periodic as point()).
    Vector3 normal(double u, double v) const;
};

/// A trivariate NURBS volume: degrees, full clamped knot vectors and poles in the three
/// directions, pole (i, j, k) at index (i * vCount + j) * wCount + k.
struct TOWGEOM_EXPORT NurbsVolume {
    int degree[3] = {0, 0, 0};          ///< degrees in u, v, w
    std::vector<double> knots[3];       ///< full knot vectors in u, v, w
    std::size_t count[3] = {0, 0, 0};   ///< poles in u, v, w
    std::vector<Point3> poles;          ///< pole (i, j, k) at (i * count[1] + j) * count[2] + k
    std::vector<double> weights;        ///< one per pole, > 0
    /// The point at (@p u, @p v, @p w).
    Point3 point(double u, double v, double w) const;
    /// The Jacobian determinant det(dX/du, dX/dv, dX/dw) at (@p u, @p v, @p w).
    double jacobian(double u, double v, double w) const;
};

/// Options of offsetCurve() and offsetSurface().
struct OffsetOptions {
    /// The largest distance allowed between the offset (at a parameter) and the exact offset
    /// point at that parameter, in your units; 0: relativeTolerance x the size of the input's
    /// control polygon.
    double tolerance = 0.0;
    double relativeTolerance = 1e-6;  ///< see tolerance
    int maxRefinements = 12;          ///< rounds of knot insertion at most
};

/// An offset curve and how well it meets the exact offset.
struct CurveOffset {
    NurbsCurve base;     ///< the input curve with the knots inserted (the same curve)
    NurbsCurve offset;   ///< the offset: the same degree, knots and weights as base
    double maxError = 0.0;         ///< the largest |offset(t) - (C(t) + d n(t))| sampled
    std::size_t knotsInserted = 0;  ///< knots inserted into the input
    /// Whether maxError met the tolerance. Not where the exact offset jumps (the curve turns a
    /// corner at a knot): refinement stops after two rounds in a row that cut the error by less
    /// than 5 %, or after OffsetOptions::maxRefinements rounds.
    bool converged = false;
};

/// An offset surface and how well it meets the exact offset.
struct SurfaceOffset {
    NurbsSurface base;    ///< the input surface with the knots inserted (the same surface)
    NurbsSurface offset;  ///< the offset: the same degrees, knots and weights as base
    double maxError = 0.0;         ///< the largest |offset(u,v) - (S(u,v) + d n(u,v))| sampled
    std::size_t knotsInserted = 0;  ///< knots inserted into the input, both directions
    /// Whether maxError met the tolerance (not at a crease: see CurveOffset::converged).
    bool converged = false;
};

/// Offsets the planar curve @p curve by @p distance in its plane (normal @p planeNormal): the
/// offset point of C(t) is C(t) + d n(t), n = C'(t) x planeNormal / |...| (to the right of the
/// curve seen from planeNormal for d > 0). The offset is a NURBS with the same degree, knots and
/// weights (Nguyen et al. 2014: the same parametrisation, as isogeometric analysis needs): its
/// poles collocate the exact offset at the Greville points; where it strays further than the
/// tolerance from the exact offset (sampled at 17 points per span), the span's middle knot is
/// inserted into the input (exactly: OpenCASCADE) and the poles solved again, until
/// CurveOffset::converged. A circle's offset is the concentric circle, to rounding.
/// @throws towgeom::Error (InvalidArgument) for an ill-formed curve, a zero normal or a curve
///         whose derivative vanishes; (Internal) if the collocation system is singular.
TOWGEOM_EXPORT CurveOffset offsetCurve(const NurbsCurve& curve, double distance, const Vector3& planeNormal,
                                       const OffsetOptions& options = {});

/// Offsets @p surface by @p distance along its unit normal (NurbsSurface::normal(); at a pole
/// its limit, below), as
/// offsetCurve() does a curve: the same degrees, knots and weights; poles collocating the exact
/// offset at the Greville points; knots inserted where it strays further than the tolerance
/// (sampled at 9 x 9 points per knot-span element), until SurfaceOffset::converged. Where a
/// boundary row (or column) of poles collapses to one point (a pole of the parametrisation, as a
/// sphere face's; NurbsSurface::normal() has no normal there), the normal is its limit from
/// inside the surface, which must be the same along the row.
/// @throws towgeom::Error (InvalidArgument) for an ill-formed surface or a degenerate normal;
///         (Unsupported) naming the point where a collapsed row's limit normal differs along it
///         (a cone's apex: its offset is not a point);
///         (Internal) if the collocation system is singular.
TOWGEOM_EXPORT SurfaceOffset offsetSurface(const NurbsSurface& surface, double distance, const OffsetOptions& options = {});

/// The ply solid between @p base and @p top (an offset of it: the same degrees, knots and
/// weights): a trivariate NURBS linear through the thickness (w from 0 at base to 1 at top).
/// @throws towgeom::Error (InvalidArgument) when the two surfaces do not share their degrees,
///         knots and weights.
TOWGEOM_EXPORT NurbsVolume plySolid(const NurbsSurface& base, const NurbsSurface& top);

/// The ply solid quadratic through its thickness between @p base, @p middle and @p top (the same
/// degrees, knots and weights): the trivariate NURBS of degree 2 in w whose poles in w are base,
/// 2 middle - (base + top) / 2 and top, so that w = 0, 1/2 and 1 give the three surfaces
/// exactly. For a ply between a surface and its normal offset the through-thickness field is
/// linear (offsetSurface()'s poles are affine in the distance on fixed knots): with middle the
/// average of base and top this is the linear ply's degree elevation, the same solid for IGA
/// codes that want quadratic functions through the thickness; another middle surface (a
/// ply whose mid-surface is designed separately) bends the ply through it.
/// @throws towgeom::Error (InvalidArgument) when the surfaces do not share their degrees, knots
///         and weights (see withKnotsOf()).
TOWGEOM_EXPORT NurbsVolume plySolid(const NurbsSurface& base, const NurbsSurface& middle, const NurbsSurface& top);

/// @p surface with the knots of @p finer inserted (exactly: OpenCASCADE's knot insertion, the
/// same surface), so that the two share their knot vectors, as plySolid() needs of surfaces
/// offset separately (offsetSurface() inserts its own knots).
/// @throws towgeom::Error (InvalidArgument) when @p finer's knot vectors do not contain
///         @p surface's, or the degrees differ.
TOWGEOM_EXPORT NurbsSurface withKnotsOf(const NurbsSurface& surface, const NurbsSurface& finer);

/// What measureVolume() found.
struct VolumeMeasure {
    /// The absolute value of the integral of the Jacobian over the parameter box: the volume
    /// when the Jacobian keeps one sign (its sign is the map's orientation: negative for a ply
    /// offset to the inside).
    double volume = 0.0;
    double minJacobian = 0.0;  ///< the smallest Jacobian at the quadrature points
    double maxJacobian = 0.0;  ///< the largest
    /// The quadrature point where the Jacobian, taken in the map's orientation (the sign of its
    /// integral), is smallest: the minimum's for a positive map, the maximum's for a negative
    /// one. Where the map folds when folds(). Its parameters (u, v, w) ...
    std::array<double, 3> weakestParameters{};
    Point3 weakestPoint{};  ///< ... and the point of the volume there.

    /// Whether the map folds (turns inside out) at a quadrature point: its Jacobian vanishes
    /// there or has the sign opposite to another point's. A sampled test: a fold narrower than
    /// the quadrature points' spacing may pass it.
    bool folds() const { return !(minJacobian > 0.0 || maxJacobian < 0.0); }
};

/// The volume of @p volume by Gauss-Legendre quadrature, @p points per knot span in each
/// direction, the range of its Jacobian at those points (of one sign everywhere: the map does
/// not fold, VolumeMeasure::folds()) and where it is weakest. @throws towgeom::Error (InvalidArgument) for an ill-formed volume or points
/// outside 1 to 40.
TOWGEOM_EXPORT VolumeMeasure measureVolume(const NurbsVolume& volume, int points = 8);

/// Writes @p volume as JSON for IGA codes: {"degrees":[p,q,r], "knots":[[..],[..],[..]],
/// "counts":[nu,nv,nw], "poles":[[x,y,z,w],...]} (poles in NurbsVolume's order; x, y, z not
/// multiplied by the weight). @throws towgeom::Error (InvalidArgument) for an ill-formed volume;
/// (WriteFailed) when the stream fails.
TOWGEOM_EXPORT void writeNurbsVolumeJson(const NurbsVolume& volume, std::ostream& out);

/// Writes @p volume sampled on a grid of @p samples x @p samples x max(1, @p samples / 2)
/// hexahedra per knot-span element as legacy VTK (ParaView), with the Jacobian as point data.
/// @throws towgeom::Error (InvalidArgument) for an ill-formed volume or samples outside 1 to 64;
///         (WriteFailed) when the stream fails.
TOWGEOM_EXPORT void writeNurbsVolumeVtk(const NurbsVolume& volume, std::ostream& out, int samples = 4);

/// @}

TOWGEOM_END_NAMESPACE
