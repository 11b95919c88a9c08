// detail::fuseByRank() on OpenCASCADE's box primitives, whose volumes are known: splits given to
// the tow ranked above, a tow with a cavity (one ranked above lies wholly inside it), the matrix
// cut in two by a tow, one piece with a cavity (the classifier picks the piece that holds it).
#include <catch2/catch.hpp>

#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <GProp_GProps.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>
#include <vector>

#include "brep/rank_fuse.hpp"

using namespace towgeom;

namespace {

TopoDS_Solid box(double x0, double y0, double z0, double x1, double y1, double z1)
{
    return TopoDS::Solid(BRepPrimAPI_MakeBox(gp_Pnt(x0, y0, z0), gp_Pnt(x1, y1, z1)).Solid());
}

double volumeOf(const TopoDS_Shape& s)
{
    GProp_GProps v;
    BRepGProp::VolumeProperties(s, v, 1e-9);
    return v.Mass();
}

double areaOf(const TopoDS_Shape& s)
{
    GProp_GProps a;
    BRepGProp::SurfaceProperties(s, a, 1e-9);
    return a.Mass();
}

/// Tow a ranks above tow b when a is given first.
bool inputOrder(std::size_t a, std::size_t b) { return a < b; }

}  // namespace

TEST_CASE("fuseByRank: a tow wholly inside a tow ranked below makes a cavity in it", "[brep][fuse]")
{
    // "inner" (1 x 1 x 1, given first) inside "outer" (4 x 2 x 2): outer keeps 16 - 1 with a cavity.
    const std::vector<TopoDS_Solid> whole = {box(1, 0.5, 0.5, 2, 1.5, 1.5), box(0, 0, 0, 4, 2, 2)};
    const std::vector<double> area = {areaOf(whole[0]), areaOf(whole[1])};
    const detail::RankFusion f = detail::fuseByRank(whole, area, inputOrder, std::nullopt, {"inner", "outer"});
    REQUIRE(f.tows[0].solids.size() == 1);
    REQUIRE(f.tows[1].solids.size() == 1);  // one solid, its outer shell and the cavity
    const TopoDS_Solid& outer = f.tows[1].solids[0];
    CHECK(BRepCheck_Analyzer(outer).IsValid());
    CHECK(std::abs(volumeOf(outer) - 15.0) <= 1e-9);
    CHECK(std::abs(f.tows[1].lostVolume - 1.0) <= 1e-9);
    CHECK(std::abs(f.tows[0].lostVolume) <= 1e-12);
    CHECK(std::abs(f.tows[1].area - (40.0 + 6.0)) <= 1e-9);  // its boundary and the cavity's
    CHECK(f.tows[1].sharedFaces == 6);  // the cavity's faces are inner's
    CHECK(f.sharedFaces == 6);
}

TEST_CASE("fuseByRank: the matrix cut in two by a tow, a tow inside one piece", "[brep][fuse]")
{
    // The cell 10 x 2 x 2; "slab" fills x 4..6 across it (and beyond), "small" floats in x 1..2:
    // the matrix is the left piece (4 x 2 x 2 less small) with a cavity, and the right one.
    const Cell cell{{0, 0, 0}, {10, 2, 2}};
    const std::vector<TopoDS_Solid> whole = {box(4, -1, -1, 6, 3, 3), box(1, 0.5, 0.5, 2, 1.5, 1.5)};
    const std::vector<double> area = {areaOf(whole[0]), areaOf(whole[1])};
    const detail::RankFusion f = detail::fuseByRank(whole, area, inputOrder, cell, {"slab", "small"});
    REQUIRE(f.tows[0].solids.size() == 1);
    CHECK(std::abs(volumeOf(f.tows[0].solids[0]) - 8.0) <= 1e-9);  // the slab inside the box
    CHECK(std::abs(f.tows[0].lostVolume - (32.0 - 8.0)) <= 1e-9);  // cut off outside
    CHECK(f.tows[0].cellFaces == 4);
    REQUIRE(f.matrix.solids.size() == 2);
    std::vector<double> pieces;
    for (const TopoDS_Solid& s : f.matrix.solids) {
        CHECK(BRepCheck_Analyzer(s).IsValid());
        pieces.push_back(volumeOf(s));
    }
    std::sort(pieces.begin(), pieces.end());
    CHECK(std::abs(pieces[0] - 15.0) <= 1e-9);  // left: 16 less the small tow's cavity
    CHECK(std::abs(pieces[1] - 16.0) <= 1e-9);  // right
}
