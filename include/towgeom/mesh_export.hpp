/// @file mesh_export.hpp
/// @brief Model files of a TextileMesh for FE pre-processors: Gmsh .msh 4.1 and Abaqus .inp.
#pragma once

#include <iosfwd>
#include <string>

#include "towgeom/textile_mesh.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// Writes @p mesh as a Gmsh 4.1 ASCII mesh: node tags are the global node numbers + 1; a surface
/// entity per tow (its tube triangles outside regions), per connected region (its triangles once,
/// as the primary has them) and per tow with end caps (TowMesh::face); physical groups
/// "TOW_NAME" per tow (a region's entity belongs to both of its tows' groups, a caps entity to its
/// tow's), "REGION_k" per region and "CAPS_NAME" per tow with caps. Written to a temporary name
/// and renamed.
/// @throws towgeom::Error (WriteFailed) naming @p path.
TOWGEOM_EXPORT void writeGmsh(const TextileMesh& mesh, const std::string& path);

/// writeGmsh() to the stream @p out.
TOWGEOM_EXPORT void writeGmsh(const TextileMesh& mesh, std::ostream& out);

/// Writes @p mesh as an Abaqus input file: *NODE (1-based global numbering), *ELEMENT TYPE=S3 per
/// tow with ELSET=TOW_NAME (element numbers consecutive over the tows in order), and per
/// connected region *ELSET REGION_k (both tows' copies) and *NSET REGION_k (its nodes), and per
/// tow with end caps *ELSET CAPS_NAME. Written to a temporary name and renamed.
/// @throws towgeom::Error (WriteFailed) naming @p path.
TOWGEOM_EXPORT void writeAbaqus(const TextileMesh& mesh, const std::string& path);

/// writeAbaqus() to the stream @p out.
TOWGEOM_EXPORT void writeAbaqus(const TextileMesh& mesh, std::ostream& out);

TOWGEOM_END_NAMESPACE
