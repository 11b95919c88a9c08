/// @file resolve.hpp
/// @brief resolveTextile(): compatible tow surface meshes that share one surface wherever two
/// tows interpenetrated (ParametricMesher + ConnectedRegion).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "towgeom/cell.hpp"
#include "towgeom/intersection_options.hpp"
#include "towgeom/mesh_options.hpp"
#include "towgeom/progress.hpp"
#include "towgeom/textile_mesh.hpp"
#include "towgeom/tow_intersection.hpp"
#include "towgeom/tow_stack.hpp"
#include "towgeom/surface_fold.hpp"
#include "towgeom/tow_surface.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

/// @defgroup resolution Resolving a textile
/// @brief resolveTextile(): compatible meshes of all tows, from the tows alone or from an IntersectionReport kept earlier (the stages chained: intersect, mesh, connect regions).
/// @{

/// How two overlapping tows share the surface between them (ResolveOptions::method).
enum class ResolutionMethod {
    /// The rank rule: inside each loop the lower-ranked tow (the secondary) gives way to the
    /// higher-ranked one (the primary), whose surface both share. The primary keeps its volume,
    /// the secondary loses the whole overlap.
    Connect,
    /// Both tows give way: inside each loop they share the mid-surface between their two
    /// surfaces (each node of the primary's surface inside the loop moved halfway to the
    /// secondary's surface along their common normal, the mean of the two surfaces' normals at
    /// the segment's ends, solved on both exact surfaces; the loop's nodes stay, so the
    /// mid-surface meets both tows exactly at the loop). Each tow loses about half of the
    /// overlap. A region where the rank rule must decide (a third tow overlaps there, another
    /// loop runs through it, its loop goes around a tow or across a cap, it reaches a face of
    /// the cell) or where the
    /// mid-surface point of a node is not found keeps the primary's surface:
    /// ConnectedRegion::surface and ConnectedRegion::note say which and why.
    Symmetric,
    /// The baseline of tools that cannot share surfaces: the tows of each interpenetrating pair
    /// are shrunk (sections scaled about their centroids, locally, by bisection) until the pair
    /// no longer interpenetrates (shrinkTows(), ShrinkOptions), then meshed each on its own: no
    /// shared surface, a gap or a contact between them. ResolveResult::shrunk says how much.
    Shrink
};

/// Options of the shrink baseline (ResolutionMethod::Shrink, shrinkTows()).
struct ShrinkOptions {
    /// Shrink both tows of a pair by the same factor; default (false): the lower-ranked only.
    bool both = false;
    /// The length along the tow over which the scale returns to 1 beyond the part the pair's
    /// curves span (cos^2 blend), in the user's units; 0 (default): the tow's size
    /// (TowSurface::towSize()).
    double blendLength = 0.0;
    /// The bisection stops when the smallest reduction f of the scale (1 - f at the overlap) that
    /// separates the pair is known to this. Default 1e-3.
    double tolerance = 1e-3;
    /// Added to the reduction the bisection found (at most down to minScale), so that the pair
    /// keeps a gap (about margin x its section size) that its meshes' chords do not close and
    /// intersectTows() does not report as touching. Default 0.02.
    double margin = 0.02;
    /// The smallest scale tried, in (0, 1): a pair that still interpenetrates there is named in
    /// ResolveResult::unresolved (UnresolvedPair::Reason::NotSeparated). Default 0.2.
    double minScale = 0.2;
};

/// What ResolutionMethod::Shrink (shrinkTows()) did to one tow.
struct ShrunkTow {
    /// The scale of each input section about its centroid (1: unchanged), in the order of
    /// TowSurface::sections().
    std::vector<double> sectionScale;
    double volumeBefore = 0.0;  ///< TowSurface::volume() of the input tow
    double volumeAfter = 0.0;   ///< TowSurface::volume() of the shrunk tow
    /// The shrunk tow's sections (the input's scaled; in the surface's order, TowSurface::
    /// sections()), to write as .stw (writeStack()) or fit again.
    TowStack stack;
    /// The largest relative change of a section's size: 1 - the smallest scale (0 unchanged).
    double largestSectionChange() const
    {
        double s = 1.0;
        for (double x : sectionScale) s = x < s ? x : s;
        return 1.0 - s;
    }
};

