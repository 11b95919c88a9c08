// resolve --volume refused because tows touch tangentially (issue 37): README says the surfaces
// are written, exit 3, and textile_volume.* files of an earlier run in the directory are left as
// they were. test_resolve_cli.cpp runs this refusal into a fresh directory and
// test_cli_behaviours.cpp the refusal for overlapping (nested) tows over earlier files; this is
// the tangential one (meshVolumes() throws Unsupported, caught by the CLI) over earlier files.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "cli_runner.hpp"

namespace fs = std::filesystem;
namespace testing = towgeom::testing;

TEST_CASE("resolve --volume refused for tows touching tangentially: earlier textile_volume files kept, surfaces replaced, exit 3",
          "[cli][behaviour][volume][tangent]")
{
    const fs::path dir = fs::temp_directory_path() / ("towgeom_volume_refused_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    const fs::path in = dir / "in", out = dir / "out";
    // A pressed orthogonal weave with no gap: flat faces of racetrack tows touching.
    REQUIRE(testing::cli("generate --weave orthogonal --tows 1x1 --layers 1 --section racetrack --overlap 0 --width 0.9 --sections 30 "
                         "--points 32 --quiet --out '" + in.string() + "'")
                .status == 0);
    std::string files;
    std::size_t tows = 0;
    for (const auto& e : fs::directory_iterator(in))
        if (e.path().extension() == ".stw") {
            files += " '" + e.path().string() + "'";
            ++tows;
        }
    REQUIRE(tows == 4);
    // An earlier run's files: its volume mesh (to be kept) and a surface and report (replaced).
    fs::create_directories(out);
    const std::map<std::string, std::string> volume{{"textile_volume.msh", "$MeshFormat\nan earlier run\n"},
                                                    {"textile_volume.inp", "*HEADING\nan earlier run\n"},
                                                    {"textile_volume.vtu", "<VTKFile>an earlier run</VTKFile>\n"}};
    const std::map<std::string, std::string> replaced{{"report.json", "{\"an\":\"earlier run\"}\n"},
                                                      {"warp_L0_0.vtk", "an earlier run\n"},
                                                      {"textile.msh", "an earlier run\n"}};
    for (const auto* group : {&volume, &replaced})
        for (const auto& [name, text] : *group) std::ofstream(out / name) << text;

    const testing::Run r = testing::cli("resolve" + files + " --volume --formats stl,vtk,msh,inp --quiet --out '" + out.string() + "'");
    INFO(r.err);
    CHECK(r.status == 3);
    CHECK(r.err.rfind("towgeom resolve: warning: no volume mesh written (--volume): tow '", 0) == 0);
    CHECK(r.err.find("touching tangentially") != std::string::npos);
    CHECK(r.err.find("[unsupported]; the surfaces are written\n") != std::string::npos);
    CHECK(r.err.find("unresolved") == std::string::npos);  // refused for the tangent alone
    for (const auto& [name, text] : volume) {
        INFO(name);
        CHECK(testing::slurp(out / name) == text);
    }
    for (const auto& [name, text] : replaced) {
        INFO(name);
        CHECK(testing::slurp(out / name) != text);
    }
    const nlohmann::json report = nlohmann::json::parse(testing::slurp(out / "report.json"));
    CHECK(report["unresolved"].empty());
    CHECK(report["volume_mesh"]["refused"].get<std::string>().find("touching tangentially") != std::string::npos);
    CHECK(report["tows"].size() == tows);
    std::size_t written = 0;
    for (const auto& e : fs::directory_iterator(out)) written += e.path().extension() == ".stl" || e.path().extension() == ".vtk";
    CHECK(written == 2 * tows);
    CHECK(fs::exists(out / "textile.inp"));
    CHECK(testing::slurp(out / "textile.msh").rfind("$MeshFormat\n4.1", 0) == 0);
    std::size_t entries = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(out)) ++entries;
    CHECK(entries == 2 * tows + 3 + 3);  // surfaces, textile.msh/.inp, report.json; the 3 kept
    fs::remove_all(dir);
}
