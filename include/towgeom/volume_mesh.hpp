/// @file volume_mesh.hpp
/// @brief Tetrahedra inside every resolved tow, conforming to the tows' surface triangles.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "towgeom/point.hpp"
#include "towgeom/report.hpp"
#include "towgeom/resolve.hpp"
#include "towgeom/textile_mesh.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// Options of meshVolumes().
struct VolumeMeshOptions {
    /// Gmsh's tetrahedral optimisation after HXT (moves and swaps interior nodes and faces only).
    bool optimize = true;
    /// 1: linear tetrahedra (4 nodes); 2: quadratic (10 nodes: Gmsh's node in the middle of every
    /// edge, the edges straight, shared by the tetrahedra and the two tows at a region).
    int order = 1;
    /// Threads for HXT (and the surfaces' checks before it); 0: as many as the machine has (so
    /// the default mesh is made on several threads). The tetrahedra may differ slightly from
    /// call to call (HXT's parallel insertion; within one process also Gmsh's state between
    /// calls); one thread in a fresh process gives the same mesh every time. Volumes and
    /// conformity do not change.
    std::size_t threads = 0;
    /// How fast the tetrahedra grow away from the surfaces: the edge length asked for at a point
    /// is the least, over the surface nodes, of the node's mean surface edge length plus
    /// (growthRate - 1) times the distance to it (neighbouring layers of tetrahedra differ in
    /// size by about this factor), at most maxSize (never below a node's own size). 1: no
    /// growth, the surfaces' sizes interpolated inside (Gmsh's default; several times more
    /// tetrahedra where there is room to grow). At most 1.5: beyond, Gmsh 4.8's HXT recovers the
    /// surfaces very slowly (minutes). The surface triangles are kept as they are either way.
    double growthRate = 1.3;
    /// The largest edge length asked for inside (with growthRate > 1); 0: 8 times the surface
    /// mesh's median edge length.
    double maxSize = 0.0;
};

/// Tetrahedra (linear, or quadratic: VolumeMeshOptions::order) filling each tow of a
/// TextileMesh (and the matrix of a cell), on the surface mesh as it is.
struct TOWGEOM_EXPORT VolumeMesh {
    /// The surface mesh's nodes first (same indices as TextileMesh::nodes), then the nodes
    /// inside the tows (and, for quadratic tetrahedra, the edges' middle nodes). Every surface
    /// triangle is a face of one tetrahedron of each tow it bounds (two at a region, one
    /// elsewhere): no corner node is added on a surface.
    std::vector<Point3> nodes;
    std::size_t surfaceNodes = 0;  ///< how many of nodes are the surface mesh's
    /// Four nodes each, ordered so that the signed volume (tetrahedronVolume()) is positive.
    std::vector<std::array<std::size_t, 4>> tetrahedra;
    /// Quadratic tetrahedra (VolumeMeshOptions::order 2): per tetrahedron the node in the middle
    /// of each of its edges (0,1), (1,2), (2,0), (0,3), (1,3), (2,3) of tetrahedra's corners (the
    /// order of Abaqus' C3D10 and VTK's quadratic tetrahedron); empty for linear ones. These
    /// nodes come after the surface mesh's nodes, mixed with the inner corners; those on a
    /// surface are in the middle of its triangles' edges.
    std::vector<std::array<std::size_t, 6>> edgeNodes;
    /// For each tetrahedron, the tow it lies in (an index into TextileMesh::tows), or
    /// TextileMesh::tows.size() for the matrix of a mesh clipped to a cell.
    std::vector<std::size_t> tow;
    /// True for the volumes of a mesh clipped to a cell: tow index TextileMesh::tows.size() is
    /// the matrix.
    bool withMatrix = false;
    /// For each tetrahedron its fibre direction (a unit vector), once addFibreDirections() has
    /// set them; empty before.
    std::vector<Vector3> fibreDirection;
    /// Wall time meshVolumes() spent in Gmsh's mesh generation (and, for order 2, its middle
    /// nodes), in seconds: the rest of its time is towgeom's own (checks before and after, the
    /// size field, reading the mesh back).
    double gmshSeconds = 0.0;
    /// The growth rate the tetrahedra were made with (VolumeMeshOptions::growthRate).
    double growthRate = 1.0;
    /// The largest size asked for (VolumeMeshOptions::maxSize, or the automatic one; 0 without
    /// growth).
    double maxSize = 0.0;

    /// The signed volume of tetrahedron @p k (meshVolumes() orders the nodes so that it is not
    /// negative).
    double tetrahedronVolume(std::size_t k) const;
    /// The summed volume of the tetrahedra of tow @p t (the matrix's: the number of tows).
    double towVolume(std::size_t t) const;
};

/// Shape of the tetrahedra of a VolumeMesh: dihedral angles (those of a regular tetrahedron are
/// 70.53 degrees; a sliver has angles near 0 and 180).
struct TOWGEOM_EXPORT TetrahedronQuality {
    double minDihedral = 0.0;  ///< the smallest dihedral angle of any tetrahedron, degrees
    double maxDihedral = 0.0;  ///< the largest, degrees
    /// Tetrahedra by their smallest dihedral angle: [0, 5), [5, 10), [10, 20), [20, 30),
    /// [30, 40), [40, 50), [50, 60), [60, 70.53] degrees.
    std::array<std::size_t, 8> histogram{};
};

