/// @file mesh_export.hpp
/// @brief Model files of a TextileMesh for FE pre-processors: Gmsh .msh 4.1 and Abaqus .inp.
#pragma once

#include <iosfwd>
#include <string>

#include "towgeom/textile_mesh.hpp"
#include "towgeom/volume_mesh.hpp"
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

/// writeGmsh() with the tetrahedra of @p volumes (meshVolumes() of @p mesh): a volume entity per
/// tow (tag: the tow's number, 1-based) bounded by its surface entities (a region's entity with
/// a negative sign for its secondary), in a physical volume TOW_NAME, its inner nodes classified
/// on it; the surface entities and groups as without volumes; and, when @p volumes has its
/// fibre directions (addFibreDirections()), $ElementData "fibre_direction" (3 components per
/// tetrahedron; zero in the matrix). A mesh clipped to a cell (TextileMesh::cell) adds the
/// matrix as physical volume MATRIX (tag: the number of tows + 1), bounded by the box's faces
/// and the tows' surfaces it touches, and a physical surface per box face, XMIN ... ZMAX (the
/// matrix's and the tows' triangles on it); so does writeGmsh(mesh) for the surfaces. Quadratic
/// tetrahedra (VolumeMesh::edgeNodes) are written as 10-node tetrahedra and the surfaces as
/// 6-node triangles (their edges' middle nodes).
/// @throws towgeom::Error (InvalidArgument) if @p volumes is not of @p mesh.
TOWGEOM_EXPORT void writeGmsh(const TextileMesh& mesh, const VolumeMesh& volumes, std::ostream& out);

/// writeGmsh(mesh, volumes, out) to @p path, written to a temporary name and renamed.
/// @throws towgeom::Error (WriteFailed) naming @p path.
TOWGEOM_EXPORT void writeGmsh(const TextileMesh& mesh, const VolumeMesh& volumes, const std::string& path);

/// Writes @p mesh as an Abaqus (and CalculiX) input file, every triangle once: *NODE (1-based
/// global numbering, each coordinate in at most 20 characters: its shortest exact text, or
/// rounded to the 13-14 significant digits that fit, as CalculiX reads only 20); *ELEMENT
/// TYPE=S3 blocks with ELSET=OWN_NAME per tow (the triangles it has alone: tube outside regions,
/// end caps) and ELSET=SHARED (the regions' triangles, in their primary's orientation); per
/// connected region *ELSET REGION_k (its triangles) and *NSET REGION_k (its nodes); per tow
/// with end caps *ELSET CAPS_NAME; per tow *ELSET TOW_NAME (its closed surface: OWN_NAME and its
/// REGION_k sets, by name); and *ELSET TEXTILE (every tow element). A mesh clipped to a cell
/// adds *ELEMENT TYPE=S3 ELSET=MATRIX_FACES (the box's faces outside the tows) and per box face
/// *NSET XMIN ... ZMAX (every node on it). Names are upper-cased by CalculiX. Written to a
/// temporary name and renamed.
/// @throws towgeom::Error (WriteFailed) naming @p path.
TOWGEOM_EXPORT void writeAbaqus(const TextileMesh& mesh, const std::string& path);

/// writeAbaqus() to the stream @p out.
TOWGEOM_EXPORT void writeAbaqus(const TextileMesh& mesh, std::ostream& out);

