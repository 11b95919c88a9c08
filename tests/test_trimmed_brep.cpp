// trimmedBrep(): the resolved bundled twill as exact solids, checked on the files read back by
// OpenCASCADE (BRepCheck_Analyzer, BRepGProp, the STEP reader's names, faces shared in the BREP)
// against the tows' exact volumes, OCCT booleans of the untrimmed tows (solids the test builds
// itself from the tows' B-spline data, not by trimmedBrep()), resolve's mesh volumes, and meshed
// by Gmsh from the STEP file.
#include <catch2/catch.hpp>

#include <towgeom/error.hpp>
#include <towgeom/resolve.hpp>
#include <towgeom/stack_reader.hpp>
#include <towgeom/trimmed_brep.hpp>
#include <towgeom/weave.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <string>

#include <unistd.h>

#include "occt_reference.hpp"
#include "synthetic_tows.hpp"

using namespace towgeom;
namespace fs = std::filesystem;

namespace {

fs::path freshDirectory(const std::string& name)
{
    const fs::path dir = fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

double relative(double a, double b) { return std::abs(a - b) / std::abs(b); }

/// Writes the references' solids to the BREP file @p path: @p tows whole (no regions, no cell),
/// each its exact solid built without trimmedBrep() (testing::writeWholeTowSolids(): OCCT's own
/// face on the tow's B-spline data, planar caps, sewn). Each must be valid, its surface the tow's
/// (within 1e-13 of its size at 400 points; measured up to 3.7e-15) and its volume (BRepGProp,
/// asked for 1e-5: 1e-7 takes 0.2 s a tow) the tow's own (TowSurface::volume(): Gauss quadrature
/// of the divergence theorem, not OCCT) within 1e-4 (measured up to 1.1e-5), which a solid
/// inside out or a cap missing would not be.
void writeUntrimmed(const std::vector<TowSurface>& tows, const std::string& path)
{
    const std::vector<testing::WholeTowSolid> whole = testing::writeWholeTowSolids(tows, path);
    REQUIRE(whole.size() == tows.size());
    for (std::size_t t = 0; t < tows.size(); ++t) {
        INFO("reference solid of " << tows[t].name() << ": volume " << whole[t].volume << ", off the tow's by "
                                   << relative(whole[t].volume, tows[t].volume()) << " relative; surface off by "
                                   << whole[t].surfaceError / tows[t].towSize() << " of the tow's size");
        CHECK(whole[t].valid);
        CHECK(whole[t].surfaceError <= 1e-13 * tows[t].towSize());
        CHECK(relative(whole[t].volume, tows[t].volume()) <= 1e-4);
    }
}

/// A cell's box corners as testing::boxCommonVolume() takes them.
std::array<std::array<double, 3>, 2> cornersOf(const Cell& cell)
{
    return {{{cell.min.x, cell.min.y, cell.min.z}, {cell.max.x, cell.max.y, cell.max.z}}};
}

/// The exact volumes of testing::crossingTubes() x and y inside @p cell, y less its overlap with x: OCCT
/// booleans on the untrimmed tubes (written to @p wholeFile).
std::array<double, 2> exactTubesInCell(const std::vector<TowSurface>& tows, const Cell& cell,
                                       const std::string& wholeFile)
{
    writeUntrimmed(tows, wholeFile);
    const auto [lo, hi] = cornersOf(cell);
    return {testing::boxCommonVolume(wholeFile, 0, lo, hi),
            testing::boxCommonVolume(wholeFile, 1, lo, hi) - testing::commonVolume(wholeFile, 1, 0)};
}

/// Runs gmsh on @p input with @p options (its output to @p output, its log to DIR/gmsh.log):
/// it must exit 0, print no error and write @p output.
void checkGmshReads(const fs::path& dir, const std::string& input, const std::string& options, const std::string& output)
{
    const std::string log = (dir / "gmsh.log").string();
    const std::string command = "gmsh '" + input + "' " + options + " -o '" + output + "' > '" + log + "' 2>&1";
    const int status = std::system(command.c_str());
    std::ifstream in(log);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    INFO(text.substr(text.size() > 3000 ? text.size() - 3000 : 0));
    CHECK(status == 0);
    CHECK(text.find("Error") == std::string::npos);
    CHECK(fs::exists(output));
}

}  // namespace

TEST_CASE("trimmed B-rep of the bundled twill: valid named solids, exact volumes, shared faces, Gmsh meshes the STEP",
          "[brep]")
{
    const std::vector<TowSurface> tows = testing::bundledTwill(TOWGEOM_EXAMPLE_DATA);
    const ResolveResult r = resolveTextile(tows);
    REQUIRE(r.mesh.regions.size() == 16);
    const TrimmedBrep brep = trimmedBrep(tows, r);
    CHECK(brep.fusedBecause().empty());  // every face bounded by its loops
    REQUIRE(brep.solids().size() == tows.size());
    CHECK(brep.sharedFaceCount() == r.mesh.regions.size());
    const fs::path dir = freshDirectory("towgeom_brep");
    const std::string step = (dir / "twill.step").string(), brepFile = (dir / "twill.brep").string();
    brep.writeStep(step);
    brep.writeBrep(brepFile);
    CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 2);  // no temporary left

