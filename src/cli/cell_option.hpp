// The --cell option of resolve and export: a box given as six numbers or as the "cell" of a
// generator's textile.json.
#pragma once

#include <string>
#include <vector>

#include "towgeom/cell.hpp"

namespace towgeom::cli {

/// --cell XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX, or --cell DIR/textile.json (its "cell", periodic as it
/// says; @p periodic (--periodic) makes either periodic).
/// @throws UsageError for a malformed list; towgeom::Error (FileNotFound, FileUnreadable,
///         InvalidArgument) naming the file.
Cell parseCell(const std::string& text, bool periodic);

}  // namespace towgeom::cli
