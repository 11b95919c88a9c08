// Tetrahedra inside the resolved tows with Gmsh: each tow's own triangles and each region's
// triangles become discrete surfaces (the nodes and triangles as they are), each tow a discrete
// volume bounded by its surfaces, meshed by HXT.
#include "towgeom/volume_mesh.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <mutex>
#include <string>

#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

/// Gmsh holds one global state: one caller at a time.
std::mutex& gmshMutex()
{
    static std::mutex m;
    return m;
}

double signedVolume(const Point3& a, const Point3& b, const Point3& c, const Point3& d)
{
    return dot(cross(b - a, c - a), d - a) / 6.0;
}

/// Gmsh started for one call (unless the host runs it): finalised, or the model removed, on exit.
class GmshSession {
public:
    GmshSession()
    {
        // Gmsh 4.8 has no isInitialized(): uninitialised, its calls do nothing, so an option
        // read leaves the value as it was.
        double probe = -1.0;
        try {
            gmsh::option::getNumber("General.Terminal", probe);
        } catch (...) {
        }
        hostOwned_ = probe != -1.0;
        if (!hostOwned_) gmsh::initialize(0, nullptr, false);
        gmsh::option::getNumber("General.Terminal", terminal_);
        gmsh::option::setNumber("General.Terminal", 0);
        gmsh::model::add(kModel);
    }
    ~GmshSession()
    {
        try {
            gmsh::model::setCurrent(kModel);
            gmsh::model::remove();
            gmsh::option::setNumber("General.Terminal", terminal_);
            if (!hostOwned_) gmsh::finalize();
        } catch (...) {
        }
    }
    GmshSession(const GmshSession&) = delete;
    GmshSession& operator=(const GmshSession&) = delete;

private:
    static constexpr const char* kModel = "towgeom_volumes";
    bool hostOwned_ = false;
    double terminal_ = 0.0;
};

/// Gmsh's last error message, for an exception it threw.
std::string gmshError()
{
    std::string last;
    try {
        gmsh::logger::getLastError(last);
    } catch (...) {
    }
    return last.empty() ? std::string("no message") : last;
}

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

