/// @file vtk_writer.hpp
/// @brief Writing triangle meshes as legacy VTK polydata (opens in ParaView).
#pragma once

#include <string>

#include "towgeom/triangle_mesh.hpp"

namespace towgeom {

/// Writes @p mesh to @p path as legacy ASCII VTK POLYDATA, with point normals when the mesh has
/// them. The file is written under a temporary name in the same directory and renamed into
/// place, so a failure never leaves a half-written file at @p path.
/// @throws towgeom::Error (WriteFailed) naming the path if the file cannot be written.
void writeVtk(const TriangleMesh& mesh, const std::string& path, const std::string& title);

}  // namespace towgeom
