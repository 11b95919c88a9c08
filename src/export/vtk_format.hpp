// Legacy VTK polydata, written to a stream (the public writeVtk() adds the atomic file).
#pragma once

#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "towgeom/triangle_mesh.hpp"

namespace towgeom::detail {

/// Integer data per triangle, by name (e.g. "tow_id", "region_id").
using VtkCellData = std::vector<std::pair<std::string, std::vector<long>>>;

/// Writes legacy VTK polydata; @p cellData per triangle, @p pointData per vertex (integers).
void writeVtkPolyData(std::ostream& out, const TriangleMesh& mesh, const std::string& title,
                      const VtkCellData& cellData = {}, const VtkCellData& pointData = {});

}  // namespace towgeom::detail