// The deprecated callback member makes GCC warn in the implicit copy and move members, at this
// definition; only the callback's own uses should warn.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
/// Options for resolveTextile().
struct ResolveOptions {
    MeshOptions mesh;                  ///< mesh size and quality
    IntersectionOptions intersection;  ///< tolerances of the intersection loops (threads below)
    /// The tows' rank: a tow whose name matches one of these shell patterns (`*`, `?`, `[...]`)
    /// ranks above one that does not; among those that both or neither match, the tow given
    /// first (lower index) ranks higher. Every tow becomes itself minus the tows ranked above
    /// it; of a pair, the higher-ranked tow is the primary (keeps its surface). Empty
    /// (default): input order.
    std::vector<std::string> primaryPatterns;
    /// How overlapping tows share their surface: the rank rule (default), the mid-surface, or
    /// not at all (the shrink baseline).
    ResolutionMethod method = ResolutionMethod::Connect;
    /// The shrink baseline's options (ResolutionMethod::Shrink).
    ShrinkOptions shrink;
    /// Worker threads (intersection and meshing); 0: one per hardware thread.
    std::size_t threads = 0;
    /// If set, every tow is clipped by this box (in the user's units) and TextileMesh::cell
    /// holds the matrix's part of the box's faces (see Cell). Needs MeshOptions::caps. Only
    /// what the box keeps is computed: resolveTextile(tows, options) intersects only the tow
    /// pairs whose bounding boxes overlap inside it (not with ResolutionMethod::Shrink), so
    /// pairs outside give no loop and no finding (a nested or touching pair there is not
    /// unresolved: it is not in the model), and each tow is meshed only along the part of its
    /// length between its cuts (nothing of a tow wholly outside). MeshOptions::maxTriangles is
    /// still checked against the whole tows.
    std::optional<Cell> cell;
    /// Progress reports of every stage (intersecting tow pairs, meshing, connecting regions)
    /// and cancellation (checked per tow pair, per tow and between stages); may be null. Not
    /// owned: it must outlive the call. Also used for the intersection unless
    /// intersection.monitor is set.
    Progress* monitor = nullptr;
    /// Progress: called with a short stage description; may be empty.
    /// @deprecated Use monitor (Progress::update()); removed in 0.3.
    [[deprecated("use ResolveOptions::monitor (towgeom::Progress); removed in 0.3")]]
    std::function<void(const std::string&)> progress;
};
#pragma GCC diagnostic pop

/// What resolution did to one tow.
struct TowResolution {
    bool primaryAnywhere = false;  ///< primary in at least one resolved pair
    bool secondaryAnywhere = false;  ///< secondary in at least one resolved pair
    /// Volume of its own mesh with its caps (ends closed by fans without caps). With a cell cut in
    /// the meshes (CellCut::Mesh) the whole tow's, before the clip (volumeAfter is inside the
    /// cell); with the parametric cut both are inside the cell.
    double volumeBefore = 0.0;
    double volumeAfter = 0.0;      ///< the same after the regions were swapped in
    double area = 0.0;             ///< surface area of the final mesh
    std::size_t boundaryLoops = 0;  ///< 0 for a tow closed by its caps, 2 for a tube open at both ends
    /// Connected pieces of the final mesh: 1, or more where a higher-ranked tow passes through
    /// this one and cuts it (each piece closed by the other tow's surface).
    std::size_t pieces = 1;
    /// The mesh size h this tow was meshed at: MeshOptions::relativeEdgeLength x its own size,
    /// or MeshOptions::edgeLength, at most a quarter of its circumference; graded by curvature
    /// (MeshOptions::chordDeviation), the largest size (its flat parts').
    double meshSize = 0.0;
    /// Where the tow's fitted surface crosses itself (findFold()), among its sampled triangles
    /// that reach into the cell if there is one (the point may lie just outside it); nullopt
    /// where it does not. Its meshes cross there unless coarser than the fold, and
    /// Gmsh's tetrahedral mesher then stops (meshVolumes() names the tow).
    std::optional<SurfaceFold> fold;
    /// "primary" (primary in some region, secondary in none), "secondary", "both" or "none".
    const char* role() const
    {
        if (primaryAnywhere && secondaryAnywhere) return "both";
        if (primaryAnywhere) return "primary";
        return secondaryAnywhere ? "secondary" : "none";
    }
};