/// Writes the tetrahedra of @p volumes (meshVolumes() of @p mesh) as an Abaqus/CalculiX input
/// file: *NODE (the nodes the tetrahedra use, 1-based global numbering, at most 20 characters a
/// number), *ELEMENT TYPE=C3D4 with ELSET=TOW_NAME per tow, per tow *NSET NODES_NAME (its nodes)
/// and START_NAME / END_NAME (the nodes of its end caps, where supports and loads go), and
/// *ELSET TEXTILE (every tow element). Two tows' elements share the nodes of their regions.
/// A mesh clipped to a cell adds *ELSET MATRIX (the matrix's elements; its nodes on the tows'
/// surfaces are the tows') and per box face *NSET XMIN ... ZMAX (every node on it). With fibre
/// directions (addFibreDirections()) also *DISTRIBUTION FIBRE_AXES (LOCATION=ELEMENT, its
/// *DISTRIBUTION TABLE COORD3D, COORD3D: per tow element the local 1-axis along its fibres, the
/// 2-axis normal to it towards global z, or y where the fibres run along z) and *ORIENTATION
/// FIBRES using it: `*SOLID SECTION, ELSET=TEXTILE, MATERIAL=M, ORIENTATION=FIBRES` gives
/// orthotropic tows their axes (Abaqus 6.14 and later; CalculiX 2.17 and later, which warns
/// that it skips the *DISTRIBUTION TABLE line). Quadratic tetrahedra (VolumeMesh::edgeNodes)
/// are written as C3D10, their middle nodes in every node set they lie on.
/// @throws towgeom::Error (InvalidArgument) if @p volumes is not of @p mesh, or its fibre
/// directions are not one unit vector per tow tetrahedron.
TOWGEOM_EXPORT void writeAbaqus(const TextileMesh& mesh, const VolumeMesh& volumes, std::ostream& out);

/// writeAbaqus(mesh, volumes, out) to @p path, written to a temporary name and renamed.
/// @throws towgeom::Error (WriteFailed) naming @p path.
TOWGEOM_EXPORT void writeAbaqus(const TextileMesh& mesh, const VolumeMesh& volumes, const std::string& path);

/// Writes periodic boundary conditions for the volume mesh of a periodic cell (Cell::periodic)
/// as an Abaqus/CalculiX include file: three reference nodes REF_X, REF_Y, REF_Z (numbered
/// after the mesh's nodes) and, for every node q on a max face with its partner p on the min
/// face (CellMesh::periodicPairs), *EQUATION u(q) - u(p) - u(REF_a) = 0 per direction, where a is
/// the axis of the pair. A node on several max faces (the box's edges and corners) is tied by
/// its highest axis only, so each node is dependent at most once and the ties chain back to the
/// min faces; the highest axis's ties come first, so no dependent node appears in a later tie
/// (Abaqus' rule). The displacement of REF_a is the cell's stretch along axis a (REF_X =
/// (eps_xx, eps_yx, eps_zx) * Lx). *NSET CORNER holds the node at the box's min corner (fix it
/// against rigid motion). With quadratic tetrahedra the middle nodes on the faces are tied too.
/// Include it after writeAbaqus(mesh, volumes)'s file; put no *BOUNDARY on the max faces' nodes
/// (they are dependent). CalculiX reports no reaction force at the reference nodes (no element
/// uses them): read the force on the max face (*NODE PRINT, NSET=XMAX, TOTALS=ONLY, RF).
/// @throws towgeom::Error (InvalidArgument) if @p mesh is not clipped to a periodic cell or
/// @p volumes is not of it.
TOWGEOM_EXPORT void writeAbaqusPeriodic(const TextileMesh& mesh, const VolumeMesh& volumes, std::ostream& out);

/// writeAbaqusPeriodic(mesh, volumes, out) to @p path, written to a temporary name and renamed.
/// @throws towgeom::Error (WriteFailed) naming @p path.
TOWGEOM_EXPORT void writeAbaqusPeriodic(const TextileMesh& mesh, const VolumeMesh& volumes, const std::string& path);

/// Writes the tetrahedra of @p volumes as a VTK XML unstructured grid (.vtu, ASCII) for
/// ParaView: the nodes, one cell (VTK_TETRA, or VTK_QUADRATIC_TETRA with VolumeMesh::edgeNodes)
/// per tetrahedron, and per cell "tow_id" (the tow's
/// index, -1 in the matrix), "material" (1 a tow, 0 the matrix) and, with fibre directions,
/// "fibre_direction" (3 components, zero in the matrix).
/// @throws towgeom::Error (InvalidArgument) if @p volumes is not of @p mesh.
TOWGEOM_EXPORT void writeVtu(const TextileMesh& mesh, const VolumeMesh& volumes, std::ostream& out);

/// writeVtu(mesh, volumes, out) to @p path, written to a temporary name and renamed.
/// @throws towgeom::Error (WriteFailed) naming @p path.
TOWGEOM_EXPORT void writeVtu(const TextileMesh& mesh, const VolumeMesh& volumes, const std::string& path);

TOWGEOM_END_NAMESPACE