    // The untrimmed tows (no regions): each pair's overlap by OCCT's boolean, independent of the loops.
    const std::string wholeFile = (dir / "whole.brep").string();
    writeUntrimmed(tows, wholeFile);
    std::vector<double> exact(tows.size());
    for (std::size_t t = 0; t < tows.size(); ++t) exact[t] = tows[t].volume();
    for (const ConnectedRegion& g : r.mesh.regions) exact[g.secondary] -= testing::commonVolume(wholeFile, g.secondary, g.primary);

    // Volumes from the STEP file; the BREP file for validity and its shared faces.
    const testing::ReadShapes fromStep = testing::readStep(step), fromBrep = testing::readBrep(brepFile, false);
    REQUIRE(fromStep.solids.size() == tows.size());
    REQUIRE(fromBrep.solids.size() == tows.size());
    for (std::size_t t = 0; t < tows.size(); ++t) {
        const BrepSolid& s = brep.solids()[t];
        const testing::ReadSolid &a = fromStep.solids[t], &b = fromBrep.solids[t];
        INFO(s.name << ": volume " << s.volume << ", read back " << a.volume << " (STEP), exact " << exact[t]
                    << ", mesh " << r.tows[t].volumeAfter << ", faces " << s.faces << ", shared " << s.sharedFaces
                    << ", tolerance " << s.maxTolerance);
        CHECK(s.valid);
        CHECK(a.valid);
        CHECK(b.valid);
        CHECK(a.name == tows[t].name());
        CHECK(relative(s.volume, exact[t]) <= 1e-6);
        CHECK(relative(a.volume, exact[t]) <= 1e-6);
        CHECK(relative(s.volume, r.tows[t].volumeAfter) <= 5e-3);
        CHECK(s.maxTolerance <= 1e-5 * tows[t].towSize());
        // 4 crossings each: a warp is the primary of 4 regions (its own face inside each loop
        // shared), a weft the secondary of 4; plus the tube and two caps.
        CHECK(s.sharedFaces == 4);
        CHECK(s.faces == 7);
    }
    // In the BREP file each shared face is one face of both solids.
    std::size_t shared = 0;
    for (const auto& entry : fromBrep.sharedFaces) {
        const std::pair<std::size_t, std::size_t> solids = entry.first;
        const auto region = std::find_if(r.mesh.regions.begin(), r.mesh.regions.end(), [&](const ConnectedRegion& g) {
            return std::minmax(g.primary, g.secondary) == std::minmax(solids.first, solids.second);
        });
        CHECK(region != r.mesh.regions.end());
        shared += entry.second;
    }
    CHECK(shared == r.mesh.regions.size());

    // Gmsh's OpenCASCADE kernel imports the STEP file and meshes every volume.
    checkGmshReads(dir, step, "-3 -clmax 0.2 -format msh4", (dir / "twill.msh").string());
    fs::remove_all(dir);
}