/// Smallest 3D angles of the final triangles.
struct TOWGEOM_EXPORT MeshQuality {
    double minAngle = 0.0;                ///< degrees, over all triangles
    std::vector<std::size_t> histogram;  ///< triangles per 5-degree bin of their smallest angle (0-5, 5-10, ... 55-60)
    std::size_t triangles = 0;            ///< distinct triangles counted (shared ones once)
    /// Tube triangles left over the size or shape bound (in the mesher's parameter space) because
    /// meeting it would have split a loop or seam edge in the last meshing round (caps are not
    /// counted: they keep the tube's end nodes, and their angles are in minAngle and histogram).
    std::size_t facesOverBounds = 0;
    /// The smallest angle a triangle should keep, in degrees: the share of MeshOptions::minAngle
    /// the mesher asks of the surface (15 degrees for the default 20).
    double angleBound = 0.0;
    /// Triangles whose smallest angle is under angleBound, of a sharp constraint corner
    /// (SharpCorner::triangles, TextileMesh::sharpCorners) and at least a third of the corner's
    /// angle: what a corner that sharp allows.
    std::size_t atSharpCorners = 0;
    /// Triangles under angleBound otherwise: away from any sharp corner, or under a third of its
    /// angle there. 0 is the goal.
    std::size_t underBound = 0;
    /// The smallest angle, in degrees, of the triangles not counted in atSharpCorners.
    double minAngleAwayFromCorners = 0.0;
    /// The fraction of triangles whose smallest angle is at least @p degrees.
    double fractionAtLeast(double degrees) const;
};

/// Wall-clock time of the stages of resolveTextile(), in milliseconds.
struct ResolveTimings {
    double intersect = 0.0;  ///< intersectTows()
    double mesh = 0.0;       ///< loop nodes and the parametric meshes
    double regions = 0.0;    ///< classification, swap, volumes, quality
};

/// A tow pair whose interpenetration was not resolved, and why. The rest of the textile is.
struct UnresolvedPair {
    /// Why the pair was left out.
    enum class Reason {
        /// The mesh of one of the tows could not be made with this pair's loops as constraints
        /// (or was not a tube): every pair with loops on that tow was left out and the textile
        /// meshed again without them.
        MeshFailed,
        /// A loop of this pair crosses a loop of another pair on a tow of both (three tows
        /// overlap there) where no triple point joins them (the third pair's loop through it is
        /// open or skipped, the point was not found, or it lies within 1 % of a chord of a seam
        /// or of another loop's fixed node, where it would make slivers), or meets it while the third
        /// pair has no resolved loop. Of two such pairs the later one (by tow indices) is left out.
        LoopsMeet,
        /// connectRegions() could not connect tow A or B with the pair's loops: the tow was not a
        /// closed surface after its regions were swapped in, a triangle inside an odd number of
        /// its loops had no region, or its loops around it did not cut it into bands alternately
        /// inside and outside the other tow. Every pair with loops on that tow was left out of the
        /// regions and the rest connected again; the pair's loop nodes stay in both meshes.
        RegionFailed,
        /// ResolutionMethod::Shrink: the pair still interpenetrates (or one tow lies inside the
        /// other) with its sections scaled down to ShrinkOptions::minScale: it is not shrunk for
        /// that pair and the rank rule resolves it.
        NotSeparated
    };
    std::size_t towA = 0;  ///< lower tow index
    std::size_t towB = 0;  ///< higher tow index
    Reason reason = Reason::MeshFailed;  ///< why
    std::string message;   ///< a sentence naming the tows and the failure
};

/// An intersection loop that was not resolved, and why (ResolveResult::skippedLoops).
struct SkippedLoop {
    /// Why the loop bounds no region.
    enum class Reason {
        /// The curve is open (IntersectionLoop::closed() false; IntersectionLoop::openReason()
        /// says where it stops: a tow's end, tangent surfaces).
        OpenCurve,
        /// The loop goes around both tows.
        AroundBothTows,
        /// The loop goes around one tow (the other passes through it or ends inside it), which is
        /// resolved only when the tows are closed by their caps (MeshOptions::caps).
        AroundTowWithoutCaps,
        /// The pair's loops go around one of the tows but do not cut it into bands alternately
        /// inside and outside the other.
        BandsDoNotAlternate,
        /// The loop runs across a tow's end cap (IntersectionLoop::crossesCap()), which is
        /// resolved only when the tows are closed by their caps (MeshOptions::caps).
        CrossesCap,
        /// The loop lies outside ResolveOptions::cell: the tows are clipped there.
        OutsideCell,
        /// The loop is thinner than its nodes can follow, where the surfaces nearly touch
        /// (pressed tows): its node polygon crosses itself in a tow's (u,v), and the overlap it
        /// bounds is at most 1/64 of the mesh size deep (half its extent times the tangent of the
        /// largest angle at which the surfaces meet along it), less than the meshes' chord
        /// deviation. A contact, not an unresolved pair: its overlap stays, and the mesh stage
        /// refines both tows there until their meshes do not cross
        /// (ResolveResult::crossingTrianglePairs counts any left). The exact solids of the
        /// general fuse (trimmedBrep()) are refused with it, as with any loop not resolved.
        Contact
    };
    std::size_t loop = 0;              ///< index in ResolveResult::intersections.loops
    Reason reason = Reason::OpenCurve;  ///< why
    std::string message;               ///< a sentence naming the tows
};