/// The dihedral angles of every tetrahedron of @p volumes.
/// @throws towgeom::Error (InvalidArgument) if a tetrahedron names a node out of range.
TOWGEOM_EXPORT TetrahedronQuality tetrahedronQuality(const VolumeMesh& volumes);

/// Meshes the inside of every tow of @p surfaces (closed tows: MeshOptions::caps) with Gmsh's
/// HXT tetrahedral mesher, the surface triangles kept as they are (Gmsh discrete entities, no
/// surface remeshing), so the tetrahedra of two tows meet face to face on their shared regions.
/// Element sizes grow from the surface mesh inwards. A tow cut into pieces by a tow ranked above
/// it (TowResolution::pieces) gets one volume per piece. A mesh clipped to a cell
/// (TextileMesh::cell) gets the matrix too: the box minus the tows, bounded by the box's faces
/// (CellMesh::triangles) and every tow triangle in no region and not on the box, its tetrahedra
/// conforming to the tows' on those triangles. Gmsh is a process-wide engine: calls
/// are serialised; the first call starts Gmsh unless the host has (it then stays started for
/// the process); each call works in a model of its own and restores the host's current model
/// and the options it sets.
/// Gmsh's library (Debian: libgmsh4.8) is loaded on the first call, not linked.
/// @throws towgeom::Error (InvalidArgument) if VolumeMeshOptions::order is not 1 or 2, its
///         growthRate not in [1, 1.5] or its maxSize negative;
///         (EngineUnavailable) if Gmsh's library cannot be loaded;
///         (InvalidArgument) if a tow's surface is not a closed 2-manifold (every edge of its
///         triangles shared by exactly two of them, no triangle twice) or a triangle is in two
///         regions (Gmsh would end the process on such input);
///         (Unsupported) naming the tows and the place if two triangles on an edge where
///         surfaces meet (a loop's, a cap's rim) lie at under 0.01 degrees to each other, the
///         least angle Gmsh 4.8's HXT accepts: tows touching tangentially (pressed flat together)
///         leave no room for a tetrahedron there (ResolutionMethod::Shrink leaves a gap);
///         (Unsupported) naming the tow(s), the place and the count if Gmsh's HXT stops and
///         surface triangles are found crossing each other (exact predicates, looked for only
///         then): a tow whose fitted surface folds (TowResolution::fold), or surfaces passing
///         through each other;
///         (Internal) with Gmsh's message if Gmsh fails otherwise, if it added, moved or renumbered a
///         surface node, or (order 2) if a tetrahedron has no node at the middle of an edge.
TOWGEOM_EXPORT VolumeMesh meshVolumes(const TextileMesh& surfaces, const VolumeMeshOptions& options = {});

/// The tow pairs that still overlap in @p result's mesh: every entry of unresolvedPairs(result)
/// but `not_separated` (ResolutionMethod::Shrink could not separate the pair and the rank rule
/// resolved it). Their tetrahedra would overlap: meshVolumes(const ResolveResult&, const
/// VolumeMeshOptions&) refuses them, and `towgeom resolve --volume` writes the surfaces without
/// a volume mesh.
TOWGEOM_EXPORT std::vector<UnresolvedPairEntry> overlappingPairs(const ResolveResult& result);

/// meshVolumes() of @p result's mesh, refused while two of its tows still overlap
/// (overlappingPairs()): a finite-element model with overlapping tows is wrong however it is
/// meshed. The TextileMesh overload does not know which pairs were left unresolved.
///
/// Every surface triangle costs about five tetrahedra: surfaces graded by curvature
/// (MeshOptions::forVolume(), what `towgeom resolve --volume` uses by default) give about a
/// quarter of the uniform default's tetrahedra at the same stiffness within 1 % (README).
///
/// @code
/// towgeom::ResolveOptions o;
/// o.mesh = towgeom::MeshOptions::forVolume();
/// const towgeom::ResolveResult r = towgeom::resolveTextile(tows, o);
/// if (towgeom::overlappingPairs(r).empty()) {
///     const towgeom::VolumeMesh v = towgeom::meshVolumes(r);
///     std::cout << v.tetrahedra.size() << " tetrahedra\n";
/// }
/// @endcode
/// @throws towgeom::Error (InvalidArgument) naming the two tows of the first overlapping pair,
/// with its code and message, and how many pairs overlap (checked before Gmsh is loaded); and
/// as meshVolumes(const TextileMesh&, const VolumeMeshOptions&).
TOWGEOM_EXPORT VolumeMesh meshVolumes(const ResolveResult& result, const VolumeMeshOptions& options = {});

/// Sets VolumeMesh::fibreDirection: for each tetrahedron, the fibre direction of its tow at the
/// point of the tow's centreline (the polyline of its sections' centroids) nearest the
/// tetrahedron's centroid. At each section the direction is the mean around the section of the
/// unit tangent along the tow, dS/du / |dS/du| (the direction TowMesh::fibreDirection gives the
/// surface triangles); between two sections it is interpolated linearly along the segment and
/// normalised. The matrix's tetrahedra (VolumeMesh::tow the number of tows) get the zero
/// vector. @p tows are the tows @p volumes was made of, in the same order and units. Runs on
/// @p threads threads (0: one per hardware thread); the result does not depend on them.
/// @throws towgeom::Error (InvalidArgument) if a tetrahedron names a tow @p tows does not have
/// (checked before any work).
TOWGEOM_EXPORT void addFibreDirections(VolumeMesh& volumes, const std::vector<TowSurface>& tows, std::size_t threads = 0);

TOWGEOM_END_NAMESPACE
