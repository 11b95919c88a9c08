// The public ParametricMesher: one tow meshed with the host's constraint polylines by the
// mesher of resolveTextile() (detail::ParametricMesher), in meshing rounds that put in the splits
// of constraint chords and seam edges the refinement asks for, then closed by its end caps.
#include "towgeom/surface_mesher.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <new>
#include <set>
#include <string>

#include "mesh/end_caps.hpp"
#include "mesh/mesh_measures.hpp"
#include "mesh/curvature_size.hpp"
#include "mesh/parametric_mesher.hpp"
#include "surface/fibre_directions.hpp"
#include "surface/frame.hpp"
#include "surface/tow_surface_impl.hpp"
#include "towgeom/error.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

constexpr int kMaxRounds = 6;                          // as resolveTextile()
constexpr std::size_t kLocal = std::size_t(1) << 60;  // marks the mesher's own new nodes

/// The constraint pieces for the internal mesher: nodes numbered in order of first use, one node
/// per distinct point (a point shared by constraints, or on the seam on both sides, is one).
struct Pieces {
    std::vector<detail::LoopConstraint> pieces;
    std::vector<UV> nodeUV;  ///< per node; seam nodes at v = vMin

    Pieces(const std::vector<MeshConstraint>& constraints, const ParameterRange& r)
    {
        std::map<std::pair<double, double>, std::size_t> pointNode;  // (u,v), seam points at vMin -> node
        for (std::size_t c = 0; c < constraints.size(); ++c) {
            const MeshConstraint& mc = constraints[c];
            const std::string which = "constraint " + std::to_string(c);
            if (mc.points.size() < (mc.closed ? 3u : 2u))
                throw Error(ErrorCode::InvalidArgument, which + " has fewer than " + (mc.closed ? "3" : "2") + " points");
            detail::LoopConstraint& piece = pieces.emplace_back();
            piece.closed = mc.closed;
            for (std::size_t k = 0; k < mc.points.size(); ++k) {
                const UV& p = mc.points[k];
                const std::string at = which + " point " + std::to_string(k);
                if (!std::isfinite(p.u) || !std::isfinite(p.v)) throw Error(ErrorCode::InvalidArgument, at + " is not finite");
                if (p.u < r.uMin || p.u > r.uMax || p.v < r.vMin || p.v > r.vMax)
                    throw Error(ErrorCode::InvalidArgument, at + " (" + std::to_string(p.u) + ", " + std::to_string(p.v) +
                                                                ") lies off the tow's (u,v) rectangle");
                const std::size_t prev = k > 0 ? k - 1 : mc.closed ? mc.points.size() - 1 : k;
                if (prev != k && mc.points[prev].u == p.u && mc.points[prev].v == p.v)
                    throw Error(ErrorCode::InvalidArgument, at + " repeats the point before it");
                const auto seamPoint = [&](const UV& q) { return q.v == r.vMin || q.v == r.vMax; };
                if (prev != k && seamPoint(p) && seamPoint(mc.points[prev]))
                    throw Error(ErrorCode::InvalidArgument, at + " and the point before it run along the seam (v = vMin or vMax): a "
                                                                 "constraint may cross the seam or touch it, not follow it");
                std::size_t node = nodeUV.size();
                const bool onSeam = p.v == r.vMin || p.v == r.vMax;
                const UV key = onSeam ? UV{p.u, r.vMin} : p;
                const auto [it, isNew] = pointNode.emplace(std::make_pair(key.u, key.v), node);
                node = it->second;
                if (isNew) nodeUV.push_back(key);
                piece.uv.push_back(p);
                piece.nodes.push_back(node);
            }
        }
    }

    /// Puts a node between consecutive nodes @p a and @p b of a piece, at the middle of the chord
    /// in (u,v); returns the split for the mesher, or false if no piece has that chord.
    bool split(std::size_t a, std::size_t b, detail::ChordSplit& out)
    {
        for (detail::LoopConstraint& c : pieces) {
            const std::size_t n = c.uv.size();
            for (std::size_t k = 0; k < n; ++k) {
                const std::size_t next = (k + 1) % n;
                if (next == 0 && !c.closed) break;
                if (!((c.nodes[k] == a && c.nodes[next] == b) || (c.nodes[k] == b && c.nodes[next] == a))) continue;
                const UV mid{0.5 * (c.uv[k].u + c.uv[next].u), 0.5 * (c.uv[k].v + c.uv[next].v)};
                out = {a, b, nodeUV.size(), mid};
                nodeUV.push_back(mid);
                c.uv.insert(c.uv.begin() + static_cast<std::ptrdiff_t>(k + 1), mid);
                c.nodes.insert(c.nodes.begin() + static_cast<std::ptrdiff_t>(k + 1), out.node);
                return true;
            }
        }
        return false;
    }
};

}  // namespace