TEST_CASE("trimmed B-rep clipped to a cell: two crossing tubes cut by the box, a third outside", "[brep][cell]")
{
    const std::vector<TowSurface> tows = testing::crossingTubes(true);
    ResolveOptions o;
    Cell cell;
    cell.min = {0.5, -1.5, -1.0};
    cell.max = {3.5, 1.5, 1.5};
    o.cell = cell;
    const ResolveResult r = resolveTextile(tows, o);
    REQUIRE(r.mesh.regions.size() == 1);
    const TrimmedBrep brep = trimmedBrep(tows, r);
    const fs::path dir = freshDirectory("towgeom_brep_cell_tubes");
    const std::string file = (dir / "cell.brep").string(), wholeFile = (dir / "whole.brep").string();
    brep.writeBrep(file);
    const auto [exactX, exactY] = exactTubesInCell(tows, cell, wholeFile);
    const double pi = std::acos(-1.0);
    const testing::ReadShapes back = testing::readBrep(file);
    REQUIRE(back.solids.size() == 3);  // x, y and the matrix; "far" has no solid
    const BrepSolid &x = brep.solids()[0], &y = brep.solids()[1], &far = brep.solids()[2];
    INFO("x: volume " << x.volume << " (" << exactX << "), area " << x.area << "; y: volume " << y.volume << " (" << exactY << ")");
    CHECK(x.valid);
    CHECK(y.valid);
    CHECK(back.solids[0].valid);
    CHECK(back.solids[1].valid);
    CHECK(relative(x.volume, exactX) <= 1e-6);
    CHECK(relative(y.volume, exactY) <= 1e-6);
    CHECK(relative(back.solids[0].volume, exactX) <= 1e-6);
    CHECK(relative(back.solids[1].volume, exactY) <= 1e-6);
    // The x tube (the primary: its own surface, the shared face included) between x = 0.5 and
    // 3.5: a cylinder of radius 0.5 and length 3, up to the fit of its 48-point sections.
    CHECK(relative(x.volume, pi * 0.25 * 3.0) <= 1e-4);
    CHECK(relative(x.area, 2.0 * pi * 0.5 * 3.0 + 2.0 * pi * 0.25) <= 1e-4);
    CHECK(x.faces == 4);  // the tube, the shared face, 2 cut faces
    CHECK(y.faces == 4);
    CHECK(x.cellFaces == 2);
    CHECK(y.cellFaces == 2);
    CHECK(x.sharedFaces == 1);
    CHECK(far.faces == 0);
    CHECK(brep.solids()[0].cellFaces + brep.solids()[1].cellFaces == 4);
    CHECK(far.volume == 0.0);
    CHECK(far.area == 0.0);
    // The matrix: the box less both tubes, measured on the file (BRepGProp over its own faces:
    // the box's faces with the cut faces as holes, and the tubes' faces it shares).
    const BrepSolid& matrix = brep.matrix();
    INFO("matrix: volume " << matrix.volume << ", read back " << back.solids[2].volume << ", area " << matrix.area);
    CHECK(matrix.name == "MATRIX");
    CHECK(matrix.valid);
    CHECK(back.solids[2].valid);
    CHECK(matrix.faces == 8);        // 6 box faces (4 with the cut faces as holes) and each tube's own face
    CHECK(matrix.cellFaces == 6);
    CHECK(matrix.sharedFaces == 2);  // the tubes' own faces; the face the tubes share is not the matrix's
    CHECK(relative(back.solids[2].volume, cell.volume() - exactX - exactY) <= 1e-6);
    CHECK(relative(matrix.volume, back.solids[2].volume) <= 1e-6);
    CHECK(relative(matrix.area, testing::readBrepArea(file, 2)) <= 1e-6);
    // x-y share the region's face; each shares its own face with the matrix.
    REQUIRE(back.sharedFaces.size() == 3);
    for (const auto& pair : back.sharedFaces) CHECK(pair.second == 1);
    // The same solids through the library's STEP writer (the CLI's --formats step is another
    // path): read back by OCCT's STEP reader, the same three solids (STEP keeps a shared face as
    // two equal faces, one per solid).
    const std::string stepFile = (dir / "cell.step").string();
    brep.writeStep(stepFile);
    const testing::ReadShapes step = testing::readStep(stepFile);
    REQUIRE(step.solids.size() == 3);
    CHECK(step.solids[0].valid);
    CHECK(step.solids[1].valid);
    CHECK(relative(step.solids[0].volume, exactX) <= 1e-6);
    CHECK(relative(step.solids[1].volume, exactY) <= 1e-6);
    CHECK(relative(step.solids[2].volume, cell.volume() - exactX - exactY) <= 1e-6);
    // BrepOptions::matrix false: the tows only.
    BrepOptions noMatrix;
    noMatrix.matrix = false;
    const TrimmedBrep towsOnly = trimmedBrep(tows, r, noMatrix);
    CHECK(towsOnly.matrix().faces == 0);
    towsOnly.writeBrep(file);
    CHECK(testing::readBrep(file, false).solids.size() == 2);
    CHECK(towsOnly.matrixNote().empty());  // not asked for
    CHECK(brep.matrixNote().empty());
    // Tows that still overlap (a pair left unresolved, hand-made here): the box less the tows
    // would not be the matrix, so it is not built and the note names the pair.
    ResolveResult still = r;
    still.unresolved.push_back({0, 1, UnresolvedPair::Reason::RegionFailed, "region failed"});
    const TrimmedBrep overlapping = trimmedBrep(tows, still);
    CHECK(overlapping.matrix().faces == 0);
    CHECK(overlapping.matrixNote().find("tows 'x' and 'y' still overlap [region_failed]") == 0);
    overlapping.writeBrep(file);
    CHECK(testing::readBrep(file, false).solids.size() == 2);
    fs::remove_all(dir);
}

TEST_CASE("trimmed B-rep clipped to a cell: a tow's end cap on a face of the box is its own face, not a cut face", "[brep][cell]")
{
    // The x tube runs from x = 0 to 4; the box's face x = 0 holds its first cap. The boolean
    // keeps that cap as the tow's face (it coincides with the box's): not a cut face, not a face
    // of the matrix, and the areas follow.
    const std::vector<TowSurface> tows = testing::crossingTubes(false);
    ResolveOptions o;
    Cell cell;
    cell.min = {0.0, -1.5, -1.0};
    cell.max = {3.5, 1.5, 1.5};
    o.cell = cell;
    const ResolveResult r = resolveTextile(tows, o);
    REQUIRE(r.mesh.regions.size() == 1);
    const TrimmedBrep brep = trimmedBrep(tows, r);
    const fs::path dir = freshDirectory("towgeom_brep_cell_cap");
    const std::string file = (dir / "cell.brep").string(), wholeFile = (dir / "whole.brep").string();
    brep.writeBrep(file);
    const auto [exactX, exactY] = exactTubesInCell(tows, cell, wholeFile);
    const BrepSolid& x = brep.solids()[0];
    INFO("x: volume " << x.volume << " (" << exactX << "), area " << x.area << ", cut faces " << x.cellFaces);
    CHECK(x.valid);
    CHECK(x.cellFaces == 1);  // only the cut at x = 3.5
    CHECK(relative(x.volume, exactX) <= 1e-6);
    CHECK(relative(x.area, testing::readBrepArea(file, 0)) <= 1e-6);
    CHECK(relative(brep.solids()[1].area, testing::readBrepArea(file, 1)) <= 1e-6);
    const BrepSolid& matrix = brep.matrix();
    INFO("matrix: " << brep.matrixNote());
    REQUIRE(matrix.faces > 0);
    CHECK(matrix.valid);
    CHECK(matrix.sharedFaces == 2);  // the tubes' own faces, not the cap on the box
    const testing::ReadShapes back = testing::readBrep(file);
    REQUIRE(back.solids.size() == 3);
    CHECK(back.solids[2].valid);
    CHECK(relative(back.solids[2].volume, cell.volume() - exactX - exactY) <= 1e-6);
    CHECK(relative(matrix.area, testing::readBrepArea(file, 2)) <= 1e-6);
    fs::remove_all(dir);
}

