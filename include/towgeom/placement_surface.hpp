/// @file placement_surface.hpp
/// @brief readPlacementSurface(), fitPlacementSurface(): a fibre-placement tool surface as a
/// NurbsSurface, from a face of a STEP or IGES file or fitted to a grid of points.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "towgeom/nurbs_offset.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// @addtogroup placement
/// @{

namespace detail {
struct FaceTrim;  // a trimmed face's curves (OpenCASCADE's face), opaque
}  // namespace detail

/// A tool surface: a face read from a CAD file, or a surface fitted to a grid of points.
struct PlacementSurface {
    /// The face's surface as a clamped NURBS over the face's (u,v) box (OpenCASCADE's
    /// GeomConvert: exact for B-spline, Bezier, analytic, revolution and extrusion surfaces; other
    /// kinds, such as offset surfaces, approximated to 1e-4), its normal turned to the face's
    /// outward side (the u direction reversed when the face is reversed). Where the face is
    /// trimmed, the surface runs on past its edges to the box (see trim). For a grid, the fitted
    /// surface.
    NurbsSurface surface;
    std::size_t faceCount = 0;  ///< faces in the file (0 for a grid)
    std::size_t face = 0;       ///< which one this is (0-based, in the file's order); the first of several joined
    /// The faces the surface is made of: one, or several joined into one surface side to side
    /// (see readPlacementSurface(const std::string&, const std::vector<std::size_t>&)); empty
    /// for a grid.
    std::vector<std::size_t> faces;
    /// The face's name in the file, empty if it has none: a STEP ADVANCED_FACE's name, or an
    /// IGES entity's Name property, else its short label with its subscript as "LABEL(n)"
    /// (none for subscript 0; blanks at either end trimmed).
    std::string name;
    /// For an approximated grid: the largest distance from a grid point to the surface (0 for a
    /// face or an interpolated grid, which passes through its points).
    double fitDeviation = 0.0;
    /// The face's trimming curves where its boundary is not its (u,v) box (an outer boundary
    /// cutting into the box, holes), kept as the file gives them (OpenCASCADE's face, opaque
    /// here); null for a grid or a face whose edges all run along its box's sides (seams and
    /// poles aside). Given the PlacementSurface, layCourses(), referenceFromPlane() and
    /// courseCoverage() end tows, references and cells at these curves (points classified by
    /// OpenCASCADE's face classifier); given its NurbsSurface alone, at the box. It holds the
    /// mapping from this surface's (u,v) to the face's own: it belongs to `surface` as read, and
    /// means nothing for a surface changed or replaced (then reset it).
    std::shared_ptr<const detail::FaceTrim> trim;
    /// How many of the face's edges bound it where it is trimmed (seams and poles not counted;
    /// 0 untrimmed). A tow ending on one is said to end on "edge K", K its index among all the
    /// face's edges, seams included, in OpenCASCADE's order (TopExp::MapShapes on the face), so
    /// K may reach past trimEdges.
    std::size_t trimEdges = 0;
};

/// Reads face @p face (0-based, in the order OpenCASCADE explores the file's shapes) of the STEP
/// (.step, .stp) or IGES (.iges, .igs) file @p path, or fits the point grid of a .grid file (see
/// fitPlacementSurface(); the file: '#' comments, a line 'grid NU NV', then NU x NV lines 'x y z',
/// v varying fastest; interpolated, @p face must be 0). Lengths come out in millimetres from
/// STEP and IGES: OpenCASCADE's readers convert the file's unit (a file in metres gives 1000 per
/// metre); a grid's are its own. Safe to call from several threads (OpenCASCADE's data exchange
/// is serialised).
/// @throws towgeom::Error (FileNotFound, FileUnreadable naming the file) when it cannot be read
///         as STEP, IGES or a grid; (InvalidArgument) for another extension, a face index past
///         the file's faces (the message gives their count) or a malformed grid (naming the
///         line); (Internal) if OpenCASCADE fails.
TOWGEOM_EXPORT PlacementSurface readPlacementSurface(const std::string& path, std::size_t face = 0);

/// Reads the first face named @p faceName (see PlacementSurface::name) of the STEP or IGES file
/// @p path, as readPlacementSurface() does by index (a part placed twice in an assembly gives
/// its faces, names and all, twice: the first placement's is read).
/// @throws towgeom::Error (InvalidArgument) for an empty name, a .grid file (no named faces),
///         or no face of that name (the message lists the names there are, or says the faces
///         have none), and as the other overload.
TOWGEOM_EXPORT PlacementSurface readPlacementSurface(const std::string& path, const std::string& faceName);

/// Reads the faces @p faces (indices as for the other overload) of the STEP or IGES file @p path
/// and joins them into one surface, so that courses run across the edges they share: each next
/// face is one with a whole side in common with the faces joined before it (within 1e-7 of
/// their size, parametrised alike along it up to scale: as the faces of a revolved or extruded
/// profile, or B-spline patches sewn side to side), its poles appended beyond that side, a
/// crease (C0) between them (see the geodesics across creases in layCourses()). The first face
/// decides which side is out (a face whose shared side runs the other way is turned over). One
/// face: as the other overload. The joined faces' names are joined by "+".
/// Faces that close into a ring (a tube of patches) are joined along all but the last shared
/// edge: where that edge is a fold it stays the surface's boundary (tows end there, on a side of
/// its (u,v) box), where it is smooth the surface is periodic across it (see NurbsSurface).
/// @throws towgeom::Error (InvalidArgument) for no faces, a face given twice or past the
///         file's faces, several faces of a .grid file, a trimmed face (a shell is joined from
///         whole faces), a face with no whole side in common with those joined before it, or one
///         whose weights along the shared side are not in proportion to the others' (another
///         rational form; the message names the face); as the other overload otherwise.
TOWGEOM_EXPORT PlacementSurface readPlacementSurface(const std::string& path, const std::vector<std::size_t>& faces);

/// A tool surface through a grid of measured points: @p uCount rows of @p vCount points, point
/// (i, j) at @p grid[i * vCount + j] (u along the rows' order, v along each row; the normal is
/// dS/du x dS/dv). With @p tolerance 0 the bicubic B-spline interpolating every point
/// (OpenCASCADE's GeomAPI_PointsToBSplineSurface, chord-length parameters; fitDeviation 0);
/// otherwise its smoothing approximation (degrees 3 to 8, C2), for noisy measurements, whose
/// largest distance from a point (nearest surface points) is fitDeviation and must be within
/// @p tolerance. The parameters are scaled to [0, 1].
/// @throws towgeom::Error (InvalidArgument) for fewer than 4 x 4 points (or more than 100000
///         a side), a grid of another size than uCount x vCount, coordinates not finite or
///         beyond 1e100, neighbours in a row or column that coincide (naming them), a negative
///         tolerance, an approximation farther than the tolerance from a point, or a grid
///         OpenCASCADE cannot fit.
TOWGEOM_EXPORT PlacementSurface fitPlacementSurface(const std::vector<Point3>& grid, std::size_t uCount, std::size_t vCount,
                                                    double tolerance = 0.0);

/// @}

TOWGEOM_END_NAMESPACE
