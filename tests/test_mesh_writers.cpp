// The mesh writers' numbers read back exactly (they are formatted with std::to_chars, the
// shortest text that reads back to the same double).
#include <catch2/catch.hpp>

#include <towgeom/vtk_writer.hpp>

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
