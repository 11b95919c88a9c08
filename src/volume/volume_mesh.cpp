// Tetrahedra inside the resolved tows with Gmsh: each shell's own triangles and each region's
// triangles (split by the shells they lie on) become discrete surfaces (the nodes and triangles
// as they are), each shell of a tow a volume of the built-in kernel bounded by its surfaces,
// meshed by HXT.
#include "towgeom/volume_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <chrono>
#include <cstdint>
#include <exception>
#include <iomanip>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>

#include "towgeom/error.hpp"
#include "core/parallel.hpp"
#include "mesh/mesh_measures.hpp"
#include "volume/volume_conformity.hpp"
#include "core/triangle_crossings.hpp"
#include "volume/facet_folds.hpp"
#include "volume/gmsh_library.hpp"
#include "volume/graded_size.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

/// Gmsh holds one global state: one caller at a time.
std::mutex& gmshMutex()
{
    static std::mutex m;
    return m;
}

/// Degrees per radian.
constexpr double kDegree = 57.295779513082321;
/// The smallest angle between two faces on an edge HXT's boundary recovery accepts (Gmsh 4.8:
/// 0.01 degrees, fixed; Mesh.AngleToleranceFacetOverlap does not change it, measured).
constexpr double kHxtFoldTolerance = 0.01 / kDegree;
/// VolumeMeshOptions::maxSize 0: this many times the surface mesh's median edge length.
constexpr double kAutoMaxSize = 8.0;
/// The largest VolumeMeshOptions::growthRate: beyond, HXT's boundary recovery slows sharply
/// (the 8x8 twill cell: 14 s at 1.5, 229 s at 2, measured with Gmsh 4.8.4).
constexpr double kLargestGrowthRate = 1.5;

/// Gmsh's size callback: the graded size (data: a detail::GradedSize).
double gradedSizeAt(int, int, double x, double y, double z, void* data)
{
    return (*static_cast<const detail::GradedSize*>(data))({x, y, z});
}

double signedVolume(const Point3& a, const Point3& b, const Point3& c, const Point3& d)
{
    return dot(cross(b - a, c - a), d - a) / 6.0;
}

/// An option Gmsh does not have: asking for it logs an error (volume meshing's sentinel).
constexpr const char* kSentinelOption = "General.TowgeomSentinelNotAnOption";

/// Gmsh's C API with its error flag checked (a failed call throws std::runtime_error with
/// Gmsh's message).
class Gmsh {
public:
    Gmsh() : api_(detail::gmshApi()) {}
    const detail::GmshApi& api() const { return api_; }
    template <class F, class... A>
    auto call(const char* name, F f, A... args) const
    {
        int ierr = 0;
        if constexpr (std::is_void_v<decltype(f(args..., &ierr))>) {
            f(args..., &ierr);
            detail::gmshCheck(api_, ierr, name);
        } else {
            auto r = f(args..., &ierr);
            detail::gmshCheck(api_, ierr, name);
            return r;
        }
    }

private:
    const detail::GmshApi& api_;
};

/// Gmsh for one call: started on the first call in the process unless the host has started it
/// (and then left running until the process exits: finalising and starting again makes Gmsh
/// print on every later probe), a model of towgeom's own made current, and on exit that model removed and the
/// host's current model and the options set here restored. Callers hold gmshMutex().
class GmshSession {
public:
    explicit GmshSession(const Gmsh& g) : g_(g)
    {
        const detail::GmshApi& api = g.api();
        static bool running = false;  // started here, or found started by the host
        if (!running) {
            // Gmsh 4.8 has no isInitialized(): uninitialised, its calls fail, so an option read
            // leaves the value as it was.
            double probe = -1.0;
            int ierr = 0;
            api.gmshOptionGetNumber("General.Terminal", &probe, &ierr);
            if (!(ierr == 0 && probe != -1.0)) {
                g.call("gmshInitialize", api.gmshInitialize, 0, nullptr, 0);
                // Finalised at exit (frees its models), before Gmsh's own statics go: this
                // object is made after the library was loaded, so it is destroyed first.
                static const struct Finalizer {
                    const detail::GmshApi* api;
                    ~Finalizer()
                    {
                        // Not while another thread meshes (exit() called elsewhere meanwhile).
                        std::unique_lock<std::mutex> l(gmshMutex(), std::try_to_lock);
                        if (!l.owns_lock()) return;
                        int e = 0;
                        api->gmshFinalize(&e);
                    }
                } finalizer{&api};
            }
            running = true;
        }
        char* current = nullptr;
        int ierr = 0;
        api.gmshModelGetCurrent(&current, &ierr);
        hadCurrent_ = ierr == 0 && current;  // the host's default model is named ""
        if (hadCurrent_) hostModel_ = current;
        if (current) api.gmshFree(current);
        for (auto& [name, value] : saved_) g.call("gmshOptionGetNumber", api.gmshOptionGetNumber, name, &value);
        try {
            g.call("gmshOptionSetNumber", api.gmshOptionSetNumber, "General.Terminal", 0.0);
            // An error in a call throws (and sets ierr), whatever the host set (3: also while
            // Gmsh's GUI runs, where 2 does not throw).
            g.call("gmshOptionSetNumber", api.gmshOptionSetNumber, "General.AbortOnError", 3.0);
            g.call("gmshModelAdd", api.gmshModelAdd, kModel);
            added_ = true;
        } catch (...) {
            restore();
            throw;
        }
    }
    ~GmshSession() { restore(); }
    GmshSession(const GmshSession&) = delete;
    GmshSession& operator=(const GmshSession&) = delete;

private:
    /// The host's state back: towgeom's model removed, the current model and the options.
    void restore() noexcept
    {
        const detail::GmshApi& api = g_.api();
        int ierr = 0;
        if (added_) {
            api.gmshModelSetCurrent(kModel, &ierr);
            api.gmshModelMeshRemoveSizeCallback(&ierr);
            api.gmshModelRemove(&ierr);
            added_ = false;
        }
        if (hadCurrent_) api.gmshModelSetCurrent(hostModel_.c_str(), &ierr);
        for (const auto& [name, value] : saved_) api.gmshOptionSetNumber(name, value, &ierr);
    }

