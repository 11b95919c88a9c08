/// @file triangle_mesh.hpp
/// @brief TriangleMesh: a plain indexed triangle mesh (value type).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "towgeom/point.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// An indexed triangle mesh: vertices and triangles as vertex indices (counter-clockwise seen from
/// the side the normals point to).
struct TriangleMesh {
    std::vector<Point3> vertices;                        ///< vertex positions
    std::vector<std::array<std::size_t, 3>> triangles;  ///< vertex indices, 0-based
    std::vector<Vector3> normals;  ///< optional per-vertex unit normals (empty or one per vertex)
};

/// The signed volume enclosed by a closed, consistently oriented mesh (positive when its
/// triangles face outwards); meaningless for an open mesh.
TOWGEOM_EXPORT double enclosedVolume(const TriangleMesh& mesh);

TOWGEOM_END_NAMESPACE
