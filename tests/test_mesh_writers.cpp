// The mesh writers' numbers read back exactly (they are formatted with std::to_chars, the
// shortest text that reads back to the same double), or in the .inp to 20 characters; VTK
// fields as FIELD arrays.
#include <catch2/catch.hpp>

#include <towgeom/error.hpp>
#include <towgeom/mesh_export.hpp>
#include <towgeom/vtk_writer.hpp>

#include <cmath>
#include <cstdlib>

#include <filesystem>
#include <fstream>
#include <limits>
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
    std::size_t rounded = 0;  // values whose shortest exact text is longer than 20
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
            rounded += x != expected;
        }
    }
    CHECK(rounded >= 3);  // -4.44e-16, -2.5e-05 and denorm_min at least
}
