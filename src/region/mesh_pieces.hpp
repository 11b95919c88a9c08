// MeshPieces: the pieces a closed loop's chords cut a tow's mesh into, so that a loop's inside
// is decided per piece rather than per triangle.
#pragma once

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

class MeshPieces {
public:
    /// @p triangles: one tow's mesh over global nodes (its edges are found once, here).
    explicit MeshPieces(const std::vector<std::array<std::size_t, 3>>& triangles);

    /// The triangles inside a closed loop whose chords join consecutive @p loopNodes (the last
    /// back to the first), given each tested triangle's own test (@p inside, sorted; @p tested
    /// says which triangles have one: a cap triangle may have none). The chords cut the mesh
    /// into pieces; a piece is inside when more than 90 % of its tested triangles are in
    /// @p inside, outside when fewer than 10 % are, and keeps its triangles' own tests between.
    /// So does the whole mesh when the chords do not cut it: a chord that is no edge (a loop
    /// clipped by a cell), or one with the same piece on both sides. A triangle's own test, its
    /// (u,v) centroid against the loop's (u,v) polygon, can fail for a triangle thin along a
    /// chord: the chord is straight in the mesher's plane, which need not be linear in (u,v).
    /// Returns sorted indices of tested triangles only.
    std::vector<std::size_t> inside(const std::vector<std::size_t>& loopNodes, const std::vector<std::size_t>& inside,
                                    const std::vector<bool>& tested) const;

    using Edge = std::pair<std::size_t, std::size_t>;  ///< (smaller node, larger node)

private:
    std::size_t triangleCount_ = 0;
    /// Every edge once per triangle using it, and the triangle, sorted.
    std::vector<std::pair<Edge, std::size_t>> edges_;
};

}  // namespace detail
TOWGEOM_END_NAMESPACE
