#include "towgeom/surface_fold.hpp"

#include <string>
#include <vector>

#include "core/triangle_crossings.hpp"
#include "towgeom/error.hpp"

TOWGEOM_BEGIN_NAMESPACE

std::optional<SurfaceFold> findFold(const TowSurface& tow, const FoldSearchOptions& options)
{
    if (options.perSpan < 1 || options.around < 8)
        throw Error(ErrorCode::InvalidArgument,
                    "the fold search needs at least 1 sample per section span and 8 around, not " + std::to_string(options.perSpan) +
                        " and " + std::to_string(options.around),
                    "tow '" + tow.name() + "'");
    // u: perSpan samples per span between the sections' parameters; v: around samples, closed.
    const std::vector<double>& sections = tow.sectionParameters();
    std::vector<double> us;
    for (std::size_t i = 0; i + 1 < sections.size(); ++i)
        for (std::size_t k = 0; k < options.perSpan; ++k)
            us.push_back(sections[i] + (sections[i + 1] - sections[i]) * static_cast<double>(k) / static_cast<double>(options.perSpan));
    us.push_back(sections.back());
    const ParameterRange range = tow.parameterRange();
    const std::size_t nv = options.around;
    std::vector<Point3> nodes;
    std::vector<UV> uvs;
    for (double u : us)
        for (std::size_t j = 0; j < nv; ++j) {
            const double v = range.vMin + range.vPeriod() * static_cast<double>(j) / static_cast<double>(nv);
            nodes.push_back(tow.point(u, v));
            uvs.push_back({u, v});
        }
    std::vector<std::size_t> triangles;  // 1-based, three per triangle
    for (std::size_t i = 0; i + 1 < us.size(); ++i)
        for (std::size_t j = 0; j < nv; ++j) {
            const std::size_t a = i * nv + j + 1, b = i * nv + (j + 1) % nv + 1, c = a + nv, d = b + nv;
            triangles.insert(triangles.end(), {a, c, d, a, d, b});
        }
    const std::optional<detail::TriangleCrossing> crossing = detail::firstCrossing(nodes, {&triangles}, options.within);
    if (!crossing) return std::nullopt;
    const std::size_t k = 3 * crossing->triangle;
    const UV &p = uvs[triangles[k] - 1], &q = uvs[triangles[k + 1] - 1], &r = uvs[triangles[k + 2] - 1];
    // The centroid's parameters on the grid: the first corner is (i, j) in both triangles of a
    // cell, the centroid a third (a, c, d) or two thirds (a, d, b) of a step further around
    // (across the seam for the last column: wrapped).
    const double step = range.vPeriod() / static_cast<double>(nv);
    double v = p.v + step * (crossing->triangle % 2 == 0 ? 1.0 : 2.0) / 3.0;
    if (v >= range.vMin + range.vPeriod()) v -= range.vPeriod();
    SurfaceFold fold;
    fold.at = crossing->at;
    fold.uv = {(p.u + q.u + r.u) / 3.0, v};
    fold.crossingPairs = crossing->pairs;
    return fold;
}

TOWGEOM_END_NAMESPACE
