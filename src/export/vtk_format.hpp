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

void writeVtkPolyData(std::ostream& out, const TriangleMesh& mesh, const std::string& title,
                      const VtkCellData& cellData = {});

}  // namespace towgeom::detail
