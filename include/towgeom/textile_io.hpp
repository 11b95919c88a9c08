/// @file textile_io.hpp
/// @brief Writing a generated textile: one `.stw` per yarn plus `textile.json`.
#pragma once

#include <string>

#include "towgeom/weave.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// What writeTextile() writes besides the stacks.
struct TextileOutput {
    bool facetedVtk = false;  ///< also NAME.faceted.vtk: the faceted yarn, ends closed (legacy VTK polydata)
    bool facetedStl = false;  ///< also NAME.faceted.stl: the same as binary STL
};

/// Writes DIR/NAME.stw for every yarn (the `.stw` format of stack_reader.hpp) and
/// DIR/textile.json: {"weave", "parameters":{...}, "yarns":[{"name","role","file","sections",
/// "points"}], "crossings":[{"warp","weft","x","y","warp_over"}], "cell":{"min":[x,y,z],
/// "max":[x,y,z],"periodic":true}} (the cell only where Textile::unitCell() has one), so later
/// tools can use roles and the unit cell (towgeom resolve --cell textile.json).
/// The directory is created if needed; all files appear only if every one was written.
/// @throws towgeom::Error (WriteFailed) naming the file that failed.
TOWGEOM_EXPORT void writeTextile(const Textile& textile, const std::string& directory, const TextileOutput& output = {});

TOWGEOM_END_NAMESPACE