TEST_CASE("trimmed B-rep with a cell face through an overlap: the shared face cut by the box stays shared", "[brep][cell]")
{
    // test_volume_mesh's "a cell face through an overlap": two tubes crossing at a shallow angle,
    // their long overlap cut across by the face x = 2 (both tows cross it there). The two solids
    // are clipped together, so the part of their shared face inside the box is one face of both.
    struct Case {
        double degrees, width, height, lift, side;
    };
    const Case c = GENERATE(Case{20.0, 0.5, 0.5, 0.6, 0.0}, Case{30.0, 0.8, 0.25, 0.4, 0.0}, Case{-30.0, 0.5, 0.5, 0.3, 0.7});
    INFO("crossing at " << c.degrees << " degrees, sections " << c.width << " x " << c.height);
    const std::vector<TowSurface> tows = testing::fitAll(testing::tubesCrossingAt(c.degrees, c.width, c.height, c.lift, c.side));
    const Cell cell = testing::crossingAtCell();
    ResolveOptions o;
    o.mesh.edgeLength = 0.1;
    o.cell = cell;
    const ResolveResult r = resolveTextile(tows, o);
    REQUIRE(r.unresolved.empty());
    REQUIRE(r.mesh.regions.size() == 1);
    REQUIRE(r.mesh.regions[0].primary == 0);
    const TrimmedBrep brep = trimmedBrep(tows, r);
    REQUIRE(brep.solids().size() == 2);
    const fs::path dir = freshDirectory("towgeom_brep_cell_overlap");
    const std::string file = (dir / "cell.brep").string(), wholeFile = (dir / "whole.brep").string();
    brep.writeBrep(file);

    // References: the untrimmed, unclipped tubes by OCCT booleans: a inside the box, b inside
    // it less its overlap with a there.
    writeUntrimmed(tows, wholeFile);
    const auto [lo, hi] = cornersOf(cell);
    const double exactA = testing::boxCommonVolume(wholeFile, 0, lo, hi);
    const double exactB = testing::boxCommonVolume(wholeFile, 1, lo, hi) - testing::boxCommonVolume(wholeFile, 0, 1, lo, hi);
    const BrepSolid &a = brep.solids()[0], &b = brep.solids()[1];
    INFO("a: volume " << a.volume << " (" << exactA << "); b: volume " << b.volume << " (" << exactB << ")");
    CHECK(a.valid);
    CHECK(b.valid);
    CHECK(relative(a.volume, exactA) <= 1e-6);
    CHECK(relative(b.volume, exactB) <= 1e-6);
    CHECK(relative(b.volume, r.tows[1].volumeAfter) <= 0.03);  // the mesh's chords cut off a little
    CHECK(brep.sharedFaceCount() == 1);
    CHECK(a.sharedFaces == 1);
    CHECK(b.sharedFaces == 1);
    CHECK(a.cellFaces >= 1);
    CHECK(b.cellFaces >= 1);
    // Read back: both tows and the matrix valid, the shared face one face of a and b, the
    // matrix's volume the box's less the exact tows'.
    const testing::ReadShapes back = testing::readBrep(file);
    REQUIRE(back.solids.size() == 3);
    for (const testing::ReadSolid& s : back.solids) CHECK(s.valid);
    CHECK(relative(back.solids[0].volume, exactA) <= 1e-6);
    CHECK(relative(back.solids[1].volume, exactB) <= 1e-6);
    CHECK(brep.matrix().valid);
    CHECK(relative(back.solids[2].volume, cell.volume() - exactA - exactB) <= 1e-6);
    CHECK(relative(brep.matrix().area, testing::readBrepArea(file, 2)) <= 1e-6);
    std::size_t ab = 0;
    for (const auto& entry : back.sharedFaces)
        if (entry.first == std::make_pair(std::size_t{0}, std::size_t{1})) ab = entry.second;
    CHECK(ab == 1);
    // The same pair also left overlapping (hand-made): clipped tow by tow, their shared face cut
    // by the box cannot stay shared; refused as unsupported, naming the pair (was an internal
    // error).
    ResolveResult still = r;
    still.unresolved.push_back({0, 1, UnresolvedPair::Reason::RegionFailed, "region failed"});
    try {
        trimmedBrep(tows, still);
        FAIL("no error");
    } catch (const Error& e) {
        INFO(e.what());
        CHECK(e.code() == ErrorCode::Unsupported);
        CHECK(std::string(e.what()).find("still overlap") != std::string::npos);
    }
    fs::remove_all(dir);
}

