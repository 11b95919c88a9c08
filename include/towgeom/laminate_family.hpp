/// @file laminate_family.hpp
/// @brief fixedAngleCurve(): the reference of a laminate family's ply, a curve on the surface
/// that crosses every 0° tow at a fixed angle theta (Schueler, Miller & Hale 2004); lay its
/// courses with layCourses().
#pragma once

#include <cstddef>
#include <vector>

#include "towgeom/nurbs_offset.hpp"
#include "towgeom/surface_offset_curves.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// @addtogroup placement
/// @{

/// Options of fixedAngleCurve().
struct FixedAngleOptions {
    /// Where the curve starts on the first 0° curve, as a fraction of its points' index range
    /// (0 its first point, 1 its last).
    double start = 0.5;
    /// The curve's step along the surface; 0, or more than 1/4 of the smallest distance between
    /// neighbouring 0° curves at the start: 1/20 of that distance. The curve's points are a step
    /// apart, except around each crossing (the step that lands on a 0° curve is shorter; a point
    /// less than half a step before a crossing is dropped, so neighbours there are up to 1.5
    /// steps apart).
    double step = 0.0;
};

/// Where a fixed-angle curve crosses a 0° curve.
struct FamilyCrossing {
    std::size_t curve = 0;  ///< the 0° curve's index
    UV uv;                  ///< the crossing's parameters on the surface
    double angle = 0.0;     ///< the angle between the two curves' tangents there, degrees
};

/// A fixed-angle curve and its crossings.
struct FixedAngleCurve {
    CurveOnSurface curve;                 ///< its points, from the first 0° curve to the last
    std::vector<FamilyCrossing> crossings;  ///< one per 0° curve, in order
};

/// The curve on @p surface that leaves @p zeroFamily's first curve at @p options.start and
/// crosses every curve of the family at @p thetaDegrees from its direction (measured from the 0°
/// tangent towards the family's next curve, in (0°, 180°)), until it meets the family's last
/// curve. The family is a set of 0° curves (such as the centrelines layCourses() lays, or a
/// reference and its offsets) with the same number of points, point i of each corresponding to
/// point i of the others. Between two curves the 0° direction is interpolated: each curve is a
/// cubic B-spline C_k(t) in (u,v) of a parameter t shared by all (the point index), the curves
/// are blended in the curve index by cubic Hermite interpolation with Catmull-Rom slopes
/// ((C_{k+1} - C_{k-1}) / 2, one-sided at the family's first and last curve), and the 0° field
/// is that blend's t-tangent: on each curve, that curve's own tangent, and C1 across the curves
/// (so the fixed-angle curve's curvature has no jumps there). The curve is the field's integral
/// curve at angle theta (RK4 along the surface), landing exactly on each 0° curve it crosses.
/// @throws towgeom::Error (InvalidArgument) for fewer than 2 curves, curves of different or
///         fewer than 4 points, non-finite or repeated consecutive points (naming the curve),
///         theta outside (0, 180), a start outside [0, 1], a negative step,
///         or a curve that leaves the family's ends or the surface before reaching the last
///         curve; (Internal) if OpenCASCADE fails.
TOWGEOM_EXPORT FixedAngleCurve fixedAngleCurve(const NurbsSurface& surface, const std::vector<CurveOnSurface>& zeroFamily,
                                               double thetaDegrees, const FixedAngleOptions& options = {});

/// @}

TOWGEOM_END_NAMESPACE
