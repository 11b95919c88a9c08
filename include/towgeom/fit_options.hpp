/// @file fit_options.hpp
/// @brief How TowSurface::fit turns a stack of sections into a surface.
#pragma once

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// The fitting methods of TowSurface::fit.
enum class FitMode {
    /// The surface passes through every input point: bicubic tensor-product interpolation, C2
    /// everywhere including across the periodic seam, not-a-knot ends along the tow. Default.
    Interpolate,
    /// Least squares on fewer control points, refined until every input point lies within
    /// FitOptions::tolerance of the surface (it becomes Interpolate if nothing coarser does).
    Approximate,
    /// The input points are used as control points (the SISL-based original method): smooth,
    /// but the surface lies inside the input polygons and loses about 0.5 % of the volume.
    ControlNet
};

/// Options for TowSurface::fit.
struct FitOptions {
    FitMode mode = FitMode::Interpolate;  ///< which method
    /// Approximate only: the largest allowed distance of an input point from the surface, in the
    /// user's units. 0 (the default) means relativeTolerance times the tow size.
    double tolerance = 0.0;
    /// Approximate only, when tolerance is 0: the tolerance relative to the tow size (the mean
    /// section perimeter divided by pi, i.e. the diameter of a round tow). Default 1e-3.
    double relativeTolerance = 1e-3;
};

/// "interpolate", "approximate" or "controlnet".
TOWGEOM_EXPORT const char* fitModeName(FitMode mode) noexcept;

TOWGEOM_END_NAMESPACE