    static constexpr const char* kModel = "towgeom_volumes";
    const Gmsh& g_;
    bool hadCurrent_ = false, added_ = false;
    std::string hostModel_;
    std::pair<const char*, double> saved_[16] = {{"General.Terminal", 0.0},
                                                {"General.AbortOnError", 0.0},
                                                {"Mesh.MeshSizeFromCurvature", 0.0},
                                                {"Mesh.MeshSizeFromPoints", 0.0},
                                                {"Mesh.MeshSizeExtendFromBoundary", 0.0},
                                                {"Mesh.MeshSizeMin", 0.0},
                                                {"Mesh.MeshSizeMax", 0.0},
                                                {"Mesh.MeshSizeFactor", 0.0},
                                                {"Mesh.ElementOrder", 0.0},
                                                {"Mesh.SubdivisionAlgorithm", 0.0},
                                                {"Mesh.HighOrderOptimize", 0.0},
                                                {"General.NumThreads", 0.0},
                                                {"Mesh.MaxNumThreads3D", 0.0},
                                                {"Mesh.Algorithm3D", 0.0},
                                                {"Mesh.Optimize", 0.0},
                                                {"Mesh.Renumber", 0.0}};
};

}  // namespace

double VolumeMesh::tetrahedronVolume(std::size_t k) const
{
    const auto& t = tetrahedra.at(k);
    return signedVolume(nodes[t[0]], nodes[t[1]], nodes[t[2]], nodes[t[3]]);
}

double VolumeMesh::towVolume(std::size_t t) const
{
    double v = 0.0;
    for (std::size_t k = 0; k < tetrahedra.size(); ++k)
        if (tow[k] == t) v += tetrahedronVolume(k);
    return v;
}

namespace {

/// The middle nodes @p middle of tetrahedron @p tet's edges in the order (0,1), (1,2), (2,0),
/// (0,3), (1,3), (2,3), each found at its edge's middle (whatever order Gmsh gave them in).
/// @throws towgeom::Error (Internal) if an edge has no node at its middle.
std::array<std::size_t, 6> middleNodes(const std::vector<Point3>& nodes, const std::array<std::size_t, 4>& tet, const std::array<std::size_t, 6>& middle)
{
    constexpr int kEdges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
    std::array<std::size_t, 6> out{};
    for (int e = 0; e < 6; ++e) {
        const Point3& a = nodes[tet[static_cast<std::size_t>(kEdges[e][0])]];
        const Point3& b = nodes[tet[static_cast<std::size_t>(kEdges[e][1])]];
        const Point3 mid = 0.5 * (a + b);
        std::size_t best = 0;
        for (std::size_t m = 1; m < 6; ++m)
            if (distance(nodes[middle[m]], mid) < distance(nodes[middle[best]], mid)) best = m;
        const double scale = std::max({std::abs(mid.x), std::abs(mid.y), std::abs(mid.z)});
        if (!(distance(nodes[middle[best]], mid) <= 1e-9 * distance(a, b) + 1e-14 * scale))
            throw Error(ErrorCode::Internal, "Gmsh's quadratic tetrahedron has no node at the middle of an edge");
        out[static_cast<std::size_t>(e)] = middle[best];
    }
    return out;
}

/// The closed surface @p triangles (a tow's, or the matrix's) split into shells (triangles
/// joined across edges): the shell of each triangle. A tow cut through by a tow ranked above it
/// has two or more.
/// @throws towgeom::Error (InvalidArgument) naming @p name if the surface is not a closed
/// 2-manifold (an edge not used by exactly two of its triangles, a triangle given twice): Gmsh's
/// HXT ends the process on such input.
std::vector<std::size_t> shellsOf(const std::vector<std::array<std::size_t, 3>>& triangles, const std::string& name, std::size_t& count)
{
    const auto fail = [&](const std::string& what) {
        throw Error(ErrorCode::InvalidArgument, name + ": its surface mesh is not a closed 2-manifold (" + what +
                                                    "): volumes need closed surfaces (tows closed by their end caps, overlaps resolved)");
    };
    // Sorting, not maps: a tow has hundreds of thousands of triangles.
    std::vector<std::array<std::size_t, 3>> keys(triangles.size());
    for (std::size_t k = 0; k < triangles.size(); ++k) {
        keys[k] = triangles[k];
        std::sort(keys[k].begin(), keys[k].end());
        if (keys[k][0] == keys[k][1] || keys[k][1] == keys[k][2]) fail("a triangle repeats a node");
    }
    std::sort(keys.begin(), keys.end());
    if (std::adjacent_find(keys.begin(), keys.end()) != keys.end()) fail("a triangle given twice");
    struct HalfEdge {
        std::size_t from, to, triangle;
    };
    std::vector<HalfEdge> half;
    half.reserve(3 * triangles.size());
    for (std::size_t k = 0; k < triangles.size(); ++k)
        for (std::size_t e = 0; e < 3; ++e) half.push_back({triangles[k][e], triangles[k][(e + 1) % 3], k});
    const auto directed = [](const HalfEdge& a, const HalfEdge& b) { return std::tie(a.from, a.to) < std::tie(b.from, b.to); };
    std::sort(half.begin(), half.end(), directed);
    for (std::size_t i = 1; i < half.size(); ++i)
        if (half[i].from == half[i - 1].from && half[i].to == half[i - 1].to)
            fail("two triangles run along an edge the same way: inconsistent orientation");
    // Each edge used once each way: its two triangles join.
    const auto undirected = [](const HalfEdge& h) { return std::make_pair(std::min(h.from, h.to), std::max(h.from, h.to)); };
    std::sort(half.begin(), half.end(), [&](const HalfEdge& a, const HalfEdge& b) { return undirected(a) < undirected(b); });
    std::vector<std::size_t> parent(triangles.size());
    for (std::size_t k = 0; k < parent.size(); ++k) parent[k] = k;
    const auto root = [&](std::size_t k) {
        while (parent[k] != k) k = parent[k] = parent[parent[k]];
        return k;
    };
    for (std::size_t i = 0; i < half.size();) {
        std::size_t j = i + 1;
        while (j < half.size() && undirected(half[j]) == undirected(half[i])) ++j;
        if (j - i != 2) fail(std::to_string(j - i) + " triangles at an edge");
        parent[root(half[i].triangle)] = root(half[i + 1].triangle);
        i = j;
    }
    std::vector<std::size_t> shell(triangles.size());
    std::vector<std::size_t> number(triangles.size(), SIZE_MAX);
    count = 0;
    for (std::size_t k = 0; k < shell.size(); ++k) {
        std::size_t& n = number[root(k)];
        if (n == SIZE_MAX) n = count++;
        shell[k] = n;
    }
    return shell;
}

}  // namespace

