#include "cell/plane_clip.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <utility>

#include "cell/axis.hpp"
#include "mesh/mesh_measures.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE
namespace detail {

using Triangle = std::array<std::size_t, 3>;

namespace {

/// Closer than this share of the box's diagonal a node lies on a face's plane but for rounding (a
/// tow's end section in the plane, as a scan cut at the cell's faces gives): it is put there
/// whatever its neighbours.
constexpr double kOnPlane = 1e-9;

/// The share of the snapping distance a node may move straight onto a plane (off its surface).
constexpr double kStraightShare = 0.1;

/// A face's plane and the side of it the box lies on.
struct Plane {
    int axis = 0;
    double at = 0.0;
    double keep = 1.0;  ///< +1: the box is where the coordinate is >= at; -1: <= at
};

std::array<Plane, 6> planesOf(const Cell& cell)
{
    std::array<Plane, 6> out;
    for (int f = 0; f < 6; ++f) {
        const CellFace face = static_cast<CellFace>(f);
        out[static_cast<std::size_t>(f)] = {axisOf(face), cell.plane(face), isMaxFace(face) ? -1.0 : 1.0};
    }
    return out;
}

struct PairHash {
    std::size_t operator()(const std::pair<std::size_t, std::size_t>& p) const noexcept
    {
        return std::hash<std::size_t>()(p.first) ^ (std::hash<std::size_t>()(p.second) * 0x9e3779b97f4a7c15ULL);
    }
};

/// Per node, the length of its shortest edge in any tow's mesh (infinity for a node of none), and
/// its neighbours along edges: of the triangles with a candidate node from firstNode on
/// (nodeEdges()); every node of none of them has no edge here.
struct NodeEdges {
    std::vector<double> shortest;
    std::vector<std::vector<std::size_t>> neighbours;
    /// Per edge (its nodes in increasing order), the third node of each triangle on it.
    std::unordered_map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t>, PairHash> thirds;
};

NodeEdges nodeEdges(const TextileMesh& mesh, std::size_t firstNode, const std::vector<char>& candidate)
{
    NodeEdges out{std::vector<double>(mesh.nodes.size(), std::numeric_limits<double>::infinity()),
                  std::vector<std::vector<std::size_t>>(mesh.nodes.size()), {}};
    const auto wanted = [&](std::size_t n) { return n >= firstNode && candidate[n]; };
    for (const TowMesh& m : mesh.tows)
        for (const Triangle& t : m.triangles) {
            if (!wanted(t[0]) && !wanted(t[1]) && !wanted(t[2])) continue;
            for (int k = 0; k < 3; ++k) {
                const std::size_t a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
                const double l = distance(mesh.nodes[a], mesh.nodes[b]);
                out.shortest[a] = std::min(out.shortest[a], l);
                out.shortest[b] = std::min(out.shortest[b], l);
                out.neighbours[a].push_back(b);
                out.neighbours[b].push_back(a);
                out.thirds[std::minmax(a, b)].push_back(t[static_cast<std::size_t>((k + 2) % 3)]);
            }
        }
    return out;
}

/// True when node @p n moved onto the plane @p q would make an edge to a neighbour already on it
/// whose triangles all lie on one side, off the plane: a crease of the surface touching the plane
/// (the matrix between it and the face pinched to a line).
bool wouldCrease(const TextileMesh& mesh, const NodeEdges& edges, std::size_t n, const Plane& q)
{
    for (std::size_t m : edges.neighbours[n]) {
        if (coord(mesh.nodes[m], q.axis) != q.at) continue;
        const auto it = edges.thirds.find(std::minmax(n, m));
        if (it == edges.thirds.end()) continue;
        int above = 0, below = 0;
        for (std::size_t w : it->second) {
            const double d = coord(mesh.nodes[w], q.axis) - q.at;
            above += d > 0.0;
            below += d < 0.0;
        }
        if (above == static_cast<int>(it->second.size()) || below == static_cast<int>(it->second.size())) return true;
    }
    return false;
}

/// True when node @p n moved to @p to would turn over one of its triangles (their normals before
/// and after pointing apart): a sliver next to it folds.
bool wouldFold(const TextileMesh& mesh, const NodeEdges& edges, std::size_t n, const Point3& to)
{
    const Point3& from = mesh.nodes[n];
    for (std::size_t m : edges.neighbours[n]) {
        const auto it = edges.thirds.find(std::minmax(n, m));
        if (it == edges.thirds.end()) continue;
        for (std::size_t w : it->second) {
            const Vector3 before = cross(mesh.nodes[m] - from, mesh.nodes[w] - from), after = cross(mesh.nodes[m] - to, mesh.nodes[w] - to);
            if (!(dot(before, after) > 0.0)) return true;
        }
    }
    return false;
}

/// The tow on whose own surface node @p n lies, when there is exactly one; else -1.
long soleTow(const NodeParameters& uv, std::size_t n)
{
    long found = -1;
    for (std::size_t t = 0; t < uv.size(); ++t)
        if (uv[t].count(n)) {
            if (found >= 0) return -1;
            found = static_cast<long>(t);
        }
    return found;
}

/// @p v moved into [vMin, vMax) by whole periods.
double wrapV(double v, const ParameterRange& r)
{
    const double period = r.vPeriod();
    v -= period * std::floor((v - r.vMin) / period);
    return v >= r.vMax ? v - period : v;
}

/// Moves @p uv on @p tow (Newton's method, the least step in (u,v)) until S(uv) lies on the plane
/// @p axis = @p at; true (with @p point) when it converged within @p limit of where it started.
bool moveAlongSurface(const TowSurface& tow, UV& uv, int axis, double at, double limit, Point3& point)
{
    const ParameterRange range = tow.parameterRange();
    if (!(uv.u >= range.uMin && uv.u <= range.uMax)) return false;  // on an end cap's chart
    const Point3 start = tow.point(uv.u, uv.v);
    UV w = uv;
    for (int iteration = 0; iteration < 12; ++iteration) {
        const SurfaceDerivatives d = tow.derivatives(w.u, w.v);
        const double r = coord(d.point, axis) - at;
        if (std::abs(r) <= 1e-12 * limit) {
            if (!(distance(d.point, start) < limit)) return false;
            point = d.point;
            coord(point, axis) = at;
            uv = {w.u, wrapV(w.v, range)};
            return true;
        }
        const double gu = coord(d.du, axis), gv = coord(d.dv, axis), g2 = gu * gu + gv * gv;
        if (!(g2 > 0.0)) return false;
        w.u -= r * gu / g2;
        w.v -= r * gv / g2;
        if (!(w.u >= range.uMin && w.u <= range.uMax)) return false;
    }
    return false;
}

/// Clips every tow of @p mesh by one plane.
class PlaneClipper {
public:
    PlaneClipper(TextileMesh& mesh, const Plane& plane) : mesh_(mesh), q_(plane) {}

