// towgeom resolve: compatible tow surface meshes sharing one surface where tows interpenetrated.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli/args.hpp"
#include "cli/brep_output.hpp"
#include "cli/cell_option.hpp"
#include "cli/resolve_input.hpp"
#include "cli/stopwatch.hpp"
#include "cli/commands.hpp"
#include "cli/progress_printer.hpp"
#include "cli/tow_input.hpp"
#include "cli/unresolved_pairs.hpp"
#include "core/parallel.hpp"
#include "io/output_files.hpp"
#include "towgeom/towgeom.hpp"


namespace towgeom::cli {

namespace {

const char* kResolveHelp = R"(Usage: towgeom resolve FILE.stw... --out DIR [options]

Fits every tow, finds where tows interpenetrate (as 'towgeom detect'), meshes every tow's
surface with the closed intersection loops as constraints, and makes the meshes compatible:
tows are ranked (--primary patterns first, then command-line order) and every tow becomes
itself minus the tows ranked above it. Inside each loop the lower tow's triangles are removed
and the higher one's put in their place, so both tows share nodes and triangles there (a
connected region). Where three tows overlap, their loops cross at triple points, solved on the
three surfaces and shared by the three meshes. Writes, all or nothing:

  DIR/NAME.stl     binary STL of each tow's final surface mesh
  DIR/NAME.vtk     legacy VTK polydata (ParaView): cell data tow_id, region_id (-1 outside
                   regions), face (0 tube, 1 start cap, 2 end cap), point data node_id (the
                   global node number)
  DIR/textile.msh  with --formats msh: Gmsh 4.1, physical groups TOW_NAME, REGION_k and
                   CAPS_NAME (a tow's two end caps); with --cell also XMIN ... ZMAX (every
                   triangle on each box face: the matrix's and the tows' caps)
  DIR/textile.step with --formats step: STEP AP214, one solid per tow named after it (with
                   --cell: per tow inside the box, clipped to it, and the matrix, the box
                   minus the tows, a solid named MATRIX; a tow cut apart by a tow ranked
                   above it or by the box: a solid per piece), for CAD-based FE tools
                   (Abaqus/CAE, ANSYS, Gmsh's OpenCASCADE kernel); your units written as
                   millimetres. DIR/textile.brep with --formats brep: the
                   same in OpenCASCADE's BREP, where shared faces stay one face of both solids
  DIR/textile.inp  with --formats inp: Abaqus, *NODE, *ELEMENT TYPE=S3 with ELSET=TOW_NAME,
                   *ELSET/*NSET REGION_k, *ELSET CAPS_NAME; with --cell also *ELSET
                   MATRIX_FACES (the box's faces outside the tows) and *NSET XMIN ... ZMAX
  DIR/report.json  {"tows":[{"name","role","volume_before","volume_after","area","triangles",
                   "boundary_loops","pieces","mesh_size"(,"largest_section_change")(,"fold":{"point":[x,y,z],
                   "uv":[u,v],"crossing_pairs"})}], "loops":[...as detect...], "findings":[...as detect...],
                   "unresolved":[{"tow_a","tow_b","reason","message"}], "regions":[{"primary",
                   "secondary","triangles","nodes","area","volume_removed","surface","note"}],
                   "triple_points":[{"tows":[3 names],"node","point":[x,y,z]}],
                   "sharp_corners":[{"tow","face","node","point":[x,y,z],"angle_deg"}],
                   "skipped":[{"tow_a","tow_b","code","reason"}], "node_count",
                   "mesh_quality":{"min_angle_deg","angle_histogram","fraction_at_least_20",
                   "triangles","faces_over_bounds","angle_bound_deg","under_bound",
                   "at_sharp_corners","min_angle_away_from_corners_deg"},
                   "mesh_rounds", "crossing_triangle_pairs", "method", "timings_ms":{"read","fit","intersect","mesh",
                   "regions","volume" (--volume),"brep" (step, brep),"write","total"}}

  role            primary (keeps its surface; with --method symmetric it gives way too, to
                  the mid-surface), secondary (gave volume), both, or none
  largest_section_change  --method shrink: 1 - the smallest scale of the tow's sections
  pieces          connected pieces of the tow's mesh: more than 1 where tows ranked above it
                  pass through it and cut it
  sharp_corners   where two constraints of a tow's mesh (loops, its seam, the rim of an end)
                  meet at less than angle_bound_deg (3/4 of --min-angle on the surface): face
                  side, start or end (cap); the triangles there keep a third of angle_deg
  under_bound     triangles under angle_bound_deg away from sharp corners (the goal: 0);
                  at_sharp_corners those under it in a corner, at least a third of its angle
  unresolved      tow pairs that meet but were not resolved (their meshes still overlap), once
                  per pair and reason: open_curve (a curve stops: both tows end in one
                  plane, caps face to face, or tangent surfaces), crosses_cap (a loop runs across a tow's
                  end cap where it ends inside the other, with --no-caps), winds_around
                  (a loop goes around a tow, one passing through the other, with --no-caps;
                  or around both tows), nested (one tow
                  inside the other), identical_or_touching (surfaces coincide or touch, no curve),
                  search_incomplete (the search for loops stopped at its budget where the
                  surfaces nearly touch over a wide area: a loop may be missing),
                  loops_meet (a loop of the pair crosses another pair's loop on a tow where no
                  triple point joins them, e.g. the third pair's loop is open, goes around a
                  tow, or the point lies at a seam; or meets it while the third pair has no
                  resolved loop there; the later pair is left out), mesh_failed (a tow could not be
                  meshed with the pair's loops: its pairs are left out, the rest resolved),
                  region_failed (a tow could not be connected with its loops, e.g. it was not
                  closed after the swap: its pairs get no region, their loop nodes stay in
                  the meshes), not_separated (--method shrink: the pair still
                  interpenetrates with its sections at a fifth of their size, or one lies
                  inside the other: not shrunk, the rank rule resolves it)
  skipped         every loop not resolved, with its code (open_curve, crosses_cap,
                  around_both_tows, around_tow_without_caps, bands_do_not_alternate,
                  outside_cell: clipped away by --cell; contact: a loop thinner than its
                  nodes can follow, where the tows nearly touch, not unresolved: its overlap
                  stays, the meshes are refined there until they do not cross) and the reason
                  as a sentence
  volume_removed  the volume of the two tows' overlap inside the region's loop: what the
                  secondary lost there when no third tow overlaps them there (with
                  --method symmetric, what both lost together there)
  surface         the surface a region's triangles lie on: primary (the primary's own) or
                  middle (--method symmetric: halfway between both tows'); note says why
                  --method symmetric kept the primary's surface there (a third tow overlaps)
  triple_points   points where three tows' surfaces meet (node: the global node number)
  angle_histogram triangles per 5-degree bin of their smallest 3D angle (0-5, 5-10, ...)
  faces_over_bounds triangles left longer than H or below the angle bound because fixing them
                  would split a loop or seam edge once more (after the last of 6 rounds)
  mesh_rounds     meshing rounds: splits a triangle needs on a loop or seam edge become exact
                  nodes of both sides, and those tows are meshed again
  crossing_triangle_pairs  pairs of triangles of two tows' tubes that still cross (exact tests):
                  where triangles cross, both tows are refined around them (up to 4 passes,
                  each halving the size there) while the pair's crossings are few and fall;
                  left are surfaces closer than the mesh follows, or tows passing through
                  each other where no loop bounds the overlap (not refined); pairs listed in
                  unresolved are not tested

Options:
  --out DIR          output directory (created if needed)
  --primary GLOB     tows whose names match rank above tows that do not (repeatable; shell
                     patterns, e.g. --primary 'warp_*'); otherwise command-line order ranks
                     them: a tow gives way to every tow ranked above it
  --method M         how overlapping tows share their surface: connect (default: the rank
                     rule, the lower-ranked tow gives way and loses the whole overlap) or
                     symmetric (both give way to the mid-surface between them, solved on both
                     exact surfaces along their common normal; each loses about half; where a
                     third tow overlaps, or a loop goes around a tow or across a cap, the rank
                     rule decides and report.json's region "note" says so), or shrink (the
                     baseline of tools without shared surfaces: each interpenetrating pair's
                     lower-ranked tow, or both with --shrink-both, has its sections scaled
                     down about their centroids along the part the pair's curves span,
                     blended back to 1 over the tow's size, by bisection until the refitted
                     pair has no curve, plus a 2 % margin; then each tow is meshed on its own
                     and DIR/shrunk/NAME.stw holds the shrunk tows)
  --shrink-both      with --method shrink: both tows of a pair give way by the same factor
  --knot-spans       also write DIR/NAME_knot_spans.json and .vtk: every knot-span element of
                     the tow's B-spline surface valid (kept whole), invalid (removed) or trimmed
                     (a trimming curve, its loops' chords or a cell's cut, runs through it),
                     with its area, kept area and trimming-curve pieces in (u,v); the VTK shows
                     the elements on the surface coloured by class (isogeometric analysis)
  --report-methods LIST
                     also resolve by each method of LIST (from connect,symmetric,shrink) on
                     the same loops and meshes and write DIR/report.html (one self-contained
                     page, opens from disk: summary, per-tow table, volume change per tow per
                     method, section area along each tow before and after, mesh quality, a 3D
                     view of --method's meshes coloured by tow or region) and DIR/report.csv
                     (a row per tow and method). The meshes written are --method's
  --mesh-size H      target 3D edge length (default: 0.1 x each tow's own size); a tow is meshed
                     at most at a quarter of its circumference (noted on stderr, and each
                     tow's "mesh_size" in report.json). With --volume and no --mesh-size the
                     surfaces are graded by curvature instead: 0.25 x each tow's size where
                     it is flat, down to 0.1 x at its sharp edges (deviation 0.01 x its size)
  --mesh-deviation D grade the surface meshes by curvature: edges at most sqrt(8 D / k) long
                     where the surface's largest curvature is k (so they stand off it by about
                     D), at most --mesh-size (then the size of the flat parts) and at least
                     1/100 of it (with --volume and no --mesh-size: D replaces the preset's
                     deviation, the sizes stay 0.25 and 0.1 x the tow size). Default: none.
                     Example: --mesh-size 0.2 --mesh-deviation 0.002
  --min-angle DEG    smallest triangle angle the mesher aims for, at most 30 (default 20)
  --loop-spacing S   node spacing along intersection loops (default: the smaller mesh size of
                     the loop's two tows)
  --formats LIST     comma-separated from stl,vtk,msh,inp,step,brep (default stl,vtk); step
                     and brep are the exact solids (--method connect): each tow's B-spline
                     face trimmed by its loops, the faces two tows share one face of both,
                     planar caps; with --cell clipped to the box (see DIR/textile.step below);
                     where three tows meet, a loop goes around a tow or across a cap, or
                     loops nest three deep, from OpenCASCADE's general fuse of the whole tows
                     by the rank rule
  --tolerance T      intersection point tolerance (default: 1e-7 x the tow size)
  --report FILE      take the intersection loops from FILE, written by 'towgeom detect
                     --save-report FILE' for the same tows in the same order, instead of
                     intersecting again (a mesh-size study intersects once); a report for
                     other tows is refused (exit 2)
  --max-triangles N  refuse (exit 2, before meshing) meshes estimated at more than N triangles,
                     all tows together (default 20000000, about 5 GB; the estimate: about 3 x
                     the tows' area (end caps included; with --cell, the box's faces too)
                     / (sqrt(3)/4 H^2), plus the refinement along loops)
  --no-caps          leave every tow a tube open at its two ends (default: each tow closed by
                     its two end caps, meshes of its end sections: a closed surface)
  --volume           also fill every tow with tetrahedra (Gmsh's HXT, the surface triangles kept
                     as they are: two tows' tetrahedra meet face to face on their regions) and
                     write DIR/textile_volume.msh (a physical volume TOW_NAME per tow, the
                     surfaces' groups as in textile.msh, each tetrahedron's fibre direction as
                     element data "fibre_direction": its tow's tangent along its centreline
                     nearest the tetrahedron), with --formats ...,inp also
                     DIR/textile_volume.inp (C3D4, ELSET TOW_NAME, NSET NODES_NAME, START_NAME,
                     END_NAME per tow, *ORIENTATION FIBRES: each element's fibre axes), with
                     vtk also DIR/textile_volume.vtu for ParaView (tow_id, material,
                     fibre_direction per tetrahedron); report.json gains "volume_mesh":
                     {"tetrahedra","order","nodes","inner_nodes" (nodes Gmsh added: inner
                     corners and, with --order 2, every middle node),"growth_rate","max_size"
                     (--volume-grading's, MAX as used),"gmsh_ms" (of the volume stage's time,
                     Gmsh's mesh generation),"tows":[{"name","tetrahedra",
                     "volume"}],"quality":{"min_dihedral_deg","max_dihedral_deg",
                     "min_dihedral_histogram_bins_deg" (lower edges: 0 5 10 20 ... 60, the last
                     bin up to 70.53),"min_dihedral_histogram"}}, with --cell also "matrix":
                     {"tetrahedra","volume"} and "tow_volume_fraction". Not made while two
                     tows still overlap (an unresolved pair other than not_separated) or where
                     two tows' surfaces meet at under 0.01 degrees (tows touching tangentially:
                     no tetrahedron fits between them; --method shrink leaves a gap); exit 3,
                     also with --allow-open: the surfaces are written, no new
                     DIR/textile_volume.*, report.json "volume_mesh": {"refused": why}.
                     Needs Gmsh's library (Debian: libgmsh4.8). With --cell also the matrix:
                     physical volume / ELSET MATRIX, groups / NSETs XMIN ... ZMAX of every node
                     on each box face; report.json "volume_mesh" gains "matrix" and
                     "tow_volume_fraction"
  --order N          with --volume: 1 linear tetrahedra (default; C3D4), 2 quadratic (10 nodes,
                     straight edges: C3D10, Gmsh's 10-node tetrahedra and 6-node triangles, VTK's
                     quadratic tetrahedra; node sets hold the middle nodes on them too)
  --volume-grading RATE,MAX
                     with --volume: how the tetrahedra grow away from the surfaces (default
                     1.3,0): the edge length asked for is the least, over the surface nodes,
                     of a node's mean surface edge plus (RATE - 1) x the distance to it, at
                     most MAX (never below a node's own size; 0: 8 x the
                     surface mesh's median edge length). 1,0 keeps the surfaces' sizes
                     throughout (several times more tetrahedra); RATE at most 1.5 (beyond,
                     Gmsh's HXT recovers the surfaces very slowly). The surface triangles, and
                     so the tows' interfaces, are the same either way
  --cell X0,Y0,Z0,X1,Y1,Z1 | --cell DIR/textile.json
                     clip every tow by this box (a unit cell for finite elements): where a face
                     cuts a tow the tow is closed by a flat cap on the face; the faces are meshed
                     around the caps (shared nodes) and, with --volume, the matrix is filled
                     too. Any box (--cell-cut mesh, the default without --periodic): a face may
                     cut a tow several times (a binder leaving and coming back: its pieces all
                     in its element set, counted in report.json's "pieces"), along its length,
                     through overlaps, at the box's edges and corners.
                     A tow wholly outside the box gets no NAME.stl / NAME.vtk. report.json gains
                     "cell". DIR/textile.json: the unit cell `towgeom generate` wrote there (one
                     repeat of a 2D weave, faces halfway between yarns, periodic; it writes one
                     when there are at least a repeat + 2 wefts and warps, e.g. 6 x 6 for a 2/2
                     twill)
  --cell-cut auto|parametric|mesh
                     how --cell cuts the tows. mesh: the resolved meshes clipped by the faces'
                     planes (new nodes on the cut edges, exactly on the planes; nodes within a
                     fifth of an edge of a plane moved onto it along their surface), any box,
                     not periodic.
                     parametric: each cut an exact curve in the tow's (u,v), a constraint of its
                     mesh; the faces must then cut tows across once, away from the box's edges
                     (else exit 2 naming the tow): for a woven cell, halfway between yarns; a
                     face may cut through an overlap of two tows that both cross it (the
                     lower-ranked tow's cap there gives way). auto (default): parametric with
                     --periodic, else mesh
  --periodic         with --cell: the textile repeats with the box; the max faces' meshes are
                     the min faces' moved by the box (every node has its partner at exactly +L),
                     refused (exit 2) where a tow's cuts on opposite faces differ by more than
                     1e-3 of its size, or where an overlap cut by a max face is not cut by the
                     min face at the same place moved by the box. With --volume --formats
                     ...,inp also DIR/textile_volume_periodic.inp: *EQUATION ties of every
                     max-face node to its min-face partner through reference nodes REF_X,
                     REF_Y, REF_Z (their displacements: the cell's stretch along each axis),
                     *NSET CORNER
  --load-cases       with --volume --cell ... --periodic: also DIR/textile_load_cases.inp, the
                     six unit-strain load cases (mean strains xx, yy, zz, yz, xz, xy of 1e-3,
                     engineering shear) through REF_X/Y/Z, the min corner held, every element's
                     stresses and volume printed; needs --tow-material and --matrix-material,
                     and --formats ...,inp for the files it includes. Run `ccx -i
                     textile_load_cases` in DIR, then `towgeom stiffness DIR` for the cell's
                     6x6 effective stiffness
  --tow-material E,NU | E1,E2,E3,NU12,NU13,NU23,G12,G13,G23
                     the tows' elastic constants: isotropic, or engineering constants in the
                     fibre axes (1 along the fibres: *ORIENTATION FIBRES)
  --matrix-material E,NU
                     the matrix's (isotropic; nine constants are taken too, in global axes)
  --face-grading GROWTH,MAX
                     with --cell: how the box's faces are meshed away from the tows: the edge
                     length grows from the finest tow's mesh size h (at the caps and wherever a
                     tow is near) by GROWTH per unit of distance to the nearest tow, up to MAX * h
                     (default 0.3,4); with --volume the matrix's tetrahedra grade with them.
                     GROWTH 0 or MAX 1 meshes every face at h
  --allow-open       exit 0 even when an intersection curve is open (or, with --no-caps, a
                     loop crosses a tow's end cap): never resolved, still named on stderr;
                     other unresolved pairs still exit 3, and so do --volume refused for it
                     and, with --cell and --formats step or brep, the MATRIX solid not built
  --threads N        worker threads (default: all hardware threads)
  --quiet            no progress lines on stderr (warnings are always printed: unresolved
                     pairs, the mesh quality note)
  -h, --help         this help

Exit status: 0 success; 3 a tow pair is unresolved (see "unresolved": one stderr line each,
also with --quiet; the files are written all the same), unless every such pair is an open curve
and --allow-open is given, and also when an output asked for is missing (--volume refused while
tows overlap; with --cell and --formats step or brep the MATRIX solid not built: a warning says
why); 2 invalid input or usage (one line on stderr naming file and line;
nothing written); 1 a file could not be written or an internal failure (e.g. the meshes fail
their own check); 130 stopped by Ctrl-C or SIGTERM while computing; a failed or stopped run
leaves DIR exactly as it was.

Examples:
  towgeom resolve examples/data/twill/*.stw --out resolved --formats stl,vtk,msh,inp
  towgeom generate --weave twill --tows 6x6 --overlap 0.08 --out weave
  towgeom resolve weave/*.stw --out cell --cell 0.5,0.5,-0.5,4.5,4.5,0.5 --periodic \
      --volume --formats msh,inp      (a periodic 4x4 unit cell: tows and matrix)
  (then open resolved/*.vtk in ParaView and colour by region_id)
)";

std::set<std::string> parseFormats(const std::optional<std::string>& text)
{
    std::set<std::string> formats;
    std::stringstream in(text ? *text : std::string("stl,vtk"));
    for (std::string f; std::getline(in, f, ',');) {
        if (f != "stl" && f != "vtk" && f != "msh" && f != "inp" && f != "step" && f != "brep")
            throw UsageError("--formats takes stl, vtk, msh, inp, step and brep, comma-separated, not '" + f + "'");
        formats.insert(f);
    }
    if (formats.empty()) throw UsageError("--formats needs at least one of stl, vtk, msh, inp, step, brep");
    return formats;
}

}  // namespace

namespace {

/// An elastic material from the command line: E,NU (isotropic) or the nine engineering
/// constants E1,E2,E3,NU12,NU13,NU23,G12,G13,G23 in the fibres' axes (1 along them).
ElasticMaterial materialOption(const std::string& option, const std::string& text)
{
    const std::vector<double> c = numberList(text);
    ElasticMaterial m;
    if (c.size() == 2) m = ElasticMaterial::isotropic(c[0], c[1]);
    else if (c.size() == 9) m = {c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8]};
    else throw UsageError("--" + option + " takes E,NU or E1,E2,E3,NU12,NU13,NU23,G12,G13,G23, not '" + text + "'");
    try {
        m.validate("--" + option);
    } catch (const Error& e) {
        throw UsageError(e.message());
    }
    return m;
}

/// --load-cases with its materials, checked before any work.
std::optional<LoadCaseMaterials> readLoadCaseMaterials(const Args& args, bool volume, const ResolveOptions& options)
{
    const bool tow = args.value("tow-material").has_value(), matrix = args.value("matrix-material").has_value();
    if (!args.has("load-cases")) {
        if (tow || matrix) throw UsageError("--tow-material and --matrix-material go with --load-cases");
        return std::nullopt;
    }
    if (!volume || !options.cell || !options.cell->periodic) throw UsageError("--load-cases needs --volume and a --periodic --cell");
    if (!tow || !matrix) throw UsageError("--load-cases needs --tow-material and --matrix-material");
    return LoadCaseMaterials{materialOption("tow-material", *args.value("tow-material")), materialOption("matrix-material", *args.value("matrix-material"))};
}

}  // namespace

int runResolve(int argc, char** argv, int first)
{
    try {
        const Args args(argc, argv, first,
                        {{"help"}, {"quiet"}, {"allow-open"}, {"out", true}, {"primary", true}, {"mesh-size", true}, {"mesh-deviation", true},
                         {"min-angle", true}, {"loop-spacing", true}, {"formats", true}, {"tolerance", true},
                         {"threads", true}, {"max-triangles", true}, {"no-caps"}, {"report", true}, {"volume"},
                         {"cell", true}, {"cell-cut", true}, {"periodic"}, {"face-grading", true}, {"order", true}, {"volume-grading", true}, {"load-cases"}, {"tow-material", true}, {"matrix-material", true}, {"method", true}, {"shrink-both"}, {"report-methods", true}, {"knot-spans"}});
        if (args.has("help")) {
            std::cout << kResolveHelp;
            return kExitOk;
        }
        if (args.positional().empty()) throw UsageError("no input files");
        const auto outDir = args.value("out");
        if (!outDir) throw UsageError("--out DIR is required");
        ResolveOptions options;
        readResolveOptions(args, options);
        options.shrink.both = args.has("shrink-both");
        if (const auto method = args.value("method")) {
            if (*method == "symmetric") options.method = ResolutionMethod::Symmetric;
            else if (*method == "shrink") options.method = ResolutionMethod::Shrink;
            else if (*method != "connect") throw UsageError("--method takes connect, symmetric or shrink, not '" + *method + "'");
        }
        if (options.shrink.both && options.method != ResolutionMethod::Shrink && !args.value("report-methods"))
            throw UsageError("--shrink-both needs --method shrink (or shrink in --report-methods)");
        if (const auto a = args.number("min-angle")) {
            if (!(*a > 0.0 && *a <= 30.0)) throw UsageError("--min-angle must lie in (0, 30] degrees");
            options.mesh.minAngle = *a;
        }
        options.mesh.caps = !args.has("no-caps");
        if (const auto grading = args.value("face-grading")) {
            if (!options.cell) throw UsageError("--face-grading needs --cell");
            const std::vector<double> g = numberList(*grading);
            if (g.size() != 2 || g[0] < 0.0 || g[1] < 1.0)
                throw UsageError("--face-grading takes GROWTH,MAX: a growth >= 0 and a largest size >= 1 (times the tows' size), not '" +
                                 *grading + "'");
            options.cell->faceSizeGrowth = g[0];
            options.cell->faceSizeMax = g[1];
        }
        if (options.cell && !options.mesh.caps) throw UsageError("--cell needs closed tows: drop --no-caps");
        if (args.has("knot-spans") && options.method == ResolutionMethod::Shrink)
            throw UsageError("--knot-spans classifies the input tows' elements; with --method shrink the meshes are of the shrunk tows");
        const bool volume = args.has("volume");
        int order = 1;
        if (const auto given = args.value("order")) {
            if (*given != "1" && *given != "2") throw UsageError("--order takes 1 (linear tetrahedra) or 2 (quadratic), not '" + *given + "'");
            if (!volume) throw UsageError("--order needs --volume");
            order = *given == "2" ? 2 : 1;
        }
        VolumeMeshOptions volumeOptions;
        volumeOptions.order = order;
        if (const auto grading = args.value("volume-grading")) {
            if (!volume) throw UsageError("--volume-grading needs --volume");
            const std::vector<double> g = numberList(*grading);
            if (g.size() != 2 || !(g[0] >= 1.0 && g[0] <= 1.5) || !(g[1] >= 0.0))
                throw UsageError("--volume-grading takes RATE,MAX: a growth rate in [1, 1.5] and a largest edge length >= 0 (0: 8 x the surface "
                                 "mesh's median edge), not '" + *grading + "'");
            volumeOptions.growthRate = g[0];
            volumeOptions.maxSize = g[1];
        }
        if (volume && !options.mesh.caps) throw UsageError("--volume needs closed tows: drop --no-caps");
        const std::optional<LoadCaseMaterials> loadCases = readLoadCaseMaterials(args, volume, options);
        const std::set<std::string> formats = parseFormats(args.value("formats"));
        if (loadCases && !formats.count("inp"))
            throw UsageError("--load-cases needs --formats ...,inp: its deck includes textile_volume.inp and textile_volume_periodic.inp");
        const bool exact = formats.count("step") || formats.count("brep");
        if (exact && options.method != ResolutionMethod::Connect)
            throw UsageError("--formats step and brep are built for --method connect only (the other methods' surfaces are not "
                             "faces of the input tows' B-splines)");
        const bool quiet = args.has("quiet");
        ProgressPrinter printer("resolve", quiet);
        options.monitor = &printer;

        const auto start = std::chrono::steady_clock::now();
        const std::vector<TowStack> stacks = readStacks(args.positional(), options.threads);
        const double readMs = msSince(start);
        auto t0 = std::chrono::steady_clock::now();
        const std::vector<TowSurface> tows = fitSurfaces(stacks, {}, "resolve", quiet, options.threads);
        const double fitMs = msSince(t0);
        const auto reportPath = args.value("report");
        // --report-methods: the methods side by side (the first is --method's, whose meshes are written).
        std::vector<ResolutionMethod> methods;
        if (const auto list = args.value("report-methods")) {
            if (reportPath) throw UsageError("--report-methods intersects the tows itself: drop --report");
            methods.push_back(options.method);
            std::stringstream in(*list);
            for (std::string name; std::getline(in, name, ',');) {
                ResolutionMethod m = ResolutionMethod::Connect;
                if (name == "symmetric") m = ResolutionMethod::Symmetric;
                else if (name == "shrink") m = ResolutionMethod::Shrink;
                else if (name != "connect") throw UsageError("--report-methods takes methods from connect,symmetric,shrink, not '" + name + "'");
                if (std::find(methods.begin(), methods.end(), m) == methods.end()) methods.push_back(m);
            }
        }
        std::optional<MethodComparison> comparison;
        const ResolveResult result = methods.empty() ? resolveExplained(tows, options, reportPath) : explainingBudget([&] {
            std::vector<ResolveResult> results;
            comparison = compareMethods(tows, methods, options, &results);
            return std::move(results.front());
        });
        const TextileMesh& mesh = result.mesh;
        // --volume with tows that still overlap (an unresolved pair): the surfaces, no tetrahedra.
        const std::vector<UnresolvedPairEntry> overlapping = volume ? overlappingPairs(result) : std::vector<UnresolvedPairEntry>{};
        std::string volumeRefused;
        if (!overlapping.empty()) {
            const UnresolvedPairEntry& p = overlapping.front();
            std::set<std::pair<std::size_t, std::size_t>> distinct;  // a pair may have several reasons
            for (const UnresolvedPairEntry& q : overlapping) distinct.insert({q.towA, q.towB});
            const std::size_t n = distinct.size();
            volumeRefused = std::to_string(n) + (n == 1 ? " tow pair still overlaps" : " tow pairs still overlap") + " (tows '" +
                            tows[p.towA].name() + "' and '" + tows[p.towB].name() + "' [" + p.code + "]" +
                            (n > 1 ? " and others" : "") + "): their tetrahedra would overlap";
        }
        bool tetrahedra = volume && overlapping.empty();
        VolumeMesh volumes;
        double volumeMs = -1.0;
        if (tetrahedra) {
            t0 = std::chrono::steady_clock::now();
            printer.update("meshing the tows' volumes (Gmsh HXT)", 0, 1);
            VolumeMeshOptions vo = volumeOptions;
            vo.threads = options.threads;
            try {
                volumes = meshVolumes(mesh, vo);
                addFibreDirections(volumes, tows, options.threads);
            } catch (const Error& e) {
                // Surfaces the tetrahedral mesher cannot take (tows touching tangentially, a tow
                // whose surface folds): the surfaces are still written, the volume mesh is
                // refused as for overlapping tows.
                if (e.code() != ErrorCode::Unsupported) throw;
                volumeRefused = e.message() + " [" + errorCodeName(e.code()) + "]";
                tetrahedra = false;
            }
            printer.update("meshing the tows' volumes (Gmsh HXT)", 1, 1);
            volumeMs = msSince(t0);
        }

        std::optional<TrimmedBrep> brep;  // the exact solids (--formats step, brep)
        double brepMs = -1.0;
        if (exact) {
            const auto brepStart = std::chrono::steady_clock::now();
            brep = buildTrimmedBrep("resolve", tows, result, printer, quiet);
            brepMs = msSince(brepStart);
        }

        // Everything is computed before anything is written.
        t0 = std::chrono::steady_clock::now();
        const std::vector<UnresolvedPairEntry> unresolved = unresolvedPairs(result);

        const auto path = [&](const std::string& file) { return (std::filesystem::path(*outDir) / file).string(); };
        detail::OutputFiles files;
        files.makeDirectory(*outDir);
        // Open every file first (OutputFiles is not thread-safe), then fill them on all threads.
        std::vector<std::ostream*> stl(tows.size(), nullptr), vtk(tows.size(), nullptr);
        for (std::size_t t = 0; t < tows.size(); ++t) {
            if (mesh.tows[t].triangles.empty()) continue;  // wholly outside the cell: no file
            if (formats.count("stl")) stl[t] = &files.open(path(tows[t].name() + ".stl"));
            if (formats.count("vtk")) vtk[t] = &files.open(path(tows[t].name() + ".vtk"));
        }
        detail::parallelFor(tows.size(), detail::workerCount(options.threads), [&](std::size_t t) {
            const TriangleMesh surface = mesh.towSurface(t);
            if (stl[t]) try {
                    writeStl(surface, *stl[t]);
                } catch (const Error& e) {
                    throw Error(e.code(), e.message(), path(tows[t].name() + ".stl"));
                }
            if (vtk[t]) {
                std::vector<long> towId(surface.triangles.size(), static_cast<long>(t)), nodeId, face;
                for (std::size_t n : mesh.towNodes(t)) nodeId.push_back(static_cast<long>(n));
                for (const TowFace f : mesh.tows[t].face) face.push_back(static_cast<long>(f));
                writeVtk(surface, *vtk[t], "towgeom resolved tow " + tows[t].name(),
                         {{"tow_id", towId}, {"region_id", mesh.tows[t].region}, {"face", face}}, {{"node_id", nodeId}});
            }
        });
        if (formats.count("msh")) writeGmsh(mesh, files.open(path("textile.msh")));
        if (formats.count("step")) brep->writeStep(files.open(path("textile.step")));
        if (formats.count("brep")) brep->writeBrep(files.open(path("textile.brep")));
        if (formats.count("inp")) writeAbaqus(mesh, files.open(path("textile.inp")));
        if (tetrahedra) writeGmsh(mesh, volumes, files.open(path("textile_volume.msh")));
        if (tetrahedra && formats.count("inp")) writeAbaqus(mesh, volumes, files.open(path("textile_volume.inp")));
        if (tetrahedra && formats.count("inp") && options.cell && options.cell->periodic)
            writeAbaqusPeriodic(mesh, volumes, files.open(path("textile_volume_periodic.inp")));
        if (tetrahedra && loadCases) writeLoadCases(mesh, volumes, *loadCases, files.open(path("textile_load_cases.inp")));
        if (tetrahedra && formats.count("vtk")) writeVtu(mesh, volumes, files.open(path("textile_volume.vtu")));
        if (args.has("knot-spans")) {  // the elements of each tow's B-spline: valid, invalid, trimmed
            std::vector<KnotSpanClassification> spans(tows.size());
            detail::parallelFor(tows.size(), detail::workerCount(options.threads), [&](std::size_t t) {
                if (!mesh.tows[t].triangles.empty()) spans[t] = classifyKnotSpans(tows, mesh, t);
            });
            for (std::size_t t = 0; t < tows.size(); ++t) {
                if (mesh.tows[t].triangles.empty()) continue;
                writeKnotSpansJson(spans[t], files.open(path(tows[t].name() + "_knot_spans.json")));
                writeKnotSpansVtk(spans[t], tows[t], files.open(path(tows[t].name() + "_knot_spans.vtk")));
            }
        }
        if (comparison) {
            writeReportHtml(*comparison, mesh, files.open(path("report.html")));
            writeReportCsv(*comparison, files.open(path("report.csv")));
        }
        if (!result.shrunk.empty()) {  // --method shrink: the shrunk tows, for detect or another tool
            files.makeDirectory(path("shrunk"));
            for (const ShrunkTow& s : result.shrunk) writeStack(files.open(path("shrunk/" + s.stack.name + ".stw")), s.stack);
        }
        const double writeMs = msSince(t0);
        ResolveReportOptions written;
        written.threads = options.threads;
        written.times.read = readMs;
        written.times.fit = fitMs;
        written.times.write = writeMs;
        written.times.volume = volumeMs;
        written.times.brep = brepMs;
        if (tetrahedra) written.volumes = &volumes;
        written.volumeRefused = volumeRefused;
        written.times.total = msSince(start);
        writeResolveReport(result, tows, files.open(path("report.json")), written);
        printer.throwIfCancelled();  // a signal while writing: nothing is committed
        files.commit();

        if (!quiet) {
            for (std::size_t t = 0; t < tows.size(); ++t)
                if (result.tows[t].pieces > 1)
                    std::cerr << "towgeom resolve: tow '" << tows[t].name() << "' is cut into " << result.tows[t].pieces
                              << " pieces by tows ranked above it that pass through it\n";
            std::cerr << "towgeom resolve: " << mesh.regions.size() << " connected regions, " << mesh.nodes.size() << " nodes, "
                      << result.quality.triangles << " triangles (smallest angle " << result.quality.minAngle << " deg)";
            if (tetrahedra) std::cerr << ", " << volumes.tetrahedra.size() << " tetrahedra";
            std::cerr << "; files in " << *outDir << "\n";
        }
        // Warnings, not progress: printed whatever --quiet says.
        if (options.mesh.edgeLength > 0.0)
            for (std::size_t t = 0; t < tows.size(); ++t)
                if (result.tows[t].meshSize < options.mesh.edgeLength)
                    std::cerr << "towgeom resolve: note: tow '" << tows[t].name() << "' meshed at h = " << result.tows[t].meshSize
                              << ", a quarter of its circumference (--mesh-size " << options.mesh.edgeLength
                              << " would leave fewer than 4 edges around it)\n";
        if (result.quality.fractionAtLeast(20.0) < 0.99 || result.quality.minAngle < 10.0)
            std::cerr << "towgeom resolve: note: mesh quality below the usual target (smallest angle "
                      << result.quality.minAngle << " deg, " << 100.0 * result.quality.fractionAtLeast(20.0)
                      << " % of triangles at least 20 deg): the mesh size may be too coarse for the tows' curvature; "
                         "try a smaller --mesh-size\n";
        if (result.crossingTrianglePairs > 0)
            std::cerr << "towgeom resolve: warning: " << result.crossingTrianglePairs
                      << " pairs of triangles of two tows' tubes still cross (report.json crossing_triangle_pairs): the "
                         "surfaces are closer there than the mesh follows after refining both around them (try a smaller "
                         "--mesh-size), or the tows pass through each other where no intersection loop bounds the overlap\n";
        for (std::size_t t = 0; t < tows.size(); ++t)  // a warning, whatever --quiet says
            if (const std::optional<SurfaceFold>& f = result.tows[t].fold)
                std::cerr << "towgeom resolve: warning: tow '" << tows[t].name() << "': its surface crosses itself near (" << f->at.x
                          << ", " << f->at.y << ", " << f->at.z << ") (u = " << f->uv.u
                          << "; report.json \"fold\"): it bends sharper than it is thick between sections far apart (or two "
                             "parts of it pass through each other); its meshes cross there unless coarser than the fold, and no "
                             "volume mesh fits; denser sections at the bend unfold it\n";
        if (!quiet)
            for (const ConnectedRegion& g : mesh.regions)
                if (!g.note.empty()) std::cerr << "towgeom resolve: note: " << g.note << "\n";
        const bool noMatrix = brep && warnAboutBrep("resolve", *brep, "textile.step/.brep");  // whatever --quiet says
        if (!volumeRefused.empty())  // a warning, whatever --quiet says
            std::cerr << "towgeom resolve: warning: no volume mesh written (--volume): " << volumeRefused << "; the surfaces are written"
                      << (overlapping.empty() ? "" : ", the pairs are named below") << "\n";
        reportContacts("resolve", result, tows);
        reportUnresolved("resolve", unresolved, tows);
        // A refused volume mesh or a missing matrix solid exits 3 even with --allow-open: an
        // output asked for is missing.
        return exitsUnresolved(unresolved, args.has("allow-open")) || !volumeRefused.empty() || noMatrix ? kExitUnresolved : kExitOk;
    } catch (const std::exception& e) {
        return reportError("resolve", e);
    }
}

}  // namespace towgeom::cli
