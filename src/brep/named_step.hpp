// Files written whole or not at all, and STEP files (AP214, OpenCASCADE's XDE writer) whose
// shapes carry names: shared by the trimmed B-rep's and the fibre-placement plan's writers.
#pragma once

#include <TopoDS_Shape.hxx>

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

/// A new empty file named @p prefix + 6 random characters + @p suffix (mkstemps: no other
/// writer, thread or process, gets the same name); its name.
std::string uniqueFile(const std::string& prefix, const std::string& suffix);

/// Writes @p path through @p write (given a temporary path next to it), then renames the
/// temporary into place; on any failure the temporary is removed and nothing is left.
/// @throws towgeom::Error (WriteFailed) naming @p path.
void writeReplacing(const std::string& path, const std::function<bool(const std::string&)>& write);

/// Writes @p shape as STEP AP214 to @p file, the shape named @p name and each of @p parts (its
/// sub-shapes) by its name (XDE); false when OpenCASCADE could not. Holds dataExchangeMutex().
bool writeNamedStep(const TopoDS_Shape& shape, const std::string& name, const std::vector<std::pair<TopoDS_Shape, std::string>>& parts,
                    const std::string& file);

/// Writes each of @p shapes as its own top-level shape (a STEP product) named by its name, to
/// @p file (AP214); false when OpenCASCADE could not. Holds dataExchangeMutex().
bool writeNamedStep(const std::vector<std::pair<TopoDS_Shape, std::string>>& shapes, const std::string& file);

}  // namespace detail
TOWGEOM_END_NAMESPACE
