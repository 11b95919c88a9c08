// A tow's solid clipped to the cell's box (OCCT booleans): the part inside, and the volume and
// area of what was cut off, so that the inside's volume and area follow from the whole solid's
// without integrating over its trimmed B-spline face again.
#pragma once

#include <TopoDS_Solid.hxx>

#include <vector>

#include <cstddef>
#include <optional>
#include <string>

#include "towgeom/cell.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// What clipSolidToCell() gives.
struct ClippedSolid {
    std::optional<TopoDS_Solid> inside;  ///< the part inside the box; none when the solid lies wholly outside
    double outsideVolume = 0.0;          ///< the volume of the parts outside the box (not measured without an inside: 0)
    double outsideArea = 0.0;            ///< the area of their boundaries, the cut faces on the box included (likewise)
    double cutArea = 0.0;                ///< the area of the inside part's cut faces (made of the box's faces)
    std::size_t cutFaces = 0;            ///< how many cut faces the inside part has
};

/// Clips @p solid (tow @p tow) to @p cell: one intersection of the solid with the box, from
/// which both the common part and the cut-off parts are built (BRepAlgoAPI_Common and _Cut on
/// one BOPAlgo_PaveFiller). Faces the box does not cut are kept as they are (the same TopoDS
/// faces), so faces shared by two tows' solids stay shared.
/// @throws towgeom::Error (Internal) naming @p tow when OpenCASCADE's boolean fails, and
///         (Unsupported) when the inside is more than one solid.
ClippedSolid clipSolidToCell(const TopoDS_Solid& solid, const Cell& cell, const std::string& tow);

/// What cutMatrix() gives.
struct MatrixCut {
    /// The box minus the tows: one solid, or several where tows cut the box apart; each valid
    /// (BRepCheck_Analyzer).
    std::vector<TopoDS_Solid> pieces;
    std::size_t faces = 0;             ///< faces of all pieces
    std::size_t sharedFaces = 0;       ///< of them, faces of a tow's solid (the same face)
    std::size_t cellFaces = 0;         ///< of them, made of the box's faces
    std::string failure;               ///< why OpenCASCADE's boolean failed (pieces empty); empty when it did not
};

/// The cell's box minus @p tows (the tows' solids clipped to it), with OpenCASCADE's boolean cut
/// (its gluing option first, the full boolean when that fails or gives an invalid solid)
/// (tows as tools; destructive as clipSolidToCell(): a tolerance the intersection raises is
/// raised on the tows' own edges, so the tows' faces it keeps stay the tows' faces).
/// A failure of the boolean is returned in MatrixCut::failure, not thrown: it costs only the
/// matrix.
MatrixCut cutMatrix(const std::vector<TopoDS_Solid>& tows, const Cell& cell);

}  // namespace detail
TOWGEOM_END_NAMESPACE
