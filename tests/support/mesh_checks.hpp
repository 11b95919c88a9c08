// Checks of triangle meshes written for the tests, independent of the code under test (no
// TextileMesh, no towgeom routine): the boundary of a triangle soup on one node numbering.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace towgeom::testing {

/// The boundary of a triangle mesh, counted from its triangles' edges alone.
struct Boundary {
    std::size_t edges = 0;             ///< edges used by exactly one triangle
    std::size_t nodesNotTwo = 0;       ///< boundary nodes with other than two boundary edges
    std::size_t nonManifoldEdges = 0;  ///< edges used by more than two triangles
    std::size_t misorientedEdges = 0;  ///< interior edges not used once in each direction
    std::size_t loops = 0;             ///< connected components of the boundary edges
};

/// The boundary of @p triangles (node indices): a tube open at both ends has two loops, every
/// boundary node on two boundary edges, no non-manifold or misoriented edge.
Boundary boundaryOf(const std::vector<std::array<std::size_t, 3>>& triangles);

}  // namespace towgeom::testing
