// MeshPieces (region/mesh_pieces.hpp): a loop's inside decided per piece of the mesh its chords
// cut it into, on a grid whose inside is known from the coordinates.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <vector>

#include "region/mesh_pieces.hpp"

using namespace towgeom::detail;

namespace {

constexpr std::size_t kN = 10;  // nodes per side

std::size_t node(std::size_t i, std::size_t j) { return i * kN + j; }

/// A 9 x 9 grid of squares, two triangles each; triangle 2 (i (kN - 1) + j) + {0, 1} in square (i, j).
std::vector<std::array<std::size_t, 3>> grid()
{
    std::vector<std::array<std::size_t, 3>> t;
    for (std::size_t i = 0; i + 1 < kN; ++i)
        for (std::size_t j = 0; j + 1 < kN; ++j) {
            t.push_back({node(i, j), node(i + 1, j), node(i + 1, j + 1)});
            t.push_back({node(i, j), node(i + 1, j + 1), node(i, j + 1)});
        }
    return t;
}

/// The square ring of nodes from (2, 2) to (6, 6), in order, and the triangles inside it.
std::vector<std::size_t> ring()
{
    std::vector<std::size_t> r;
    for (std::size_t j = 2; j < 6; ++j) r.push_back(node(2, j));
    for (std::size_t i = 2; i < 6; ++i) r.push_back(node(i, 6));
    for (std::size_t j = 6; j > 2; --j) r.push_back(node(6, j));
    for (std::size_t i = 6; i > 2; --i) r.push_back(node(i, 2));
    return r;
}

std::vector<std::size_t> insideRing()
{
    std::vector<std::size_t> in;
    for (std::size_t i = 2; i < 6; ++i)
        for (std::size_t j = 2; j < 6; ++j) {
            in.push_back(2 * (i * (kN - 1) + j));
            in.push_back(2 * (i * (kN - 1) + j) + 1);
        }
    std::sort(in.begin(), in.end());
    return in;
}

}  // namespace

TEST_CASE("MeshPieces: a piece's triangles follow its majority, an open or mixed loop keeps each triangle's own test",
          "[region][pieces]")
{
    const std::vector<std::array<std::size_t, 3>> triangles = grid();
    const MeshPieces pieces(triangles);
    const std::vector<bool> all(triangles.size(), true);
    const std::vector<std::size_t> exact = insideRing();
    REQUIRE(exact.size() == 32);
    // Two inside triangles missed, one outside triangle (square (0, 0)) taken: the pieces put
    // them right.
    std::vector<std::size_t> own(exact.begin() + 2, exact.end());
    own.push_back(0);
    std::sort(own.begin(), own.end());
    CHECK(pieces.inside(ring(), own, all) == exact);
    CHECK(pieces.inside(ring(), exact, all) == exact);
    // 8 of the 32 inside claimed (25 %): no majority either way, the own tests stand; 2 of 32
    // (6 %): the piece is outside.
    const std::vector<std::size_t> quarter(exact.begin(), exact.begin() + 8), two(exact.begin(), exact.begin() + 2);
    CHECK(pieces.inside(ring(), quarter, all) == quarter);
    CHECK(pieces.inside(ring(), two, all).empty());
    // A chord that is no edge of the mesh (the ring with one node left out: its neighbours are
    // not joined): the chords do not cut the mesh, each triangle's own test stands.
    std::vector<std::size_t> gap = ring();
    gap.erase(gap.begin() + 1);
    CHECK(pieces.inside(gap, own, all) == own);
    // Triangles without a test (as a cap's) neither vote nor come out: with half the inside
    // untested, the two missed ones (untested too) stay out, the rest is decided by the others.
    std::vector<bool> someTested = all;
    for (std::size_t k = 0; k < 16; ++k) someTested[exact[k]] = false;
    const std::vector<std::size_t> testedInside(exact.begin() + 16, exact.end());
    CHECK(pieces.inside(ring(), own, someTested) == testedInside);
}

TEST_CASE("MeshPieces: a loop that cuts nothing off (the same piece on both sides of a chord) keeps each triangle's own test",
          "[region][pieces]")
{
    // Two grids side by side, not joined: a ring in the first leaves the second a piece of its
    // own, but a ring whose chords run where the mesh has no edge cuts nothing.
    std::vector<std::array<std::size_t, 3>> triangles = grid();
    const std::size_t first = triangles.size();
    for (const auto& t : grid()) triangles.push_back({t[0] + kN * kN, t[1] + kN * kN, t[2] + kN * kN});
    const MeshPieces pieces(triangles);
    const std::vector<bool> all(triangles.size(), true);
    const std::vector<std::size_t> exact = insideRing();
    std::vector<std::size_t> own(exact.begin() + 2, exact.end());
    CHECK(pieces.inside(ring(), own, all) == exact);
    // A loop along the second grid's diagonal and back (a slit): its chords are edges with the
    // same piece on both sides.
    const std::vector<std::size_t> diagonal{node(1, 1) + kN * kN, node(2, 2) + kN * kN, node(3, 3) + kN * kN, node(2, 2) + kN * kN};
    const std::vector<std::size_t> some{first + 5, first + 7};
    CHECK(pieces.inside(diagonal, some, all) == some);
}