VolumeMesh meshVolumes(const TextileMesh& surfaces, const VolumeMeshOptions& options)
{
    const std::size_t towCount = surfaces.tows.size();
    for (std::size_t t = 0; t < towCount; ++t)
        if (surfaces.boundaryLoopCount(t) != 0)
            throw Error(ErrorCode::InvalidArgument, "tow '" + surfaces.tows[t].name + "': its surface mesh is not closed (" +
                                                        std::to_string(surfaces.boundaryLoopCount(t)) +
                                                        " boundary loops): volumes need tows closed by their end caps");

    // Discrete surfaces: 1..T each tow's own triangles, T+1.. each region's (its primary's copy).
    struct Surface {
        int tag;
        std::vector<std::size_t> nodes;     // classified here: nodes no earlier surface used
        std::vector<std::size_t> triangles; // 3 node tags each
    };
    std::vector<Surface> patches;
    std::vector<std::vector<int>> bounds(towCount);
    std::vector<char> classified(surfaces.nodes.size(), 0);
    const auto add = [&](Surface& s, const std::array<std::size_t, 3>& tri) {
        for (std::size_t n : tri) {
            if (!classified[n]) {
                classified[n] = 1;
                s.nodes.push_back(n);
            }
            s.triangles.push_back(n + 1);
        }
    };
    for (std::size_t t = 0; t < towCount; ++t) {
        Surface s{static_cast<int>(patches.size()) + 1, {}, {}};
        const TowMesh& m = surfaces.tows[t];
        for (std::size_t k = 0; k < m.triangles.size(); ++k)
            if (m.region[k] < 0) add(s, m.triangles[k]);
        if (s.triangles.empty()) continue;
        bounds[t].push_back(s.tag);
        patches.push_back(std::move(s));
    }
    for (const ConnectedRegion& g : surfaces.regions) {
        Surface s{static_cast<int>(patches.size()) + 1, {}, {}};
        for (std::size_t k : g.triangles) add(s, surfaces.tows[g.primary].triangles[k]);
        if (s.triangles.empty()) continue;
        bounds[g.primary].push_back(s.tag);
        bounds[g.secondary].push_back(-s.tag);  // the primary's orientation: inward for the secondary
        patches.push_back(std::move(s));
    }

    VolumeMesh out;
    out.nodes = surfaces.nodes;
    out.surfaceNodes = surfaces.nodes.size();
    std::lock_guard<std::mutex> lock(gmshMutex());
    GmshSession session;
    std::string where = "the tows' volumes";  // for messages
    try {
        for (const Surface& s : patches) {
            gmsh::model::addDiscreteEntity(2, s.tag);
            std::vector<std::size_t> tags;
            std::vector<double> coords;
            for (std::size_t n : s.nodes) {
                tags.push_back(n + 1);
                coords.insert(coords.end(), {surfaces.nodes[n].x, surfaces.nodes[n].y, surfaces.nodes[n].z});
            }
            gmsh::model::mesh::addNodes(2, s.tag, tags, coords);
            gmsh::model::mesh::addElementsByType(s.tag, 2, {}, s.triangles);
        }
        // Each tow a volume of the built-in kernel bounded by its discrete surfaces (Gmsh meshes
        // those; a discrete volume it leaves empty).
        for (std::size_t v = 0; v < towCount; ++v)
            if (!bounds[v].empty())
                gmsh::model::geo::addVolume({gmsh::model::geo::addSurfaceLoop(bounds[v])}, static_cast<int>(v) + 1);
        gmsh::model::geo::synchronize();
        gmsh::option::setNumber("Mesh.Algorithm3D", 10);  // HXT
        gmsh::option::setNumber("Mesh.Optimize", options.optimize ? 1 : 0);
        gmsh::option::setNumber("General.NumThreads", static_cast<double>(options.threads));
        gmsh::option::setNumber("Mesh.Renumber", 0);  // keep the surface nodes' tags (= index + 1)
        gmsh::model::mesh::generate(3);

        // No node may have been added on a surface (the surfaces are the tows' interfaces).
        std::vector<std::size_t> tags;
        std::vector<double> coords, params;
        gmsh::model::mesh::getNodes(tags, coords, params, 2, -1, false, false);
        for (std::size_t n : tags)
            if (n > surfaces.nodes.size() || !classified[n - 1])
                throw Error(ErrorCode::Internal, "Gmsh added a node on a tow's surface while meshing the volumes");
        // Every node: the surface's keep their indices, Gmsh's new ones (whatever their tags:
        // Gmsh numbers on from the largest tag it was given) are appended.
        gmsh::model::mesh::getNodes(tags, coords, params, -1, -1, false, false);
        std::vector<std::size_t> index;  // by Gmsh tag
        for (std::size_t k = 0; k < tags.size(); ++k) {
            const std::size_t tag = tags[k];
            if (index.size() <= tag) index.resize(tag + 1, SIZE_MAX);
            const bool ours = tag <= surfaces.nodes.size() && classified[tag - 1];
            if (ours) {
                const Point3 at{coords[3 * k], coords[3 * k + 1], coords[3 * k + 2]};
                if (!(distance(surfaces.nodes[tag - 1], at) == 0.0))
                    throw Error(ErrorCode::Internal, "Gmsh moved or renumbered surface node " + std::to_string(tag));
                index[tag] = tag - 1;
            } else {
                index[tag] = out.nodes.size();
                out.nodes.push_back({coords[3 * k], coords[3 * k + 1], coords[3 * k + 2]});
            }
        }
        const auto node = [&](std::size_t tag) {
            if (tag >= index.size() || index[tag] == SIZE_MAX) throw Error(ErrorCode::Internal, "Gmsh gave a tetrahedron an unknown node");
            return index[tag];
        };
        for (std::size_t t = 0; t < towCount; ++t) {
            if (bounds[t].empty()) continue;
            where = "tow '" + surfaces.tows[t].name + "'";
            std::vector<std::size_t> elements, nodes;
            gmsh::model::mesh::getElementsByType(4, elements, nodes, static_cast<int>(t) + 1);
            if (elements.empty()) throw Error(ErrorCode::Internal, "Gmsh made no tetrahedron");
            for (std::size_t e = 0; e < elements.size(); ++e) {
                std::array<std::size_t, 4> tet{node(nodes[4 * e]), node(nodes[4 * e + 1]), node(nodes[4 * e + 2]), node(nodes[4 * e + 3])};
                if (signedVolume(out.nodes[tet[0]], out.nodes[tet[1]], out.nodes[tet[2]], out.nodes[tet[3]]) < 0.0) std::swap(tet[2], tet[3]);
                out.tetrahedra.push_back(tet);
                out.tow.push_back(t);
            }
        }
    } catch (const Error& e) {
        throw Error(e.code(), where + ": " + e.message());
    } catch (const std::exception& e) {
        throw Error(ErrorCode::Internal, "Gmsh failed meshing " + where + ": " + e.what() + " (" + gmshError() + ")");
    } catch (...) {
        throw Error(ErrorCode::Internal, "Gmsh failed meshing " + where + ": " + gmshError());
    }
    return out;
}

TOWGEOM_END_NAMESPACE