TEST_CASE("trimmed B-rep of a periodic twill cell: solids clipped by the box, cut faces on its planes, shared faces kept", "[brep][cell]")
{
    // The 6x6 2/2 twill clipped to its 4x4 repeat (test_volume_mesh): 8 tows cut by two opposite
    // faces each, 4 wholly outside; 16 regions inside, 20 loops outside (skipped, not trimmed).
    const std::vector<TowSurface> tows = testing::fittedTwill22SixBySix();
    ResolveOptions o;
    o.mesh.edgeLength = 0.2;
    const Cell cell = testing::twill22RepeatCell();
    o.cell = cell;
    const ResolveResult r = resolveTextile(tows, o);
    REQUIRE(r.mesh.regions.size() == 16);
    const TrimmedBrep brep = trimmedBrep(tows, r);
    REQUIRE(brep.solids().size() == tows.size());
    CHECK(brep.sharedFaceCount() == 16);
    const fs::path dir = freshDirectory("towgeom_brep_cell");
    const std::string step = (dir / "cell.step").string(), brepFile = (dir / "cell.brep").string();
    brep.writeStep(step);
    brep.writeBrep(brepFile);

    // References: the untrimmed, unclipped tows (no regions, no cell) by OCCT booleans: each
    // tow's part inside the box less its overlaps with the tows above it there. The warps are
    // primaries (nothing to subtract); of the wefts one (weft_1) is measured so (each overlap is
    // an OCCT boolean of two tows, seconds each); every solid is also measured on the STEP file.
    const std::string wholeFile = (dir / "whole.brep").string();
    writeUntrimmed(tows, wholeFile);
    const auto [lo, hi] = cornersOf(cell);
    std::vector<double> exact(tows.size(), -1.0);  // -1: not measured
    for (std::size_t t = 0; t < tows.size(); ++t)
        if (tows[t].name().rfind("warp", 0) == 0 || tows[t].name() == "weft_1") exact[t] = testing::boxCommonVolume(wholeFile, t, lo, hi);
    std::size_t subtracted = 0;
    for (const ConnectedRegion& g : r.mesh.regions)
        if (tows[g.secondary].name() == "weft_1") {
            exact[g.secondary] -= testing::commonVolume(wholeFile, g.secondary, g.primary);
            ++subtracted;
        }
    CHECK(subtracted == 4);

    const testing::ReadShapes fromBrep = testing::readBrep(brepFile, false);  // the tubes' test measures read-back volumes
    std::size_t inside = 0;
    double tows_volume = 0.0;
    for (std::size_t t = 0; t < tows.size(); ++t) {
        const BrepSolid& s = brep.solids()[t];
        INFO(s.name << ": volume " << s.volume << ", exact " << exact[t] << ", mesh " << r.tows[t].volumeAfter << ", faces "
                    << s.faces << ", shared " << s.sharedFaces);
        if (r.mesh.tows[t].triangles.empty()) {  // wholly outside: no solid
            CHECK(s.faces == 0);
            CHECK(s.volume == 0.0);
            if (exact[t] >= 0.0) CHECK(exact[t] <= 1e-12);
            continue;
        }
        REQUIRE(inside < fromBrep.solids.size());
        CHECK(fromBrep.solids[inside].valid);
        CHECK(s.valid);
        if (exact[t] >= 0.0) CHECK(relative(s.volume, exact[t]) <= 1e-6);
        // The faceted mesh at h = 0.2 lies inside the exact solid: its chords cut off about 3 %.
        CHECK(r.tows[t].volumeAfter < s.volume);
        CHECK(relative(s.volume, r.tows[t].volumeAfter) <= 0.04);
        CHECK(s.faces == 7);  // the tube, 4 shared faces, 2 cut faces on the box
        CHECK(s.cellFaces == 2);
        CHECK(s.sharedFaces == 4);
        tows_volume += s.volume;
        ++inside;
    }
    CHECK(inside == 8);
    CHECK(fromBrep.solids.size() == 9);  // and the matrix
    CHECK(tows_volume < cell.volume());
    // The matrix: the box less the 8 tows, bounded by the 6 box faces (with the cut faces as
    // holes) and each tow's own face (the same face as the tow's).
    const BrepSolid& matrix = brep.matrix();
    CHECK(matrix.valid);
    CHECK(fromBrep.solids[8].valid);
    CHECK(matrix.faces == 14);
    CHECK(matrix.cellFaces == 6);
    CHECK(matrix.sharedFaces == 8);
    // Its faces as read back: the box's less the cut faces plus the tows' own faces.
    CHECK(relative(matrix.area, testing::readBrepArea(brepFile, 8)) <= 1e-6);
    std::size_t shared = 0;
    for (const auto& entry : fromBrep.sharedFaces) shared += entry.second;
    CHECK(shared == 16 + 8);

    // Gmsh's OpenCASCADE kernel reads the STEP file (-0: the model as read, written back as
    // BREP; the bundled twill's test meshes its STEP file).
    checkGmshReads(dir, step, "-0", (dir / "gmsh.brep").string());
    fs::remove_all(dir);
}

TEST_CASE("trimmed B-rep of a ring-shaped overlap: the island is a face of both tows, the ring shared", "[brep][nested]")
{
    // A round tube over a dented one: an outer loop with an island loop inside it (test_resolve_scans).
    testing::Sampling along, across;
    along.sections = 41;
    along.points = 64;
    across.sections = 161;
    across.points = 64;
    const std::vector<TowSurface> tows = {TowSurface::fit(testing::tubeAlongX(0.5, 4.0, 0.0, 0.0, 0.0, along, "x")),
                                          TowSurface::fit(testing::dentedTubeAlongY(0.4, 0.82, 0.15, 0.12, across, "y"))};
    const ResolveResult r = resolveTextile(tows);
    REQUIRE(r.mesh.regions.size() == 1);
    REQUIRE(r.mesh.regions[0].holes.size() == 1);
    const TrimmedBrep brep = trimmedBrep(tows, r);
    const fs::path dir = freshDirectory("towgeom_brep_ring");
    const std::string file = (dir / "ring.brep").string(), whole = (dir / "whole.brep").string();
    brep.writeBrep(file);
    writeUntrimmed(tows, whole);
    const double overlap = testing::commonVolume(whole, 0, 1);
    const testing::ReadShapes back = testing::readBrep(file);
    REQUIRE(back.solids.size() == 2);
    for (std::size_t t = 0; t < 2; ++t) {
        const BrepSolid& s = brep.solids()[t];
        const double exact = tows[t].volume() - (t == 1 ? overlap : 0.0);
        INFO(s.name << ": volume " << s.volume << ", read back " << back.solids[t].volume << ", exact " << exact << ", overlap "
                    << overlap << ", faces " << s.faces);
        CHECK(s.valid);
        CHECK(back.solids[t].valid);
        CHECK(relative(s.volume, exact) <= 1e-6);
        CHECK(relative(back.solids[t].volume, exact) <= 1e-6);
        CHECK(s.faces == 5);  // the tube with a hole, the ring (shared), the island, two caps
        CHECK(s.loops == 2);
    }
    REQUIRE(back.sharedFaces.size() == 1);
    CHECK(back.sharedFaces[0].second == 1);
    fs::remove_all(dir);
}

