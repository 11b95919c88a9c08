/// @file trimmed_brep.hpp
/// @brief trimmedBrep(): the resolved tows as exact solids — each tow's B-spline face trimmed by
/// its intersection loops, the faces two tows share built once and used by both, planar end
/// caps — and their STEP (AP214) and BREP files, for CAD-based FE workflows.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "towgeom/resolve.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// @defgroup brep Exact geometry out
/// @brief The resolved tows as trimmed B-spline solids (OpenCASCADE B-rep), STEP and BREP files.
/// @{

/// Options of trimmedBrep().
struct BrepOptions {
    /// The tolerance of the loops' edges (the largest distance between an edge's 3D curve and
    /// its curves on the two surfaces it lies on), in your units; 0: relativeTolerance times the
    /// smallest tow size. An edge that needs more (its curves built from the loop's points
    /// deviate further) gets what it needs: BrepSolid::maxTolerance reports it.
    double tolerance = 0.0;
    /// The tolerance relative to the smallest tow size when tolerance is 0.
    double relativeTolerance = 1e-6;
    /// With a cell: also build the matrix, the box minus the clipped tows (TrimmedBrep::matrix()),
    /// with OpenCASCADE's boolean cut (measured on the 6x6 twill's 4x4 cell, 8 tows inside:
    /// 0.4 s on two cores, 2 s on one). false: the tows only.
    bool matrix = true;
};

/// One resolved tow as a solid.
struct BrepSolid {
    std::string name;           ///< the tow's name
    /// The solid's volume: the tow's exact volume (TowSurface::volume()) changed by what its
    /// loops cut out and put in (OpenCASCADE's BRepGProp over the faces inside the loops, 1e-9
    /// relative) and, with a cell, less what the box cuts off (BRepGProp over those parts, 1e-9
    /// of their volume). Built by the general fuse (TrimmedBrep::fusedBecause()): the tow's exact
    /// volume less its splits it gives to tows ranked above it or that lie outside the box
    /// (BRepGProp, 1e-9 of theirs); the solid's own integral read back agrees within its
    /// edges' tolerance times its area (OpenCASCADE's intersection curves of nearly tangent
    /// surfaces carry a few 1e-6 of the tow size).
    double volume = 0.0;
    double area = 0.0;          ///< the area of its boundary (computed as the volume is)
    /// Faces of its shell (of all its solids, for a tow cut apart): its own (tube pieces, caps
    /// or cut faces on a cell's box) and the shared ones; 0 for a tow wholly outside the cell,
    /// or (general fuse) wholly inside tows ranked above it (no solid). The general fuse splits
    /// a tow's surface where other tows' surfaces meet it, so it counts more tube pieces.
    std::size_t faces = 0;
    std::size_t sharedFaces = 0;  ///< faces it shares with another tow's solid (the same face in both)
    /// With a cell: its cut faces, made of the box's faces where the box cuts it (2 for a tow
    /// cut at both ends; 0 for a tow wholly inside); 0 without a cell.
    std::size_t cellFaces = 0;
    /// Intersection loops of its regions (trimming curves; built by the general fuse, its own
    /// trimming curves are OpenCASCADE's intersections of the whole tows).
    std::size_t loops = 0;
    bool valid = false;         ///< BRepCheck_Analyzer accepts the solid (false where there is none: faces 0)
    double maxTolerance = 0.0;  ///< the largest tolerance of its edges and vertices, in your units
};

