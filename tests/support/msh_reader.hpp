// A reader of Gmsh's MSH 4.1 (ASCII) and 2.2 files for the tests, written from Gmsh's format
// description and independent of towgeom's writer: nodes, elements with the entity they are in,
// the physical groups and which entities (4.1) or elements (2.2) belong to each. Header-only.
#pragma once

#include <towgeom/point.hpp>

#include <array>
#include <cstddef>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace towgeom::testing {

struct MshFile {
    struct Element {
        int type = 0;                  ///< Gmsh element type (2: 3-node triangle, 4: 4-node tetrahedron)
        int dim = 0;                   ///< of its entity (4.1); of its physical group (2.2)
        int entity = 0;                ///< its entity's tag
        std::vector<int> physicals;    ///< 2.2: its physical tag (one per line); 4.1: its entity's
        std::vector<std::size_t> nodes;  ///< node tags
    };
    std::string version;                                  ///< "4.1" or "2.2"
    std::map<std::pair<int, int>, std::string> names;     ///< (dim, physical tag) -> name, quotes removed
    std::size_t declaredNames = 0;                        ///< the count in the $PhysicalNames header
    std::map<std::pair<int, int>, std::vector<int>> entityPhysicals;  ///< 4.1: (dim, entity tag) -> physical tags
    std::map<std::size_t, Point3> nodes;                  ///< node tag -> coordinates
    std::vector<Element> elements;                        ///< in file order (2.2: an element once per line)
    std::size_t declaredElements = 0;                     ///< the count in the $Elements header

    /// The physical tag named @p name (any dimension); throws when there is none.
    std::pair<int, int> physical(const std::string& name) const
    {
        for (const auto& [key, n] : names)
            if (n == name) return key;
        throw std::runtime_error("no physical group " + name);
    }
    /// Elements in the physical group (@p dim, @p tag).
    std::vector<const Element*> inPhysical(int dim, int tag) const
    {
        std::vector<const Element*> out;
        for (const Element& e : elements)
            if (e.dim == dim)
                for (int p : e.physicals)
                    if (p == tag) {
                        out.push_back(&e);
                        break;
                    }
        return out;
    }
};

namespace msh_detail {

inline void expect(std::istream& in, const std::string& word)
{
    std::string w;
    in >> w;
    if (w != word) throw std::runtime_error("MSH: expected " + word + ", read '" + w + "'");
}

inline std::vector<int> readTags(std::istream& in)
{
    std::size_t n = 0;
    in >> n;
    std::vector<int> tags(n);
    for (int& t : tags) in >> t;
    return tags;
}

}  // namespace msh_detail

