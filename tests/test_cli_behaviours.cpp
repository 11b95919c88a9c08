// Behaviour users rely on that no other test covered (issue 37): Ctrl-C, detect --chordal,
// determinism on one thread, --shrink-both, courses.vtk read by VTK, an earlier run's volume
// files kept (the .msh physical groups: test_msh_groups.cpp). Each through the command line, as users meet it.
#include <catch2/catch.hpp>

#include <towgeom/tow_surface.hpp>
#include <towgeom/stack_reader.hpp>
#include <towgeom/textile_io.hpp>

#include <nlohmann/json.hpp>

#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <filesystem>
#include <set>
#include <spawn.h>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <vector>

#include "cgal_reference.hpp"
#include "cli_runner.hpp"
#include "occt_reference.hpp"
#include "synthetic_tows.hpp"

namespace fs = std::filesystem;
using namespace towgeom;
using testing::cli;
using testing::Run;

extern char** environ;

namespace {

const double kPi = 3.14159265358979323846;

fs::path scratch(const std::string& name)
{
    const fs::path dir = fs::temp_directory_path() / ("towgeom_behaviour_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    return dir;
}

std::vector<std::string> twillFiles()
{
    std::vector<std::string> files;
    for (const auto& e : fs::directory_iterator(std::string(TOWGEOM_EXAMPLE_DATA) + "/twill"))
        if (e.path().extension() == ".stw") files.push_back(e.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

std::string quoted(const std::vector<std::string>& files)
{
    std::string s;
    for (const std::string& f : files) s += " '" + f + "'";
    return s;
}

nlohmann::json jsonFile(const fs::path& p) { return nlohmann::json::parse(testing::slurp(p)); }

}  // namespace

TEST_CASE("Ctrl-C stops a running towgeom resolve: exit 130, one line, nothing written", "[cli][behaviour][signal]")
{
    const fs::path out = scratch("interrupt");
    // The twill at h = 0.01 takes several seconds to mesh; SIGINT comes 1.5 s after the start.
    std::vector<std::string> args{TOWGEOM_CLI, "resolve"};
    for (const std::string& f : twillFiles()) args.push_back(f);
    for (const char* a : {"--mesh-size", "0.01", "--quiet", "--out"}) args.push_back(a);
    args.push_back(out.string());
    const fs::path err = scratch("interrupt_err");
    posix_spawn_file_actions_t files;
    posix_spawn_file_actions_init(&files);
    posix_spawn_file_actions_addopen(&files, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawnattr_t attributes;  // SIGINT handled as by default, as in a terminal
    posix_spawnattr_init(&attributes);
    sigset_t defaults;
    sigemptyset(&defaults);
    sigaddset(&defaults, SIGINT);
    posix_spawnattr_setsigdefault(&attributes, &defaults);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = 0;
    REQUIRE(posix_spawn(&pid, TOWGEOM_CLI, &files, &attributes, argv.data(), environ) == 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    int status = 0;
    REQUIRE(waitpid(pid, &status, WNOHANG) == 0);  // still running: the signal stops real work
    const auto signalled = std::chrono::steady_clock::now();
    REQUIRE(::kill(pid, SIGINT) == 0);
    REQUIRE(waitpid(pid, &status, 0) == pid);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - signalled).count();
    posix_spawn_file_actions_destroy(&files);
    posix_spawnattr_destroy(&attributes);
    INFO(testing::slurp(err));
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 130);
    // How soon it stops depends on the stage in hand and the machine's load (1.1 s alone, 6.8 s
    // with other builds running): reported, not held.
    WARN("stopped " << seconds << " s after SIGINT");
    CHECK(testing::slurp(err) == "towgeom resolve: stopped by a signal (Ctrl-C or SIGTERM); nothing written [cancelled]\n");
    CHECK_FALSE(fs::exists(out));
    fs::remove(err);
}

TEST_CASE("towgeom detect --chordal C: points follow C, and the curve's length converges as C", "[cli][behaviour][intersection]")
{
    // warp_0 x weft_0 of the bundled twill, one closed curve. A polyline whose chords stray by at
    // most C from the curve needs ~1/sqrt(C) points, and its length falls short by ~C (per unit
    // of curvature): 16 times finer gives ~4 times the points and ~1/16 of the shortfall.
    const std::vector<std::string> all = twillFiles();
    const std::string pair = quoted({all[0], all[4]});
    std::vector<double> points, lengths;
    for (const double c : {1e-3, 6.25e-5, 3.90625e-6}) {
        const Run r = cli("detect" + pair + " --chordal " + std::to_string(c) + " --quiet");
        REQUIRE(r.status == 0);
        const nlohmann::json j = nlohmann::json::parse(r.out);
        REQUIRE(j["loops"].size() == 1);
        points.push_back(j["loops"][0]["point_count"].get<double>());
        lengths.push_back(j["loops"][0]["length"].get<double>());
    }
    INFO("points " << points[0] << ", " << points[1] << ", " << points[2] << "; lengths " << lengths[0] << ", " << lengths[1] << ", "
                   << lengths[2]);
    for (int k = 0; k < 2; ++k) {
        CHECK(points[k + 1] / points[k] > 3.0);  // measured 4.2 and 4.7
        CHECK(points[k + 1] / points[k] < 6.0);
    }
    const double shortfall0 = lengths[2] - lengths[0], shortfall1 = lengths[2] - lengths[1];
    CHECK(shortfall0 > 0.0);
    CHECK(shortfall1 > 0.0);
    CHECK(shortfall0 / shortfall1 > 10.0);  // measured 19 (16 and the finest's own shortfall)
    CHECK(shortfall0 / shortfall1 < 32.0);
    CHECK(shortfall0 <= 2e-3);  // about C times the curve's length (1.65)
}

TEST_CASE("towgeom resolve on one thread is deterministic: the same files twice, byte for byte", "[cli][behaviour][determinism]")
{
    const fs::path dir = scratch("determinism");
    for (const char* run : {"a", "b"}) {
        const Run r = cli("resolve" + quoted(twillFiles()) + " --threads 1 --formats stl,vtk,msh,inp --quiet --out '" + (dir / run).string() + "'");
        REQUIRE(r.status == 0);
    }
    std::size_t files = 0;
    for (const auto& e : fs::directory_iterator(dir / "a")) {
        const std::string name = e.path().filename().string();
        INFO(name);
        if (name == "report.json") {
            nlohmann::json a = jsonFile(e.path()), b = jsonFile(dir / "b" / name);
            CHECK(a.erase("timings_ms") == 1);  // the one part that may differ
            b.erase("timings_ms");
            CHECK(a == b);
        } else {
            CHECK(testing::slurp(e.path()) == testing::slurp(dir / "b" / name));
        }
        ++files;
    }
    CHECK(files == 8 * 2 + 3);  // STL and VTK per tow, textile.msh, textile.inp, report.json
    fs::remove_all(dir);
}

TEST_CASE("towgeom resolve --method shrink --shrink-both: every tow of a pair gives way, none overlaps after", "[cli][behaviour][shrink]")
{
    const fs::path out = scratch("shrink_both");
    for (const bool both : {false, true}) {
        INFO("--shrink-both: " << both);
        const fs::path o = out / (both ? "both" : "one");
        const Run r = cli("resolve" + quoted(twillFiles()) + " --method shrink" + (both ? " --shrink-both" : "") + " --quiet --out '" + o.string() + "'");
        REQUIRE(r.status == 0);
        const nlohmann::json report = jsonFile(o / "report.json");
        double lost = 0.0;
        std::size_t shrunk = 0;
        for (const auto& t : report["tows"]) {
            lost += t["volume_before"].get<double>() - t["volume_after"].get<double>();
            const double change = t["largest_section_change"].get<double>();
            shrunk += change > 0.0;
            // The secondary (the wefts, ranked below the warps by input order) gives way alone
            // unless both do.
            if (!both && t["name"].get<std::string>().rfind("warp", 0) == 0) CHECK(change == 0.0);
        }
        CHECK(shrunk == (both ? 8u : 4u));
        CHECK(lost == Approx(both ? 0.933 : 0.818).margin(0.005));  // README: 0.933 with --shrink-both, 0.818 without
        // The shrunk tows, fitted again and faceted densely: CGAL finds no curve between any two.
        std::vector<TriangleMesh> faceted;
        for (const auto& e : fs::directory_iterator(o / "shrunk")) {
            const TowSurface t = TowSurface::fit(readStackFile(e.path().string()));
            faceted.push_back(t.tessellate(2 * t.sectionCount(), 64));
        }
        REQUIRE(faceted.size() == 8);
        std::size_t curves = 0;
        for (std::size_t i = 0; i < faceted.size(); ++i)
            for (std::size_t j = i + 1; j < faceted.size(); ++j) {
                const testing::IntersectionPolylines p = testing::surfaceIntersection(faceted[i], faceted[j]);
                curves += p.closed + p.open;
            }
        CHECK(curves == 0);
    }
    fs::remove_all(out);
}

TEST_CASE("courses.vtk of towgeom courses is read by VTK: a polyline per centreline and edge, the points of courses.json", "[cli][behaviour][courses]")
{
    const fs::path dir = scratch("courses_vtk");
    fs::create_directories(dir);
    const fs::path tool = dir / "tool.step";
    testing::writeCylinderFace(tool.string(), 2.0, 2.0, -kPi / 2, kPi / 2);
    const Run r = cli("courses '" + tool.string() + "' --reference plane:2,0,1,0,1,0 --points 21 --tow-width 0.3 --tows 3 --exact --quiet --out '" +
                      (dir / "out").string() + "'");
    INFO(r.err);
    REQUIRE(r.status == 0);
    // VTK's own legacy reader (Debian python3-vtk9; meshio reads no POLYDATA): a polyline per
    // tow's centreline, right and left edge, their points those of courses.json in order.
    const fs::path json = dir / "out" / "courses.json", vtk = dir / "out" / "courses.vtk";
    const Run py = testing::runShell(
        "/usr/bin/python3 -c \"import json, vtk\n"
        "r = vtk.vtkPolyDataReader(); r.SetFileName('" + vtk.string() + "'); r.Update(); o = r.GetOutput()\n"
        "j = json.load(open('" + json.string() + "'))\n"
        "ps = [p for t in j['tows'] for c in ('centreline', 'right', 'left') for p in t[c]['points']]\n"
        "d = max(max(abs(a - b) for a, b in zip(o.GetPoint(k), p)) for k, p in enumerate(ps))\n"
        "print(o.GetNumberOfPoints(), len(ps), o.GetNumberOfLines(), o.GetNumberOfCells(), d)\" 2>&1");
    INFO(py.out);
    REQUIRE(py.status == 0);
    std::istringstream in(py.out);
    std::size_t points = 0, inJson = 0, lines = 0, cells = 0;
    double largest = 1.0;
    in >> points >> inJson >> lines >> cells >> largest;
    CHECK(points == 3 * 3 * 21);  // 3 tows x (centreline, 2 edges) x 21 points
    CHECK(inJson == points);
    CHECK(lines == 9);
    CHECK(cells == 9);
    CHECK(largest <= 1e-12);  // the same points (17 significant digits written)
    fs::remove_all(dir);
}

TEST_CASE("resolve --volume refused while tows overlap leaves an earlier run's textile_volume files as they were", "[cli][behaviour][volume]")
{
    // Nested tows (one inside the other: an unresolved pair) give no tetrahedra: README says the
    // surfaces are written, exit 3, and textile_volume.* of an earlier run are left as they were.
    const fs::path dir = scratch("volume_kept");
    fs::create_directories(dir / "out");
    testing::Sampling s;
    s.points = 32;
    std::string files;
    for (const TowStack& t : {testing::tubeAlongX(0.5, 4.0, 0.0, 0.0, 0.0, s, "outer"), testing::tubeAlongX(0.25, 4.0, 0.0, 0.0, 0.0, s, "inner")}) {
        std::ofstream o(dir / (t.name + ".stw"));
        writeStack(o, t);
        files += " '" + (dir / (t.name + ".stw")).string() + "'";
    }
    const std::map<std::string, std::string> earlier{{"textile_volume.inp", "*HEADING\nan earlier run\n"},
                                                     {"textile_volume.vtu", "<VTKFile>an earlier run</VTKFile>\n"},
                                                     {"textile_volume.msh", "$MeshFormat\nan earlier run\n"}};
    for (const auto& [name, text] : earlier) std::ofstream(dir / "out" / name) << text;
    const Run r = cli("resolve" + files + " --volume --formats inp,msh,vtk --quiet --out '" + (dir / "out").string() + "'");
    INFO(r.err);
    CHECK(r.status == 3);
    CHECK(r.err.find("[nested]") != std::string::npos);
    for (const auto& [name, text] : earlier) {
        INFO(name);
        CHECK(testing::slurp(dir / "out" / name) == text);
    }
    const nlohmann::json report = jsonFile(dir / "out" / "report.json");
    CHECK(report["volume_mesh"].contains("refused"));
    CHECK(fs::exists(dir / "out" / "outer.vtk"));  // the surfaces are written
    fs::remove_all(dir);
}