TEST_CASE("trimmed B-rep: what is not built yet is refused, naming it", "[brep]")
{
    const std::vector<TowSurface> tows = testing::bundledTwill(TOWGEOM_EXAMPLE_DATA);
    ResolveOptions o;
    o.method = ResolutionMethod::Symmetric;
    const ResolveResult symmetric = resolveTextile(tows, o);
    try {
        trimmedBrep(tows, symmetric);
        FAIL("no error");
    } catch (const Error& e) {
        CHECK(e.code() == ErrorCode::Unsupported);
        CHECK(std::string(e.what()).find("connect") != std::string::npos);
    }
    const std::vector<TowSurface> fewer(tows.begin(), tows.begin() + 3);
    CHECK_THROWS_AS(trimmedBrep(fewer, symmetric), Error);
}

TEST_CASE("trimmed B-rep where three tows meet at a point: each tow minus the tows ranked above it, faces shared",
          "[brep][triple]")
{
    // The loops of the three pairs cross each other at two triple points: their faces are not
    // bounded by whole loops, and the solids come from OpenCASCADE's general fuse of the whole
    // tows, each split given to the highest-ranked tow it lies in.
    const std::vector<TowSurface> tows = testing::fitAll(testing::threeTowsAtAPoint(0.3, 0.41));
    const fs::path dir = freshDirectory("towgeom_brep_triple");
    const std::string wholeFile = (dir / "whole.brep").string();
    for (const bool wFirst : {false, true}) {
        INFO((wFirst ? "w ranked first" : "in input order"));
        ResolveOptions o;
        if (wFirst) o.primaryPatterns = {"w"};
        const ResolveResult r = resolveTextile(tows, o);
        REQUIRE(r.mesh.triplePoints.size() == 2);
        REQUIRE(r.unresolved.empty());
        const TrimmedBrep brep = trimmedBrep(tows, r);
        CHECK(brep.fusedBecause().find("three tows meet") != std::string::npos);
        const std::string file = (dir / "three.brep").string();
        brep.writeBrep(file);
        if (!wFirst) writeUntrimmed(tows, wholeFile);
        const testing::ReadShapes back = testing::readBrep(file);
        REQUIRE(back.solids.size() == 3);
        // The highest-ranked tow keeps its whole volume; the second loses its overlap with it
        // (OCCT's boolean of the untrimmed tows); every tow its mesh's volume within 0.5 %.
        const std::size_t top = wFirst ? 2 : 0, second = wFirst ? 0 : 1;
        CHECK(relative(brep.solids()[top].volume, tows[top].volume()) <= 1e-9);
        CHECK(relative(brep.solids()[second].volume, tows[second].volume() - testing::commonVolume(wholeFile, second, top)) <= 1e-6);
        double kept = 0.0;
        for (std::size_t t = 0; t < 3; ++t) {
            const BrepSolid& s = brep.solids()[t];
            INFO(s.name << ": volume " << s.volume << ", read back " << back.solids[t].volume << ", mesh " << r.tows[t].volumeAfter
                        << ", faces " << s.faces << ", shared " << s.sharedFaces);
            CHECK(s.valid);
            CHECK(back.solids[t].valid);
            CHECK(relative(back.solids[t].volume, s.volume) <= 1e-6);
            CHECK(relative(s.volume, r.tows[t].volumeAfter) <= 5e-3);
            CHECK(s.sharedFaces >= 2);  // with each of the two others
            CHECK(relative(testing::readBrepArea(file, t), s.area) <= 1e-6);
            kept += s.volume;
        }
        // Each pair shares a face, the same face in both solids.
        std::set<std::pair<std::size_t, std::size_t>> pairs;
        for (const auto& [pair, count] : back.sharedFaces) pairs.insert(pair);
        CHECK(pairs == std::set<std::pair<std::size_t, std::size_t>>{{0, 1}, {0, 2}, {1, 2}});
        CHECK(brep.sharedFaceCount() >= 3);
        // Nothing counted twice or lost: the three solids fill the tows' union (OCCT's fuse of the
        // untrimmed tows: the same whichever ranks first).
        CHECK(relative(kept, testing::unionVolume(wholeFile)) <= 1e-6);
    }
    fs::remove_all(dir);
}

