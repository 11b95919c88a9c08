// The kernel side of TrimmedBrep: the compound of the tows' solids.
#pragma once

#include <TopoDS_Compound.hxx>
#include <TopoDS_Solid.hxx>

#include <string>
#include <vector>

#include "towgeom/trimmed_brep.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

struct TrimmedBrep::Impl {
    TopoDS_Compound compound;          // the solids, shared faces shared
    // One per tow in input order (with a cell: per tow inside it), then the matrix's pieces.
    std::vector<TopoDS_Solid> solids;
    std::vector<std::string> names;    // their tows' names; MATRIX for the matrix's pieces
};

TOWGEOM_END_NAMESPACE