namespace {

/// The tetrahedra in Gmsh's current mesh whose volume is under 1e-9 of the cube of their mean
/// edge length (flat: their nodes nearly in one plane).
std::size_t flatTetrahedra(const Gmsh& g)
{
    const detail::GmshApi& api = g.api();
    std::size_t* t = nullptr;
    double *c = nullptr, *p = nullptr;
    std::size_t nt = 0, nc = 0, np = 0;
    g.call("gmshModelMeshGetNodes", api.gmshModelMeshGetNodes, &t, &nt, &c, &nc, &p, &np, -1, -1, 0, 0);
    const std::vector<std::size_t> tags = detail::gmshTake(api, t, nt);
    const std::vector<double> coords = detail::gmshTake(api, c, nc);
    detail::gmshTake(api, p, np);
    std::vector<std::size_t> position;  // by tag
    for (std::size_t k = 0; k < tags.size(); ++k) {
        if (position.size() <= tags[k]) position.resize(tags[k] + 1, SIZE_MAX);
        position[tags[k]] = k;
    }
    std::size_t *e = nullptr, *n = nullptr, ne = 0, nn = 0;
    g.call("gmshModelMeshGetElementsByType", api.gmshModelMeshGetElementsByType, 4, &e, &ne, &n, &nn, -1, std::size_t(0), std::size_t(1));
    detail::gmshTake(api, e, ne);
    const std::vector<std::size_t> nodes = detail::gmshTake(api, n, nn);
    std::size_t flat = 0;
    for (std::size_t k = 0; k + 3 < nodes.size(); k += 4) {
        Point3 q[4];
        for (int i = 0; i < 4; ++i) {
            const std::size_t at = nodes[k + static_cast<std::size_t>(i)] < position.size() ? position[nodes[k + static_cast<std::size_t>(i)]] : SIZE_MAX;
            if (at == SIZE_MAX) return 0;  // not ours to judge: the checks below name it
            q[i] = {coords[3 * at], coords[3 * at + 1], coords[3 * at + 2]};
        }
        double edges = 0.0;
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j) edges += distance(q[i], q[j]);
        const double mean = edges / 6.0;
        if (std::abs(signedVolume(q[0], q[1], q[2], q[3])) < 1e-9 * mean * mean * mean) ++flat;
    }
    return flat;
}

}  // namespace

