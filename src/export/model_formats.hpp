// Gmsh and Abaqus model files written to streams (mesh_export.hpp adds the atomic files).
#pragma once

#include <ostream>

#include "towgeom/textile_mesh.hpp"

namespace towgeom::detail {

void writeGmshMsh41(std::ostream& out, const TextileMesh& mesh);
void writeAbaqusInp(std::ostream& out, const TextileMesh& mesh);

}  // namespace towgeom::detail
