/// @file surface_offset_curves.hpp
/// @brief Fibre-placement courses (first part): a curve on a NURBS surface offset by a distance
/// along the surface, as Schueler, Miller & Hale (2004) do (the point moved along N x T and
/// projected back, with their error estimate), or exactly (a geodesic perpendicular to the
/// curve), with the true on-surface distance measured by geodesics.
#pragma once

#include <cstddef>
#include <vector>

#include "towgeom/nurbs_offset.hpp"
#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// @addtogroup placement
/// @{

/// A curve on a surface: points given by their (u,v), with their positions.
struct CurveOnSurface {
    std::vector<UV> uv;          ///< parameters on the surface, in order along the curve
    std::vector<Point3> points;  ///< the surface's points there
};

/// How offsetOnSurface() moves each point.
enum class SurfaceOffsetMethod {
    /// Schueler et al.: the point moved by d along O = N x T (N the surface normal, T the curve's
    /// tangent) and projected back onto the surface (the nearest point, OpenCASCADE). On a
    /// curved surface it lands short of d along the surface: by about d (1 - psi / tan psi), tan
    /// psi = d kappa, kappa the normal curvature along O (their Eq. 2).
    ProjectTangent,
    /// Exact: the end of the geodesic of length d leaving the point perpendicular to the curve
    /// (geodesic equation integrated with RK4 on the exact surface).
    Geodesic
};

/// Options of offsetOnSurface().
struct SurfaceOffsetOptions {
    SurfaceOffsetMethod method = SurfaceOffsetMethod::ProjectTangent;  ///< how points move
    /// The largest RK4 step of a geodesic is its length over this (the steps adapt below it:
    /// two half steps must agree to 1e-12 of the parameter box).
    int geodesicSteps = 64;
};

/// One offset of a curve on a surface, point by point, with its error.
struct SurfaceOffsetStep {
    CurveOnSurface curve;                ///< the offset curve's points (one per input point)
    std::vector<double> estimatedError;  ///< per point, Schueler's d (1 - psi / tan psi)
    /// Per point, the length of the shortest geodesic from the input point to its offset
    /// (shooting on the geodesic equation): the true on-surface distance, d for an exact offset.
    std::vector<double> geodesicDistance;
};

/// Offsets @p curve on @p surface by @p distance, to the left of the curve seen from the
/// surface's normal side (O = N x T for d > 0), each point separately (see
/// SurfaceOffsetMethod), and measures each offset point's true distance along the surface.
/// @throws towgeom::Error (InvalidArgument) for fewer than 2 points, points off the surface's
///         parameter range, a normal or tangent that vanishes, or an offset that leaves the
///         surface or would cross a closed surface's seam (the surface's (u,v) box is all there
///         is); (Internal) if OpenCASCADE fails.
TOWGEOM_EXPORT SurfaceOffsetStep offsetOnSurface(const NurbsSurface& surface, const CurveOnSurface& curve, double distance,
                                                 const SurfaceOffsetOptions& options = {});

/// The curve on @p surface through the parameters @p uv (their positions filled in).
/// @throws towgeom::Error (InvalidArgument) for a parameter off the surface's range or an
///         ill-formed surface.
TOWGEOM_EXPORT CurveOnSurface curveOnSurface(const NurbsSurface& surface, const std::vector<UV>& uv);

/// The length of the geodesic on @p surface from the point at @p from to the one at @p to that
/// leaves nearest the chord's direction (shot from @p from, its direction and length corrected by
/// Newton's method until it ends at @p to): the shortest one for points closer than the
/// surface's radii of curvature. @p steps as SurfaceOffsetOptions::geodesicSteps.
/// @throws towgeom::Error (InvalidArgument) when shooting does not converge or a geodesic leaves
///         the surface's parameter range; (Internal) if OpenCASCADE fails.
TOWGEOM_EXPORT double geodesicDistance(const NurbsSurface& surface, const UV& from, const UV& to, int steps = 64);

/// @}

TOWGEOM_END_NAMESPACE
