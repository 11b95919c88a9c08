/// @file vtk_writer.hpp
/// @brief Writing triangle meshes as legacy VTK polydata (opens in ParaView).
#pragma once

#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

#include "towgeom/triangle_mesh.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// Writes @p mesh to @p path as legacy ASCII VTK POLYDATA, with point normals when the mesh has
/// them. The file is written under a temporary name in the same directory and renamed into
/// place, so a failure never leaves a half-written file at @p path.
/// @throws towgeom::Error (WriteFailed) naming the path if the file cannot be written.
TOWGEOM_EXPORT void writeVtk(const TriangleMesh& mesh, const std::string& path, const std::string& title);

/// Integer fields by name (e.g. "tow_id", "region_id"), one value per triangle or per vertex.
using VtkIntegerFields = std::vector<std::pair<std::string, std::vector<long>>>;

/// Writes @p mesh to @p out as legacy ASCII VTK POLYDATA titled @p title, with point normals when
/// the mesh has them, @p cellData per triangle and @p pointData per vertex (each field as long as
/// the triangles or vertices), each set as one FIELD block (arrays of type int) that legacy
/// readers read whole by default.
/// @throws towgeom::Error (InvalidArgument) if a field's length does not match.
TOWGEOM_EXPORT void writeVtk(const TriangleMesh& mesh, std::ostream& out, const std::string& title, const VtkIntegerFields& cellData = {},
              const VtkIntegerFields& pointData = {});

TOWGEOM_END_NAMESPACE
