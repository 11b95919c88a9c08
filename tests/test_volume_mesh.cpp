// meshVolumes(): tetrahedra inside the resolved twill's tows, checked independently of Gmsh's
// own bookkeeping: every face of a tetrahedron is shared by exactly two tetrahedra, or lies on
// a surface triangle (one tetrahedron of each tow that triangle bounds: two on a shared region,
// of the two tows); per tow the tetrahedra fill its closed surface's volume; none is inverted.
#include <catch2/catch.hpp>

#include <towgeom/towgeom.hpp>

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "synthetic_tows.hpp"

using namespace towgeom;

namespace {

std::vector<TowSurface> twill(const std::vector<std::string>& names)
{
    std::vector<TowSurface> tows;
    for (const std::string& n : names) tows.push_back(TowSurface::fit(readStackFile(std::string(TOWGEOM_EXAMPLE_DATA) + "/twill/" + n + ".stw")));
    return tows;
}

using Face = std::array<std::size_t, 3>;

Face sorted(std::size_t a, std::size_t b, std::size_t c)
{
    Face f{a, b, c};
    std::sort(f.begin(), f.end());
    return f;
}

}  // namespace

namespace {

/// The independent checks of a volume mesh @p v of @p res: no flat or inverted tetrahedron, each
/// tow's tetrahedra fill its closed surface's volume, every interior face shared by two
/// tetrahedra of one tow, every surface triangle a face of one tetrahedron of each tow it bounds.
void checkConforming(const ResolveResult& res, const VolumeMesh& v)
{
    REQUIRE(v.surfaceNodes == res.mesh.nodes.size());
    REQUIRE(v.tetrahedra.size() == v.tow.size());
    for (std::size_t n = 0; n < v.surfaceNodes; ++n) REQUIRE(distance(v.nodes[n], res.mesh.nodes[n]) == 0.0);
    std::size_t flat = 0;
    for (std::size_t k = 0; k < v.tetrahedra.size(); ++k) {
        const auto& t = v.tetrahedra[k];
        double longest = 0.0;
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j) longest = std::max(longest, distance(v.nodes[t[i]], v.nodes[t[j]]));
        flat += !(v.tetrahedronVolume(k) > 1e-9 * longest * longest * longest);
    }
    CHECK(flat == 0);
    for (std::size_t t = 0; t < res.mesh.tows.size(); ++t) {
        INFO("tow " << res.mesh.tows[t].name);
        CHECK(v.towVolume(t) == Approx(res.tows[t].volumeAfter).epsilon(1e-9));
    }
    std::map<Face, std::vector<std::size_t>> surfaceTows;  // face -> tows it bounds
    for (std::size_t t = 0; t < res.mesh.tows.size(); ++t)
        for (const auto& tri : res.mesh.tows[t].triangles) surfaceTows[sorted(tri[0], tri[1], tri[2])].push_back(t);
    std::map<Face, std::vector<std::size_t>> faceTets;  // face -> tows of the tetrahedra on it
    for (std::size_t k = 0; k < v.tetrahedra.size(); ++k) {
        const auto& t = v.tetrahedra[k];
        for (const Face& f : {sorted(t[0], t[1], t[2]), sorted(t[0], t[1], t[3]), sorted(t[0], t[2], t[3]), sorted(t[1], t[2], t[3])})
            faceTets[f].push_back(v.tow[k]);
    }
    std::size_t interiorNotTwo = 0, interiorAcrossTows = 0, surfaceWrong = 0, surfaceMissing = 0, onInterface = 0;
    for (const auto& [f, tows] : faceTets) {
        const auto s = surfaceTows.find(f);
        if (s == surfaceTows.end()) {
            interiorNotTwo += tows.size() != 2;
            interiorAcrossTows += tows.size() == 2 && tows[0] != tows[1];
        } else {
            std::vector<std::size_t> a = tows, b = s->second;
            std::sort(a.begin(), a.end());
            std::sort(b.begin(), b.end());
            surfaceWrong += a != b;
            onInterface += b.size() == 2;
        }
    }
    for (const auto& [f, tows] : surfaceTows) surfaceMissing += faceTets.count(f) == 0;
    CHECK(interiorNotTwo == 0);
    CHECK(interiorAcrossTows == 0);
    CHECK(surfaceWrong == 0);
    CHECK(surfaceMissing == 0);
    std::size_t shared = 0;
    for (const ConnectedRegion& g : res.mesh.regions) shared += g.triangles.size();
    CHECK(onInterface == shared);  // each region triangle: a tetrahedron of each of its two tows
    WARN(v.tetrahedra.size() << " tetrahedra, " << v.nodes.size() - v.surfaceNodes << " inner nodes, " << shared
                             << " interface triangles");
}

}  // namespace