VolumeMesh meshVolumes(const TextileMesh& surfaces, const VolumeMeshOptions& options)
{
    if (options.order != 1 && options.order != 2)
        throw Error(ErrorCode::InvalidArgument, "the tetrahedra's order must be 1 (linear) or 2 (quadratic), not " + std::to_string(options.order));
    if (!(options.growthRate >= 1.0 && options.growthRate <= kLargestGrowthRate))
        throw Error(ErrorCode::InvalidArgument, "the tetrahedra's growth rate must lie in [1, 1.5], not " + std::to_string(options.growthRate));
    if (!(options.maxSize >= 0.0) || !std::isfinite(options.maxSize))
        throw Error(ErrorCode::InvalidArgument, "the tetrahedra's largest size must be 0 (automatic) or a positive length, not " +
                                                    std::to_string(options.maxSize));
    const bool quadratic = options.order == 2;
    const std::size_t towCount = surfaces.tows.size();
    for (std::size_t t = 0; t < towCount; ++t)
        if (surfaces.boundaryLoopCount(t) != 0)
            throw Error(ErrorCode::InvalidArgument, "tow '" + surfaces.tows[t].name + "': its surface mesh is not closed (" +
                                                        std::to_string(surfaces.boundaryLoopCount(t)) +
                                                        " boundary loops): volumes need tows closed by their end caps");
    // One volume per shell of each tow (a tow cut through by one ranked above it has several).
    std::vector<std::vector<std::size_t>> shell(towCount);
    std::vector<std::size_t> firstVolume(towCount + 1, 0);  // volume v of tow t: firstVolume[t] + shell
    std::vector<std::size_t> shellCount(towCount, 0);
    std::vector<std::exception_ptr> refused(towCount);  // the first tow's is thrown, whatever the threads did
    detail::parallelFor(towCount, detail::workerCount(options.threads), [&](std::size_t t) {
        try {
            shell[t] = shellsOf(surfaces.tows[t].triangles, "tow '" + surfaces.tows[t].name + "'", shellCount[t]);
        } catch (...) {
            refused[t] = std::current_exception();
        }
    });
    for (const std::exception_ptr& e : refused)
        if (e) std::rethrow_exception(e);
    for (std::size_t t = 0; t < towCount; ++t) firstVolume[t + 1] = firstVolume[t] + shellCount[t];
    // Clipped to a cell: the matrix, "tow" towCount, is one volume per piece: its boundary (the
    // box's faces minus the caps, and every tow's free triangles reversed) split into shells; a
    // shell enclosing a positive volume is a piece (a pocket sealed by tows against the box's
    // faces is one more), one enclosing a negative volume a tow wholly inside, a hole of the
    // largest piece.
    const bool matrix = surfaces.cell.has_value();
    const auto onCellFace = [&](const TowMesh& m, std::size_t k) {
        return k < m.face.size() && (m.face[k] == TowFace::Cell || (m.face[k] == TowFace::Start && m.cutAt[0]) ||
                                     (m.face[k] == TowFace::End && m.cutAt[1]));
    };
    std::vector<std::array<std::size_t, 3>> matrixBoundary;  // the cell's triangles, then each tow's free ones reversed
    std::vector<std::size_t> matrixShell;                     // per triangle of matrixBoundary
    std::vector<std::size_t> firstFree(towCount + 1, 0);      // tow t's free triangles from matrixBoundary[firstFree[t]]
    std::vector<std::size_t> pieceOfShell;                    // matrix volume (from firstVolume[towCount]) of each shell
    double matrixVolume = 0.0;                                // enclosed by its boundary, for the check of the tetrahedra
    std::size_t matrixPieces = 0;
    if (matrix) {
        matrixBoundary = surfaces.cell->triangles;
        for (std::size_t t = 0; t < towCount; ++t) {
            firstFree[t] = matrixBoundary.size();
            const TowMesh& m = surfaces.tows[t];
            for (std::size_t k = 0; k < m.triangles.size(); ++k)
                if (m.region[k] < 0 && !onCellFace(m, k)) matrixBoundary.push_back({m.triangles[k][0], m.triangles[k][2], m.triangles[k][1]});
        }
        firstFree[towCount] = matrixBoundary.size();
        std::size_t shells = 0;
        matrixShell = shellsOf(matrixBoundary, "the matrix", shells);
        std::vector<std::vector<std::array<std::size_t, 3>>> byShell(shells);
        for (std::size_t k = 0; k < matrixBoundary.size(); ++k) byShell[matrixShell[k]].push_back(matrixBoundary[k]);
        std::vector<double> enclosedBy(shells);
        for (std::size_t i = 0; i < shells; ++i) {
            enclosedBy[i] = detail::signedVolume(surfaces.nodes, byShell[i]);
            matrixVolume += enclosedBy[i];
        }
        pieceOfShell.assign(shells, 0);
        for (std::size_t i = 0; i < shells; ++i)
            if (enclosedBy[i] > 0.0) pieceOfShell[i] = matrixPieces++;
        // A hole (a tow wholly inside the matrix) belongs to the smallest piece around it.
        for (std::size_t i = 0; i < shells; ++i) {
            if (enclosedBy[i] > 0.0) continue;
            const Point3& probe = surfaces.nodes[byShell[i].front()[0]];
            std::size_t around = shells;
            for (std::size_t j = 0; j < shells; ++j)
                if (enclosedBy[j] > 0.0 && (around == shells || enclosedBy[j] < enclosedBy[around]) &&
                    detail::windingNumber(surfaces.nodes, byShell[j], probe) > 0.5)
                    around = j;
            if (around == shells)
                throw Error(ErrorCode::Internal, "the matrix: a tow inside it lies in none of its pieces");
            pieceOfShell[i] = pieceOfShell[around];
        }
    }
    std::vector<std::size_t> volumeTow(firstVolume[towCount] + matrixPieces, towCount);
    for (std::size_t t = 0; t < towCount; ++t)
        for (std::size_t v = firstVolume[t]; v < firstVolume[t + 1]; ++v) volumeTow[v] = t;
    const auto nameOf = [&](std::size_t t) { return t < towCount ? "tow '" + surfaces.tows[t].name + "'" : std::string("the matrix"); };

    // Discrete surfaces: each shell's own triangles, then each region's (its primary's copy).
    struct Surface {
        int tag = 0;
        std::vector<std::size_t> nodes;     // classified here: nodes no earlier surface used
        std::vector<std::size_t> triangles; // 3 node tags each
        /// Its triangles as node indices (Gmsh's tags are the indices + 1).
        std::vector<std::array<std::size_t, 3>> indexed() const
        {
            std::vector<std::array<std::size_t, 3>> out;
            for (std::size_t k = 0; k + 2 < triangles.size(); k += 3) out.push_back({triangles[k] - 1, triangles[k + 1] - 1, triangles[k + 2] - 1});
            return out;
        }
    };
    std::vector<Surface> patches;
    constexpr std::size_t kNoTow = static_cast<std::size_t>(-1);
    std::vector<std::array<std::size_t, 2>> patchTows;  // the tows (towCount: the matrix) each patch bounds
    std::vector<std::vector<int>> bounds(volumeTow.size());
    std::vector<char> classified(surfaces.nodes.size(), 0);
    // No triangle twice (regions sharing one): each given one's sorted nodes and who gave it,
    // checked once all are in.
    std::vector<std::pair<std::array<std::size_t, 3>, std::size_t>> given;
    std::vector<std::string> giver;
    const auto add = [&](Surface& s, const std::array<std::size_t, 3>& tri) {
        auto key = tri;
        std::sort(key.begin(), key.end());
        given.emplace_back(key, giver.size() - 1);
        for (std::size_t n : tri) {
            if (!classified[n]) {
                classified[n] = 1;
                s.nodes.push_back(n);
            }
            s.triangles.push_back(n + 1);
        }
    };
    // Each shell's own triangles in parts: on the cell's faces (its caps where the cell cut it),
    // and the rest, which the matrix shares, split by the matrix's piece it bounds.
    const auto matrixPiece = [&](std::size_t boundaryTriangle) { return firstVolume[towCount] + pieceOfShell[matrixShell[boundaryTriangle]]; };
    for (std::size_t t = 0; t < towCount; ++t) {
        const TowMesh& m = surfaces.tows[t];
        giver.push_back(nameOf(t));
        std::map<std::pair<std::size_t, std::size_t>, Surface> parts;  // (volume, matrix volume or kNoTow)
        for (std::size_t k = 0, free = firstFree[t]; k < m.triangles.size(); ++k) {
            if (m.region[k] >= 0) continue;
            const bool cellPart = onCellFace(m, k);
            const std::size_t beside = !matrix || cellPart ? kNoTow : matrixPiece(free++);
            add(parts[{firstVolume[t] + shell[t][k], beside}], m.triangles[k]);
        }
        for (auto& [key, part] : parts) {
            part.tag = static_cast<int>(patches.size()) + 1;
            bounds[key.first].push_back(part.tag);
            if (key.second != kNoTow) bounds[key.second].push_back(-part.tag);  // the tow's outward normal points into the matrix
            patches.push_back(std::move(part));
            patchTows.push_back({t, key.second == kNoTow ? kNoTow : towCount});
        }
    }
    if (matrix) {  // the box's faces minus the tows' caps, outward, by face and piece
        const CellMesh& cell = *surfaces.cell;
        giver.push_back("the cell's faces");
        std::map<std::pair<std::size_t, std::size_t>, Surface> parts;  // (face, matrix volume)
        for (std::size_t k = 0; k < cell.triangles.size(); ++k) add(parts[{static_cast<std::size_t>(cell.face.at(k)), matrixPiece(k)}], cell.triangles[k]);
        for (auto& [key, part] : parts) {
            part.tag = static_cast<int>(patches.size()) + 1;
            bounds[key.second].push_back(part.tag);
            patches.push_back(std::move(part));
            patchTows.push_back({towCount, kNoTow});
        }
    }
    // A region's triangles, split by the shells they lie on (a third tow may cut a region's
    // tows into pieces): one surface per (primary's shell, secondary's shell).
    for (std::size_t r = 0; r < surfaces.regions.size(); ++r) {
        const ConnectedRegion& reg = surfaces.regions[r];
        if (reg.primary >= towCount || reg.secondary >= towCount)
            throw Error(ErrorCode::InvalidArgument, "region " + std::to_string(r + 1) + " names a tow out of range");
        const TowMesh& primary = surfaces.tows[reg.primary];
        const TowMesh& secondary = surfaces.tows[reg.secondary];
        giver.push_back("region " + std::to_string(r + 1));
        std::vector<std::pair<std::array<std::size_t, 3>, std::size_t>> onSecondary;  // sorted nodes, the secondary's triangle
        for (std::size_t k = 0; k < secondary.triangles.size(); ++k)
            if (secondary.region[k] == static_cast<long>(r)) {
                auto key = secondary.triangles[k];
                std::sort(key.begin(), key.end());
                onSecondary.emplace_back(key, k);
            }
        std::sort(onSecondary.begin(), onSecondary.end());
        std::map<std::pair<std::size_t, std::size_t>, Surface> parts;
        for (std::size_t k : reg.triangles) {
            if (k >= primary.triangles.size())
                throw Error(ErrorCode::InvalidArgument, "region " + std::to_string(r + 1) + " names a triangle out of range");
            auto key = primary.triangles[k];
            std::sort(key.begin(), key.end());
            const auto copy = std::lower_bound(onSecondary.begin(), onSecondary.end(), std::make_pair(key, std::size_t(0)));
            if (copy == onSecondary.end() || copy->first != key)
                throw Error(ErrorCode::InvalidArgument, "region " + std::to_string(r + 1) + ": a triangle is not on its secondary tow's surface");
            Surface& part = parts[{shell[reg.primary][k], shell[reg.secondary][copy->second]}];
            add(part, primary.triangles[k]);
        }
        for (auto& [shells, part] : parts) {
            part.tag = static_cast<int>(patches.size()) + 1;
            bounds[firstVolume[reg.primary] + shells.first].push_back(part.tag);
            bounds[firstVolume[reg.secondary] + shells.second].push_back(-part.tag);  // the primary's orientation: inward for the secondary
            patches.push_back(std::move(part));
            patchTows.push_back({reg.primary, reg.secondary});
        }
    }
    std::sort(given.begin(), given.end());
    for (std::size_t i = 1; i < given.size(); ++i)
        if (given[i].first == given[i - 1].first) {
            const std::size_t a = std::min(given[i].second, given[i - 1].second), b = std::max(given[i].second, given[i - 1].second);
            if (b < towCount && a != b) {
                // Two tows' own surfaces on the same three nodes (loop nodes of both): they touch
                // with no gap there, the limit of the sharp wedge refused below.
                const auto& tri = given[i].first;
                const Point3 at = (1.0 / 3.0) * (surfaces.nodes[tri[0]] + surfaces.nodes[tri[1]] + surfaces.nodes[tri[2]]);
                std::ostringstream text;
                text << giver[a] << " and " << giver[b] << ": a surface triangle near (" << at.x << ", " << at.y << ", " << at.z
                     << ") is on both tows' own surfaces: no tetrahedron fits between them (tows touching tangentially, e.g. "
                        "pressed flat together; the shrink method leaves a gap)";
                throw Error(ErrorCode::Unsupported, text.str());
            }
            throw Error(ErrorCode::InvalidArgument, giver[b] + ": a surface triangle belongs to two regions or to a region and a tow's own surface");
        }
    for (std::size_t v = 0; v < bounds.size(); ++v)
        if (bounds[v].empty()) throw Error(ErrorCode::Internal, nameOf(volumeTow[v]) + ": a piece of it has no surface");
    // What the tetrahedra must fill (checked after meshing): each tow's surface faces out.
    std::vector<double> enclosed;
    for (std::size_t t = 0; t < towCount; ++t) {
        enclosed.push_back(detail::signedVolume(surfaces.nodes, surfaces.tows[t].triangles));
        if (!surfaces.tows[t].triangles.empty() && !(enclosed.back() > 0.0))  // none: wholly outside a cell
            throw Error(ErrorCode::InvalidArgument, nameOf(t) + ": its surface encloses a volume of " + std::to_string(enclosed.back()) +
                                                        ": its triangles must face out (counter-clockwise seen from outside)");
    }
    if (matrix) enclosed.push_back(matrixVolume);

    std::vector<const std::vector<std::size_t>*> patchTriangles;
    for (const Surface& s : patches) patchTriangles.push_back(&s.triangles);
    // The tows (and the matrix) two patches bound.
    const auto bounding = [&](std::size_t a, std::size_t b) {
        std::vector<std::size_t> involved;
        for (std::size_t t : {patchTows[a][0], patchTows[a][1], patchTows[b][0], patchTows[b][1]})
            if (t != kNoTow && std::find(involved.begin(), involved.end(), t) == involved.end()) involved.push_back(t);
        std::sort(involved.begin(), involved.end());
        return involved;
    };
    const auto names = [&](const std::vector<std::size_t>& involved) {
        std::string who;
        for (std::size_t i = 0; i < involved.size(); ++i)
            who += (i == 0 ? "" : i + 1 == involved.size() ? " and " : ", ") + nameOf(involved[i]);
        return who;
    };
    // Triangles crossing each other (a tow whose surface folds, surfaces passing through each
    // other) stop HXT late, after its other work, with "a segment and a facet intersect at
    // (x, y, z)". Looked for only then (about 20 s on a scan's cell of 3.3 M triangles, against
    // the 50 s HXT had spent), to refuse naming the surfaces; @p gmshSaid is Gmsh's message.
    const auto refuseCrossings = [&](const std::string& gmshSaid) {
        const std::optional<detail::TriangleCrossing> crossing = detail::firstCrossing(surfaces.nodes, patchTriangles);
        if (!crossing) return;
        // A patch's own tow (towCount: the cell's faces), and the tows it bounds.
        const std::size_t ownA = patchTows[crossing->surfaceA][0], ownB = patchTows[crossing->surfaceB][0];  // towCount: the cell's faces
        std::ostringstream text;
        text.precision(6);
        // A tow's surface is its own patch and its regions': two patches of one tow cross it.
        std::size_t common = kNoTow;
        for (std::size_t a : patchTows[crossing->surfaceA])
            for (std::size_t b : patchTows[crossing->surfaceB])
                if (a == b && a < towCount && common == kNoTow) common = a;
        const bool itself = common != kNoTow;
        if (itself) {
            text << nameOf(common) << ": its surface crosses itself";
        } else {
            std::vector<std::size_t> involved = bounding(crossing->surfaceA, crossing->surfaceB);
            involved.erase(std::remove(involved.begin(), involved.end(), towCount), involved.end());  // the matrix
            const bool faces = ownA == towCount || ownB == towCount;
            text << names(involved) << (involved.empty() ? "" : faces ? " and " : "") << (faces ? "the cell's faces" : "")
                 << ": their surfaces cross";
        }
        text << " near (" << crossing->at.x << ", " << crossing->at.y << ", " << crossing->at.z << ") (" << crossing->pairs
             << " crossing triangle pair(s) in all; Gmsh: " << gmshSaid << "): no volume mesh fits there";
        if (itself)
            text << ". A tow's surface folds where it bends sharper than it is thick between sections far apart (a cubic "
                    "through them overshoots; TowResolution::fold): denser sections there unfold it";
        throw Error(ErrorCode::Unsupported, text.str());
    };
    {
        // Surfaces meeting at an angle below HXT's tolerance (tows touching tangentially) stop it
        // with a message on the terminal: refused here, before Gmsh, naming the tows and the place.
        if (const std::optional<detail::FacetFold> fold = detail::sharpestFold(surfaces.nodes, patchTriangles, kHxtFoldTolerance)) {
            const std::string who = names(bounding(fold->surfaceA, fold->surfaceB));
            std::ostringstream text;
            text.precision(2);
            text << who << ": two surface triangles on an edge meet at " << fold->angle * kDegree << " degrees near (";
            text.precision(6);
            text << fold->at.x << ", " << fold->at.y << ", " << fold->at.z << "), below the " << std::setprecision(2)
                 << kHxtFoldTolerance * kDegree
                 << " degrees Gmsh's HXT needs: no tetrahedron fits in that wedge (tows touching tangentially, e.g. pressed "
                    "flat together; the shrink method leaves a gap)";
            throw Error(ErrorCode::Unsupported, text.str());
        }
    }

    // Sizes growing away from the surfaces (none: the surfaces' sizes interpolated inside).
    std::optional<detail::GradedSize> grading;
    if (options.growthRate > 1.0) {
        std::vector<std::array<std::size_t, 3>> all;
        for (const Surface& s : patches) {
            const std::vector<std::array<std::size_t, 3>> own = s.indexed();
            all.insert(all.end(), own.begin(), own.end());
        }
        grading.emplace(surfaces.nodes, all, options.growthRate - 1.0, options.maxSize > 0.0 ? options.maxSize : -kAutoMaxSize);
    }

    VolumeMesh out;
    out.nodes = surfaces.nodes;
    out.surfaceNodes = surfaces.nodes.size();
    out.growthRate = grading ? options.growthRate : 1.0;
    out.maxSize = grading ? grading->largest() : 0.0;
    out.withMatrix = matrix;
    const Gmsh g;  // loads Gmsh's library (EngineUnavailable if it cannot)
    const detail::GmshApi& api = g.api();
    std::unique_lock<std::mutex> lock(gmshMutex());
    std::string where = "the tows' volumes";  // for messages
    bool hxtStopped = false;  // Gmsh's mesh generation failed (threw, logged an error, or left a volume empty)
    try {
        GmshSession session(g);
        for (Surface& s : patches) {
            g.call("gmshModelAddDiscreteEntity", api.gmshModelAddDiscreteEntity, 2, s.tag, nullptr, std::size_t(0));
            std::vector<std::size_t> tags;
            std::vector<double> coords;
            for (std::size_t n : s.nodes) {
                tags.push_back(n + 1);
                coords.insert(coords.end(), {surfaces.nodes[n].x, surfaces.nodes[n].y, surfaces.nodes[n].z});
            }
            g.call("gmshModelMeshAddNodes", api.gmshModelMeshAddNodes, 2, s.tag, tags.data(), tags.size(), coords.data(), coords.size(),
                   nullptr, std::size_t(0));
            g.call("gmshModelMeshAddElementsByType", api.gmshModelMeshAddElementsByType, s.tag, 2, nullptr, std::size_t(0),
                   s.triangles.data(), s.triangles.size());
        }
        // Each tow a volume of the built-in kernel bounded by its discrete surfaces (Gmsh meshes
        // those; a discrete volume it leaves empty).
        for (std::size_t v = 0; v < bounds.size(); ++v) {
            if (bounds[v].empty()) continue;
            int loop = g.call("gmshModelGeoAddSurfaceLoop", api.gmshModelGeoAddSurfaceLoop, bounds[v].data(), bounds[v].size(), -1);
            g.call("gmshModelGeoAddVolume", api.gmshModelGeoAddVolume, &loop, std::size_t(1), static_cast<int>(v) + 1);
        }
        g.call("gmshModelGeoSynchronize", api.gmshModelGeoSynchronize);
        const auto option = [&](const char* name, double value) { g.call("gmshOptionSetNumber", api.gmshOptionSetNumber, name, value); };
        option("Mesh.Algorithm3D", 10);  // HXT
        option("Mesh.Optimize", options.optimize ? 1 : 0);
        // HXT runs on General.NumThreads threads: 0 there means one (not one per hardware
        // thread, as options.threads == 0 does here).
        const double threads = static_cast<double>(detail::workerCount(options.threads));
        option("General.NumThreads", threads);
        option("Mesh.MaxNumThreads3D", threads);
        option("Mesh.Renumber", 0);  // keep the surface nodes' tags (= index + 1)
        // Linear elements from generate() whatever the host set (order 2 comes after the check
        // below), no subdivision, no high-order optimisation.
        option("Mesh.ElementOrder", 1);
        option("Mesh.SubdivisionAlgorithm", 0);
        option("Mesh.HighOrderOptimize", 0);
        // Sizes from towgeom's field alone, or (no grading) the surfaces' interpolated inside,
        // whatever the host set.
        option("Mesh.MeshSizeExtendFromBoundary", grading ? 0 : 1);
        option("Mesh.MeshSizeMin", 0);  // Gmsh's defaults: no bound, no scaling
        option("Mesh.MeshSizeMax", 1e22);
        option("Mesh.MeshSizeFactor", 1);
        option("Mesh.MeshSizeFromCurvature", 0);
        option("Mesh.MeshSizeFromPoints", 1);
        if (grading) {
            g.call("gmshModelMeshSetSizeCallback", api.gmshModelMeshSetSizeCallback, &gradedSizeAt, static_cast<void*>(&*grading));
        }
        const auto generateStart = std::chrono::steady_clock::now();
        // Gmsh 4.8 throws an error out of its mesh generation before it releases its own lock
        // (CTX::lock, released only at the end of GenerateMesh): every later generate in the
        // process would then return at once, meshing nothing. So here an error stops the meshing
        // without throwing (AbortOnError 1), and an error logged during it (generate clears the
        // last one when it starts), or a volume left without tetrahedra (below), is the failure.
        // Either way its cause is looked for out of Gmsh's session and towgeom's lock
        // (hxtStopped). A sentinel error logged first tells a generate that never ran (the lock
        // held by a host's call that threw) from one that failed.
        option("General.AbortOnError", 1);
        double unused = 0.0;
        int sentinelError = 0;
        api.gmshOptionGetNumber(kSentinelOption, &unused, &sentinelError);  // logs "... option ..." as the last error
        const std::string sentinel = detail::gmshLastErrorText(api);
        try {
            g.call("gmshModelMeshGenerate", api.gmshModelMeshGenerate, 3);
        } catch (...) {
            hxtStopped = true;
            throw;
        }
        option("General.AbortOnError", 3);
        if (const std::string error = detail::gmshLastErrorText(api); !sentinel.empty() && error == sentinel) {
            throw Error(ErrorCode::Internal, "Gmsh's mesh generation did not run: Gmsh is locked by an earlier call in this process that "
                                             "failed (a generate outside towgeom that threw); restart the process");
        } else if (!error.empty()) {
            hxtStopped = true;
            throw std::runtime_error("its mesh generation failed (last error: " + error + ")");
        }
        // Gmsh's tetrahedral optimiser once more, forced (its Mesh.Optimize pass leaves flat
        // tetrahedra HXT makes with a size callback: a point inserted a hair from a surface
        // triangle, 2e-20 in volume beside a region of a scan-like cell; CalculiX's uniform strain
        // was then off by 0.15 %).
        if (options.optimize) g.call("gmshModelMeshOptimize", api.gmshModelMeshOptimize, "", 1, 1, nullptr, std::size_t(0));
        // HXT on several threads varies run to run, and now and then a flat tetrahedron (2.8e-20
        // in a cell of 1.1) survives that pass: CalculiX's uniform strain was then 0.17-3.5 % off
        // (seed 1's first random box of tests/test_cell_any_box.cpp, 1 run in 5 two at a time).
        // Optimising again did not always remove it (an inner node a hair from a surface
        // triangle), so each retry first relocates the inner nodes (Gmsh's "Relocate3D": each
        // moved to the best place for its tetrahedra, the surface nodes fixed), then optimises;
        // while their count falls, at most twice. In 12 runs after the change one flat
        // tetrahedron (3.5e-17 of its edge cubed) was left by HXT and removed so, the strain as
        // in the other runs (3e-7). (Debian's Gmsh 4.8 has no Netgen optimiser.)
        if (options.optimize)
            for (std::size_t attempt = 0, flat = flatTetrahedra(g); attempt < 2 && flat > 0; ++attempt) {
                g.call("gmshModelMeshOptimize", api.gmshModelMeshOptimize, "Relocate3D", 1, 1, nullptr, std::size_t(0));
                g.call("gmshModelMeshOptimize", api.gmshModelMeshOptimize, "", 1, 1, nullptr, std::size_t(0));
                const std::size_t left = flatTetrahedra(g);
                if (left >= flat) break;
                flat = left;
            }

        const auto nodesOn = [&](int dim, std::vector<std::size_t>& tags, std::vector<double>& coords) {
            std::size_t* t = nullptr;
            double *c = nullptr, *p = nullptr;
            std::size_t nt = 0, nc = 0, np = 0;
            g.call("gmshModelMeshGetNodes", api.gmshModelMeshGetNodes, &t, &nt, &c, &nc, &p, &np, dim, -1, 0, 0);
            tags = detail::gmshTake(api, t, nt);
            coords = detail::gmshTake(api, c, nc);
            detail::gmshTake(api, p, np);
        };
        // No node may have been added on a surface (the surfaces are the tows' interfaces); then
        // quadratic tetrahedra get their middle nodes (checked below, edge by edge).
        std::vector<std::size_t> tags;
        std::vector<double> coords;
        nodesOn(2, tags, coords);
        for (std::size_t n : tags)
            if (n > surfaces.nodes.size() || !classified[n - 1])
                throw Error(ErrorCode::Internal, "Gmsh added a node on a tow's surface while meshing the volumes");
        if (quadratic) g.call("gmshModelMeshSetOrder", api.gmshModelMeshSetOrder, 2);
        out.gmshSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - generateStart).count();
        // Every node: the surface's keep their indices, Gmsh's new ones are appended.
        nodesOn(-1, tags, coords);
        std::vector<std::size_t> index;  // by Gmsh tag
        std::vector<std::size_t> added;  // positions in tags of the nodes Gmsh added
        for (std::size_t k = 0; k < tags.size(); ++k) {
            const std::size_t tag = tags[k];
            if (index.size() <= tag) index.resize(tag + 1, SIZE_MAX);
            if (tag <= surfaces.nodes.size() && classified[tag - 1]) {
                const Point3 at{coords[3 * k], coords[3 * k + 1], coords[3 * k + 2]};
                if (!(distance(surfaces.nodes[tag - 1], at) == 0.0))
                    throw Error(ErrorCode::Internal, "Gmsh moved or renumbered surface node " + std::to_string(tag));
                index[tag] = tag - 1;
            } else {
                added.push_back(k);
            }
        }
        // HXT on several threads (Gmsh 4.8) may insert one point twice, as two nodes with the
        // same coordinates, each with its own tetrahedra: a crack of zero width. Nodes at the same
        // point are one node (then every inner face is shared by two tetrahedra again), the first
        // in Gmsh's order; the others keep Gmsh's order.
        const auto at = [&](std::size_t k) { return std::make_tuple(coords[3 * k], coords[3 * k + 1], coords[3 * k + 2]); };
        std::vector<std::size_t> byPlace = added;
        std::stable_sort(byPlace.begin(), byPlace.end(), [&](std::size_t a, std::size_t b) { return at(a) < at(b); });
        std::vector<std::size_t> same(tags.size(), SIZE_MAX);  // by position in tags: the first node at its point
        for (std::size_t i = 1; i < byPlace.size(); ++i)
            if (at(byPlace[i]) == at(byPlace[i - 1])) same[byPlace[i]] = same[byPlace[i - 1]] == SIZE_MAX ? byPlace[i - 1] : same[byPlace[i - 1]];
        for (std::size_t k : added) {
            if (same[k] != SIZE_MAX) {
                index[tags[k]] = index[tags[same[k]]];
                continue;
            }
            index[tags[k]] = out.nodes.size();
            out.nodes.push_back({coords[3 * k], coords[3 * k + 1], coords[3 * k + 2]});
        }
        const auto node = [&](std::size_t tag) {
            if (tag >= index.size() || index[tag] == SIZE_MAX) throw Error(ErrorCode::Internal, "Gmsh gave a tetrahedron an unknown node");
            return index[tag];
        };
        for (std::size_t v = 0; v < bounds.size(); ++v) {
            if (bounds[v].empty()) continue;
            const std::size_t t = volumeTow[v];
            where = nameOf(t);
            std::size_t *e = nullptr, *n = nullptr, ne = 0, nn = 0;
            const int type = quadratic ? 11 : 4;  // 10-node or 4-node tetrahedra
            const std::size_t per = quadratic ? 10 : 4;
            g.call("gmshModelMeshGetElementsByType", api.gmshModelMeshGetElementsByType, type, &e, &ne, &n, &nn, static_cast<int>(v) + 1,
                   std::size_t(0), std::size_t(1));
            const std::vector<std::size_t> elements = detail::gmshTake(api, e, ne), nodes = detail::gmshTake(api, n, nn);
            if (elements.empty() || nodes.size() != per * elements.size()) {
                hxtStopped = true;
                throw Error(ErrorCode::Internal, "Gmsh made no tetrahedron (" + detail::gmshLastError(api) + ")");
            }
            for (std::size_t k = 0; k < elements.size(); ++k) {
                const std::size_t* q = &nodes[per * k];
                std::array<std::size_t, 4> tet{node(q[0]), node(q[1]), node(q[2]), node(q[3])};
                if (signedVolume(out.nodes[tet[0]], out.nodes[tet[1]], out.nodes[tet[2]], out.nodes[tet[3]]) < 0.0) std::swap(tet[2], tet[3]);
                out.tetrahedra.push_back(tet);
                out.tow.push_back(t);
                if (quadratic) out.edgeNodes.push_back(middleNodes(out.nodes, tet, {node(q[4]), node(q[5]), node(q[6]), node(q[7]), node(q[8]), node(q[9])}));
            }
        }
    } catch (const Error& e) {
        if (hxtStopped) {
            lock.unlock();
            refuseCrossings(e.message());
        }
        throw Error(e.code(), where + ": " + e.message());
    } catch (const std::exception& e) {
        if (hxtStopped) {
            lock.unlock();
            refuseCrossings(e.what());
        }
        throw Error(ErrorCode::Internal, "Gmsh failed meshing " + where + ": " + e.what());
    }
    lock.unlock();  // Gmsh is done
    // Checked here, not trusted to Gmsh: the tetrahedra conform to each other and to the
    // surfaces, and fill each tow's surface (and the matrix's).
    detail::ConformityTarget target;
    for (std::size_t s = 0; s < patches.size(); ++s) {
        auto& list = patchTows[s][1] == kNoTow ? target.outer : target.between;
        const std::vector<std::array<std::size_t, 3>> own = patches[s].indexed();
        list.insert(list.end(), own.begin(), own.end());
    }
    target.volume = std::move(enclosed);
    for (std::size_t t = 0; t < target.volume.size(); ++t) target.name.push_back(nameOf(t));
    detail::checkConformity(out, target, detail::workerCount(options.threads));
    return out;
}

