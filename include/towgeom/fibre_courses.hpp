/// @file fibre_courses.hpp
/// @brief layCourses(): the tows of fibre-placement courses on a NURBS surface, offset from a
/// reference curve as Schueler, Miller & Hale (2004) do (or exactly, by geodesics), each tow's
/// edges as curves on the surface, and the gap or overlap between neighbouring tows measured
/// along the surface.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

#include "towgeom/nurbs_offset.hpp"
#include "towgeom/placement_surface.hpp"
#include "towgeom/surface_offset_curves.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// @addtogroup placement
/// @{

/// Options of layCourses(). Lengths are in the surface's units.
struct CourseOptions {
    double towWidth = 0.0;         ///< W > 0: the width of the band one tow covers on the surface
    std::size_t towsPerCourse = 1;  ///< N >= 1 tows laid side by side in one pass of the head
    std::size_t courses = 1;       ///< K >= 1 courses, each to the left of the last
    /// The distance along the surface between neighbouring tows' centrelines; 0: towWidth (tows
    /// edge to edge). Less gives overlaps, more gaps.
    double spacing = 0.0;
    /// How centrelines are placed: SurfaceOffsetMethod::ProjectTangent (Schueler et al., with
    /// their per-step error) or Geodesic (exact).
    SurfaceOffsetMethod method = SurfaceOffsetMethod::ProjectTangent;
    /// The largest difference allowed between an offset step's distance and the true distance
    /// along the surface; 0: 1e-3 x towWidth. CoursePlan::withinTolerance says whether every
    /// step met it (it is a check, not a refinement: the method decides the placement).
    double tolerance = 0.0;
    int geodesicSteps = 64;  ///< as SurfaceOffsetOptions::geodesicSteps
    /// The smallest steering radius the head can lay a tow along (its centreline's radius of
    /// geodesic curvature); 0: not checked. Tows that need less are listed in
    /// CoursePlan::belowSteeringRadius (they are laid all the same).
    double minSteeringRadius = 0.0;
};

/// One offset step of the plan: a curve placed at a distance from another, point by point.
struct CourseStep {
    std::string from;    ///< the curve it was offset from ("reference", or a course's name)
    double distance = 0.0;  ///< the distance asked for (negative: to the right)
    /// Per point, the true distance along the surface from the point it was offset from (the
    /// geodesic between the two, shot by Newton's method from the chord). For a geodesic step
    /// Newton starts from the step's own geodesic, which ends there: the value is |distance|
    /// (re-shot, not measured independently); NaN at points carried to the boundary.
    std::vector<double> geodesicDistance;
    /// Per point, Schueler's Eq. 2 estimate of the shortfall |distance| - geodesicDistance.
    std::vector<double> estimatedError;
};

/// A course's centreline, the middle of its N tows.
struct CourseCentre {
    std::string name;       ///< "c1", "c2", ...
    CurveOnSurface curve;   ///< its points
    CourseStep step;        ///< how it was placed (the first course's is the reference itself: no points)
};

/// One tow of the plan.
struct TowPath {
    std::string name;            ///< "c<course>_t<tow>", both from 1, tows from right to left
    std::size_t course = 0;      ///< its course, from 0
    CurveOnSurface centreline;   ///< where the head lays its middle
    CourseStep step;             ///< how the centreline was placed from its course's centreline
    /// Its right edge: the centreline's exact (geodesic) offset by -W/2. With the left edge, the
    /// band the tow covers, W wide along the surface whatever the planning method. Cut at the
    /// face's boundary like the centreline; empty (as is its curve) where the whole edge lies
    /// off the face (a tow laid along the boundary, overhanging it).
    CurveOnSurface right;
    CurveOnSurface left;  ///< its left edge: the centreline's geodesic offset by +W/2
    /// The right edge as a curve on the surface: the cubic B-spline in the surface's (u,v)
    /// interpolating its points (OpenCASCADE), poles given as (u, v, 0), parameter the (u,v)
    /// chord length.
    NurbsCurve rightCurve;
    NurbsCurve leftCurve;  ///< the left edge likewise
    double length = 0.0;   ///< the centreline's length along the surface
    /// The side of the face the centreline starts on (within 1e-9 of it): a side of its parameter
    /// box ("u_min", "u_max", "v_min", "v_max") or, on a trimmed face (PlacementSurface::trim),
    /// "edge K" (K the edge's index among the face's edges; a box side where no edge is that
    /// near): cut there (its offset left the face), carried there
    /// (its course's curve starts on that side, the offset inside it), or there already; empty
    /// where it starts inside the face, as its course's curve does.
    std::string startBoundary;
    std::string endBoundary;  ///< likewise for its end
    /// Per centreline point, its geodesic curvature (the in-plane curvature a head steers: the
    /// curvature of the centreline seen along the surface's normal; positive turning left),
    /// from its (u,v) cubic.
    std::vector<double> geodesicCurvature;
    /// The smallest steering radius along the centreline, 1 / max |geodesic curvature|
    /// (infinity for a geodesic).
    double steeringRadius = 0.0;
};