// The deprecated member skipped makes GCC warn in the implicit copy and move members, at this
// definition; only its own uses should warn.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
/// The result of resolveTextile().
struct ResolveResult {
    IntersectionReport intersections;  ///< every loop found (open ones included)
    TextileMesh mesh;                  ///< the compatible meshes
    std::vector<TowResolution> tows;   ///< per input tow
    /// Loops that were not resolved (open; across a cap or winding around a tow without caps,
    /// around both tows, or cutting it into bands that do not alternate; outside the cell; a
    /// contact), in loop order, with the reason.
    std::vector<SkippedLoop> skippedLoops;
    /// skippedLoops as (loop index, message).
    /// @deprecated Use skippedLoops (typed reasons); removed in 0.3.
    [[deprecated("use ResolveResult::skippedLoops; removed in 0.3")]]
    std::vector<std::pair<std::size_t, std::string>> skipped;
    /// Tow pairs left unresolved so that the rest of the textile could be (their loops are in
    /// intersections.loops but bound no region).
    std::vector<UnresolvedPair> unresolved;
    MeshQuality quality;               ///< of the final meshes
    /// The method the regions were made with (ResolveOptions::method); per region,
    /// ConnectedRegion::surface says which surface it got.
    ResolutionMethod method = ResolutionMethod::Connect;
    /// Each tow's rank (0 first) as the regions were made: the tows whose name matches one of
    /// ResolveOptions::primaryPatterns, then the others, each in input order; a tow gives way to
    /// every tow ranked above it. Empty in a result not made by connectRegions() (meshTows()'s).
    std::vector<std::size_t> ranks;
    /// ResolutionMethod::Shrink: per tow, its sections' scales and exact volumes before and after
    /// (empty otherwise). Then intersections holds the curves left between the shrunk tows (none
    /// when every pair was separated), TowResolution::volumeAfter is the shrunk tow's mesh volume
    /// and volumeBefore the input tow's at the same resolution: its exact volume times the
    /// shrunk tow's mesh volume over its exact volume (equal for a tow left unchanged).
    std::vector<ShrunkTow> shrunk;
    /// Meshing rounds: the mesher never splits a loop or seam edge itself; where a triangle needs
    /// such a split to meet the bounds, the split became a node of both sides and the tows
    /// concerned were meshed again, at most 6 rounds (1 when no split was needed). The rounds run
    /// again after each refinement around crossing triangles (crossingTrianglePairs): the most
    /// rounds any run took.
    std::size_t meshRounds = 0;
    /// Pairs of triangles of two tows' tube meshes (before regions and end caps) that still
    /// cross after the mesh stage's refinement around crossings (exact triangle tests, as in
    /// CGAL's self-intersection test). Where two tows' triangles cross, both are refined around
    /// them, each pass halving the size there, up to 4 passes, while the pair's crossings are few
    /// (at most 16 plus 1 % of the smaller mesh's triangles) and fall from pass to pass. What is
    /// left: surfaces closer than the mesh follows after 4 passes, or two tows passing through each
    /// other where no loop bounds the overlap (many crossings, not refined). Pairs left unresolved
    /// (unresolved, skippedLoops other than outside the cell or a contact,
    /// IntersectionReport::findings other than a contact) are not tested; 0 when no other two
    /// tows' tubes cross.
    std::size_t crossingTrianglePairs = 0;
    ResolveTimings timings;            ///< where the time went
};
#pragma GCC diagnostic pop