/// The resolved textile as one compound of solids, one per tow in input order (with a cell, one
/// per tow inside it; several for a tow cut apart by a tow ranked above it or by the box, see
/// trimmedBrep()); faces shared by two tows are one face used by both solids (with opposite
/// orientations).
class TOWGEOM_EXPORT TrimmedBrep {
public:
    /// The solids, one per input tow (with a cell, a tow wholly outside it has faces 0 and is not
    /// in the compound or the files).
    const std::vector<BrepSolid>& solids() const { return solids_; }
    /// The number of faces shared by two solids.
    std::size_t sharedFaceCount() const { return sharedFaces_; }
    /// With a cell (and BrepOptions::matrix): the matrix, the cell's box minus the tows' clipped
    /// solids, named MATRIX in the files (one solid, or several where tows cut the box apart;
    /// with a cavity where tows lie wholly inside the box).
    /// Its faces are the box's faces minus the tows' cut faces, and the tows' faces that no other
    /// tow shares: in writeBrep() those are the tows' own faces (the same face in both solids),
    /// in writeStep() written again for the matrix. volume is the box's less the tows' volumes
    /// (BrepSolid::volume), area the box's less the tows' faces on it plus the tows' faces it
    /// bounds (their BRepGProp areas), sharedFaces the faces it shares with the tows, cellFaces
    /// its faces on the box; valid: OpenCASCADE's checker accepts every piece, and its faces on
    /// the tows are exactly the tows' faces no other tow shares and not on the box (built by the
    /// general fuse, TrimmedBrep::fusedBecause(): the box's splits inside no tow, valid as its
    /// checker says). faces 0
    /// without a cell, without BrepOptions::matrix, or when it is not built (matrixNote() says
    /// why; then the files hold the tows only). A tow named MATRIX cannot be told from it in the
    /// files.
    const BrepSolid& matrix() const { return matrix_; }
    /// Why the matrix was not built although asked for (a cell and BrepOptions::matrix): tows
    /// that still overlap (the box less the tows would not be the matrix; the first pair named,
    /// as overlappingPairs() gives them), or OpenCASCADE's boolean failing or giving a solid
    /// that fails the checks above. Empty when it was built or not asked for (with the general
    /// fuse, pairs that still overlap are refused instead).
    const std::string& matrixNote() const { return matrixNote_; }
    /// Empty when the loops bound every face; otherwise why the solids were built from the whole
    /// tows by OpenCASCADE's general fuse (what the loops alone do not build, as the loop path
    /// refused it; see trimmedBrep()).
    const std::string& fusedBecause() const { return fusedBecause_; }

    /// Writes the compound as STEP AP214 to @p path, each solid named after its tow (the name of
    /// its MANIFOLD_SOLID_BREP), lengths in millimetres as STEP needs a unit: your units are
    /// written as they are (1 of yours = 1 mm). A shared face is written once per solid (each solid
    /// a closed shell of its own, which CAD readers and Gmsh import as solids): STEP readers see
    /// two coincident faces; writeBrep() keeps it one face. (OpenCASCADE's non-manifold STEP mode
    /// would keep it shared, but its solids then read back as shells: Gmsh finds no volume.)
    /// Written under a temporary name and renamed into place, so a failure leaves no file.
    /// @throws towgeom::Error (WriteFailed) naming @p path.
    void writeStep(const std::string& path) const;
    /// Writes the compound in OpenCASCADE's native BREP format to @p path (shared faces stay
    /// shared: one face referenced by both solids). Written as writeStep() is.
    /// @throws towgeom::Error (WriteFailed) naming @p path.
    void writeBrep(const std::string& path) const;
    /// writeStep() to a stream (OpenCASCADE writes STEP to files only: through a temporary file).
    /// @throws towgeom::Error (WriteFailed) when the temporary file cannot be written or read.
    void writeStep(std::ostream& out) const;
    /// writeBrep() to a stream.
    void writeBrep(std::ostream& out) const;

    /// Kernel data (opaque).
    struct Impl;
    /// Kernel data (the library's own use).
    const Impl& impl() const { return *impl_; }
    /// Made by trimmedBrep().
    TrimmedBrep(std::shared_ptr<const Impl> impl, std::vector<BrepSolid> solids, std::size_t sharedFaces, BrepSolid matrix = {},
                std::string matrixNote = {}, std::string fusedBecause = {});

private:
    std::shared_ptr<const Impl> impl_;
    std::vector<BrepSolid> solids_;
    std::size_t sharedFaces_ = 0;
    BrepSolid matrix_;
    std::string matrixNote_;
    std::string fusedBecause_;
};

