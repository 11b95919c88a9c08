/// @file stl_writer.hpp
/// @brief Writing triangle meshes as binary STL.
#pragma once

#include <iosfwd>
#include <string>

#include "towgeom/triangle_mesh.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// Writes @p mesh to @p path as binary STL (facet normals from the triangles' orientation),
/// under a temporary name renamed into place, so a failure never leaves a half-written file.
/// @throws towgeom::Error (WriteFailed) naming the path if the file cannot be written.
TOWGEOM_EXPORT void writeStl(const TriangleMesh& mesh, const std::string& path);

/// Writes @p mesh to @p out as binary STL; @p out must be opened in binary mode.
/// @throws towgeom::Error (WriteFailed) if the stream fails.
TOWGEOM_EXPORT void writeStl(const TriangleMesh& mesh, std::ostream& out);

TOWGEOM_END_NAMESPACE