ParametricMesher::ParametricMesher(TowSurface surface, const SurfaceMeshOptions& options)
    : surface_(std::move(surface)), options_(options)
{
    const auto finitePositive = [](double x) { return x > 0.0 && std::isfinite(x); };
    if (!(options.edgeLength == 0.0 || finitePositive(options.edgeLength)))
        throw Error(ErrorCode::InvalidArgument, "the edge length must be 0 (relative) or finite and positive");
    if (options.edgeLength == 0.0 && !finitePositive(options.relativeEdgeLength))
        throw Error(ErrorCode::InvalidArgument, "the relative edge length must be finite and positive");
    if (!(options.minAngle > 0.0 && options.minAngle <= 30.0))
        throw Error(ErrorCode::InvalidArgument, "the minimum angle must lie in (0, 30] degrees");
    if (options.maxTriangles == 0) throw Error(ErrorCode::InvalidArgument, "the triangle limit must be at least 1");
    for (const double x : {options.chordDeviation, options.relativeChordDeviation, options.minEdgeLength, options.relativeMinEdgeLength})
        if (!(x >= 0.0 && std::isfinite(x)))
            throw Error(ErrorCode::InvalidArgument, "chord deviation and smallest edge length (absolute and relative) must be >= 0 and finite");
    h_ = options.edgeLength > 0.0 ? options.edgeLength : options.relativeEdgeLength * surface_.towSize();
    const double around = 3.14159265358979323846 * surface_.towSize();
    if (h_ > around / 4.0)
        throw Error(ErrorCode::InvalidArgument, "edge length " + std::to_string(h_) + " is too coarse for tow '" + surface_.name() +
                                                    "': at least 4 edges around it are needed (at most " +
                                                    std::to_string(around / 4.0) + ")");
}

