/// @file surface_fold.hpp
/// @brief findFold(): where a tow's fitted surface crosses itself (it folds), which no volume
/// mesh can fill and whose triangles cross in every surface mesh written.
#pragma once

#include <cstddef>
#include <optional>

#include "towgeom/export.hpp"
#include "towgeom/point.hpp"
#include "towgeom/tow_surface.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// @addtogroup resolution
/// @{

/// A place where a tow's surface crosses itself.
struct SurfaceFold {
    Point3 at;                     ///< a point of the surface there (a crossing triangle's centroid)
    UV uv;                         ///< that centroid's parameters on the sampling grid (v within the period)
    std::size_t crossingPairs = 0;  ///< crossing triangle pairs of the sampled surface
};

/// How finely findFold() samples the surface.
struct FoldSearchOptions {
    std::size_t perSpan = 4;   ///< samples along the tow between two consecutive sections (at least 1)
    std::size_t around = 32;   ///< samples around the tow (at least 8)
    /// Only where the sampled surface's triangles meet this box (a cell); empty (default): everywhere.
    BoundingBox within;
};

/// Where @p tow's surface crosses itself, or nullopt if its sampled surface does not. A tube fitted
/// through sections folds where it bends sharper than it is thick between sections far apart: the
/// cubic through them overshoots, and its inner side passes through its outer side (two parts of
/// a tow passing through each other are found too). Its surface meshes then cross there unless
/// they are coarser than the fold, and Gmsh's tetrahedral mesher stops on them; denser sections at
/// the bend unfold it. The end caps are not searched.
///
/// The surface is sampled on a grid (FoldSearchOptions::perSpan points between consecutive
/// sections' parameters, FoldSearchOptions::around points around, closed across the seam) and
/// its triangles tested pairwise by exact predicates (triangles sharing nodes cross only beyond
/// what they share). A fold narrower than the grid can be missed; what is found is a real
/// crossing of the sampled surface.
///
/// Thread-safe; reentrant.
/// @throws Error (InvalidArgument) for options below their minimum.
TOWGEOM_EXPORT std::optional<SurfaceFold> findFold(const TowSurface& tow, const FoldSearchOptions& options = {});

/// @}

TOWGEOM_END_NAMESPACE