/// Reads @p path (MSH 4.1 or 2.2, ASCII); throws std::runtime_error on what it cannot read.
inline MshFile readMsh(const std::string& path)
{
    using namespace msh_detail;
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    MshFile m;
    std::string section;
    while (in >> section) {
        if (section == "$MeshFormat") {
            int binary = 0, size = 0;
            in >> m.version >> binary >> size;
            if (binary != 0) throw std::runtime_error("MSH: binary");
            expect(in, "$EndMeshFormat");
        } else if (section == "$PhysicalNames") {
            in >> m.declaredNames;
            for (std::size_t k = 0; k < m.declaredNames; ++k) {
                int dim = 0, tag = 0;
                in >> dim >> tag >> std::ws;
                std::string name;
                std::getline(in, name);
                if (name.size() >= 2 && name.front() == '"' && name.back() == '"') name = name.substr(1, name.size() - 2);
                m.names[{dim, tag}] = name;
            }
            expect(in, "$EndPhysicalNames");
        } else if (section == "$Entities") {
            std::array<std::size_t, 4> count{};
            for (std::size_t& c : count) in >> c;
            for (int dim = 0; dim < 4; ++dim)
                for (std::size_t k = 0; k < count[static_cast<std::size_t>(dim)]; ++k) {
                    int tag = 0;
                    double box[6];
                    in >> tag;
                    for (int c = 0; c < (dim == 0 ? 3 : 6); ++c) in >> box[c];
                    m.entityPhysicals[{dim, tag}] = readTags(in);
                    if (dim > 0) readTags(in);  // bounding entities
                }
            expect(in, "$EndEntities");
        } else if (section == "$Nodes") {
            if (m.version.rfind("4", 0) == 0) {
                std::size_t blocks = 0, total = 0, minTag = 0, maxTag = 0;
                in >> blocks >> total >> minTag >> maxTag;
                for (std::size_t b = 0; b < blocks; ++b) {
                    int dim = 0, entity = 0, parametric = 0;
                    std::size_t n = 0;
                    in >> dim >> entity >> parametric >> n;
                    if (parametric != 0) throw std::runtime_error("MSH: parametric nodes");
                    std::vector<std::size_t> tags(n);
                    for (std::size_t& t : tags) in >> t;
                    for (std::size_t t : tags) {
                        Point3 p;
                        in >> p.x >> p.y >> p.z;
                        m.nodes[t] = p;
                    }
                }
                if (m.nodes.size() != total) throw std::runtime_error("MSH: node count");
            } else {
                std::size_t n = 0;
                in >> n;
                for (std::size_t k = 0; k < n; ++k) {
                    std::size_t t = 0;
                    Point3 p;
                    in >> t >> p.x >> p.y >> p.z;
                    m.nodes[t] = p;
                }
            }
            expect(in, "$EndNodes");
        } else if (section == "$Elements") {
            const auto nodesOf = [](int type) -> std::size_t {
                switch (type) {
                case 1: return 2;
                case 2: return 3;
                case 4: return 4;
                case 15: return 1;
                default: throw std::runtime_error("MSH: element type " + std::to_string(type));
                }
            };
            if (m.version.rfind("4", 0) == 0) {
                std::size_t blocks = 0, minTag = 0, maxTag = 0;
                in >> blocks >> m.declaredElements >> minTag >> maxTag;
                for (std::size_t b = 0; b < blocks; ++b) {
                    MshFile::Element e;
                    std::size_t n = 0;
                    in >> e.dim >> e.entity >> e.type >> n;
                    const auto found = m.entityPhysicals.find({e.dim, e.entity});
                    if (found != m.entityPhysicals.end()) e.physicals = found->second;
                    e.nodes.resize(nodesOf(e.type));
                    for (std::size_t k = 0; k < n; ++k) {
                        std::size_t tag = 0;
                        in >> tag;
                        for (std::size_t& v : e.nodes) in >> v;
                        m.elements.push_back(e);
                    }
                }
            } else {
                in >> m.declaredElements;
                for (std::size_t k = 0; k < m.declaredElements; ++k) {
                    MshFile::Element e;
                    std::size_t tag = 0;
                    in >> tag >> e.type;
                    const std::vector<int> tags = readTags(in);  // physical, elementary, ...
                    if (tags.size() >= 2) e.entity = tags[1];
                    if (!tags.empty() && tags[0] != 0) e.physicals = {tags[0]};
                    e.dim = e.type == 4 ? 3 : e.type == 2 ? 2 : e.type == 1 ? 1 : 0;
                    e.nodes.resize(nodesOf(e.type));
                    for (std::size_t& v : e.nodes) in >> v;
                    m.elements.push_back(e);
                }
            }
            if (m.elements.size() != m.declaredElements) throw std::runtime_error("MSH: element count");
            expect(in, "$EndElements");
        } else if (!section.empty() && section[0] == '$') {
            const std::string end = "$End" + section.substr(1);  // skipped whole
            std::string line;
            while (std::getline(in, line))
                if (line.rfind(end, 0) == 0) break;
        }
        if (!in) throw std::runtime_error("MSH: cannot read " + section + " of " + path);
    }
    return m;
}

}  // namespace towgeom::testing