SurfaceMesh ParametricMesher::mesh(const std::vector<MeshConstraint>& constraints) const
{
    const ParameterRange r = surface_.parameterRange();
    Pieces pieces(constraints, r);
    // As resolveTextile(): about 3 triangles per equilateral triangle of side h in the area; with
    // a size function, (h / size)^2 times as many on average over a grid of the (u,v) rectangle.
    MeshOptions grading;
    grading.chordDeviation = options_.chordDeviation;
    grading.relativeChordDeviation = options_.relativeChordDeviation;
    grading.minEdgeLength = options_.minEdgeLength;
    grading.relativeMinEdgeLength = options_.relativeMinEdgeLength;
    const std::shared_ptr<const detail::CurvatureSize> graded = detail::curvatureSizeFor(surface_, grading, h_);
    double finer = graded ? graded->densityOverLargest() : 1.0;
    if (options_.size) {
        double sum = 0.0;
        constexpr int kGrid = 16;
        for (int i = 0; i < kGrid; ++i)
            for (int j = 0; j < kGrid; ++j) {
                const UV at{r.uMin + (r.uMax - r.uMin) * (i + 0.5) / kGrid, r.vMin + r.vPeriod() * (j + 0.5) / kGrid};
                const double hl = options_.size(at);
                if (!(hl > 0.0) || !std::isfinite(hl))
                    throw Error(ErrorCode::InvalidArgument, "the mesh size function gives " + std::to_string(hl) + " at (u, v) = (" +
                                                                std::to_string(at.u) + ", " + std::to_string(at.v) + ")",
                                "tow '" + surface_.name() + "'");
                const double ratio = h_ / std::clamp(graded ? std::min(hl, graded->at(at)) : hl, h_ / 100.0, h_);
                sum += ratio * ratio;
            }
        // The grid has both sizes; it may miss a graded tow's sharp edges, which the graded
        // field's own mean has.
        finer = std::max(finer, sum / (kGrid * kGrid));
    }
    const double estimate = finer * 3.0 * surface_.area() / (std::sqrt(3.0) / 4.0 * h_ * h_);
    if (!(estimate <= static_cast<double>(options_.maxTriangles)))
        throw Error(ErrorCode::TooLarge, "the mesh would have about " + std::to_string(static_cast<long long>(estimate)) +
                                             " triangles, over the limit of " + std::to_string(options_.maxTriangles) +
                                             " (SurfaceMeshOptions::maxTriangles); refused before meshing",
                    "tow '" + surface_.name() + "'");
    // In a frame where the tow is about unit size (as resolveTextile()), so that the mesh does
    // not depend on the units.
    const detail::Frame frame = detail::Frame::around(surface_.boundingBox(), surface_.towSize());
    const TowSurface tow = detail::inFrame(surface_, frame);
    const double h = frame.lengthToFrame(h_);

    std::vector<Point3> nodes;  // frame
    for (const UV& p : pieces.nodeUV) nodes.push_back(tow.point(p.u, p.v));
    detail::MeshSizes sizes{h, options_.minAngle, {}, {}};
    if (options_.size || graded)
        sizes.sizeAt = [&](const UV& at) {
            const double user = options_.size ? (graded ? std::min(options_.size(at), graded->at(at)) : options_.size(at)) : graded->at(at);
            return frame.lengthToFrame(user);
        };
    detail::ParametricMesher mesher(tow, sizes);
    detail::MeshRequests requests;
    SurfaceMesh out;
    std::vector<double> seamU;
    try {
        mesher.mesh(pieces.pieces, {}, requests);
        out.rounds = 1;
        for (; out.rounds < static_cast<std::size_t>(kMaxRounds) && !requests.empty(); ++out.rounds) {
            std::vector<detail::ChordSplit> splits;
            std::set<std::pair<std::size_t, std::size_t>> chords;
            for (const detail::MeshRequests::OnLoop& q : requests.onLoop) chords.emplace(std::min(q.a, q.b), std::max(q.a, q.b));
            for (const auto& [a, b] : chords) {
                detail::ChordSplit s;
                if (!pieces.split(a, b, s)) continue;
                nodes.push_back(tow.point(s.at.u, s.at.v));
                splits.push_back(s);
            }
            const std::vector<double> newSeamU = requests.seamU;
            seamU.insert(seamU.end(), newSeamU.begin(), newSeamU.end());
            requests = {};
            if (!mesher.split(splits, newSeamU, requests)) {
                requests = {};
                mesher.mesh(pieces.pieces, seamU, requests);
            }
        }
    } catch (const Error&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw;  // out of memory is not the input's geometry
    } catch (const std::exception& e) {
        throw Error(ErrorCode::Internal, std::string("the mesher failed: ") + e.what(), "tow '" + surface_.name() + "'");
    }
    std::vector<detail::ParametricMesh> meshes{mesher.result(kLocal)};
    detail::ParametricMesh& m = meshes.front();
    const std::size_t base = nodes.size();
    std::vector<UV> uv = pieces.nodeUV;
    for (const UV& p : m.newNodes) {
        nodes.push_back(tow.point(p.u, p.v));
        uv.push_back(p);
    }
    for (auto& tri : m.triangles)
        for (std::size_t& n : tri)
            if (n >= kLocal) n = base + (n - kLocal);
    out.fibreDirection = detail::fibreDirections(tow, m.centroids);
    std::vector<std::vector<TowFace>> face{std::vector<TowFace>(m.triangles.size(), TowFace::Side)};
    if (options_.caps) {
        detail::closeEnds({tow}, {h}, options_.minAngle, 1, meshes, face, nodes);
        detail::appendCapDirections(tow, face[0], out.fibreDirection);
    }
    uv.resize(nodes.size(), {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()});
    const std::size_t ends = detail::boundaryLoops(m.triangles).size();
    if (ends != (options_.caps ? 0u : 2u))
        throw Error(ErrorCode::Internal,
                    "the mesh is not a " + std::string(options_.caps ? "closed surface" : "tube open at its two ends") + " (" +
                        std::to_string(ends) + " boundary loops)",
                    "tow '" + surface_.name() + "'");
    // Every constraint chord must be a mesh edge: constraints that cross, end on another's chord,
    // or run along the seam or an end are split by points no constraint lists.
    std::set<std::pair<std::size_t, std::size_t>> edges;
    for (const auto& t : m.triangles)
        for (int k = 0; k < 3; ++k) edges.emplace(std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]));
    for (std::size_t c = 0; c < pieces.pieces.size(); ++c) {
        const std::vector<std::size_t>& n = pieces.pieces[c].nodes;
        const std::size_t chords = pieces.pieces[c].closed ? n.size() : n.size() - 1;
        for (std::size_t k = 0; k < chords; ++k)
            if (!edges.count(std::minmax(n[k], n[(k + 1) % n.size()])))
                throw Error(ErrorCode::InvalidArgument,
                            "constraint " + std::to_string(c) + ": its chord from point " + std::to_string(k) +
                                " is not an edge of the mesh: constraints may meet only at points they share, and may "
                                "not cross, end on another's chord, or run along the seam or an end of the tow",
                            "tow '" + surface_.name() + "'");
    }
    out.triangles = std::move(m.triangles);
    out.face = std::move(face[0]);
    out.uv = std::move(uv);
    for (const Point3& p : nodes) out.nodes.push_back(frame.toUser(p));
    for (const detail::LoopConstraint& c : pieces.pieces) out.constraintNodes.push_back(c.nodes);
    return out;
}

TOWGEOM_END_NAMESPACE
