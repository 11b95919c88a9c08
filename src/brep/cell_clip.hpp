// A tow's solid clipped to the cell's box (OCCT booleans): the part inside, and the volume and
// area of what was cut off, so that the inside's volume and area follow from the whole solid's
// without integrating over its trimmed B-spline face again.
#pragma once

#include <TopoDS_Face.hxx>
#include <TopoDS_Solid.hxx>

#include <vector>

#include <cstddef>
#include <optional>
#include <string>

#include "towgeom/cell.hpp"
#include "towgeom/resolve.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/trimmed_brep.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// What clipSolidsToCell() gives for one solid.
struct ClippedSolid {
    std::optional<TopoDS_Solid> inside;  ///< the part inside the box; none when the solid lies wholly outside
    double outsideVolume = 0.0;          ///< the volume of the parts outside the box (not measured without an inside: 0)
    double outsideArea = 0.0;            ///< the area of their boundaries, the cut faces on the box included (likewise)
    double cutArea = 0.0;                ///< the area of the inside part's cut faces (made of the box's faces)
    std::size_t cutFaces = 0;            ///< how many cut faces the inside part has
    /// The inside part's faces on the box (the boolean's images of the box's faces): its cut
    /// faces, and its own faces that coincide with the box's (an end cap in a box plane).
    std::vector<TopoDS_Face> onBox;
};

/// Clips @p solids (tows @p names, as many) to @p cell. One solid: one intersection with the box
/// (one BOPAlgo_PaveFiller), from which its common part and cut-off parts are built
/// (BRepAlgoAPI_Common and _Cut on that filler). Several: one general fuse of them all with the
/// box (BRepAlgoAPI_BuilderAlgo), a solid's inside part being its split that is also a split of
/// the box; a face two of them share that the box cuts is split once, so its part inside stays
/// one face of both. Faces the box does not cut are kept as they are (the same TopoDS faces).
/// Clip the tows that share a face the box cuts together; each of the others alone
/// (intersecting tows with each other costs time). The cut faces are the inside part's images of
/// the box's faces that are not the solid's own faces (a cap coinciding with a box face is not
/// cut).
/// @throws towgeom::Error (Internal) naming the tows when OpenCASCADE's boolean fails, and
///         (Unsupported) naming the tow whose inside is more than one solid.
std::vector<ClippedSolid> clipSolidsToCell(const std::vector<TopoDS_Solid>& solids, const Cell& cell,
                                           const std::vector<std::string>& names);

/// What clipTowsToCell() adds up.
struct ClippedTows {
    double onBoxAreas = 0.0;      ///< the area of the tows' faces on the box (with @p areas)
    double freeAreas = 0.0;       ///< the area of the tows' faces no other tow shares and not on the box (with @p areas)
    std::size_t sharedFaces = 0;  ///< faces two clipped solids share (each counted once)
    std::vector<TopoDS_Face> onBox;  ///< the tows' faces on the box (ClippedSolid::onBox)
};

/// A face two tows share (a region's face on its primary).
struct SharedFace {
    std::size_t towA = 0, towB = 0;
    TopoDS_Face face;
};

/// trimmedBrep()'s tows clipped to the cell of @p resolved (which has one): @p built[t], the
/// solid of tow t, becomes its part inside the box (null when it lies wholly outside), and
/// @p solids[t] its volume, area, faces, shared and cut faces. The two tows of a face in
/// @p shared whose bounding box (BRepBndLib::AddOptimal) reaches a face of the box, or comes
/// within 5 % of the smaller tow's size of one, are clipped together (clipSolidsToCell()), so the
/// part of the face inside stays shared (not the pairs that still overlap, overlappingPairs():
/// their common part would be a piece of both); the others alone. Each face of @p shared keeps
/// at least its part inside. With @p areas the areas the matrix needs are measured too.
/// @throws towgeom::Error (Internal) when a tow's solid and its mesh disagree on being inside,
///         or a shared face is lost; as clipSolidsToCell().
ClippedTows clipTowsToCell(const std::vector<TowSurface>& tows, const ResolveResult& resolved, const std::vector<SharedFace>& shared,
                           std::vector<TopoDS_Solid>& built, std::vector<BrepSolid>& solids, bool areas);

/// What cutMatrix() gives.
struct MatrixCut {
    /// The box minus the tows: one solid, or several where tows cut the box apart; each valid
    /// (BRepCheck_Analyzer).
    std::vector<TopoDS_Solid> pieces;
    std::size_t faces = 0;             ///< faces of all pieces
    std::size_t sharedFaces = 0;       ///< of them, faces of a tow's solid (the same face)
    std::size_t cellFaces = 0;         ///< of them, made of the box's faces
    std::string failure;               ///< why there is no matrix (pieces empty); empty when there is
};

/// The cell's box minus @p tows (the tows' solids clipped to it, not overlapping; @p onBox their
/// faces on the box, ClippedTows::onBox), with OpenCASCADE's boolean cut: its gluing option
/// first, the full boolean when that fails or its result does not pass the checks (each piece
/// valid for BRepCheck_Analyzer; the pieces' faces on the tows exactly the tows' faces no other
/// tow shares and not in @p onBox, each in one piece). Tows as tools, destructive as
/// clipSolidsToCell(): a tolerance the intersection raises is raised on the tows' own edges, so
/// the tows' faces it keeps stay the tows' faces.
/// A failure is returned in MatrixCut::failure, not thrown: it costs only the matrix.
MatrixCut cutMatrix(const std::vector<TopoDS_Solid>& tows, const Cell& cell, const std::vector<TopoDS_Face>& onBox);

}  // namespace detail
TOWGEOM_END_NAMESPACE