    void clip()
    {
        for (std::size_t t = 0; t < mesh_.tows.size(); ++t) clipTow(t);
    }

private:
    int side(std::size_t n) const
    {
        const double d = q_.keep * (coord(mesh_.nodes[n], q_.axis) - q_.at);
        return d > 0.0 ? 1 : d < 0.0 ? -1 : 0;
    }
    /// The node where edge (@p a, @p b) crosses the plane, on the edge (a part of the resolved
    /// surface), exactly on the plane.
    std::size_t cutNode(std::size_t a, std::size_t b)
    {
        const auto key = std::minmax(a, b);
        const auto it = cut_.find(key);
        if (it != cut_.end()) return it->second;
        const Point3 pa = mesh_.nodes[a], pb = mesh_.nodes[b];
        const double da = coord(pa, q_.axis) - q_.at, db = coord(pb, q_.axis) - q_.at;
        Point3 p = pa + (da / (da - db)) * (pb - pa);
        coord(p, q_.axis) = q_.at;
        const std::size_t n = mesh_.nodes.size();
        mesh_.nodes.push_back(p);
        cut_.emplace(key, n);
        return n;
    }
    void clipTow(std::size_t t)
    {
        TowMesh& m = mesh_.tows[t];
        TowMesh kept;
        const auto keep = [&](const Triangle& tri, std::size_t k) {
            kept.triangles.push_back(tri);
            if (k < m.region.size()) kept.region.push_back(m.region[k]);
            if (k < m.face.size()) kept.face.push_back(m.face[k]);
            if (k < m.fibreDirection.size()) kept.fibreDirection.push_back(m.fibreDirection[k]);
        };
        for (std::size_t k = 0; k < m.triangles.size(); ++k) {
            const Triangle& tri = m.triangles[k];
            const std::array<int, 3> s{side(tri[0]), side(tri[1]), side(tri[2])};
            const bool anyOut = s[0] < 0 || s[1] < 0 || s[2] < 0, anyIn = s[0] > 0 || s[1] > 0 || s[2] > 0;
            if (!anyIn) continue;  // outside, or in the plane (the face's cap covers it)
            if (!anyOut) {
                keep(tri, k);
                continue;
            }
            std::vector<std::size_t> polygon;
            for (std::size_t i = 0; i < 3; ++i) {
                const std::size_t j = (i + 1) % 3;
                if (s[i] >= 0) polygon.push_back(tri[i]);
                if (s[i] * s[j] < 0) polygon.push_back(cutNode(tri[i], tri[j]));
            }
            if (polygon.size() == 3) {
                keep({polygon[0], polygon[1], polygon[2]}, k);
                continue;
            }
            // A quad: split along its shorter diagonal (ties by the smaller node), the same
            // split whichever way round it runs (a region's two copies).
            const auto length2 = [&](std::size_t x, std::size_t y) {
                const Vector3 d = mesh_.nodes[polygon[x]] - mesh_.nodes[polygon[y]];
                return dot(d, d);
            };
            const double d02 = length2(0, 2), d13 = length2(1, 3);
            const bool first = d02 < d13 || (d02 == d13 && std::min(polygon[0], polygon[2]) < std::min(polygon[1], polygon[3]));
            const std::size_t o = first ? 0 : 1;
            keep({polygon[o], polygon[o + 1], polygon[(o + 2) % 4]}, k);
            keep({polygon[o], polygon[(o + 2) % 4], polygon[(o + 3) % 4]}, k);
        }
        m.triangles = std::move(kept.triangles);
        m.region = std::move(kept.region);
        m.face = std::move(kept.face);
        m.fibreDirection = std::move(kept.fibreDirection);
    }

