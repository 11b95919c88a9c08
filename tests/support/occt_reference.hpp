// Independent references for the tests, computed by OpenCASCADE on files read back (not with
// the code that wrote them): the solids of a STEP or BREP file, their validity, volumes and
// names, the faces two solids share, and the volumes of their pairwise overlaps (OCCT booleans).
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <towgeom/tow_surface.hpp>

namespace towgeom::testing {

/// One solid read back.
struct ReadSolid {
    std::string name;      ///< its name in the file (STEP: the representation item's name), or empty
    bool valid = false;    ///< BRepCheck_Analyzer accepts it
    double volume = 0.0;   ///< BRepGProp, relative precision 1e-7
    std::size_t faces = 0;  ///< faces of its shells
};

/// What a STEP or BREP file holds.
struct ReadShapes {
    std::vector<ReadSolid> solids;  ///< in the file's order
    /// Pairs of solids (indices) with a face in common (the same face, TopoDS IsSame), and how many.
    std::vector<std::pair<std::pair<std::size_t, std::size_t>, std::size_t>> sharedFaces;
};

/// Reads @p path with OCCT's STEP reader (XDE, names of sub-shapes on).
ReadShapes readStep(const std::string& path);
/// Reads @p path with OCCT's BREP reader; volumes only when @p volumes (seconds per trimmed
/// solid), else 0.
ReadShapes readBrep(const std::string& path, bool volumes = true);
/// One edge of a STEP file read back: its name (XDE) and points along its 3D curve.
struct ReadEdge {
    std::string name;
    std::vector<towgeom::Point3> points;  ///< @p samples points evenly in the curve's parameter
};

/// The named edges of the STEP file @p path (OCCT's XDE reader), each sampled at @p samples points.
std::vector<ReadEdge> readStepEdges(const std::string& path, int samples);

/// Writes the lateral face of a cylinder of @p radius about the z axis from z = 0 to @p height
/// (OCCT's primitive) alone to the STEP file @p path, or IGES when the path ends in .igs; with
/// @p fromAngle < @p toAngle only the part between those angles (a face on OCCT's cylindrical
/// surface).
void writeCylinderFace(const std::string& path, double radius, double height, double fromAngle = 0.0, double toAngle = 0.0);
/// Writes a face of a sphere of @p radius about the origin (OCCT's spherical surface: u the
/// longitude over [0, 2 pi), v the latitude, poles at v = -pi/2 and pi/2) alone to the STEP file
/// @p path: the latitudes from @p fromLatitude to @p toLatitude.
void writeSphereFace(const std::string& path, double radius, double fromLatitude, double toLatitude);
/// Writes the whole face of a torus about the z axis (OCCT's toroidal surface: u the angle about
/// the axis, v the angle about the tube, v = 0 on the outer equator at distance @p major +
/// @p minor) alone to the STEP file @p path.
void writeTorusFace(const std::string& path, double major, double minor);
/// Writes a flat disk of @p radius about the origin in the plane z = 0 (OCCT's plane trimmed by
/// one circular edge: its (u,v) box is the square about it) alone to the STEP file @p path;
/// with @p cutX < @p radius the part x > cutX cut off by a straight edge (a "D": edge 0 the
/// arc, edge 1 the line); @p reversed writes the face reversed (its normal -z); with
/// @p holeRadius > 0 a circular hole of that radius about (@p holeX, 0).
void writeDiskFace(const std::string& path, double radius, double cutX, bool reversed = false, double holeX = 0.0, double holeRadius = 0.0);
/// Writes a shell of two faces to the STEP file @p path: the lateral face of a cylinder of
/// @p radius about the z axis from z = 0 to @p height (face 0) and the lateral face of a cone
/// from that radius at z = @p height to @p topRadius at z = @p height + @p coneHeight (face 1),
/// sewn along their shared circle (OCCT's primitives, BRepBuilderAPI_Sewing).
void writeCylinderConeShell(const std::string& path, double radius, double height, double topRadius, double coneHeight);
/// Writes a folded sheet of two flat bilinear B-spline faces to the STEP file @p path: face 0
/// the rectangle [0, 4] x [0, 2] of the plane z = 0 (u along x, v along y), face 1 a trapezoid
/// turned up about the line y = 2 by @p fold radians: its side on that line from x = 0 to 4, its
/// far side, 2 from it within its plane, from x = 0.5 to 3.5 (so that its v runs across the fold
/// at a slant: the two faces' parameters meet at a crease whose rates differ).
void writeFoldedSheet(const std::string& path, double fold);
/// Writes the lateral face of a cylinder of @p radius about the z axis from z = 0 to @p height,
/// with two holes where a cylinder of @p holeRadius about the line x = 0, z = @p height / 2 (the
/// y axis raised) passes through it (OCCT's boolean cut: the holes at y = -+radius, away from the
/// cylinder's seam at x = radius, y = 0), alone to the STEP file @p path.
void writeHoledCylinderFace(const std::string& path, double radius, double height, double holeRadius);

/// One whole tow as built by writeWholeTowSolids().
struct WholeTowSolid {
    bool valid = false;   ///< BRepCheck_Analyzer accepts it
    double volume = 0.0;  ///< BRepGProp, relative precision 1e-5
    double surfaceError = 0.0;  ///< largest distance of its surface from TowSurface::point() at 400 (u,v): the data carried over
};

/// Writes every tow of @p tows whole (untrimmed, unclipped) as one solid to the BREP file @p path,
/// in order, built without trimmedBrep(): a Geom_BSplineSurface from the tow's B-spline data
/// (extractBezier(): degrees, knots, control points; periodic in v unrolled, cut to one period by
/// Geom_BSplineSurface::Segment), its face with its natural bounds, two planar caps on its end
/// iso-curves (BRepBuilderAPI_MakeFace, planes only), sewn (BRepBuilderAPI_Sewing) and made a
/// solid oriented outwards (BRepLib::OrientClosedSolid).
/// @throws std::runtime_error when a step fails (not sewn into one closed shell, a cap not planar).
std::vector<WholeTowSolid> writeWholeTowSolids(const std::vector<TowSurface>& tows, const std::string& path);

/// The volume of the common part of solids @p i and @p j of the BREP file @p path
/// (BRepAlgoAPI_Common).
double commonVolume(const std::string& path, std::size_t i, std::size_t j);
/// The volume of solid @p i of the BREP file @p path inside the box [@p min, @p max]
/// (BRepAlgoAPI_Common with OCCT's box primitive).
double boxCommonVolume(const std::string& path, std::size_t i, const std::array<double, 3>& min, const std::array<double, 3>& max);
/// The volume of the part of solids @p i and @p j of the BREP file @p path common to both and
/// inside the box [@p min, @p max] (two BRepAlgoAPI_Common).
double boxCommonVolume(const std::string& path, std::size_t i, std::size_t j, const std::array<double, 3>& min,
                       const std::array<double, 3>& max);
/// The volume of the union of the solids of the BREP file @p path (BRepAlgoAPI_Fuse).
double unionVolume(const std::string& path);
/// The boundary area of solid @p i of the BREP file @p path (BRepGProp, relative precision 1e-7).
double readBrepArea(const std::string& path, std::size_t i);
/// The @p n-point Gauss-Legendre rule on [0, 1] as (point, weight) pairs (OCCT's
/// math::GaussPoints and math::GaussWeights on [-1, 1], mapped).
std::vector<std::array<double, 2>> gaussLegendre01(int n);

}  // namespace towgeom::testing
