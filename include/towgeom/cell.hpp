/// @file cell.hpp
/// @brief Cell: the box a textile is clipped to for a finite-element model of its unit cell
/// (ResolveOptions::cell), and CellMesh, what the clipped mesh holds on the box's faces.
#pragma once

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// A face of the cell's box.
enum class CellFace : unsigned char {
    XMin,  ///< x = min.x
    XMax,  ///< x = max.x
    YMin,  ///< y = min.y
    YMax,  ///< y = max.y
    ZMin,  ///< z = min.z
    ZMax   ///< z = max.z
};

/// "xmin", "xmax", "ymin", "ymax", "zmin" or "zmax".
TOWGEOM_EXPORT const char* cellFaceName(CellFace face) noexcept;

/// How a Cell cuts the tows.
enum class CellCut : unsigned char {
    /// Parametric for a periodic cell, Mesh otherwise.
    Auto,
    /// In each tow's (u,v) before meshing: each cut an exact curve around the tube, a constraint
    /// of the tow's mesh; the faces must cut each tow at most once at each end, all around, away
    /// from the box's edges (what a periodic cell needs: its faces' nodes pair up).
    Parametric,
    /// In the resolved meshes: every triangle clipped by the faces' planes (each new node on its
    /// edge, exactly on the plane: the clipped surfaces are parts of the resolved ones but where
    /// a node was moved, next),
    /// nodes closer to a plane it cuts past them than a fifth of their shortest edge first moved
    /// onto it along their surface (where that fails, only those within a fiftieth, straight;
    /// never turning a triangle over); nodes of a tow touching a face (not cut by it) are nodes
    /// of the face's mesh; each face meshed around
    /// the cuts. Any box: a face may cut a tow several times, along its length, through its
    /// overlaps with other tows, or at an edge or corner of the box; every piece is closed by its
    /// caps. Not periodic.
    Mesh
};

/// "auto", "parametric" or "mesh".
TOWGEOM_EXPORT const char* cellCutName(CellCut cut) noexcept;