TEST_CASE("trimmed B-rep of a tow crossed by two others, above and below: two loops on it, apart, each face shared",
          "[brep]")
{
    // x (r 0.5 along x) ranked first; y1 and y2 (r 0.3 along y at x = 2) cross it at its top
    // (axis z = 0.45) and its bottom (z = -0.45), 0.3 apart: two loops on x whose (u,v) boxes do
    // not overlap, each region a face shared by x and one y.
    const std::vector<TowSurface> tows = testing::fitAll(
        {testing::tubeAlongX(0.5, 4.0, 0.0, 0.0, 0.0), testing::tubeAlongY(0.3, 0.45, {}, "y1"), testing::tubeAlongY(0.3, -0.45, {}, "y2")});
    const ResolveResult r = resolveTextile(tows);
    REQUIRE(r.unresolved.empty());
    REQUIRE(r.mesh.regions.size() == 2);
    const TrimmedBrep brep = trimmedBrep(tows, r);
    const fs::path dir = freshDirectory("towgeom_brep_two_loops");
    const std::string file = (dir / "two.brep").string(), wholeFile = (dir / "whole.brep").string();
    brep.writeBrep(file);
    writeUntrimmed(tows, wholeFile);
    const testing::ReadShapes back = testing::readBrep(file);
    REQUIRE(back.solids.size() == 3);
    for (std::size_t t = 0; t < 3; ++t) {
        INFO(tows[t].name() << ": volume " << brep.solids()[t].volume);
        CHECK(brep.solids()[t].valid);
        CHECK(back.solids[t].valid);
        // x keeps its whole volume; each y its own less its overlap with x (OCCT's common of the
        // untrimmed reference solids).
        const double expected = t == 0 ? tows[0].volume() : tows[t].volume() - testing::commonVolume(wholeFile, t, 0);
        CHECK(relative(brep.solids()[t].volume, expected) <= 1e-6);
        CHECK(relative(back.solids[t].volume, expected) <= 1e-6);
    }
    std::set<std::pair<std::size_t, std::size_t>> pairs;
    for (const auto& [pair, count] : back.sharedFaces) pairs.insert(pair);
    CHECK(pairs == std::set<std::pair<std::size_t, std::size_t>>{{0, 1}, {0, 2}});
    CHECK(relative(back.solids[0].volume + back.solids[1].volume + back.solids[2].volume, testing::unionVolume(wholeFile)) <= 1e-6);
    fs::remove_all(dir);
}

TEST_CASE("trimmed B-rep of a tow through another or ending inside it: cut into pieces, its cap given way", "[brep][through]")
{
    for (const bool endsInside : {false, true}) {
        INFO((endsInside ? "thin ends inside outer" : "thin passes through outer"));
        const std::vector<TowSurface> tows = testing::fitAll(testing::thinThrough(endsInside));
        const ResolveResult r = resolveTextile(tows);  // outer (given first) above thin
        REQUIRE(r.unresolved.empty());
        const TrimmedBrep brep = trimmedBrep(tows, r);
        const fs::path dir = freshDirectory("towgeom_brep_through");
        const std::string file = (dir / "through.brep").string(), wholeFile = (dir / "whole.brep").string();
        brep.writeBrep(file);
        writeUntrimmed(tows, wholeFile);
        const testing::ReadShapes back = testing::readBrep(file);
        // thin through outer leaves two pieces, one on each side; ending inside, one.
        REQUIRE(back.solids.size() == (endsInside ? 2u : 3u));
        const BrepSolid &outer = brep.solids()[0], &thin = brep.solids()[1];
        CHECK(outer.valid);
        CHECK(thin.valid);
        CHECK(relative(outer.volume, tows[0].volume()) <= 1e-9);
        CHECK(relative(thin.volume, tows[1].volume() - testing::commonVolume(wholeFile, 1, 0)) <= 1e-6);
        CHECK(relative(thin.volume, r.tows[1].volumeAfter) <= 5e-3);
        double thinBack = 0.0;
        for (std::size_t k = 1; k < back.solids.size(); ++k) {
            CHECK(back.solids[k].valid);
            CHECK(back.solids[k].volume > 0.0);
            thinBack += back.solids[k].volume;
        }
        CHECK(relative(back.solids[0].volume, outer.volume) <= 1e-6);
        CHECK(relative(thinBack, thin.volume) <= 1e-6);
        // Each piece of thin shares with outer the part of outer's surface it gave way to.
        for (std::size_t k = 1; k < back.solids.size(); ++k) {
            const bool shares = std::any_of(back.sharedFaces.begin(), back.sharedFaces.end(),
                                            [&](const auto& s) { return s.first == std::make_pair(std::size_t{0}, k); });
            CHECK(shares);
        }
        fs::remove_all(dir);
    }
}

