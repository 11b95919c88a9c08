/// @file mesh_options.hpp
/// @brief MeshOptions: size and quality of the tow surface meshes (ParametricMesher).
#pragma once

namespace towgeom {

/// How each tow's surface is meshed. Lengths are in the user's units; 0 means "relative to the
/// tow size" (TowSurface::towSize(), the smallest of the textile's tows).
struct MeshOptions {
    /// Target edge length h of the 3D triangles: every edge is at most about h in 3D (measured
    /// with the surface's metric), except loop chords, which are at the loop spacing.
    /// 0 (default): relativeEdgeLength x tow size. At most a quarter of the smallest tow's
    /// circumference (pi x tow size).
    double edgeLength = 0.0;
    /// edgeLength relative to the tow size when edgeLength is 0. Default 0.1.
    double relativeEdgeLength = 0.1;
    /// The smallest angle the mesher aims for, in degrees (at most 30). Default 20.
    double minAngle = 20.0;
    /// Spacing of the nodes along intersection loops. 0 (default): the edge length h. A smaller
    /// spacing refines the mesh along loops ("high" refinement), a larger one coarsens it.
    double loopSpacing = 0.0;
};

}  // namespace towgeom