/// The gap (positive) or overlap (negative) between two neighbouring tows, measured along the
/// surface: from each centreline point of the right-hand tow, the geodesic perpendicular to it
/// (to its left) is followed until it meets the left-hand tow's centreline; its length less W.
struct TowGap {
    std::size_t right = 0;  ///< the right-hand tow's index in CoursePlan::tows
    std::size_t left = 0;   ///< the left-hand tow's index (right + 1)
    bool betweenCourses = false;      ///< the last tow of one course and the first of the next
    /// Per centreline point of the right-hand tow, the width: gap > 0, overlap < 0; NaN where the
    /// perpendicular does not meet the other tow (past its ends, or off the surface).
    std::vector<double> width;
    double minWidth = 0.0;  ///< the smallest width measured (NaN if none)
    double maxWidth = 0.0;  ///< the largest width measured (NaN if none)
    std::size_t measured = 0;               ///< points where the width was measured
};

/// What layCourses() lays.
struct CoursePlan {
    CurveOnSurface reference;            ///< the reference curve: the first course's centreline
    std::vector<CourseCentre> courses;   ///< K course centrelines, each offset N x spacing from the last
    std::vector<TowPath> tows;           ///< K x N tows, course by course, right to left
    std::vector<TowGap> gaps;            ///< between each tow and the next (K N - 1)
    double towWidth = 0.0;   ///< W as used
    double spacing = 0.0;    ///< the spacing as used
    double tolerance = 0.0;  ///< the tolerance as used
    SurfaceOffsetMethod method = SurfaceOffsetMethod::ProjectTangent;  ///< as used
    double largestStepError = 0.0;  ///< the largest | |d| - true distance | over every step
    bool withinTolerance = true;    ///< whether largestStepError <= tolerance
    /// The course centrelines and tows (by name) that lie off the surface entirely, not laid. A
    /// course whose centreline is off the face still has its tows tried (offset from the course
    /// before by the combined distance, TowPath::step from that course); no later course is.
    std::vector<std::string> offSurface;
    double minSteeringRadius = 0.0;  ///< as asked (0: not checked)
    /// The tows (names) whose steering radius is below CourseOptions::minSteeringRadius.
    std::vector<std::string> belowSteeringRadius;
};

/// Lays @p options.courses courses of @p options.towsPerCourse tows on @p surface from
/// @p reference, the first course's centreline; all to the reference's left (O = N x T, N the
/// surface's normal, T the reference's direction). Course k + 1's centreline is course k's
/// offset by N x spacing; each tow's centreline is its course centreline's offset by
/// (i - (N - 1) / 2) x spacing (one step each, as a head lays a course: the step's error does not
/// add up across a course, but from course to course it does). Each tow's edges are then its
/// centreline's exact offsets by -+W/2, and the gaps between neighbours are measured
/// (TowGap). Point i of each offset curve is offset from point i of the curve before, except at
/// the face's boundary:
/// - **Trimmed, not refused**: where offsets leave the face, the longest run of points that
///   stays on it is kept and ended exactly where the offset meets the boundary (the base point
///   found by bisection on the base curve's cubic interpolation); where the curve offset from
///   runs to the boundary and its offset stops inside, the offset is carried on along its end
///   direction by a geodesic to the boundary (those points' step distances are NaN). Each tow's
///   TowPath::startBoundary / endBoundary say where, TowPath::length how long it is. Courses and
///   tows wholly off the face are listed in CoursePlan::offSurface. The boundary is the face's
///   parameter box here; the overload given a PlacementSurface ends them at its trimming curves.
///   Each curve of a tow (its centreline, each edge) keeps its longest run on the face: a tow
///   crossing a hole is laid on one side of it, and an edge crossing a hole its centreline
///   misses is cut short there (courseCoverage() shows what that leaves). A hole between two
///   points of a curve is found by probing the (u,v) chord between them.
/// - **Seams**: where the surface closes smoothly (a cylinder's, sphere's or torus's angle; see
///   NurbsSurface::point()) curves and geodesics cross the seam, their u (or v) running on past
///   the box, and a closed reference (last point = first) gives closed courses.
/// - **Poles**: a geodesic that meets a point where the parametrisation is singular (a sphere's
///   pole) is refused, the message naming the place.
/// - **Creases** (faces joined side to side, see readPlacementSurface() of several faces: interior
///   knots of multiplicity at least the degree, where the surface is only C0): a geodesic runs
///   up to the crease and on across it as the two faces unfolded into one plane there carry it
///   (its component along the crease and its speed kept), so offsets and gaps are measured
///   across the shared edge as on one face.
/// @throws towgeom::Error (InvalidArgument) for a non-positive width, no tows or courses, a
///         negative spacing or tolerance, a reference of fewer than 4 points, no tow left on the
///         surface, or a singular point met (the message names the course or tow); (Internal)
///         if OpenCASCADE fails.
TOWGEOM_EXPORT CoursePlan layCourses(const NurbsSurface& surface, const CurveOnSurface& reference, const CourseOptions& options);