TEST_CASE("trimmed B-rep where three tows meet inside a cell: clipped by the box, the matrix around them", "[brep][triple][cell]")
{
    const std::vector<TowSurface> tows = testing::fitAll(testing::threeTowsAtAPoint(0.3, 0.41));
    // A box that cuts x and y at both ends (w ends inside), and one around all three: the matrix
    // is then the box with a cavity, the tows' union (an inner shell of the same solid).
    for (const bool around : {false, true}) {
        INFO((around ? "the box around the tows" : "the box cutting x and y"));
        ResolveOptions o;
        Cell cell;
        cell.min = around ? Point3{-3.0, -4.0, -3.0} : Point3{0.3, -1.3, -0.7};
        cell.max = around ? Point3{7.0, 4.0, 4.0} : Point3{3.3, 1.7, 1.4};
        o.cell = cell;
        const ResolveResult r = resolveTextile(tows, o);
        REQUIRE(r.mesh.triplePoints.size() == 2);
        const TrimmedBrep brep = trimmedBrep(tows, r);
        const fs::path dir = freshDirectory("towgeom_brep_triple_cell");
        const std::string file = (dir / "cell.brep").string();
        brep.writeBrep(file);
        const testing::ReadShapes back = testing::readBrep(file);
        const BrepSolid& matrix = brep.matrix();
        INFO(brep.matrixNote());
        REQUIRE(matrix.faces > 0);
        REQUIRE(back.solids.size() == 4);  // each tow one solid, the matrix one
        double total = 0.0;  // read back: the tows' and the matrix's solids fill the box
        for (const testing::ReadSolid& s : back.solids) {
            CHECK(s.valid);
            CHECK(s.volume > 0.0);  // an inside-out solid would still add up
            total += s.volume;
        }
        CHECK(relative(total, cell.volume()) <= 1e-6);
        CHECK(relative(back.solids.back().volume, matrix.volume) <= 1e-6);
        CHECK(relative(testing::readBrepArea(file, back.solids.size() - 1), matrix.area) <= 1e-6);
        for (std::size_t t = 0; t < 3; ++t) {
            const BrepSolid& s = brep.solids()[t];
            INFO(s.name << ": volume " << s.volume << ", mesh " << r.tows[t].volumeAfter << ", cut faces " << s.cellFaces);
            CHECK(s.valid);
            CHECK(s.cellFaces == (t < 2 && !around ? 2u : 0u));
            CHECK(relative(s.volume, r.tows[t].volumeAfter) <= 5e-3);
            CHECK(relative(back.solids[t].volume, s.volume) <= 1e-6);
        }
        fs::remove_all(dir);
    }
}

TEST_CASE("trimmed B-rep of pressed layers: loops nested three deep, built by the general fuse", "[brep][scan]")
{
    // A warp and a weft of a pressed 3D orthogonal weave whose flat faces touch with no gap: the
    // fitted surfaces cross a little over the contact, in shallow loops inside loops inside loops.
    std::vector<TowStack> pair;
    for (const TowStack& s : testing::pressedOrthogonal(2, 2, 0.0))
        if (s.name == "warp_L0_0" || s.name == "weft_L0_0") pair.push_back(s);
    REQUIRE(pair.size() == 2);
    const std::vector<TowSurface> tows = testing::fitAll(pair);
    const ResolveResult r = resolveTextile(tows);
    REQUIRE(r.unresolved.empty());
    REQUIRE(r.intersections.loops.size() >= 3);
    const TrimmedBrep brep = trimmedBrep(tows, r);
    CHECK(brep.fusedBecause().find("more than two deep") != std::string::npos);
    const fs::path dir = freshDirectory("towgeom_brep_pressed");
    const std::string file = (dir / "pressed.brep").string(), wholeFile = (dir / "whole.brep").string();
    brep.writeBrep(file);
    writeUntrimmed(tows, wholeFile);
    const testing::ReadShapes back = testing::readBrep(file);
    REQUIRE(back.solids.size() == 2);
    // The warp (given first) keeps its volume; the weft loses the shallow overlap (OCCT's boolean
    // of the untrimmed tows, built independently).
    const double overlap = testing::commonVolume(wholeFile, 1, 0);
    const double exact[2] = {tows[0].volume(), tows[1].volume() - overlap};
    for (std::size_t t = 0; t < 2; ++t) {
        const BrepSolid& s = brep.solids()[t];
        INFO(s.name << ": volume " << s.volume << ", exact " << exact[t] << ", read back " << back.solids[t].volume << ", mesh "
                    << r.tows[t].volumeAfter << ", faces " << s.faces << ", overlap " << overlap);
        CHECK(s.valid);
        CHECK(back.solids[t].valid);
        if (t == 0) {
            CHECK(relative(s.volume, exact[t]) <= 1e-6);
        } else {
            // The overlap is a sliver 2.6e-5 of the volume between nearly tangent surfaces, whose
            // OCCT booleans disagree: the solid read back (its own faces) is the tow less the
            // independent boolean's overlap within 10 % of that overlap (measured 2.9 %: 1.4e-6 of
            // the volume); the volume trimmedBrep() reports (the tow's exact volume less the fuse's
            // lost split, measured on the split) within 30 % of it (measured 17 %: 8.6e-6 of the
            // volume; against solids from trimmedBrep() itself this was 0). A weft that kept its
            // overlap would be off by all of it.
            CHECK(std::abs(back.solids[t].volume - exact[t]) <= 0.1 * overlap);
            CHECK(std::abs(s.volume - exact[t]) <= 0.3 * overlap);
        }
        // Read back, the solid's own integral: OpenCASCADE's curves where the surfaces are nearly
        // tangent carry a tolerance (5e-6 here), and a gap that wide between faces moves the
        // integral by up to the tolerance times the area (measured: 3.7e-6 for the weft, 7e-6
        // of its volume; the loop path's twill, 1e-6).
        CHECK(std::abs(back.solids[t].volume - s.volume) <= s.maxTolerance * s.area);
        CHECK(relative(s.volume, r.tows[t].volumeAfter) <= 5e-3);
        CHECK(s.sharedFaces >= 1);
    }
    CHECK(exact[1] < tows[1].volume());  // the overlap is real, if shallow
    REQUIRE(!back.sharedFaces.empty());
    fs::remove_all(dir);
}