TEST_CASE("meshVolumes: conforming tetrahedra fill each resolved tow of the twill", "[volume]")
{
    ResolveOptions o;
    o.mesh.edgeLength = 0.12;
    const ResolveResult res = resolveTextile(twill({"warp_0", "warp_1", "weft_0", "weft_1"}), o);
    REQUIRE(res.mesh.regions.size() == 4);
    checkConforming(res, meshVolumes(res.mesh));
    // A further call in the process (Gmsh stays started), on one thread: as good.
    VolumeMeshOptions one;
    one.threads = 1;
    checkConforming(res, meshVolumes(res.mesh, one));
}

TEST_CASE("meshVolumes: a tow cut in two by a tow ranked above it gets a volume per piece", "[volume]")
{
    // A thin tube through a thick one, the thick ranked first: the thin one becomes two pieces.
    testing::Sampling s;
    s.sections = 41;
    s.points = 32;
    const std::vector<TowSurface> tows{TowSurface::fit(testing::tubeAlongX(0.5, 4.0, 0.0, 0.0, 0.0, s, "outer")),
                                       TowSurface::fit(testing::tubeAlongY(0.1, 0.0, s, "thin"))};
    ResolveOptions o;
    o.mesh.edgeLength = 0.08;
    const ResolveResult res = resolveTextile(tows, o);
    REQUIRE(res.tows[1].pieces == 2);
    VolumeMesh v = meshVolumes(res.mesh);
    checkConforming(res, v);
    // Straight tubes: every tetrahedron's fibre direction is its tube's axis (up to the fit's
    // error), along increasing u.
    addFibreDirections(v, tows);
    REQUIRE(v.fibreDirection.size() == v.tetrahedra.size());
    double offAxis = 0.0;
    for (std::size_t k = 0; k < v.tetrahedra.size(); ++k) {
        const Vector3 axis = v.tow[k] == 0 ? Vector3{1, 0, 0} : Vector3{0, 1, 0};
        offAxis = std::max(offAxis, norm(v.fibreDirection[k] - axis));
    }
    WARN("fibre directions: largest distance from the tube's axis " << offAxis);
    CHECK(offAxis < 1e-6);
    std::vector<TowSurface> one{tows[0]};
    CHECK_THROWS_AS(addFibreDirections(v, one), Error);  // tetrahedra of tow 1, one tow given
}

TEST_CASE("meshVolumes refuses a triangle given twice or turned over before Gmsh sees it", "[volume]")
{
    ResolveOptions o;
    o.mesh.edgeLength = 0.2;
    ResolveResult res = resolveTextile(twill({"warp_0", "weft_0"}), o);
    REQUIRE(res.mesh.regions.size() == 1);
    TextileMesh twice = res.mesh;
    twice.regions.push_back(twice.regions.front());  // its triangles in two regions
    try {
        meshVolumes(twice);
        FAIL("no error");
    } catch (const Error& e) {
        CHECK(e.code() == ErrorCode::InvalidArgument);
        CHECK(e.message().find("region 2") != std::string::npos);  // its triangles are region 1's
    }
    TextileMesh flipped = res.mesh;
    std::swap(flipped.tows[1].triangles.front()[0], flipped.tows[1].triangles.front()[1]);  // one triangle turned over
    try {
        meshVolumes(flipped);
        FAIL("no error");
    } catch (const Error& e) {
        CHECK(e.code() == ErrorCode::InvalidArgument);
        CHECK(e.message().find("tow 'weft_0'") != std::string::npos);
        CHECK(e.message().find("inconsistent orientation") != std::string::npos);
    }
    TextileMesh doubled = res.mesh;
    doubled.tows[0].triangles.push_back(doubled.tows[0].triangles.front());
    doubled.tows[0].region.push_back(doubled.tows[0].region.front());
    doubled.tows[0].face.push_back(doubled.tows[0].face.front());
    try {
        meshVolumes(doubled);
        FAIL("no error");
    } catch (const Error& e) {
        CHECK(e.code() == ErrorCode::InvalidArgument);
        CHECK(e.message().find("tow 'warp_0'") != std::string::npos);
    }
}

TEST_CASE("meshVolumes refuses tows that are not closed", "[volume]")
{
    ResolveOptions o;
    o.mesh.edgeLength = 0.2;
    o.mesh.caps = false;
    const ResolveResult res = resolveTextile(twill({"warp_0", "weft_0"}), o);
    try {
        meshVolumes(res.mesh);
        FAIL("no error");
    } catch (const Error& e) {
        CHECK(e.code() == ErrorCode::InvalidArgument);
        CHECK(e.message().find("tow 'warp_0': its surface mesh is not closed") != std::string::npos);
    }
}