/// As the other overload, on the face @p tool: its trimming curves (PlacementSurface::trim), not
/// only its box, end the tows, courses and the reference (cut to its longest run on the face,
/// ended where its (u,v) cubic crosses the boundary; CoursePlan::reference is that run). A point
/// is on the face where OpenCASCADE's face classifier puts it, on the face's own parameters.
/// @throws towgeom::Error as the other overload; (InvalidArgument) also when fewer than 4 of
///         the reference's points lie on the face.
TOWGEOM_EXPORT CoursePlan layCourses(const PlacementSurface& tool, const CurveOnSurface& reference, const CourseOptions& options);

/// Writes @p plan as JSON: {"method", "tow_width", "spacing", "tolerance", "largest_step_error",
/// "within_tolerance", "reference":{"uv":[[u,v],..], "points":[[x,y,z],..]}, "courses":[{"name",
/// "from", "distance", "centreline":{"uv","points"}, "geodesic_distance", "estimated_error"}],
/// "tows":[{"name", "course", "from", "distance", "centreline", "right", "left",
/// "right_curve":{"degree","knots","poles":[[u,v,weight],..]}, "left_curve",
/// "geodesic_distance", "estimated_error", "length", "start_boundary", "end_boundary" (a side
/// of the box, "edge K" on a trimmed face, or null), "geodesic_curvature", "steering_radius" (null for infinity)}],
/// "gaps":[{"right", "left" (the tows' names), "between_courses", "min", "max", "measured",
/// "width"}], "off_surface":[names], "min_steering_radius", "below_steering_radius":[names]} ("from": the curve a step started from;
/// NaN widths and distances as null).
/// @throws towgeom::Error (InvalidArgument) for a plan whose gaps do not match its tows;
///         (WriteFailed) when the stream fails.
TOWGEOM_EXPORT void writeCoursePlanJson(const CoursePlan& plan, std::ostream& out);

/// Writes @p plan's tow curves to the STEP (AP214) file @p path, whole or not at all: each tow's
/// centreline, right and left edge (empty edges left out) an edge, its own product named
/// "<tow>/centreline", "<tow>/right", "<tow>/left" (what CAD systems list), its curve on @p surface (the plan's) the points' (u,v) cubic (as
/// TowPath::rightCurve), its 3D curve approximated from that by OpenCASCADE to @p tolerance (0:
/// 1e-6 x the tow width; never below OpenCASCADE's confusion, 1e-7).
/// @throws towgeom::Error (InvalidArgument) for a negative tolerance or a curve whose points
///         repeat; (WriteFailed) naming the file; (Internal) if OpenCASCADE fails.
TOWGEOM_EXPORT void writeCoursePlanStep(const NurbsSurface& surface, const CoursePlan& plan, const std::string& path, double tolerance = 0.0);

/// As the other overload, to @p out (through a temporary file: OpenCASCADE writes files).
/// @throws towgeom::Error as the other overload; (WriteFailed) when the stream fails.
TOWGEOM_EXPORT void writeCoursePlanStep(const NurbsSurface& surface, const CoursePlan& plan, std::ostream& out, double tolerance = 0.0);

/// Writes @p plan's centrelines and edges as legacy VTK polylines (ParaView), cell data "tow"
/// (index in CoursePlan::tows) and "kind" (0 centreline, 1 right edge, 2 left edge), point data
/// "gap" (each tow centreline point's width to the tow on its left; 0 elsewhere and where not
/// measured). @throws towgeom::Error (InvalidArgument) for a plan whose gaps do not match its
///         tows; (WriteFailed) when the stream fails.
TOWGEOM_EXPORT void writeCoursePlanVtk(const CoursePlan& plan, std::ostream& out);

/// @}

TOWGEOM_END_NAMESPACE