/// Builds the resolved tows of @p resolved (resolveTextile() of @p tows, ResolutionMethod::
/// Connect) as exact solids. Tow t's solid is bounded by
/// - its own B-spline surface (periodic in v; its seam put where no loop crosses it), without
///   the inside of each loop where it gives way to a higher-ranked tow or where it is the primary
///   of a connected region (those insides are faces of their own),
/// - the faces it shares: for each ConnectedRegion, the primary's surface inside the loop (minus
///   the islands of ConnectedRegion::holes), in the primary's solid as it is and in the
///   secondary's reversed; each island stays a face of both tows' own surfaces,
/// - its two planar end caps (the end sections' planes).
///
/// With a cell (ResolveOptions::cell), each solid is then clipped to the cell's box by
/// OpenCASCADE's boolean common: where the box cuts a tow its caps are the cut faces on the
/// box's planes (the cell faces after clipping), and a tow wholly outside the box has no solid
/// (BrepSolid::faces 0, volume 0; it is left out of the compound and the files). Faces the box
/// does not cut stay as they are, so the shared faces stay shared; the two tows of a loop that
/// crosses a face of the cell (or comes near one) are clipped together, so the part of their
/// shared face inside the box stays one face of both. The matrix, the box minus the clipped
/// tows, is built too (TrimmedBrep::matrix(), BrepOptions::matrix), unless tows still overlap
/// (TrimmedBrep::matrixNote()).
/// Each loop is one edge: a periodic B-spline through its points (chord-length parameters) with a
/// periodic B-spline curve through its (u,v) points on each of the two surfaces, made same-
/// parameter by OpenCASCADE. BrepSolid::valid says whether OpenCASCADE's checker accepts each
/// solid (check it before you hand the file on).
///
/// Tow pairs resolveTextile() left unresolved (ResolveResult::unresolved) and loops it skipped
/// (ResolveResult::skippedLoops) are not trimmed here either: those tows' solids overlap there,
/// as their meshes do (refused instead where the general fuse is needed, or where the cell's
/// box cuts a face such a pair shares).
///
/// @code
/// const towgeom::ResolveResult r = towgeom::resolveTextile(tows);
/// const towgeom::TrimmedBrep brep = towgeom::trimmedBrep(tows, r);
/// for (const towgeom::BrepSolid& s : brep.solids())
///     std::cout << s.name << ": volume " << s.volume << (s.valid ? "" : " (invalid)") << "\n";
/// brep.writeStep("textile.step");
/// @endcode
///
/// Where the loops alone cannot bound the faces — three tows meeting at a point (loops of two
/// pairs crossing on a tow), a loop that winds around a tow (one passes through the other, which
/// it cuts into pieces) or runs across an end cap (a tow ending inside another), a region inside
/// another's island, loops that leave no v around a tow free for its face's seam, a tow the
/// cell's box cuts into more than one solid (untested: resolveTextile() refuses a cell face
/// that crosses a tow twice) — the solids are built from the tows' whole solids
/// instead: OpenCASCADE's general fuse of them all (and of the cell's box) splits them where they
/// meet, each split goes to the highest-ranked tow it lies in (of a pair, its regions' primary;
/// without a region, ResolveResult::ranks),
/// and each tow is the union of its splits, so the surface where tows overlapped is one face of
/// both there too, and with a cell the box's splits inside no tow are the matrix. A tow cut
/// apart is then several solids of its name in the compound and the files (BrepSolid sums them).
///
/// @throws towgeom::Error (InvalidArgument) when @p resolved is not of @p tows; (Unsupported)
///         naming what this version does not build: other methods than Connect, an end section
///         that is not planar, and, where the general fuse is needed, a tow pair or loop that
///         resolveTextile() left overlapping; (Internal) if OpenCASCADE fails.
TOWGEOM_EXPORT TrimmedBrep trimmedBrep(const std::vector<TowSurface>& tows, const ResolveResult& resolved,
                                       const BrepOptions& options = {});

/// @}

TOWGEOM_END_NAMESPACE