std::vector<UnresolvedPairEntry> overlappingPairs(const ResolveResult& result)
{
    // A tow with no triangles (wholly outside a cell) overlaps nothing in the mesh, whatever the
    // report's findings (which have no place) say about it.
    const auto meshed = [&](std::size_t t) { return t < result.mesh.tows.size() && !result.mesh.tows[t].triangles.empty(); };
    std::vector<UnresolvedPairEntry> pairs = unresolvedPairs(result);
    pairs.erase(std::remove_if(pairs.begin(), pairs.end(),
                               [&](const UnresolvedPairEntry& p) { return p.code == "not_separated" || !meshed(p.towA) || !meshed(p.towB); }),
                pairs.end());
    return pairs;
}

VolumeMesh meshVolumes(const ResolveResult& result, const VolumeMeshOptions& options)
{
    const std::vector<UnresolvedPairEntry> pairs = overlappingPairs(result);
    if (!pairs.empty()) {
        const UnresolvedPairEntry& p = pairs.front();
        const auto name = [&](std::size_t t) { return t < result.mesh.tows.size() ? result.mesh.tows[t].name : std::to_string(t); };
        std::set<std::pair<std::size_t, std::size_t>> distinct;  // a pair may have several reasons
        for (const UnresolvedPairEntry& q : pairs) distinct.insert({q.towA, q.towB});
        const std::size_t more = distinct.size() - 1;
        std::string others;
        if (more > 0) others = " (and " + std::to_string(more) + (more == 1 ? " other pair)" : " other pairs)");
        throw Error(ErrorCode::InvalidArgument, "tows '" + name(p.towA) + "' and '" + name(p.towB) + "' still overlap [" + p.code +
                                                    "]: " + p.message + others + "; their tetrahedra would overlap: no volume mesh");
    }
    return meshVolumes(result.mesh, options);
}

TOWGEOM_END_NAMESPACE
