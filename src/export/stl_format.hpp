// Binary STL, written to a stream by CGAL (the public writeStl() adds the atomic file).
#pragma once

#include <ostream>

#include "towgeom/triangle_mesh.hpp"

namespace towgeom::detail {

/// @p out must be opened in binary mode. Returns false when CGAL reports a failure.
bool writeStlBinary(std::ostream& out, const TriangleMesh& mesh);

}  // namespace towgeom::detail
