// Gmsh .msh 4.1 (ASCII) and Abaqus .inp, from one global node numbering.
#include "towgeom/mesh_export.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <set>

#include <ostream>

#include "export/cell_face_triangles.hpp"
#include "export/edge_middles.hpp"
#include "export/number_writer.hpp"
#include "export/volume_mesh_checks.hpp"
#include "io/output_files.hpp"
#include "towgeom/error.hpp"
#include "towgeom/export.hpp"

TOWGEOM_BEGIN_NAMESPACE

namespace {

using detail::NumberWriter;

/// Abaqus and Gmsh names: letters, digits and underscores.
std::string label(const std::string& prefix, const std::string& name)
{
    std::string s = prefix + name;
    for (char& c : s)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') c = '_';
    return s;
}

std::string upper(std::string s)
{
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

/// The tows' names as set names take them (label() after a prefix of up to 5 characters, such
/// as CAPS_): Abaqus and CalculiX allow 80 characters and do not tell case apart, so a name
/// that is too long, or the same as an earlier one but for case or the characters label()
/// replaces, is cut and given the tow's number (NAME_7).
std::vector<std::string> towLabels(const TextileMesh& mesh)
{
    constexpr std::size_t kLongest = 80 - 5;
    std::vector<std::string> labels;
    std::set<std::string> taken;  // upper-cased
    for (std::size_t t = 0; t < mesh.tows.size(); ++t) {
        const std::string base = label("", mesh.tows[t].name);
        std::string l = base;
        for (std::size_t n = t + 1; l.size() > kLongest || taken.count(upper(l)); n += mesh.tows.size()) {
            const std::string suffix = "_" + std::to_string(n);
            l = base.substr(0, kLongest - suffix.size()) + suffix;
        }
        taken.insert(upper(l));
        labels.push_back(l);
    }
    return labels;
}

/// True when triangle @p k of @p m lies on one of its end caps.
bool isCap(const TowMesh& m, std::size_t k) { return k < m.face.size() && m.face[k] != TowFace::Side; }

/// The face of @p box whose plane the three nodes of @p t lie on (a TowFace::Cell cap's).
CellFace cellFaceOf(const Cell& box, const std::vector<Point3>& nodes, const std::array<std::size_t, 3>& t)
{
    for (int f = 0; f < 6; ++f) {
        const CellFace face = static_cast<CellFace>(f);
        const double at = box.plane(face);
        const auto on = [&](std::size_t n) { return (f < 2 ? nodes[n].x : f < 4 ? nodes[n].y : nodes[n].z) == at; };
        if (on(t[0]) && on(t[1]) && on(t[2])) return face;
    }
    throw Error(ErrorCode::Internal, "a cap on the cell lies on none of its faces");
}

}  // namespace

namespace {

/// Per face of a cell (a mesh clipped to one), *NSET XMIN ... ZMAX: every node on it (with
/// @p middles, a quadratic volume mesh's middle nodes on it too).
void writeCellFaceSets(const TextileMesh& mesh, std::ostream& out, const detail::EdgeMiddles* middles = nullptr)
{
    if (!mesh.cell) return;
    for (std::size_t f = 0; f < 6; ++f) {
        const std::vector<std::size_t> nodes =
            middles ? middles->withMiddles(mesh.cell->faceNodes[f], detail::cellFaceTriangles(mesh, static_cast<CellFace>(f))) : mesh.cell->faceNodes[f];
        if (nodes.empty()) continue;
        out << "*NSET, NSET=" << upper(cellFaceName(static_cast<CellFace>(f))) << '\n';
        for (std::size_t k = 0; k < nodes.size(); ++k) out << nodes[k] + 1 << (k % 16 == 15 || k + 1 == nodes.size() ? "\n" : ", ");
    }
}

/// The tetrahedra of @p volumes by the tow they fill, the matrix's last (index: the tow count).
std::vector<std::vector<std::size_t>> tetrahedraBySolid(const TextileMesh& mesh, const VolumeMesh& volumes)
{
    detail::checkVolumeMeshOf(mesh, volumes);
    std::vector<std::vector<std::size_t>> tets(mesh.tows.size() + 1);
    for (std::size_t k = 0; k < volumes.tetrahedra.size(); ++k) tets[volumes.tow[k]].push_back(k);
    return tets;
}

/// writeGmsh() with, when @p volumes is given, a volume entity per tow holding its tetrahedra.
void writeGmshModel(const TextileMesh& mesh, const VolumeMesh* volumes, std::ostream& out)
{
    if (volumes) detail::checkVolumeMeshOf(mesh, *volumes);
    const std::vector<Point3>& nodes = volumes ? volumes->nodes : mesh.nodes;
    out << std::setprecision(std::numeric_limits<double>::max_digits10);
    // Surface entities, every triangle in one: per tow its tube and its cap triangles outside
    // regions, then per region its triangles (the primary's copy, in both tows' groups; the
    // secondary's reversed copy is the same element), its cap triangles apart. Physical groups:
    // tows 1..T, regions T+1..T+R, then CAPS_NAME per tow with caps.
    struct Entity {
        std::vector<std::array<std::size_t, 3>> triangles;
        std::vector<std::size_t> physical;
        std::vector<std::pair<std::size_t, int>> bounds;  // (tow, +1 outward / -1 inward)
    };
    std::vector<Entity> entities;
    const std::size_t towCount = mesh.tows.size();
    const std::vector<std::string> names = towLabels(mesh);
    // CAPS_NAME groups, numbered after the tows' and the regions'.
    std::vector<std::size_t> capGroup(towCount, 0);
    std::vector<std::pair<std::size_t, std::string>> capGroups;  // (group, name)
    for (std::size_t t = 0; t < towCount; ++t)
        for (std::size_t k = 0; k < mesh.tows[t].triangles.size() && capGroup[t] == 0; ++k)
            if (isCap(mesh.tows[t], k)) {
                capGroup[t] = towCount + mesh.regions.size() + capGroups.size() + 1;
                capGroups.emplace_back(capGroup[t], label("CAPS_", names[t]));
            }
    const auto add = [&](Entity&& e) {
        if (!e.triangles.empty()) entities.push_back(std::move(e));
    };
    // Clipped to a cell: a group per box face (after the caps'), the matrix the volume after the
    // tows' (tag towCount + 1), bounded by the box's faces and the tows' triangles not on them.
    std::array<std::size_t, 6> faceGroup{};
    if (mesh.cell)
        for (std::size_t f = 0; f < 6; ++f) faceGroup[f] = towCount + mesh.regions.size() + capGroups.size() + f + 1;
    const std::size_t matrix = towCount;
    for (std::size_t t = 0; t < towCount; ++t) {
        const TowMesh& m = mesh.tows[t];
        Entity side, caps;
        std::array<Entity, 6> onCell;  // its caps on the cell's faces, per face
        side.physical = {t + 1};
        caps.physical = {t + 1, capGroup[t]};
        side.bounds = caps.bounds = {{t, 1}};
        if (mesh.cell) side.bounds.emplace_back(matrix, -1), caps.bounds.emplace_back(matrix, -1);
        for (std::size_t f = 0; f < 6; ++f) {
            onCell[f].physical = {t + 1, capGroup[t], faceGroup[f]};
            onCell[f].bounds = {{t, 1}};
        }
        for (std::size_t k = 0; k < m.triangles.size(); ++k) {
            if (m.region[k] >= 0) continue;
            const std::size_t end = k < m.face.size() && m.face[k] == TowFace::End ? 1 : 0;
            const bool cellCap = k < m.face.size() && m.face[k] == TowFace::Cell && mesh.cell;
            Entity& e = !isCap(m, k)   ? side
                        : cellCap      ? onCell[static_cast<std::size_t>(cellFaceOf(mesh.cell->box, mesh.nodes, m.triangles[k]))]
                        : m.cutAt[end] ? onCell[static_cast<std::size_t>(*m.cutAt[end])]
                                       : caps;
            e.triangles.push_back(m.triangles[k]);
        }
        add(std::move(side));
        add(std::move(caps));
        for (Entity& e : onCell) add(std::move(e));
    }
    if (mesh.cell)
        for (std::size_t f = 0; f < 6; ++f) {
            Entity e;
            e.physical = {faceGroup[f]};
            e.bounds = {{matrix, 1}};
            for (std::size_t k = 0; k < mesh.cell->triangles.size(); ++k)
                if (static_cast<std::size_t>(mesh.cell->face.at(k)) == f) e.triangles.push_back(mesh.cell->triangles[k]);
            add(std::move(e));
        }
    // A region's triangles once (the primary's copy; once even where regions share one), its
    // cap triangles apart, also in the primary's CAPS_ group.
    std::set<std::pair<std::size_t, std::size_t>> written;
    for (std::size_t r = 0; r < mesh.regions.size(); ++r) {
        const ConnectedRegion& g = mesh.regions[r];
        Entity side, caps;
        side.physical = {g.primary + 1, g.secondary + 1, towCount + r + 1};
        caps.physical = {g.primary + 1, g.secondary + 1, towCount + r + 1, capGroup[g.primary]};
        side.bounds = caps.bounds = {{g.primary, 1}, {g.secondary, -1}};
        for (std::size_t k : g.triangles)
            if (written.emplace(g.primary, k).second)
                (isCap(mesh.tows[g.primary], k) ? caps : side).triangles.push_back(mesh.tows[g.primary].triangles[k]);
        add(std::move(side));
        add(std::move(caps));
    }
    // Volumes (with a volume mesh): one per tow with tetrahedra, its tag the tow's number.
    const std::vector<std::vector<std::size_t>> tets = volumes ? tetrahedraBySolid(mesh, *volumes) : std::vector<std::vector<std::size_t>>(towCount + 1);
    std::vector<std::size_t> solids;  // tows (then the matrix) with tetrahedra
    for (std::size_t t = 0; t <= towCount; ++t)
        if (!tets[t].empty()) solids.push_back(t);
    out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
    // A tow with no triangle (wholly outside a cell) names no group.
    std::size_t towGroups = 0;
    for (const TowMesh& m : mesh.tows) towGroups += m.triangles.empty() ? 0 : 1;
    out << "$PhysicalNames\n" << towGroups + mesh.regions.size() + capGroups.size() + (mesh.cell ? 6 : 0) + solids.size() << '\n';
    for (std::size_t t = 0; t < towCount; ++t)
        if (!mesh.tows[t].triangles.empty()) out << "2 " << t + 1 << " \"" << label("TOW_", names[t]) << "\"\n";
    for (std::size_t r = 0; r < mesh.regions.size(); ++r) out << "2 " << towCount + r + 1 << " \"REGION_" << r + 1 << "\"\n";
    for (const auto& [group, name] : capGroups) out << "2 " << group << " \"" << name << "\"\n";
    if (mesh.cell)
        for (std::size_t f = 0; f < 6; ++f) out << "2 " << faceGroup[f] << " \"" << upper(cellFaceName(static_cast<CellFace>(f))) << "\"\n";
    for (std::size_t t : solids) out << "3 " << t + 1 << " \"" << (t == matrix ? std::string("MATRIX") : label("TOW_", names[t])) << "\"\n";
    out << "$EndPhysicalNames\n";
    // Quadratic tetrahedra: 10-node tetrahedra (Gmsh's order: edges 01, 12, 20, 03, 23, 13) and
    // 6-node triangles (edges 01, 12, 20).
    const bool quadratic = volumes && !volumes->edgeNodes.empty();
    const detail::EdgeMiddles middles = volumes ? detail::EdgeMiddles(*volumes) : detail::EdgeMiddles(VolumeMesh{});
    const auto triangleNodes = [&](const std::array<std::size_t, 3>& t) {
        std::vector<std::size_t> n(t.begin(), t.end());
        if (quadratic)
            for (int e = 0; e < 3; ++e) {
                const std::size_t* m = middles.of(t[static_cast<std::size_t>(e)], t[static_cast<std::size_t>((e + 1) % 3)]);
                if (!m) throw Error(ErrorCode::InvalidArgument, "a surface triangle's edge is no edge of the quadratic tetrahedra");
                n.push_back(*m);
            }
        return n;
    };
    const auto tetNodes = [&](std::size_t k) {
        const auto& q = volumes->tetrahedra[k];
        std::vector<std::size_t> n(q.begin(), q.end());
        if (quadratic)
            for (int e : {0, 1, 2, 3, 5, 4}) n.push_back(volumes->edgeNodes[k][static_cast<std::size_t>(e)]);
        return n;
    };
    // Each node is classified on the first entity that uses it: surfaces first, then volumes.
    std::vector<std::size_t> owner(nodes.size(), 0);
    std::vector<std::vector<std::size_t>> blocks(entities.size()), solidBlocks(solids.size());
    for (std::size_t e = 0; e < entities.size(); ++e)
        for (const auto& t : entities[e].triangles)
            for (std::size_t n : triangleNodes(t))
                if (owner[n] == 0) {
                    owner[n] = e + 1;
                    blocks[e].push_back(n);
                }
    for (std::size_t v = 0; v < solids.size(); ++v)
        for (std::size_t k : tets[solids[v]])
            for (std::size_t n : tetNodes(k))
                if (owner[n] == 0) {
                    owner[n] = entities.size() + v + 1;
                    solidBlocks[v].push_back(n);
                }
    const auto box = [&](auto&& each) {
        Point3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
        each([&](std::size_t n) {
            const Point3& p = nodes[n];
            lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
            hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
        });
        out << lo.x << ' ' << lo.y << ' ' << lo.z << ' ' << hi.x << ' ' << hi.y << ' ' << hi.z;
    };
    out << "$Entities\n0 0 " << entities.size() << ' ' << solids.size() << '\n';
    for (std::size_t e = 0; e < entities.size(); ++e) {
        out << e + 1 << ' ';
        box([&](auto visit) {
            for (const auto& t : entities[e].triangles)
                for (std::size_t n : t) visit(n);
        });
        out << ' ' << entities[e].physical.size();
        for (std::size_t p : entities[e].physical) out << ' ' << p;
        out << " 0\n";
    }
    for (std::size_t t : solids) {
        std::vector<long> bounding;
        for (std::size_t e = 0; e < entities.size(); ++e)
            for (const auto& [tow, sign] : entities[e].bounds)
                if (tow == t) bounding.push_back(sign * static_cast<long>(e + 1));
        out << t + 1 << ' ';
        box([&](auto visit) {
            for (std::size_t k : tets[t])
                for (std::size_t n : volumes->tetrahedra[k]) visit(n);
        });
        out << " 1 " << t + 1 << ' ' << bounding.size();
        for (long b : bounding) out << ' ' << b;
        out << '\n';
    }
    out << "$EndEntities\n";
    std::size_t used = 0;
    for (const auto& b : blocks) used += b.size();
    for (const auto& b : solidBlocks) used += b.size();
    out << "$Nodes\n" << entities.size() + solids.size() << ' ' << used << " 1 " << nodes.size() << '\n';
    {
        NumberWriter w(out);
        const auto block = [&](int dim, std::size_t tag, const std::vector<std::size_t>& ns) {
            w.number(dim).text(" ").number(tag).text(" 0 ").number(ns.size()).end();
            for (std::size_t n : ns) w.number(n + 1).end();
            for (std::size_t n : ns) w.number(nodes[n].x).text(" ").number(nodes[n].y).text(" ").number(nodes[n].z).end();
        };
        for (std::size_t e = 0; e < entities.size(); ++e) block(2, e + 1, blocks[e]);
        for (std::size_t v = 0; v < solids.size(); ++v) block(3, solids[v] + 1, solidBlocks[v]);
    }
    out << "$EndNodes\n";
    std::size_t elements = 0;
    for (const Entity& e : entities) elements += e.triangles.size();
    for (std::size_t t : solids) elements += tets[t].size();
    out << "$Elements\n" << entities.size() + solids.size() << ' ' << elements << " 1 " << elements << '\n';
    std::size_t id = 0;
    {
        NumberWriter w(out);
        for (std::size_t e = 0; e < entities.size(); ++e) {
            w.text("2 ").number(e + 1).text(quadratic ? " 9 " : " 2 ").number(entities[e].triangles.size()).end();
            for (const auto& t : entities[e].triangles) {
                w.number(++id);
                for (std::size_t n : triangleNodes(t)) w.text(" ").number(n + 1);
                w.end();
            }
        }
        for (std::size_t t : solids) {
            w.text("3 ").number(t + 1).text(quadratic ? " 11 " : " 4 ").number(tets[t].size()).end();
            for (std::size_t k : tets[t]) {
                w.number(++id);
                for (std::size_t n : tetNodes(k)) w.text(" ").number(n + 1);
                w.end();
            }
        }
    }
    out << "$EndElements\n";
    // The tetrahedra's fibre directions (addFibreDirections()) as a 3-component element field;
    // the tetrahedra's element tags follow the triangles', in the order written above.
    if (volumes && volumes->fibreDirection.size() == volumes->tetrahedra.size() && !volumes->tetrahedra.empty()) {
        std::size_t tetCount = 0;
        for (std::size_t t : solids) tetCount += tets[t].size();
        out << "$ElementData\n1\n\"fibre_direction\"\n1\n0\n3\n0\n3\n" << tetCount << '\n';
        NumberWriter w(out);
        std::size_t tag = elements - tetCount;
        for (std::size_t t : solids)
            for (std::size_t k : tets[t]) {
                const Vector3& d = volumes->fibreDirection[k];
                w.number(++tag).text(" ").number(d.x).text(" ").number(d.y).text(" ").number(d.z).end();
            }
        w.flush();
        out << "$EndElementData\n";
    }
}

}  // namespace

void writeGmsh(const TextileMesh& mesh, std::ostream& out) { writeGmshModel(mesh, nullptr, out); }

void writeGmsh(const TextileMesh& mesh, const VolumeMesh& volumes, std::ostream& out) { writeGmshModel(mesh, &volumes, out); }

void writeGmsh(const TextileMesh& mesh, const VolumeMesh& volumes, const std::string& path)
{
    detail::OutputFiles files;
    writeGmsh(mesh, volumes, files.open(path));
    files.commit();
}

void writeAbaqus(const TextileMesh& mesh, std::ostream& out)
{
    // Every triangle once: each tow's own (tube outside regions, caps) under OWN_NAME, the
    // regions' under SHARED in their primary's orientation (REGION_k lists region k's); TOW_NAME,
    // the tow's closed surface, and TEXTILE, every element, are sets of those sets.
    constexpr std::size_t kField = 20;  // CalculiX reads at most 20 characters of a number
    out << "*HEADING\ntowgeom: compatible tow surface meshes (" << mesh.tows.size() << " tows, " << mesh.regions.size()
        << " connected regions), every triangle once\n";
    std::vector<std::vector<std::size_t>> capElements(mesh.tows.size()), regionElements(mesh.regions.size());
    std::vector<std::string> owns(mesh.tows.size());  // OWN_ set per tow, empty if it has none
    const std::vector<std::string> names = towLabels(mesh);
    {
        NumberWriter w(out);
        w.text("*NODE").end();
        for (std::size_t k = 0; k < mesh.nodes.size(); ++k)
            w.number(k + 1).text(", ").fitted(mesh.nodes[k].x, kField).text(", ").fitted(mesh.nodes[k].y, kField).text(", ").fitted(mesh.nodes[k].z, kField).end();
        std::size_t id = 0;
        const auto element = [&](const std::array<std::size_t, 3>& t) {
            w.number(++id).text(", ").number(t[0] + 1).text(", ").number(t[1] + 1).text(", ").number(t[2] + 1).end();
        };
        for (std::size_t tow = 0; tow < mesh.tows.size(); ++tow) {
            const TowMesh& m = mesh.tows[tow];
            bool any = false;
            for (std::size_t k = 0; k < m.triangles.size(); ++k) {
                if (m.region[k] >= 0) continue;
                if (!any) {
                    owns[tow] = label("OWN_", names[tow]);
                    w.text("*ELEMENT, TYPE=S3, ELSET=").text(owns[tow].c_str()).end();
                    any = true;
                }
                element(m.triangles[k]);
                if (isCap(m, k)) capElements[tow].push_back(id);
            }
        }
        // Region triangles, each once even where regions share one (three tows at a point).
        std::map<std::pair<std::size_t, std::size_t>, std::size_t> written;  // (primary, triangle) -> element
        bool any = false;
        for (std::size_t r = 0; r < mesh.regions.size(); ++r) {
            const ConnectedRegion& g = mesh.regions[r];
            for (std::size_t k : g.triangles) {
                const auto [at, added] = written.emplace(std::make_pair(g.primary, k), id + 1);
                if (added) {
                    if (!any) w.text("*ELEMENT, TYPE=S3, ELSET=SHARED").end();
                    any = true;
                    element(mesh.tows[g.primary].triangles[k]);
                    if (isCap(mesh.tows[g.primary], k)) capElements[g.primary].push_back(id);
                }
                regionElements[r].push_back(at->second);
            }
        }
        // A cell's faces outside the tows (the matrix's side of the box).
        if (mesh.cell && !mesh.cell->triangles.empty()) {
            w.text("*ELEMENT, TYPE=S3, ELSET=MATRIX_FACES").end();
            for (const auto& t : mesh.cell->triangles) element(t);
        }
    }
    writeCellFaceSets(mesh, out);
    const auto list = [&](const std::vector<std::size_t>& ids, std::size_t offset) {
        for (std::size_t k = 0; k < ids.size(); ++k) out << ids[k] + offset << (k % 16 == 15 || k + 1 == ids.size() ? "\n" : ", ");
    };
    const auto setNames = [&](const std::vector<std::string>& sets) {
        for (std::size_t k = 0; k < sets.size(); ++k) out << sets[k] << (k % 8 == 7 || k + 1 == sets.size() ? "\n" : ", ");
    };
    // Sets are defined before any set that names them.
    for (std::size_t r = 0; r < mesh.regions.size(); ++r) {
        if (!regionElements[r].empty()) {
            out << "*ELSET, ELSET=REGION_" << r + 1 << '\n';
            list(regionElements[r], 0);
        }
        if (mesh.regions[r].nodes.empty()) continue;
        out << "*NSET, NSET=REGION_" << r + 1 << '\n';
        list(mesh.regions[r].nodes, 1);
    }
    for (std::size_t t = 0; t < mesh.tows.size(); ++t) {
        if (capElements[t].empty()) continue;
        std::sort(capElements[t].begin(), capElements[t].end());
        out << "*ELSET, ELSET=" << label("CAPS_", names[t]) << '\n';
        list(capElements[t], 0);
    }
    std::vector<std::string> all;
    for (std::size_t t = 0; t < mesh.tows.size(); ++t) {
        std::vector<std::string> sets;
        if (!owns[t].empty()) sets.push_back(owns[t]);
        for (std::size_t r = 0; r < mesh.regions.size(); ++r)
            if (!regionElements[r].empty() && (mesh.regions[r].primary == t || mesh.regions[r].secondary == t))
                sets.push_back("REGION_" + std::to_string(r + 1));
        if (!owns[t].empty()) all.push_back(owns[t]);
        if (sets.empty()) continue;
        out << "*ELSET, ELSET=" << label("TOW_", names[t]) << '\n';
        setNames(sets);
    }
    if (std::any_of(regionElements.begin(), regionElements.end(), [](const std::vector<std::size_t>& e) { return !e.empty(); }))
        all.push_back("SHARED");
    if (!all.empty()) {
        out << "*ELSET, ELSET=TEXTILE\n";
        setNames(all);
    }
}

void writeGmsh(const TextileMesh& mesh, const std::string& path)
{
    detail::OutputFiles files;
    writeGmsh(mesh, files.open(path));
    files.commit();
}

void writeAbaqus(const TextileMesh& mesh, const VolumeMesh& volumes, std::ostream& out)
{
    constexpr std::size_t kField = 20;
    const std::vector<std::string> names = towLabels(mesh);
    const std::size_t towCount = mesh.tows.size();
    const std::vector<std::vector<std::size_t>> tets = tetrahedraBySolid(mesh, volumes);  // checks volumes
    const bool quadratic = !volumes.edgeNodes.empty();
    const char* type = quadratic ? "C3D10" : "C3D4";
    const detail::EdgeMiddles middles(volumes);
    out << "*HEADING\ntowgeom: tetrahedra of " << towCount << " tows" << (tets[towCount].empty() ? "" : " and the matrix") << " ("
        << type << "), conforming on their shared surfaces\n";
    std::vector<char> used(volumes.nodes.size(), 0);
    for (const auto& t : volumes.tetrahedra)
        for (std::size_t n : t) used[n] = 1;
    for (const auto& e : volumes.edgeNodes)
        for (std::size_t n : e) used.at(n) = 1;
    std::vector<std::string> solids;
    {
        NumberWriter w(out);
        w.text("*NODE").end();
        for (std::size_t k = 0; k < volumes.nodes.size(); ++k)
            if (used[k])
                w.number(k + 1).text(", ").fitted(volumes.nodes[k].x, kField).text(", ").fitted(volumes.nodes[k].y, kField).text(", ").fitted(volumes.nodes[k].z, kField).end();
        std::size_t id = 0;
        for (std::size_t t = 0; t <= towCount; ++t) {
            if (tets[t].empty()) continue;
            solids.push_back(t == towCount ? std::string("MATRIX") : label("TOW_", names[t]));
            w.text("*ELEMENT, TYPE=").text(type).text(", ELSET=").text(solids.back().c_str()).end();
            for (std::size_t k : tets[t]) {
                const auto& q = volumes.tetrahedra[k];
                w.number(++id).text(", ").number(q[0] + 1).text(", ").number(q[1] + 1).text(", ").number(q[2] + 1).text(", ").number(q[3] + 1);
                if (quadratic)  // C3D10's middle nodes: edges 12, 23, 31, 14, 24, 34 (1-based), as edgeNodes
                    for (std::size_t m : volumes.edgeNodes[k]) w.text(", ").number(m + 1);
                w.end();
            }
        }
        // Fibre directions (addFibreDirections()): each tow element's local 1-axis along its
        // fibres, the 2-axis normal to it towards global z (y where the fibres run along z); an
        // *ORIENTATION FIBRES for *SOLID SECTION, ..., ORIENTATION=FIBRES.
        if (!volumes.fibreDirection.empty() && towCount > 0 && solids.size() > (tets[towCount].empty() ? 0u : 1u)) {
            constexpr std::size_t kAxis = 16;  // a line stays within CalculiX's 132 characters
            w.text("*DISTRIBUTION TABLE, NAME=FIBRE_AXES_TABLE").end().text("COORD3D, COORD3D").end();
            w.text("*DISTRIBUTION, NAME=FIBRE_AXES, LOCATION=ELEMENT, TABLE=FIBRE_AXES_TABLE").end();
            w.text(", 1., 0., 0., 0., 1., 0.").end();
            id = 0;
            for (std::size_t t = 0; t < towCount; ++t)
                for (std::size_t k : tets[t]) {
                    const Vector3& d = volumes.fibreDirection[k];
                    if (!(std::abs(norm(d) - 1.0) < 1e-6))
                        throw Error(ErrorCode::InvalidArgument, "tetrahedron " + std::to_string(k) + " of tow '" + mesh.tows[t].name +
                                                                    "' has a fibre direction that is not a unit vector");
                    const Vector3 a = (1.0 / norm(d)) * d;
                    const Vector3 up = std::abs(a.z) < 0.9 ? Vector3{0.0, 0.0, 1.0} : Vector3{0.0, 1.0, 0.0};
                    Vector3 b = up - dot(up, a) * a;
                    b = (1.0 / norm(b)) * b;
                    w.number(++id);
                    for (double x : {a.x, a.y, a.z, b.x, b.y, b.z}) w.text(", ").fitted(x, kAxis);
                    w.end();
                }
            w.text("*ORIENTATION, NAME=FIBRES").end();
            w.text("FIBRE_AXES").end();
        }
    }
    const auto list = [&](const std::vector<std::size_t>& ids) {
        for (std::size_t k = 0; k < ids.size(); ++k) out << ids[k] + 1 << (k % 16 == 15 || k + 1 == ids.size() ? "\n" : ", ");
    };
    // Node sets per tow: all its nodes, and those of each end cap (where loads and supports go).
    for (std::size_t t = 0; t < towCount; ++t) {
        if (tets[t].empty()) continue;
        std::set<std::size_t> all;
        for (std::size_t k : tets[t]) {
            all.insert(volumes.tetrahedra[k].begin(), volumes.tetrahedra[k].end());
            if (quadratic) all.insert(volumes.edgeNodes[k].begin(), volumes.edgeNodes[k].end());
        }
        out << "*NSET, NSET=" << label("NODES_", names[t]) << '\n';
        list(std::vector<std::size_t>(all.begin(), all.end()));
        for (const TowFace face : {TowFace::Start, TowFace::End}) {
            std::set<std::size_t> cap;
            std::vector<std::array<std::size_t, 3>> capTriangles;
            const TowMesh& m = mesh.tows[t];
            for (std::size_t k = 0; k < m.triangles.size() && k < m.face.size(); ++k)
                if (m.face[k] == face) {
                    cap.insert(m.triangles[k].begin(), m.triangles[k].end());
                    capTriangles.push_back(m.triangles[k]);
                }
            if (cap.empty()) continue;
            out << "*NSET, NSET=" << label(face == TowFace::Start ? "START_" : "END_", names[t]) << '\n';
            list(middles.withMiddles(std::vector<std::size_t>(cap.begin(), cap.end()), capTriangles));
        }
    }
    writeCellFaceSets(mesh, out, &middles);
    if (!tets[towCount].empty()) solids.pop_back();  // TEXTILE: the tows only
    if (!solids.empty()) {
        out << "*ELSET, ELSET=TEXTILE\n";
        for (std::size_t k = 0; k < solids.size(); ++k) out << solids[k] << (k % 8 == 7 || k + 1 == solids.size() ? "\n" : ", ");
    }
}

void writeAbaqus(const TextileMesh& mesh, const VolumeMesh& volumes, const std::string& path)
{
    detail::OutputFiles files;
    writeAbaqus(mesh, volumes, files.open(path));
    files.commit();
}

void writeAbaqus(const TextileMesh& mesh, const std::string& path)
{
    detail::OutputFiles files;
    writeAbaqus(mesh, files.open(path));
    files.commit();
}

TOWGEOM_END_NAMESPACE
