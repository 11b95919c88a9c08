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
    /// loops' length x (1/loopSpacing - 1/h) for a loop spacing below h; graded by curvature,
    /// the area's mean of (h / size)^2 times as many; with a Cell, its six
    /// faces counted at the finest tow's h: an upper bound, they are graded coarser away from the
    /// tows, Cell::faceSizeGrowth) and refuses a mesh over this with ErrorCode::TooLarge. Default
    /// 20 million (about 5 GB); must be at least 1.
    std::size_t maxTriangles = 20000000;
    /// Close every tow by its two end caps (default): the polygon of the tube's end nodes at each
    /// end, meshed in its best-fit plane (Newell's normal; the end section's plane for planar
    /// input sections) (TowFace::Start, TowFace::End), so every tow's mesh
    /// is a closed surface. False: tubes open at their two ends.
    bool caps = true;

    /// Chord deviation d, for a mesh graded by the surface's curvature: where the largest
    /// principal curvature is k, edges are at most sqrt(8 d / k) long (an edge of length s
    /// stands off an arc of radius 1/k by about s^2 k / 8), never longer than the edge length h
    /// above (which becomes the size of the flat parts, the seam and the end caps) nor shorter
    /// than minEdgeLength, growing by at most the distance between two points of the surface.
    /// 0 (default) with relativeChordDeviation 0: no grading, edges at about h everywhere.
    double chordDeviation = 0.0;
    /// chordDeviation relative to the tow size, when chordDeviation is 0. Default 0 (off).
    double relativeChordDeviation = 0.0;
    /// The shortest edges a mesh graded by curvature asks for (at a flat tow's sharp edges,
    /// where the fitted surface's curvature is that of a crease); 0 (default) with
    /// relativeMinEdgeLength 0: h / 100. Taken within [h / 100, h].
    double minEdgeLength = 0.0;
    /// minEdgeLength relative to the tow size, when minEdgeLength is 0. Default 0.
    double relativeMinEdgeLength = 0.0;

    /// The sizes for a volume mesh (meshVolumes()), where every surface triangle costs about five
    /// tetrahedra: graded by curvature (relativeChordDeviation 0.01) from edges of a quarter of
    /// the tow size (relativeEdgeLength 0.25) where the tows are flat down to the default size
    /// (relativeMinEdgeLength 0.1, a tenth of the tow size) at their sharp edges. On the 8x8
    /// twill about a quarter of the default's surface triangles and tetrahedra (see
    /// benchmarks/bench_resolve --volume --cell).
    static MeshOptions forVolume()
    {
        MeshOptions o;
        o.relativeEdgeLength = 0.25;
        o.relativeChordDeviation = 0.01;
        o.relativeMinEdgeLength = 0.1;
        return o;
    }
};

TOWGEOM_END_NAMESPACE
