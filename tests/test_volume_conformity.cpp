// The check of every volume mesh (issue 39): tetrahedra conforming to each other and to the
// surfaces, filling their volumes. Two tetrahedra on one triangle, the double pyramid of a
// triangle (0,0,0), (1,0,0), (0,1,0) with apexes at z = 1 and z = -1 (volume 1/6 + 1/6), and the
// ways a mesher's output can break it.
#include <catch2/catch.hpp>

#include <string>

#include "towgeom/error.hpp"
#include "volume/volume_conformity.hpp"

using namespace towgeom;

namespace {

/// Nodes A, B, C of the shared triangle, D above, E below, and F, a copy of C at its point.
VolumeMesh doublePyramid()
{
    VolumeMesh m;
    m.nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.2, 0.2, 1}, {0.2, 0.2, -1}, {0, 1, 0}};
    m.surfaceNodes = 5;
    m.tetrahedra = {{0, 1, 2, 3}, {0, 2, 1, 4}};
    m.tow = {0, 0};
    return m;
}

/// Its outside (6 triangles, outward), one tow of volume 1/3, with C in the lower half given as
/// @p c.
detail::ConformityTarget outside(std::size_t c = 2)
{
    detail::ConformityTarget t;
    t.outer = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {c, 1, 4}, {0, 4, 1}, {0, c, 4}};
    t.volume = {1.0 / 3.0};
    t.name = {"tow 'a'"};
    return t;
}

std::string refusal(const VolumeMesh& m, const detail::ConformityTarget& t)
{
    try {
        detail::checkConformity(m, t);
    } catch (const Error& e) {
        CHECK(e.code() == ErrorCode::Internal);
        return e.message();
    }
    return "";
}

}  // namespace

TEST_CASE("a conforming volume mesh passes the check", "[volume][conformity]")
{
    CHECK(refusal(doublePyramid(), outside()).empty());
    // The same two tetrahedra as two tows: the shared triangle lies between them.
    VolumeMesh m = doublePyramid();
    m.tow = {0, 1};
    detail::ConformityTarget t = outside();
    t.between = {{0, 1, 2}};
    t.volume = {1.0 / 6.0, 1.0 / 6.0};
    t.name = {"tow 'a'", "tow 'b'"};
    CHECK(refusal(m, t).empty());
}

TEST_CASE("a crack, a face of three tetrahedra, a missing side or volume: refused, naming the place", "[volume][conformity]")
{
    SECTION("two nodes at one point: the inner face is on one tetrahedron each side (a crack)")
    {
        VolumeMesh m = doublePyramid();
        m.tetrahedra[1] = {0, 5, 1, 4};
        const std::string why = refusal(m, outside(5));
        CHECK(why.find("an inner face belongs to one tetrahedron only (a crack)") != std::string::npos);
        CHECK(why.find("at (0.333333, 0.333333, 0)") != std::string::npos);
    }
    SECTION("a third tetrahedron on the shared face")
    {
        VolumeMesh m = doublePyramid();
        m.nodes.push_back({0.3, 0.3, 0.5});
        m.tetrahedra.push_back({0, 1, 2, 6});
        m.tow.push_back(0);
        CHECK(refusal(m, outside()).find("a face is shared by 3 tetrahedra") != std::string::npos);
    }
    SECTION("a surface triangle between two volumes with one side only")
    {
        detail::ConformityTarget t = outside();
        t.outer.pop_back();
        t.between = {{0, 2, 4}};
        CHECK(refusal(doublePyramid(), t).find("a surface triangle between two volumes has 1 and 0 tetrahedra on its two sides") !=
              std::string::npos);
    }
    SECTION("an outside triangle facing in: its tetrahedron lies outside it")
    {
        detail::ConformityTarget t = outside();
        t.outer[0] = {1, 3, 2};
        CHECK(refusal(doublePyramid(), t).find("a surface triangle on the outside has 0 tetrahedra inside it and 1 outside") !=
              std::string::npos);
    }
    SECTION("two tetrahedra on the same side of their face: the mesh folds")
    {
        VolumeMesh m = doublePyramid();
        m.nodes.push_back({0.3, 0.3, 0.5});
        m.tetrahedra[1] = {0, 1, 2, 6};  // inside the upper one, not below
        detail::ConformityTarget t = outside();
        t.outer = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {1, 2, 6}, {0, 6, 2}, {0, 1, 6}};
        CHECK(refusal(m, t).find("two tetrahedra lie on the same side of a face (the mesh folds)") != std::string::npos);
    }
    SECTION("tetrahedra that do not fill the tow's volume")
    {
        detail::ConformityTarget t = outside();
        t.volume = {1.0 / 3.0 + 1e-7};
        CHECK(refusal(doublePyramid(), t).find("does not fill tow 'a'") != std::string::npos);
        t.volume = {1.0 / 3.0 + 1e-12};
        CHECK(refusal(doublePyramid(), t).empty());
    }
}
