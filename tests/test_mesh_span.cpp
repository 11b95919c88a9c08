// A tow meshed over part of its length only (MeshSizes::uSpan, what a cell keeps): the mesh
// stops about h beyond the span, covers it, keeps its seam closed, and costs the span's share.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "mesh/parametric_mesher.hpp"
#include "towgeom/tow_surface.hpp"

using namespace towgeom;

namespace {

/// A circular tube of radius 0.5 along x from 0 to 10: 21 sections of 16 points.
TowSurface straightTube()
{
    TowStack stack;
    stack.name = "tube";
    for (int i = 0; i <= 20; ++i) {
        std::vector<Point3>& s = stack.sections.emplace_back();
        for (int j = 0; j < 16; ++j) {
            const double a = 2.0 * 3.14159265358979323846 * j / 16.0;
            s.push_back({0.5 * i, 0.5 * std::cos(a), 0.5 * std::sin(a)});
        }
    }
    return TowSurface::fit(stack);
}

detail::ParametricMesh meshOf(const TowSurface& tow, std::optional<std::array<double, 2>> span)
{
    detail::MeshSizes sizes{0.2, 20.0, {}, span};
    detail::ParametricMesher mesher(tow, sizes);
    detail::MeshRequests requests;
    mesher.mesh({}, {}, requests);
    return mesher.result(0);
}

}  // namespace

TEST_CASE("a tow meshed over a span of its length: the span covered, h beyond it at most, the seam closed", "[mesh][cell]")
{
    const TowSurface tow = straightTube();
    const ParameterRange r = tow.parameterRange();
    const double perX = (r.uMax - r.uMin) / 10.0;  // u per unit of x (chord-length parameters)
    const std::array<double, 2> span{r.uMin + 4.0 * perX, r.uMin + 6.0 * perX};  // x in [4, 6]
    const detail::ParametricMesh whole = meshOf(tow, std::nullopt);
    const detail::ParametricMesh part = meshOf(tow, span);
    double lo = r.uMax, hi = r.uMin;
    for (const UV& p : part.newNodes) {
        lo = std::min(lo, p.u);
        hi = std::max(hi, p.u);
    }
    const double h = 0.2 * perX;
    CHECK(lo <= span[0]);
    CHECK(hi >= span[1]);
    CHECK(lo >= span[0] - 1.5 * h);
    CHECK(hi <= span[1] + 1.5 * h);
    // About the span's share of the triangles (x in [3.8, 6.2] of [0, 10]).
    const double share = static_cast<double>(part.triangles.size()) / static_cast<double>(whole.triangles.size());
    CHECK(share > 0.2);
    CHECK(share < 0.3);
    // A tube open at its two new ends: every edge used twice the opposite way round but the two
    // rims, each a closed row of edges around the tube.
    std::vector<std::pair<std::size_t, std::size_t>> edges, open;
    for (const auto& t : part.triangles)
        for (int k = 0; k < 3; ++k) edges.emplace_back(t[k], t[(k + 1) % 3]);
    std::sort(edges.begin(), edges.end());
    for (const auto& [a, b] : edges)
        if (!std::binary_search(edges.begin(), edges.end(), std::make_pair(b, a))) open.emplace_back(a, b);
    CHECK(std::adjacent_find(edges.begin(), edges.end()) == edges.end());
    std::size_t atStart = 0, atEnd = 0;
    for (const auto& [a, b] : open) {
        const double u = part.newNodes[a].u;
        (std::abs(u - lo) < 1e-12 ? atStart : atEnd) += std::abs(part.newNodes[b].u - u) < 1e-12 ? 1 : 0;
    }
    CHECK(atStart + atEnd == open.size());  // every open edge runs along a rim (constant u)
    CHECK(atStart > 10);
    CHECK(atEnd > 10);
}
