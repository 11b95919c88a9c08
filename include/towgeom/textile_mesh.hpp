/// @file textile_mesh.hpp
/// @brief TextileMesh: the surface meshes of all tows on one global node numbering, with the
/// connected regions where tows share their surface.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "towgeom/cell.hpp"
#include "towgeom/point.hpp"
#include "towgeom/triangle_mesh.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// Which part of a tow's closed surface a triangle lies on.
enum class TowFace : unsigned char {
    Side,   ///< the tube (the fitted surface, or a region taken from another tow)
    Start,  ///< the cap closing the tow's first section
    End,    ///< the cap closing its last section
    /// A cap on a face of a cell (ResolveOptions::cell) that cut the tow, with CellCut::Mesh (a
    /// tow may have several, on several faces); the parametric cut's caps are Start or End
    /// triangles with TowMesh::cutAt set.
    Cell
};

/// One tow's surface mesh: triangles over the global nodes, counter-clockwise seen from outside
/// the tow (normals point out of the tow, also on a shared region, where they point out of the
/// tow the triangles belong to).
struct TowMesh {
    std::string name;                                  ///< the tow's name
    std::vector<std::array<std::size_t, 3>> triangles;  ///< global node indices
    /// For each triangle: the index of the connected region it belongs to, or -1.
    std::vector<long> region;
    /// For each triangle: the tube, one of the two end caps (MeshOptions::caps), or a cap on a
    /// cell's face (CellCut::Mesh).
    std::vector<TowFace> face;
    /// For each triangle the fibre direction of the surface it lies on: the unit tangent along
    /// that tow, dS/du / |dS/du| at the triangle's (u,v) centroid — this tow's for its own
    /// triangles, the other tow's for a region's triangles taken from it; on an end cap, that of
    /// the cap's end section (its mean over v).
    std::vector<Vector3> fibreDirection;
    /// Every node of this tow's mesh that lies on its own surface with its (u,v) there (v in
    /// [vMin, vMax)), sorted by node: its own nodes and its loops' nodes, not the caps' own
    /// nodes nor those of another tow's surface it took (a loop node, on both surfaces, has its
    /// (u,v) on each tow in that tow's list). A loop node on an end cap (a loop across the cap)
    /// has u beyond the tube's range, in the cap's chart: TowSurface::pointOnClosed().
    std::vector<std::pair<std::size_t, UV>> parameters;
    /// Clipped to a cell (ResolveOptions::cell): the face whose plane cut the tow at its start
    /// ([0]) and at its end ([1]); there the TowFace::Start or End triangles are the tow's cap
    /// on that face, not its own end section. Empty where the end is the tow's own.
    std::array<std::optional<CellFace>, 2> cutAt{};
};

/// Which surface a connected region's triangles lie on (ResolveOptions::method).
enum class SharedSurface : unsigned char {
    Primary,  ///< the primary's own surface inside the loop (the rank rule)
    Middle    ///< the mid-surface halfway between both tows' surfaces (ResolutionMethod::Symmetric)
};

/// Where two tows overlapped, the surface between them: the primary's (the higher-ranked tow's)
/// triangles inside one closed intersection loop of the pair that lie inside the secondary and
/// inside no other tow ranked above the secondary, now shared by both tows (same nodes, same
/// triangles, opposite orientation in the secondary). With two tows: the primary's surface inside
/// the loop.
struct ConnectedRegion {
    std::size_t primary = 0;             ///< tow index of the primary tow
    std::size_t secondary = 0;           ///< tow index of the secondary tow
    /// Index of the loop in the intersection report. Where a tow passes through another, the
    /// band between two loops around it is one region, named by the first of them.
    std::size_t loop = 0;
    /// Loops of the same tow pair inside this one (islands where the surfaces separate again):
    /// holes of the region, by index in the intersection report.
    std::vector<std::size_t> holes;
    std::vector<std::size_t> triangles;  ///< indices into the primary's TowMesh::triangles
    std::vector<std::size_t> nodes;      ///< global nodes of those triangles (sorted)
    /// Global nodes on the loop that bound the region's triangles, in loop order (where a
    /// higher-ranked third tow covers part of the loop, its nodes there are left out).
    std::vector<std::size_t> loopNodes;
    double area = 0.0;                   ///< area of the shared surface
    /// The volume of the two tows' overlap inside the loop: what the secondary lost there when no
    /// third tow overlaps them there (then the secondary's loss is volumeBefore - volumeAfter).
    double volumeRemoved = 0.0;
    /// The surface the region's triangles lie on. Its interior nodes (off every loop) lie on the
    /// primary's surface for SharedSurface::Primary, between both tows for Middle; then they are
    /// on neither tow's surface and in neither tow's TowMesh::parameters.
    SharedSurface surface = SharedSurface::Primary;
    /// Why ResolutionMethod::Symmetric kept the primary's surface here (a sentence); empty
    /// otherwise.
    std::string note;
};

