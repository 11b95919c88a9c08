/// @file mesh_options.hpp
/// @brief MeshOptions: size and quality of the tow surface meshes (ParametricMesher).
#pragma once

#include <cstddef>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// How each tow's surface is meshed. Lengths are in the user's units; 0 means "relative to the
/// tow size" (TowSurface::towSize() of each tow).
struct MeshOptions {
    /// Target edge length h of the 3D triangles: every edge is at most about h in 3D (measured
    /// with the surface's metric), except loop chords, which are at the loop spacing.
    /// 0 (default): relativeEdgeLength x each tow's own size. A size given here applies to
    /// every tow, but a tow is meshed at most at a quarter of its own circumference (pi x its
    /// size; at least 4 edges around): TowResolution::meshSize says what each tow got.
    double edgeLength = 0.0;
    /// edgeLength relative to the tow size when edgeLength is 0. Default 0.1.
    double relativeEdgeLength = 0.1;
    /// The smallest angle the mesher aims for, in degrees (at most 30). Default 20. It is asked in
    /// the plane each tow is meshed in, and 3/4 of it (15 degrees by default) on the surface for
    /// faces longer than an eighth of the local mesh size (below, the plane's refinement would
    /// not converge on the surface's shape). Faces whose refinement would split a loop chord or
    /// seam edge in the last round may stay under it (MeshQuality::facesOverBounds).
    double minAngle = 20.0;
    /// Spacing of the nodes along intersection loops. 0 (default): the smaller mesh size of the
    /// loop's two tows. A smaller spacing refines the mesh along loops ("high" refinement), a
    /// larger one coarsens it.
    double loopSpacing = 0.0;
    /// The most triangles the meshes may have, all tows together (about 250 bytes of memory
    /// each while meshing). resolveTextile() estimates the count before meshing (about 3 x the
    /// tows' area (end caps included) / (sqrt(3)/4 h^2), the mesher keeping every edge below h, plus about 20 x the
    /// loops' length x (1/loopSpacing - 1/h) for a loop spacing below h; with a Cell, its six
    /// faces counted at the finest tow's h: an upper bound, they are graded coarser away from the
    /// tows, Cell::faceSizeGrowth) and refuses a mesh over this with ErrorCode::TooLarge. Default
    /// 20 million (about 5 GB); must be at least 1.
    std::size_t maxTriangles = 20000000;
    /// Close every tow by its two end caps (default): the polygon of the tube's end nodes at each
    /// end, meshed in its best-fit plane (Newell's normal; the end section's plane for planar
    /// input sections) (TowFace::Start, TowFace::End), so every tow's mesh
    /// is a closed surface. False: tubes open at their two ends.
    bool caps = true;
};

TOWGEOM_END_NAMESPACE
