// The mesh writers' numbers read back exactly (they are formatted with std::to_chars, the
// shortest text that reads back to the same double), or in the .inp to 20 characters; VTK
// fields as FIELD arrays.
#include <catch2/catch.hpp>

#include <towgeom/error.hpp>
#include <towgeom/mesh_export.hpp>
#include <towgeom/resolve.hpp>
#include <towgeom/tow_surface.hpp>
#include <towgeom/vtk_writer.hpp>

#include "synthetic_tows.hpp"

#include <cmath>
#include <cstdlib>

#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>

namespace fs = std::filesystem;
using namespace towgeom;

TEST_CASE("writeVtk: every coordinate and index reads back exactly", "[export]")
{
    TriangleMesh mesh;
    const double awkward[] = {1.0 / 3.0, -0.1, 1e-300, -1e22, 0.0, 2.0 / 3.0 * 1e-7, std::numeric_limits<double>::denorm_min(),
                              std::numeric_limits<double>::max(), 123456789.123456789};
    for (std::size_t k = 0; k + 2 < std::size(awkward); ++k) mesh.vertices.push_back({awkward[k], awkward[k + 1], awkward[k + 2]});
    for (std::size_t k = 0; k + 2 < mesh.vertices.size(); ++k) mesh.triangles.push_back({k, k + 1, k + 2});
    const fs::path dir = fs::temp_directory_path() / "towgeom_test_mesh_writers";
    fs::create_directories(dir);
    const fs::path path = dir / "awkward.vtk";
    writeVtk(mesh, path.string(), "awkward numbers");

    std::ifstream in(path);
    std::string line, word;
    while (std::getline(in, line) && line.rfind("POINTS", 0) != 0) {
    }
    REQUIRE(line == "POINTS " + std::to_string(mesh.vertices.size()) + " double");
    for (const Point3& p : mesh.vertices) {
        REQUIRE(std::getline(in, line));
        std::istringstream s(line);
        double x = 0, y = 0, z = 0;
        s >> x >> y >> z;
        CHECK(x == p.x);
        CHECK(y == p.y);
        CHECK(z == p.z);
    }
    REQUIRE(std::getline(in, line));
    CHECK(line == "POLYGONS " + std::to_string(mesh.triangles.size()) + " " + std::to_string(4 * mesh.triangles.size()));
    for (const auto& t : mesh.triangles) {
        REQUIRE(std::getline(in, line));
        CHECK(line == "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]));
    }
    fs::remove_all(dir);
}

TEST_CASE("writeVtk: integer fields as one FIELD block per section, names checked", "[export]")
{
    TriangleMesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    mesh.triangles = {{0, 1, 2}, {1, 3, 2}};
    std::ostringstream out;
    writeVtk(mesh, out, "fields", {{"tow_id", {7, 7}}, {"region_id", {-1, 3}}}, {{"node_id", {10, 11, 12, 13}}});
    const std::string vtk = out.str();
    CHECK(vtk.find("SCALARS") == std::string::npos);
    CHECK(vtk.find("POINT_DATA 4\nFIELD FieldData 1\nnode_id 1 4 int\n10\n11\n12\n13\n") != std::string::npos);
    CHECK(vtk.find("CELL_DATA 2\nFIELD FieldData 2\ntow_id 1 2 int\n7\n7\nregion_id 1 2 int\n-1\n3\n") != std::string::npos);
    std::ostringstream bad;
    CHECK_THROWS_AS(writeVtk(mesh, bad, "fields", {{"tow id", {1, 1}}}), Error);
    CHECK_THROWS_AS(writeVtk(mesh, bad, "fields", {{"", {1, 1}}}), Error);
}

TEST_CASE("writeAbaqus: coordinates in at most 20 characters, as close as they fit", "[export]")
{
    // CalculiX reads 20 characters of a number: -4.440892098500626E-16 (22) was refused.
    const double awkward[] = {-4.440892098500626e-16, 1.0 / 3.0, -2.5175373421983983e-05, -0.7156870298109141, 1e-300,
                              -std::numeric_limits<double>::denorm_min(), -std::numeric_limits<double>::max(), 123456789.123456789, 0.0};
    TextileMesh m;
    for (std::size_t k = 0; k + 2 < std::size(awkward); ++k) m.nodes.push_back({awkward[k], awkward[k + 1], awkward[k + 2]});
    TowMesh t;
    t.name = "t";
    for (std::size_t k = 0; k + 2 < m.nodes.size(); ++k) {
        t.triangles.push_back({k, k + 1, k + 2});
        t.region.push_back(-1);
        t.face.push_back(TowFace::Side);
    }
    m.tows.push_back(t);
    std::ostringstream out;
    writeAbaqus(m, out);
    std::istringstream in(out.str());
    std::string line;
    while (std::getline(in, line) && line != "*NODE") {
    }
    std::set<double> rounded;  // distinct values whose shortest exact text is longer than 20
    for (std::size_t k = 0; k < m.nodes.size(); ++k) {
        REQUIRE(std::getline(in, line));
        std::istringstream fields(line);
        std::string field;
        std::getline(fields, field, ',');
        CHECK(field == std::to_string(k + 1));
        for (const double expected : {m.nodes[k].x, m.nodes[k].y, m.nodes[k].z}) {
            REQUIRE(std::getline(fields, field, ','));
            if (field[0] == ' ') field.erase(0, 1);
            INFO(field);
            CHECK(field.size() <= 20);
            const double x = std::strtod(field.c_str(), nullptr);
            // 13 significant digits at least: relative 5e-13 (denormals: absolute).
            CHECK(std::abs(x - expected) <= 5e-13 * std::abs(expected) + 1e-320);
            if (x != expected) rounded.insert(expected);
        }
    }
    CHECK(rounded.size() >= 3);  // -4.44e-16, -2.5175373421983983e-05, -0.7156870298109141 at least
}

namespace {

/// The number of data lines after the first keyword line starting with @p keyword (to the next
/// keyword), entries counted per comma for set lists.
std::size_t entries(const std::string& inp, const std::string& keyword, bool lines)
{
    std::istringstream in(inp);
    std::size_t n = 0;
    bool inside = false;
    for (std::string line; std::getline(in, line);) {
        if (!line.empty() && line[0] == '*') {
            inside = line == keyword || line.rfind(keyword + ",", 0) == 0;
            continue;
        }
        if (inside) n += lines ? 1 : static_cast<std::size_t>(std::count(line.begin(), line.end(), ',')) + 1;
    }
    return n;
}

}  // namespace

TEST_CASE("writeAbaqus and writeGmsh: a cap's triangles in a region stay in its CAPS_ set, every triangle once", "[export][caps]")
{
    // The stub ends inside the other tube: part of its end cap lies in the region.
    testing::Sampling s;
    s.points = 48;
    std::vector<TowSurface> tows{TowSurface::fit(testing::tubeAlongX(0.5, 2.0, 0.0, 0.0, 0.0, s, "stub")),
                                 TowSurface::fit(testing::tubeAlongY(0.5, 0.7, s, "across"))};
    ResolveOptions o;
    o.mesh.edgeLength = 0.1;
    o.primaryPatterns = {"stub"};
    const ResolveResult res = resolveTextile(tows, o);
    REQUIRE(res.mesh.regions.size() == 1);
    const TowMesh& stub = res.mesh.tows[0];
    std::size_t caps = 0, capsInRegion = 0;
    for (std::size_t k = 0; k < stub.triangles.size(); ++k)
        if (stub.face[k] != TowFace::Side) {
            ++caps;
            capsInRegion += stub.region[k] >= 0;
        }
    REQUIRE(capsInRegion > 0);
    std::set<std::array<std::size_t, 3>> unique;
    for (const TowMesh& m : res.mesh.tows)
        for (auto t : m.triangles) {
            std::sort(t.begin(), t.end());
            unique.insert(t);
        }
    std::ostringstream inp;
    writeAbaqus(res.mesh, inp);
    CHECK(entries(inp.str(), "*ELSET, ELSET=CAPS_stub", false) == caps);
    std::size_t elements = 0;
    for (const char* block : {"*ELEMENT, TYPE=S3, ELSET=OWN_stub", "*ELEMENT, TYPE=S3, ELSET=OWN_across", "*ELEMENT, TYPE=S3, ELSET=SHARED"})
        elements += entries(inp.str(), block, true);
    CHECK(elements == unique.size());
    // The .msh: every element once.
    std::ostringstream msh;
    writeGmsh(res.mesh, msh);
    std::istringstream in(msh.str());
    std::string line;
    while (std::getline(in, line) && line != "$Elements") {
    }
    std::size_t blocks = 0, count = 0;
    REQUIRE(std::getline(in, line));
    std::istringstream(line) >> blocks >> count;
    std::set<std::array<std::size_t, 3>> written;
    std::size_t read = 0;
    for (std::size_t b = 0; b < blocks; ++b) {
        REQUIRE(std::getline(in, line));
        std::size_t dim = 0, tag = 0, type = 0, n = 0;
        std::istringstream(line) >> dim >> tag >> type >> n;
        for (std::size_t e = 0; e < n; ++e) {
            REQUIRE(std::getline(in, line));
            std::istringstream fields(line);
            std::size_t id = 0;
            std::array<std::size_t, 3> t{};
            fields >> id >> t[0] >> t[1] >> t[2];
            for (std::size_t& v : t) --v;
            std::sort(t.begin(), t.end());
            written.insert(t);
            ++read;
        }
    }
    CHECK(read == count);
    CHECK(read == unique.size());
    CHECK(written == unique);
}

TEST_CASE("writeAbaqus: set names stay distinct without case and within 80 characters", "[export]")
{
    TextileMesh m;
    m.nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const std::string longName(78, 'a');
    for (const std::string& name : {std::string("Tow"), std::string("tow"), std::string("a-b"), std::string("a_b"), longName}) {
        TowMesh t;
        t.name = name;
        t.triangles = {{0, 1, 2}};
        t.region = {-1};
        t.face = {TowFace::Start};
        m.tows.push_back(t);
    }
    std::ostringstream out;
    writeAbaqus(m, out);
    std::istringstream in(out.str());
    std::set<std::string> seen;  // upper-cased, as CalculiX reads them
    std::size_t sets = 0, tooLong = 0;
    for (std::string line; std::getline(in, line);) {
        const auto at = line.find("SET=");
        if (line.empty() || line[0] != '*' || at == std::string::npos) continue;
        std::string name = line.substr(at + 4);
        tooLong += name.size() > 80;
        for (char& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        seen.insert(name);
        ++sets;
    }
    CHECK(sets == seen.size());
    CHECK(tooLong == 0);
    CHECK(out.str().find("ELSET=OWN_Tow\n") != std::string::npos);
    CHECK(out.str().find("ELSET=OWN_tow_2\n") != std::string::npos);
    CHECK(out.str().find("ELSET=OWN_a_b_4\n") != std::string::npos);
}
