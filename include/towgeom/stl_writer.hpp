/// @file stl_writer.hpp
/// @brief Writing triangle meshes as binary STL.
#pragma once

#include <string>

#include "towgeom/triangle_mesh.hpp"

namespace towgeom {

/// Writes @p mesh to @p path as binary STL (facet normals from the triangles' orientation),
/// under a temporary name renamed into place, so a failure never leaves a half-written file.
/// @throws towgeom::Error (WriteFailed) naming the path if the file cannot be written.
void writeStl(const TriangleMesh& mesh, const std::string& path);

}  // namespace towgeom
