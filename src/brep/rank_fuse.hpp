// The rank rule on exact solids by OpenCASCADE's general fuse: every tow's whole solid (and the
// cell's box) split against each other, each split given to the highest-ranked tow it lies in,
// each tow the union of its splits. The way trimmedBrep() builds what its loops alone cannot
// (three tows at a point, loops across end caps or around a tow, a tow cut into pieces).
#pragma once

#include <TopoDS_Solid.hxx>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "towgeom/cell.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// One tow (or the matrix) as fuseByRank() gives it.
struct FusedSolid {
    /// The union of its splits: one solid per connected shell (a tow cut apart by a tow ranked
    /// above it, or by the box, has several); none when nothing of it is kept.
    std::vector<TopoDS_Solid> solids;
    double lostVolume = 0.0;   ///< the volume of its whole solid's splits it does not keep (tows: inside tows ranked above it, outside the box)
    double area = 0.0;         ///< the area of its boundary (from its whole solid's, see fuseByRank())
    std::size_t faces = 0;       ///< faces of its solids
    std::size_t sharedFaces = 0; ///< of them, faces of another tow's solids too (the same face)
    std::size_t cellFaces = 0;   ///< of them, cut faces: made of the box's faces, not its own
    double onBoxArea = 0.0;      ///< the area of its faces on the box (cut faces and its own faces there)
    double freeArea = 0.0;       ///< the area of its faces no other tow shares and not on the box
};

/// What fuseByRank() gives.
struct RankFusion {
    std::vector<FusedSolid> tows;  ///< per whole solid given, in order
    FusedSolid matrix;             ///< with a cell: the box's splits inside no tow (its volume and area not set)
    std::size_t sharedFaces = 0;   ///< faces two tows' solids share (each counted once)
};

/// The rank rule on @p whole, the tows' whole solids (closed by their caps; @p wholeArea their
/// boundaries' areas, @p names for messages): one general fuse of them all (and of @p cell's
/// box when given; BRepAlgoAPI_BuilderAlgo) splits them where they meet; a split inside several
/// tows goes to the one ranked above the others (@p above(a, b): tow a ranks above tow b), a split
/// outside the box is dropped, and each tow becomes the union of its splits (the faces between two
/// of its splits left out). A face between splits of two tows is the same face in both, so the
/// surface where tows overlapped is shared. With a cell the box's splits inside no tow are the
/// matrix. Areas are measured on the faces that changed only: a tow's is its whole solid's less
/// its faces' parts it does not keep plus the faces it gains.
/// @throws towgeom::Error (Internal) naming the tows when OpenCASCADE's general fuse fails or
///         a split lies in tows none of which ranks above the others.
RankFusion fuseByRank(const std::vector<TopoDS_Solid>& whole, const std::vector<double>& wholeArea,
                      const std::function<bool(std::size_t, std::size_t)>& above, const std::optional<Cell>& cell,
                      const std::vector<std::string>& names);

}  // namespace detail
TOWGEOM_END_NAMESPACE