/// Meshes every tow in its (u,v) rectangle with the closed intersection loops as constraints
/// (ParametricMesher: CGAL constrained Delaunay mesher in a parameter space scaled by the
/// surface's lengths, loop nodes shared by both tows, seam nodes shared by both sides of the
/// seam), then makes every tow itself minus the tows ranked above it (ResolveOptions::
/// primaryPatterns): a triangle of tow t inside a higher-ranked tow is removed; one inside
/// lower-ranked tows only is also a triangle of the highest-ranked of them (ConnectedRegion),
/// so the two tows share nodes and triangles there. With two tows: inside each loop the
/// secondary's triangles are replaced by the primary's.
///
/// A triangle lies inside tow o when its (u,v) centroid lies inside an odd number of the loops
/// of its pair with o (exact point-in-polygon, CGAL): a loop nested in one of the same pair bounds
/// an island (ConnectedRegion::holes). Where loops of two pairs sharing a tow cross, the three
/// tows' surfaces meet: the triple point is solved on the three surfaces and made one node of
/// the three pairs' loops (TextileMesh::triplePoints). Loops that wind around a tow (it passes
/// through the other tow, or ends inside it) cut it into bands alternately inside and outside
/// the other, its end caps in the first and last band (MeshOptions::caps; without caps they are
/// not resolved): a tow given way to one it passes through is cut into pieces. Open loops are not
/// resolved (see ResolveResult::skipped). A tow whose mesh cannot be made costs only the tow pairs
/// with loops on it: they are listed in ResolveResult::unresolved and the rest of the textile is
/// resolved.
///
/// @code
/// towgeom::ResolveOptions options;
/// options.primaryPatterns = {"binder*"};  // binders first, then the rest in input order
/// const towgeom::ResolveResult r = towgeom::resolveTextile(tows, options);
/// for (const towgeom::TriplePoint& p : r.mesh.triplePoints)
///     std::cout << "tows " << p.tows[0] << ", " << p.tows[1] << ", " << p.tows[2] << " meet at node " << p.node << "\n";
/// @endcode
/// With MeshOptions::caps (default) every tow is closed by its two end caps (TowMesh::face).
///
/// @throws towgeom::Error (InvalidArgument) for bad options, including a relative mesh size
/// over pi / 4, and for a mesh size too coarse for a concave end section (its cap's polygon of
/// end nodes is not simple; the message names the tow and end); (TooLarge) when the estimated triangle count is
/// over MeshOptions::maxTriangles (checked before intersecting, and with the loops' refinement
/// before meshing); (Internal) if a kernel fails outside the meshing of a tow.
TOWGEOM_EXPORT ResolveResult resolveTextile(const std::vector<TowSurface>& tows, const ResolveOptions& options = {});

/// resolveTextile() with the intersection loops already computed: @p report is intersectTows()
/// of these @p tows (kept, filtered, or read back with readIntersectionReport()), so that one
/// intersection serves several meshes, for a mesh-size study. resolveTextile(tows, options) is
/// this with `intersectTows(tows, options.intersection)`, so both give the same meshes (with
/// ResolveOptions::cell, for Connect and Symmetric, it intersects only the pairs that may meet
/// inside the cell, whose loops are all that the cell's meshes use: the meshes are the same;
/// the other pairs' loops and findings are absent from ResolveResult::intersections and
/// ResolveResult::unresolved instead of skipped as outside the cell or reported).
/// ResolveOptions::intersection is used only for its checks here; ResolveResult::intersections
/// is @p report and ResolveTimings::intersect is 0.
///
/// @code
/// const towgeom::IntersectionReport loops = towgeom::intersectTows(tows);  // once
/// for (double h : {0.2, 0.1, 0.05}) {
///     towgeom::ResolveOptions options;
///     options.mesh.relativeEdgeLength = h;
///     const towgeom::ResolveResult r = towgeom::resolveTextile(tows, loops, options);
///     std::cout << h << ": " << r.quality.triangles << " triangles\n";
/// }
/// @endcode
///
/// @throws towgeom::Error as resolveTextile(); (InvalidArgument) also when a loop of @p report
/// is not between two of @p tows (a tow index out of range, or tows of other names at its
/// indices: the report of another textile or of the tows in another order).
TOWGEOM_EXPORT ResolveResult resolveTextile(const std::vector<TowSurface>& tows, const IntersectionReport& report,
                             const ResolveOptions& options = {});

/// @}

TOWGEOM_END_NAMESPACE
