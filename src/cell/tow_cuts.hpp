// Where the faces of a cell cut the tows: per tow, the plane of at most one face across its start
// and one across its end, each cut a closed curve around the tube given by exact points (the
// plane's intersection with each v-isoline, OCCT's curve/surface intersection) at the tow's mesh
// size. The cuts are constraints of the tow's (u,v) mesh; the part beyond them is dropped.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <functional>
#include <vector>

#include "cell/face_crossings.hpp"
#include "mesh/loop_nodes.hpp"
#include "towgeom/cell.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// One face's cut of one tow: a station per v_k = vMin + k * period / N, k = 0..N-1, and one at
/// each point where an intersection loop of the tow crosses the face (FaceCrossing), in
/// increasing v (a v_k station too close to such a point is left out, never the first).
struct TowCut {
    CellFace face = CellFace::XMin;
    std::vector<UV> uv;               ///< (u_k, v_k) on the tow; u_k where the isoline meets the plane
    std::vector<std::size_t> nodes;   ///< the global node of each station, exactly on the plane
};

/// The cuts of every tow of a textile by a cell.
struct CellCuts {
    std::vector<char> outside;                                  ///< per tow: nothing of it inside the cell
    std::vector<std::array<std::optional<TowCut>, 2>> cuts;     ///< per tow: across its start, across its end
    std::vector<char> cutNode;                                  ///< per global node: a node of some cut
    std::vector<double> vPeriod;                                ///< per tow: its v period

    /// True when (@p p.u, @p p.v) of tow @p tow lies on its kept side of both of its cuts (the
    /// cut polylines interpolated linearly in (u,v)); false for a tow outside.
    bool keeps(std::size_t tow, const UV& p) const;
    /// The u of tow @p tow that its cuts can keep: from its start cut's smallest u (else
    /// @p range.uMin) to its end cut's largest (else @p range.uMax); none for a tow outside.
    std::optional<std::array<double, 2>> keptSpan(std::size_t tow, const ParameterRange& range) const;
    /// Tow @p tow's cut at end @p end (0 its start, 1 its end) as a constraint of its mesh: from
    /// the station at vMin around to the same node at vMax.
    LoopConstraint constraint(std::size_t tow, int end, const ParameterRange& range) const;
};

/// The cuts of @p tows (in the normalised frame) by @p cell (the same frame) at the tows' mesh
/// sizes @p towH; the cut nodes are appended to @p nodes. With Cell::periodic the cut on a max
/// face is the same tow's min-face cut moved by the box's size (same stations). A face through a
/// tow's end section (within 1e-9 of the tow's size of its plane, on either side) cuts it on its
/// rim: the cut's u is kept 1e-9 of the u range inside (its nodes on the plane all the same), so
/// the end cap is dropped and the cut closes the tow; a tow beyond the plane that touches it
/// (within that distance) is outside.
/// @throws Error (InvalidArgument) naming the tow and face where a face's plane does not cut a
/// tow once all around inside the face's rectangle, two faces cut one end (the tow crosses an
/// edge of the box), or (periodic) a tow is cut by one face of a pair only or its moved cut
/// lies farther than Cell::periodTolerance from its surface. The points @p loopCrossings (nodes
/// already in @p nodes) become stations of both their tows' cuts by their face; with a periodic
/// cell a max face's crossing (FaceCrossing::partner) goes in at the index its partner took in
/// the min face's cut, with the same stations left out, so the two cuts stay paired station by
/// station (InvalidArgument naming the tows when that breaks the order around the tow).
/// Each cut's stations lie evenly around the tow at its mesh size @p towH, or, where @p sizeAt
/// gives a tow a graded size, at the smallest that size is along the cut.
CellCuts cutTows(const std::vector<TowSurface>& tows, const Cell& cell, const std::vector<double>& towH, std::vector<Point3>& nodes,
                 const std::vector<FaceCrossing>& loopCrossings = {}, const std::vector<std::function<double(const UV&)>>& sizeAt = {});

}  // namespace detail
TOWGEOM_END_NAMESPACE
