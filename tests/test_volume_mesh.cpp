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

TEST_CASE("meshVolumes: conforming tetrahedra fill each resolved tow of the twill", "[volume]")
{
    ResolveOptions o;
    o.mesh.edgeLength = 0.12;
    const ResolveResult res = resolveTextile(twill({"warp_0", "warp_1", "weft_0", "weft_1"}), o);
    REQUIRE(res.mesh.regions.size() == 4);
    const VolumeMesh v = meshVolumes(res.mesh);
    REQUIRE(v.surfaceNodes == res.mesh.nodes.size());
    REQUIRE(v.tetrahedra.size() == v.tow.size());
    for (std::size_t n = 0; n < v.surfaceNodes; ++n) REQUIRE(distance(v.nodes[n], res.mesh.nodes[n]) == 0.0);

    // No inverted or flat tetrahedron (relative to the size of its edges).
    std::size_t flat = 0;
    for (std::size_t k = 0; k < v.tetrahedra.size(); ++k) {
        const auto& t = v.tetrahedra[k];
        double longest = 0.0;
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j) longest = std::max(longest, distance(v.nodes[t[i]], v.nodes[t[j]]));
        flat += !(v.tetrahedronVolume(k) > 1e-9 * longest * longest * longest);
    }
    CHECK(flat == 0);

    // Each tow's tetrahedra fill the volume its closed surface bounds.
    for (std::size_t t = 0; t < res.mesh.tows.size(); ++t) {
        INFO("tow " << res.mesh.tows[t].name);
        CHECK(v.towVolume(t) == Approx(res.tows[t].volumeAfter).epsilon(1e-9));
    }

    // Faces: the surface triangles of each tow, and every tetrahedron face.
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
