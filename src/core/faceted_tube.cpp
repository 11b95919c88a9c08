// facetedTube(): a stack's sections joined by flat triangles.
#include "towgeom/tow_stack.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

TriangleMesh facetedTube(const TowStack& stack, bool closeEnds)
{
    const auto& s = stack.sections;
    const std::size_t m = s.size(), n = stack.pointsPerSection();
    TriangleMesh mesh;
    mesh.vertices.reserve(m * n + 2);
    for (const auto& section : s) mesh.vertices.insert(mesh.vertices.end(), section.begin(), section.end());
    const auto id = [n](std::size_t i, std::size_t j) { return i * n + j % n; };
    mesh.triangles.reserve(2 * (m - 1) * n + (closeEnds ? 2 * n : 0));
    for (std::size_t i = 0; i + 1 < m; ++i)
        for (std::size_t j = 0; j < n; ++j) {
            mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    if (!closeEnds || m == 0) return mesh;
    for (const std::size_t i : {std::size_t(0), m - 1}) {
        Point3 c;
        for (const Point3& p : s[i]) c = c + p;
        mesh.vertices.push_back((1.0 / static_cast<double>(n)) * c);
        const std::size_t centre = mesh.vertices.size() - 1;
        // Each cap edge runs opposite to the side triangle that shares it.
        for (std::size_t j = 0; j < n; ++j) {
            if (i == 0)
                mesh.triangles.push_back({centre, id(i, j), id(i, j + 1)});
            else
                mesh.triangles.push_back({centre, id(i, j + 1), id(i, j)});
        }
    }
    return mesh;
}

TOWGEOM_END_NAMESPACE