/// An axis-aligned box in the user's units. With ResolveOptions::cell set, every tow is clipped
/// by it: where a face's plane cuts a tow, the cut (the plane's intersection with the tow's
/// surface, exact points at the tow's mesh size) is a constraint of the tow's mesh, the part
/// outside is dropped and the cut is closed by a planar cap on the face; a tow wholly outside
/// the box keeps no triangle. The box's faces are meshed around the caps (nodes shared with
/// them): with the tows' surfaces, the closed surface of the matrix (TextileMesh::cell).
///
/// Two ways to cut (#cut, CellCut). CellCut::Mesh (the default for a box that is not periodic)
/// clips the resolved meshes: any box, wherever its faces, edges and corners meet the tows (a
/// binder leaving the box and coming back is two pieces, both in its element set;
/// TowResolution::pieces counts them). CellCut::Parametric (periodic cells) cuts each tow in
/// its (u,v): what is clipped is a tow that crosses a face's plane once along its length, all
/// around (one cut around the tube), inside the face's rectangle. Refused there
/// (towgeom::Error, InvalidArgument, naming the tow (and the face) or the tow pair): a tow that
/// crosses a plane more than once, runs along it or crosses an edge of the box. Choose a
/// periodic cell's faces between crossings (for a woven unit cell: halfway between neighbouring
/// yarns). The rest of this comment is about the parametric cut.
///
/// A face may cut through an overlap of two tows that both cross it (tows pressed together
/// along their length): where their intersection loop crosses the face, the point on both
/// surfaces and on the face (Newton's method from the loop's chord) is a node of the loop, of
/// both tows' cuts and of the face's mesh; the loop's part inside the box bounds the region the
/// two share, and on the face the part of the lower-ranked tow's cut inside the higher-ranked
/// tow's is that tow's cap (the lower-ranked tow's cap is its section minus the other's). This
/// is the rank rule's work: with ResolutionMethod::Symmetric such a region keeps the
/// higher-ranked tow's surface (ConnectedRegion::note says so). With #periodic, each
/// crossing of a max face is the crossing of the same two tows on the opposite min face moved by
/// the box (refused when none lies within periodTolerance of the tows' size), so the faces' nodes
/// still pair up. Refused (naming the two tows) for a loop that goes around a tow, runs across
/// an end cap inside the box (across the caps outside it is fine: tows overlapping along their
/// whole length), or crosses the box near an edge.
struct TOWGEOM_EXPORT Cell {
    Point3 min;  ///< lower corner
    Point3 max;  ///< upper corner
    /// The textile repeats with the box's size along each axis along which tows cross the box:
    /// the cuts and the face meshes on max.x are those on min.x moved by max.x - min.x (nodes
    /// on the two faces pair up exactly), likewise y and z. A tow cut by the min face must be
    /// cut by the max face too, where its cut is the min face's moved (within periodTolerance).
    bool periodic = false;
    /// How far (relative to the tow's size) a node of a tow's cut moved from the min face onto
    /// the max face may lie from the max face's cut of that tow at the same place around it (the
    /// same v: the tow's sections must start at the same place around it on both faces, as
    /// generated textiles' do): a larger gap means the textile does not repeat with the box
    /// (refused). The moved node is the max face's node: its distance from the tow's surface is
    /// at most this gap.
    double periodTolerance = 1e-3;
    /// How fast the edge length of the box's faces grows away from the tows: at a point of a
    /// face it is h + faceSizeGrowth * d, where h is the finest tow's mesh size and d the
    /// distance (in 3D) to the nearest node of any tow's surface mesh (parts outside the cell
    /// included; with periodic, the nearer of the point and its partner on the opposite face),
    /// up to faceSizeMax * h; the caps (within each cut's bounding box) are meshed at h. So a
    /// face is fine where a tow crosses it or passes close to it, coarse elsewhere, and the
    /// matrix's tetrahedra follow (Gmsh grades the volume from its boundary).
    /// faceSizeGrowth = 0 or faceSizeMax = 1 meshes every face at h. The box's edges are
    /// divided at h.
    double faceSizeGrowth = 0.3;
    /// The box's faces' largest edge length, relative to the finest tow's mesh size (>= 1); see
    /// faceSizeGrowth.
    double faceSizeMax = 4.0;
    /// How the faces cut the tows (CellCut); Parametric and Auto for a periodic cell.
    CellCut cut = CellCut::Auto;

    /// Throws towgeom::Error (InvalidArgument) unless min < max on every axis, all finite,
    /// periodTolerance > 0, faceSizeGrowth >= 0 and faceSizeMax >= 1, all finite, and a
    /// periodic cell's cut is not CellCut::Mesh.
    void validate() const;
    /// The coordinate of @p face's plane.
    double plane(CellFace face) const;
    /// True when the tows are cut in their meshes (CellCut::Mesh, or Auto without #periodic).
    bool cutsMeshes() const { return cut == CellCut::Mesh || (cut == CellCut::Auto && !periodic); }
    /// The box's volume.
    double volume() const { return (max.x - min.x) * (max.y - min.y) * (max.z - min.z); }
};

/// What clipping to a Cell adds to a TextileMesh: the box and the matrix's part of its faces.
struct TOWGEOM_EXPORT CellMesh {
    Cell box;  ///< the cell, in the user's units
    /// The box's faces minus the tows' caps on them, over TextileMesh::nodes, counter-clockwise
    /// seen from outside the box. With every tow triangle that lies in no region and on no
    /// cell face (TowMesh::cutAt), reversed, they make the closed surface of the matrix.
    std::vector<std::array<std::size_t, 3>> triangles;
    std::vector<CellFace> face;  ///< the face of each triangle
    /// Per face (index by CellFace), every node on it (matrix and tow caps), sorted; exactly on
    /// the face's plane.
    std::array<std::vector<std::size_t>, 6> faceNodes;
    /// With Cell::periodic, per axis (0 x, 1 y, 2 z): every node of the min face with its partner
    /// on the max face, the same point moved by the box's size along the axis (exactly, in
    /// floating point), ordered by the min face's node.
    std::array<std::vector<std::pair<std::size_t, std::size_t>>, 3> periodicPairs;
};

TOWGEOM_END_NAMESPACE
