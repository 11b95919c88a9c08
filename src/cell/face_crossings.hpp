// Where an intersection loop crosses a face of the cell: the points on both tows' surfaces and
// on the face's plane (the loop's triple points with the plane), which become nodes of the loop,
// of both tows' cuts by that face and of the face's mesh. The part of the loop beyond the face
// is dropped with the tows' parts there; inside, the loop runs from such a point to the next.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "mesh/loop_nodes.hpp"
#include "towgeom/cell.hpp"
#include "towgeom/intersection_loop.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// One point where a loop of tows A and B crosses a face of the cell.
struct FaceCrossing {
    CellFace face = CellFace::XMin;
    std::size_t towA = 0, towB = 0;  ///< the loop's tows
    std::size_t node = 0;            ///< its global node, exactly on the face's plane
    UV onA, onB;                     ///< on each tow, v within its period
    /// With a periodic cell, for a crossing of a max face: the index of the crossing of the same
    /// two tows on the opposite min face that it is (moved by the box's size); else SIZE_MAX.
    std::size_t partner = SIZE_MAX;
};

/// True when global point @p p lies in the box of @p cell (its faces included).
bool inCellBox(const Cell& cell, const Point3& p);

/// True when the segment [@p p, @p q] meets the box of @p cell (its faces included).
bool segmentMeetsBox(const Point3& p, const Point3& q, const Cell& cell);

/// True when @p loop passes through the box of @p cell and leaves it: some chord of its points
/// meets the box and some point lies outside.
bool loopCrossesCellBox(const IntersectionLoop& loop, const Cell& cell);

/// For each loop @p shared[k] with @p across(k) true: finds every chord of it that crosses a
/// face's plane from inside the box to outside (or back), solves the exact point there (on both
/// surfaces and on the plane, Newton's method on four equations from the chord's point), inserts
/// it into the loop's nodes and appends it to @p nodes. A loop node inside the box closer than
/// @p closeness(k) to such a point is dropped (it would make slivers at the face). The loop's
/// nodes outside the box stay in it (its polygon still bounds the overlap on each tow); the
/// meshes take only its pieces inside (clipLoopPieces()). With Cell::periodic, each crossing of a
/// max face is paired with the crossing of the same two tows on the opposite min face whose
/// point, moved by the box's size, lies nearest: its node (in the loop too) is put exactly
/// there, so the two faces' cuts and meshes pair up (FaceCrossing::partner).
/// @throws Error (InvalidArgument) naming the two tows when the point is not found, lies outside
/// the face's rectangle, or a chord crosses two faces' planes (near an edge of the box); with a
/// periodic cell, when a crossing has no partner within Cell::periodTolerance of the tows' size.
std::vector<FaceCrossing> crossCellFaces(const std::vector<TowSurface>& tows, const std::vector<IntersectionLoop>& loops,
                                         std::vector<SharedLoop>& shared, const std::function<bool(std::size_t)>& across,
                                         const std::function<double(std::size_t)>& closeness, const Cell& cell,
                                         std::vector<Point3>& nodes);

/// The parts of @p pieces (a loop's constraints on one tow) whose nodes lie in the box of
/// @p cell: each maximal run of consecutive such nodes of at least two nodes, open.
std::vector<LoopConstraint> clipLoopPieces(const std::vector<LoopConstraint>& pieces, const Cell& cell, const std::vector<Point3>& nodes);

}  // namespace detail
TOWGEOM_END_NAMESPACE
