// Legacy VTK polydata, written to a stream (the public writeVtk() adds the atomic file).
#pragma once

#include <ostream>
#include <string>

#include "towgeom/triangle_mesh.hpp"

namespace towgeom::detail {

void writeVtkPolyData(std::ostream& out, const TriangleMesh& mesh, const std::string& title);

}  // namespace towgeom::detail
