// textile.msh's physical groups as Gmsh itself reads them (issue 37): the gmsh binary reads the
// file and writes it again as MSH 2.2, where an element is listed once per physical group it
// belongs to; the triangles of each group there are those report.json and the tows' .vtk files
// give for it; the names in the file are exactly those expected, and gmsh -check reads it.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "msh_reader.hpp"

namespace fs = std::filesystem;
using namespace towgeom;
using testing::cli;
using testing::Run;

namespace {

/// The integers of the FIELD array @p name (one component) of a legacy VTK file's CELL_DATA.
std::vector<int> vtkCellArray(const fs::path& file, const std::string& name)
{
    std::ifstream in(file);
    std::string word;
    while (in >> word && word != "CELL_DATA") {
    }
    while (in >> word) {
        if (word != name) continue;
        std::size_t components = 0, count = 0;
        std::string type;
        in >> components >> count >> type;
        REQUIRE(components == 1);
        std::vector<int> values(count);
        for (int& v : values) in >> v;
        REQUIRE(in);
        return values;
    }
    FAIL("no cell array " << name << " in " << file);
    return {};
}

}  // namespace

TEST_CASE("textile.msh as gmsh reads it: each tow's, region's and caps' group holds the triangles report.json and the .vtk give",
          "[cli][behaviour][msh]")
{
    const fs::path dir = fs::temp_directory_path() / ("towgeom_msh_groups_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    std::string files;
    for (const auto& e : fs::directory_iterator(std::string(TOWGEOM_EXAMPLE_DATA) + "/twill"))
        if (e.path().extension() == ".stw") files += " '" + e.path().string() + "'";
    const Run r = cli("resolve" + files + " --mesh-size 0.15 --formats vtk,msh --quiet --out '" + (dir / "out").string() + "'");
    INFO(r.err);
    REQUIRE(r.status == 0);
    const nlohmann::json report = nlohmann::json::parse(testing::slurp(dir / "out" / "report.json"));
    REQUIRE(report["tows"].size() == 8);
    REQUIRE(report["regions"].size() == 16);

    // Gmsh reads the file and writes it again: MSH 2.2 lists an element once per physical group.
    const Run g = testing::runShell("gmsh '" + (dir / "out" / "textile.msh").string() + "' -0 -format msh22 -o '" +
                                    (dir / "gmsh.msh").string() + "' 2>&1");
    INFO(g.out);
    REQUIRE(g.status == 0);
    CHECK(g.out.find("Error") == std::string::npos);
    const testing::MshFile byGmsh = testing::readMsh((dir / "gmsh.msh").string());
    CHECK(byGmsh.version == "2.2");
    std::map<std::string, std::size_t> perGroup;  // group name -> triangles Gmsh lists in it
    std::size_t notTriangles = 0, notOneGroup = 0;
    for (const testing::MshFile::Element& e : byGmsh.elements) {
        notTriangles += e.type != 2;
        notOneGroup += e.physicals.size() != 1;
        if (e.physicals.size() == 1) ++perGroup[byGmsh.names.at({2, e.physicals[0]})];
    }
    CHECK(notTriangles == 0);
    CHECK(notOneGroup == 0);
    CHECK(perGroup.size() == 8 + 8 + 16);

    // Per tow: its closed surface (own triangles, caps and shared regions) as report.json counts
    // it and as many cells as its .vtk; its caps the .vtk's cells with face 1 or 2.
    std::size_t towTriangles = 0, regionTriangles = 0;
    std::map<std::string, std::vector<int>> regionIds;  // per tow, of its .vtk cells
    for (const auto& t : report["tows"]) {
        const std::string name = t["name"];
        INFO(name);
        const std::vector<int> face = vtkCellArray(dir / "out" / (name + ".vtk"), "face");
        regionIds[name] = vtkCellArray(dir / "out" / (name + ".vtk"), "region_id");
        std::size_t caps = 0;
        for (int f : face) caps += f == 1 || f == 2;
        CHECK(caps > 0);
        CHECK(perGroup["TOW_" + name] == t["triangles"].get<std::size_t>());
        CHECK(perGroup["TOW_" + name] == face.size());
        CHECK(perGroup["CAPS_" + name] == caps);
        towTriangles += t["triangles"].get<std::size_t>();
    }
    // Per region k: report.json's regions[k - 1], and the cells with region_id k - 1 in the
    // .vtk of both its tows (a shared region: the same triangles in both).
    for (std::size_t k = 0; k < report["regions"].size(); ++k) {
        const auto& region = report["regions"][k];
        INFO("REGION_" << k + 1);
        const std::size_t n = region["triangles"];
        CHECK(perGroup["REGION_" + std::to_string(k + 1)] == n);
        for (const std::string& tow : {region["primary"].get<std::string>(), region["secondary"].get<std::string>()}) {
            std::size_t inVtk = 0;
            for (int id : regionIds[tow]) inVtk += id == static_cast<int>(k);
            CHECK(inVtk == n);
        }
        regionTriangles += n;
    }
    // textile.msh itself: its $PhysicalNames exactly a TOW_ and a CAPS_ per tow and REGION_1..16,
    // surfaces, each its own tag; gmsh -check reads it; every triangle listed once (a shared
    // region's triangle is in two tows).
    const testing::MshFile written = testing::readMsh((dir / "out" / "textile.msh").string());
    CHECK(written.version == "4.1");
    std::set<std::string> names, expected;
    std::size_t notSurfaces = 0;
    for (const auto& [key, name] : written.names) {
        notSurfaces += key.first != 2;
        names.insert(name);
    }
    for (const auto& t : report["tows"]) {
        expected.insert("TOW_" + t["name"].get<std::string>());
        expected.insert("CAPS_" + t["name"].get<std::string>());
    }
    for (std::size_t k = 1; k <= report["regions"].size(); ++k) expected.insert("REGION_" + std::to_string(k));
    CHECK(notSurfaces == 0);
    CHECK(written.names.size() == written.declaredNames);  // no (dim, tag) twice
    CHECK(names.size() == written.declaredNames);          // no name twice
    CHECK(names == expected);
    const Run check = testing::runShell("gmsh -check '" + (dir / "out" / "textile.msh").string() + "' 2>&1");
    CHECK(check.status == 0);
    CHECK(check.out.find("Error") == std::string::npos);
    CHECK(written.elements.size() == towTriangles - regionTriangles);
    CHECK(byGmsh.nodes.size() == written.nodes.size());
    fs::remove_all(dir);
}