/// A point where three tows' surfaces meet: the intersection loops of their three pairs cross
/// there. Solved on the three surfaces and one node of the three tows' meshes.
struct TriplePoint {
    std::size_t node = 0;             ///< the global node
    std::array<std::size_t, 3> tows{};  ///< the three tows, ascending
};

/// A corner of a tow mesh's constraints sharper than the mesh's angle bound
/// (MeshQuality::angleBound): two intersection loops meeting, or a loop meeting the seam of the
/// tow's parametrisation or the rim of its end at a small angle, on its side surface or on one
/// of its end caps (not yet on the caps a cell's faces make). No triangle in the corner can
/// keep the bound near its apex; MeshQuality judges the triangles there by the corner's own angle.
struct SharpCorner {
    std::size_t node = 0;        ///< the global node at the corner's apex
    std::size_t tow = 0;         ///< the tow whose mesh has the corner
    TowFace face = TowFace::Side;  ///< on the tow's side surface or on one of its end caps
    /// Degrees: the corner's angle on the tow's surface between its two constraints (as meshed:
    /// with ResolutionMethod::Symmetric a region's nodes move to the mid-surface afterwards).
    double angle = 0.0;
    /// The corner's triangles still in the tow's mesh: those at its apex in its wedge, and those
    /// reachable from them without crossing a constraint whose corners all lie within
    /// h / (2 sin(angle / 2)) of the apex (at most 20 h; h the tow's mesh size): where the wedge
    /// is narrower than h. MeshQuality asks a third of the corner's angle of them. A corner none
    /// of whose triangles is left (given up to a region of a tow ranked above, or beyond a
    /// cell's cut) is not listed.
    std::vector<std::array<std::size_t, 3>> triangles;
};

/// An intersection loop in the meshes: the global nodes both tows' meshes share along it.
struct MeshedLoop {
    std::size_t loop = 0;            ///< index in the intersection report
    /// Its global nodes in loop order, the first not repeated (a node of both tows' meshes; after
    /// connectRegions(), the nodes some triangle still uses: where a higher-ranked third tow covers
    /// part of the loop, its nodes there are gone). With a cell, only its nodes inside the box: a
    /// loop across a face runs from node to node on the face through the box only (connectRegions()
    /// follows IntersectionLoop::points() outside).
    std::vector<std::size_t> nodes;
};

/// The meshes of all tows of a textile on one node numbering: a node on an intersection loop
/// or in a connected region is the same node in every tow that uses it.
struct TOWGEOM_EXPORT TextileMesh {
    std::vector<Point3> nodes;             ///< global node positions
    std::vector<TowMesh> tows;             ///< one per input tow, in input order
    /// One per resolved loop that is not a hole of another and keeps triangles (a loop whose
    /// surface lies wholly inside a third, higher-ranked tow has none).
    std::vector<ConnectedRegion> regions;
    std::vector<TriplePoint> triplePoints;  ///< where three tows' resolved loops cross
    /// The constraint corners sharper than MeshQuality::angleBound, in tow order (a node may have
    /// several: one per tow, and per wedge).
    std::vector<SharpCorner> sharpCorners;
    /// The loops the tows were meshed with (meshTows(): every closed loop meshed; after
    /// connectRegions(): those of the tow pairs resolved), in report order.
    std::vector<MeshedLoop> loops;
    /// Clipped to a cell (ResolveOptions::cell): the box and the matrix's part of its faces.
    std::optional<CellMesh> cell;

    /// Tow @p tow's mesh as a standalone TriangleMesh (only the nodes it uses, renumbered in
    /// the order the triangles first use them).
    TriangleMesh towSurface(std::size_t tow) const;
    /// The global node of each vertex of towSurface(@p tow).
    std::vector<std::size_t> towNodes(std::size_t tow) const;
    /// The same, with any open end closed by a fan from the centroid of its boundary loop (for
    /// volumes of tubes meshed without caps); a closed mesh as it is.
    TriangleMesh closedTowSurface(std::size_t tow) const;
    /// The number of boundary loops (closed chains of edges used by one triangle only) of tow
    /// @p tow's mesh: 0 for a tow closed by its caps, 2 for a tube open at both ends.
    std::size_t boundaryLoopCount(std::size_t tow) const;
};

/// The mesh of @p triangles over @p nodes as a standalone TriangleMesh: only the nodes used,
/// renumbered in the order the triangles first use them.
TOWGEOM_EXPORT TriangleMesh surfaceOf(const std::vector<Point3>& nodes, const std::vector<std::array<std::size_t, 3>>& triangles);

/// The mesh of @p triangles over @p nodes (only the nodes used, renumbered) with each boundary
/// loop closed by a fan from its centroid: for the volume of an open tube.
TOWGEOM_EXPORT TriangleMesh closedSurface(const std::vector<Point3>& nodes, const std::vector<std::array<std::size_t, 3>>& triangles);

TOWGEOM_END_NAMESPACE
