/// @file surface_mesher.hpp
/// @brief ParametricMesher: one tow's surface meshed in its (u,v) rectangle with the host's own
/// constraint polylines, on its own (the meshing stage of resolveTextile()).
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

#include "towgeom/export.hpp"
#include "towgeom/point.hpp"
#include "towgeom/textile_mesh.hpp"
#include "towgeom/tow_surface.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// @defgroup meshing Meshing one tow
/// @brief ParametricMesher: the mesher of resolveTextile() for one tow and any constraints.
/// @{

/// A polyline on a tow that the mesh must follow: every point becomes a node and every chord a
/// chain of mesh edges (the mesher may add nodes on a chord, never move one).
struct MeshConstraint {
    /// (u,v) on the tow: u within its range, v within [vMin, vMax]. A curve over the seam is
    /// given as pieces that end on v = vMin and v = vMax at the same u: a point on the seam is
    /// one node on both sides. Consecutive points differ. Equal points (in this or another
    /// constraint) are one node: constraints may meet there, and nowhere else — they may not
    /// cross, end on another's chord, or run along the seam or an end of the tow.
    std::vector<UV> points;
    bool closed = false;  ///< the last point joins the first (which is not repeated)
};

/// Size and shape of ParametricMesher's mesh.
struct SurfaceMeshOptions {
    /// Target 3D edge length h, in the user's units; 0 (default): relativeEdgeLength x the tow
    /// size (TowSurface::towSize()). At most a quarter of the tow's circumference.
    double edgeLength = 0.0;
    double relativeEdgeLength = 0.1;  ///< h relative to the tow size when edgeLength is 0
    double minAngle = 20.0;           ///< smallest triangle angle aimed for, degrees in (0, 30] (as MeshOptions::minAngle)
    /// Optional: the target edge length at a (u,v) of the tow, in the user's units, for a mesh
    /// graded where the host needs it (finer near a contact, a crack, a sensor). Taken within
    /// [h / 100, h] with h the edge length above, which stays the size of the seam and end
    /// stations. With grading by curvature, the smaller of the two. Called from the meshing
    /// thread; must be finite and positive (InvalidArgument otherwise).
    std::function<double(const UV&)> size;
    bool caps = true;                 ///< close the tube by its two end caps
    /// Refuse (TooLarge) a mesh estimated at more triangles (3 x the surface's area / (sqrt(3)/4
    /// h^2)), before meshing.
    std::size_t maxTriangles = 20'000'000;
    /// Grading by curvature, as MeshOptions::chordDeviation: edges at most sqrt(8 d / k) where
    /// the surface's largest principal curvature is k, within [minEdgeLength, h]. 0 (default,
    /// with relativeChordDeviation 0): none.
    double chordDeviation = 0.0;
    double relativeChordDeviation = 0.0;  ///< chordDeviation relative to the tow size when it is 0
    double minEdgeLength = 0.0;           ///< shortest graded edge; 0 (with the relative one 0): h / 100
    double relativeMinEdgeLength = 0.0;   ///< minEdgeLength relative to the tow size when it is 0
};

/// One tow's mesh made by ParametricMesher.
struct SurfaceMesh {
    std::vector<Point3> nodes;  ///< 3D positions, the user's units
    /// Per node its (u,v) on the tow (on the seam: v = vMin); NaN for the nodes inside the end
    /// caps, which lie in the caps' planes, not on the surface.
    std::vector<UV> uv;
    /// Triangles, counter-clockwise seen from outside the tow.
    std::vector<std::array<std::size_t, 3>> triangles;
    std::vector<TowFace> face;  ///< per triangle: tube (Side) or end cap (Start, End)
    /// Per triangle the fibre direction: the unit tangent along the tow, dS/du / |dS/du| at the
    /// triangle's (u,v) centroid; on a cap, that of the cap's end section (its mean over v).
    std::vector<Vector3> fibreDirection;
    /// Per constraint its nodes in order, those the mesher added on its chords included (the
    /// first not repeated at the end of a closed one).
    std::vector<std::vector<std::size_t>> constraintNodes;
    /// Meshing rounds: where meeting the bounds needed a constraint chord or a seam edge split,
    /// the split was added and the tow meshed on from there (at most 6).
    std::size_t rounds = 0;
};

/// Meshes one TowSurface in its (u,v) rectangle with CGAL's constrained Delaunay mesher, in a
/// parameter space scaled by the surface's lengths along and around the tow (conformally: as
/// long across the tow as along it, wherever its girth changes) so that triangles are well
/// shaped in 3D; the nodes on v = vMin and v = vMax are the same, so the mesh is a
/// tube closed across the seam, closed at its ends by its caps (SurfaceMeshOptions::caps). This
/// is the mesher resolveTextile() runs on every tow with the intersection loops as constraints;
/// here the constraints are the host's (cut lines, sensor paths, its own loops).
///
/// @code
/// towgeom::ParametricMesher mesher(tow);   // default: h = 0.1 x the tow size, caps
/// towgeom::MeshConstraint ring;            // a closed curve around (u, v) = (0.5, 0.5)
/// for (int k = 0; k < 24; ++k)
///     ring.points.push_back({0.5 + 0.05 * std::cos(k * M_PI / 12), 0.5 + 0.1 * std::sin(k * M_PI / 12)});
/// ring.closed = true;
/// const towgeom::SurfaceMesh m = mesher.mesh({ring});
/// // m.constraintNodes[0]: the ring's nodes, joined by mesh edges; m.uv: every node's (u,v)
/// @endcode
class TOWGEOM_EXPORT ParametricMesher {
public:
    /// A mesher of @p surface (kept by value: TowSurface is a cheap shared handle).
    /// @throws towgeom::Error (InvalidArgument) for an edge length that is not finite and
    /// positive, a minimum angle outside (0, 30], or h over a quarter of the tow's circumference.
    explicit ParametricMesher(TowSurface surface, const SurfaceMeshOptions& options = {});

    /// The surface meshed with @p constraints. Results do not depend on the units (computed in a
    /// frame where the tow is about unit size).
    /// @throws towgeom::Error (InvalidArgument) naming the constraint and point for a point off
    /// the rectangle or not finite, fewer than 2 points (3 when closed), two consecutive points
    /// alike, or a chord that is not a mesh edge (constraints that cross, end on another's
    /// chord, or run along the seam or an end); (TooLarge) for a mesh estimated over
    /// SurfaceMeshOptions::maxTriangles; (Internal) if the mesher cannot make a valid tube.
    SurfaceMesh mesh(const std::vector<MeshConstraint>& constraints = {}) const;

    /// The target edge length h in the user's units.
    double edgeLength() const { return h_; }

private:
    TowSurface surface_;
    SurfaceMeshOptions options_;
    double h_ = 0.0;
};

/// @}

TOWGEOM_END_NAMESPACE