    TextileMesh& mesh_;
    Plane q_;
    std::unordered_map<std::pair<std::size_t, std::size_t>, std::size_t, PairHash> cut_;
};

}  // namespace

NodeParameters nodeParameters(const TextileMesh& mesh)
{
    NodeParameters out(mesh.tows.size());
    for (std::size_t t = 0; t < mesh.tows.size(); ++t)
        for (const auto& [n, w] : mesh.tows[t].parameters) out[t].emplace(n, w);
    return out;
}

std::size_t snapToCellPlanes(TextileMesh& mesh, NodeParameters& uv, const std::vector<TowSurface>& tows, const Cell& cell,
                             double fraction, std::size_t firstNode, unsigned faces)
{
    const std::array<Plane, 6> planes = planesOf(cell);
    // Only nodes within fraction x the longest edge of a plane can be within fraction x their own
    // shortest edge of it: the edges of the others' triangles are not needed (a scan's cell has
    // millions of them).
    double longest = 0.0;
    for (const TowMesh& m : mesh.tows)
        for (const Triangle& t : m.triangles)
            if (t[0] >= firstNode || t[1] >= firstNode || t[2] >= firstNode)
                for (int k = 0; k < 3; ++k)
                    longest = std::max(longest, distance(mesh.nodes[t[static_cast<std::size_t>(k)]], mesh.nodes[t[static_cast<std::size_t>((k + 1) % 3)]]));
    std::vector<char> candidate(mesh.nodes.size(), 0);
    for (std::size_t n = firstNode; n < mesh.nodes.size(); ++n)
        for (std::size_t f = 0; f < 6; ++f)
            if ((faces & (1u << f)) && std::abs(coord(mesh.nodes[n], planes[f].axis) - planes[f].at) < fraction * longest) candidate[n] = 1;
    const NodeEdges edges = nodeEdges(mesh, firstNode, candidate);
    const double onPlane = kOnPlane * distance(cell.min, cell.max);
    const std::vector<double>& shortest = edges.shortest;
    std::size_t moved = 0;
    for (std::size_t n = firstNode; n < mesh.nodes.size(); ++n) {
        if (!std::isfinite(shortest[n])) continue;
        const double limit = fraction * shortest[n];
        unsigned on = 0;  // the planes it lies on
        for (std::size_t f = 0; f < 6; ++f)
            if (coord(mesh.nodes[n], planes[f].axis) == planes[f].at) on |= 1u << f;
        for (std::size_t f = 0; f < 6; ++f) {
            if (!(faces & (1u << f))) continue;
            const Plane& q = planes[f];
            Point3& p = mesh.nodes[n];
            const double d = coord(p, q.axis) - q.at;
            if (d == 0.0 || !(std::abs(d) < limit)) continue;
            if (std::abs(d) < onPlane) {  // on it but for rounding
                coord(p, q.axis) = q.at;
                on |= 1u << f;
                ++moved;
                continue;
            }
            bool near = true;  // within the limit of the face's rectangle
            for (int b = 0; b < 3; ++b)
                if (b != q.axis && !(coord(p, b) >= coord(cell.min, b) - limit && coord(p, b) <= coord(cell.max, b) + limit)) near = false;
            if (!near) continue;
            // Only where the plane cuts an edge of it: a surface that comes close to the plane
            // without crossing it is not pressed onto it (it would touch the face along a line).
            bool crossed = false;
            for (std::size_t m : edges.neighbours[n]) {
                const double e = coord(mesh.nodes[m], q.axis) - q.at;
                crossed = crossed || (e != 0.0 && (e > 0.0) != (d > 0.0));
            }
            if (!crossed || wouldCrease(mesh, edges, n, q)) continue;
            bool alongSurface = false;
            if (on == 0) {
                const long t = soleTow(uv, n);
                if (t >= 0) {
                    UV w = uv[static_cast<std::size_t>(t)].at(n);
                    Point3 onPlane;
                    if (moveAlongSurface(tows[static_cast<std::size_t>(t)], w, q.axis, q.at, 2.0 * limit, onPlane) &&
                        !wouldFold(mesh, edges, n, onPlane)) {
                        p = onPlane;
                        uv[static_cast<std::size_t>(t)][n] = w;
                        alongSurface = true;
                    }
                }
            }
            if (!alongSurface) {
                // Straight off its surface: only a hair (a surface grazing the plane stays as it is).
                if (!(std::abs(d) < kStraightShare * limit)) continue;
                Point3 onPlane = p;
                coord(onPlane, q.axis) = q.at;
                if (wouldFold(mesh, edges, n, onPlane)) continue;
                p = onPlane;
            }
            on |= 1u << f;
            ++moved;
        }
    }
    return moved;
}

void clipToCellPlanes(TextileMesh& mesh, NodeParameters& uv, const std::vector<TowSurface>& tows, const Cell& cell, double fraction)
{
    const std::array<Plane, 6> planes = planesOf(cell);
    const std::size_t given = mesh.nodes.size();
    for (std::size_t f = 0; f < planes.size(); ++f) {
        // The nodes the earlier planes made (on their planes) close to this one: onto it too.
        snapToCellPlanes(mesh, uv, tows, cell, fraction, given, 1u << f);
        PlaneClipper(mesh, planes[f]).clip();
    }
    // The regions as clipped: their triangles where the primary keeps them.
    for (ConnectedRegion& region : mesh.regions) {
        region.triangles.clear();
        region.nodes.clear();
        region.area = 0.0;
    }
    for (std::size_t t = 0; t < mesh.tows.size(); ++t) {
        const TowMesh& m = mesh.tows[t];
        for (std::size_t k = 0; k < m.triangles.size() && k < m.region.size(); ++k) {
            if (m.region[k] < 0 || mesh.regions[static_cast<std::size_t>(m.region[k])].primary != t) continue;
            ConnectedRegion& region = mesh.regions[static_cast<std::size_t>(m.region[k])];
            region.triangles.push_back(k);
            region.nodes.insert(region.nodes.end(), m.triangles[k].begin(), m.triangles[k].end());
            region.area += triangleArea(mesh.nodes, m.triangles[k]);
        }
    }
    for (ConnectedRegion& region : mesh.regions) {
        std::sort(region.nodes.begin(), region.nodes.end());
        region.nodes.erase(std::unique(region.nodes.begin(), region.nodes.end()), region.nodes.end());
        std::vector<std::size_t> loopNodes;
        for (std::size_t n : region.loopNodes)
            if (std::binary_search(region.nodes.begin(), region.nodes.end(), n)) loopNodes.push_back(n);
        region.loopNodes = std::move(loopNodes);
    }
}

}  // namespace detail
TOWGEOM_END_NAMESPACE
