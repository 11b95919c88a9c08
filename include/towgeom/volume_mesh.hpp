/// @file volume_mesh.hpp
/// @brief Tetrahedra inside every resolved tow, conforming to the tows' surface triangles.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "towgeom/point.hpp"
#include "towgeom/textile_mesh.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// Options of meshVolumes().
struct VolumeMeshOptions {
    /// Gmsh's tetrahedral optimisation after HXT (moves and swaps interior nodes and faces only).
    bool optimize = true;
    /// Threads for HXT; 0: as many as the machine has.
    std::size_t threads = 0;
};

/// Linear tetrahedra filling each tow of a TextileMesh, on the surface mesh as it is.
struct TOWGEOM_EXPORT VolumeMesh {
    /// The surface mesh's nodes first (same indices as TextileMesh::nodes), then the nodes
    /// inside the tows. Every surface triangle is a face of one tetrahedron of each tow it bounds
    /// (two at a region, one elsewhere): no node is added on a surface.
    std::vector<Point3> nodes;
    std::size_t surfaceNodes = 0;  ///< how many of nodes are the surface mesh's
    /// Four nodes each, ordered so that the signed volume (tetrahedronVolume()) is positive.
    std::vector<std::array<std::size_t, 4>> tetrahedra;
    /// For each tetrahedron, the tow it lies in (an index into TextileMesh::tows).
    std::vector<std::size_t> tow;

    /// The signed volume of tetrahedron @p k (meshVolumes() orders the nodes so that it is not
    /// negative).
    double tetrahedronVolume(std::size_t k) const;
    /// The summed volume of the tetrahedra of tow @p t.
    double towVolume(std::size_t t) const;
};

/// Meshes the inside of every tow of @p surfaces (closed tows: MeshOptions::caps) with Gmsh's
/// HXT tetrahedral mesher, the surface triangles kept as they are (Gmsh discrete entities, no
/// surface remeshing), so the tetrahedra of two tows meet face to face on their shared regions.
/// Element sizes grow from the surface mesh inwards. Gmsh is a process-wide engine: calls are
/// serialised; Gmsh is initialised and finalised here unless the host has initialised it (then
/// only the model made here is removed).
/// Gmsh's library (Debian: libgmsh4.8) is loaded on the first call, not linked.
/// @throws towgeom::Error (EngineUnavailable) if Gmsh's library cannot be loaded;
///         (InvalidArgument) if a tow's surface is not closed (its triangles'
///         edges must each be shared by two of them);
///         (Internal) with Gmsh's message if Gmsh fails, or if it added, moved or renumbered a
///         surface node.
TOWGEOM_EXPORT VolumeMesh meshVolumes(const TextileMesh& surfaces, const VolumeMeshOptions& options = {});

TOWGEOM_END_NAMESPACE
