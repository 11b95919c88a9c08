// Ctrl-C into an output directory that already holds files (issue 37): README and --help say a
// stopped run leaves DIR exactly as it was. The Ctrl-C test of test_cli_behaviours.cpp stops a
// run during meshing, into a DIR that did not exist; here the signal comes while the volumes are
// meshed, which nothing interrupts, so the run goes on to write every file (as temporaries next to
// the ones they replace, seen here) and must then take them all back instead of committing.
#include <catch2/catch.hpp>

#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <spawn.h>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

#include "cli_runner.hpp"

namespace fs = std::filesystem;
namespace testing = towgeom::testing;

extern char** environ;

TEST_CASE("Ctrl-C while resolve writes: exit 130, an existing output directory left byte for byte", "[cli][behaviour][signal][interrupt]")
{
    const fs::path dir = fs::temp_directory_path() / ("towgeom_interrupt_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    const fs::path out = dir / "out", err = dir / "err";
    // An earlier run's files, some of which this run would replace, and files of the user's.
    fs::create_directories(out / "notes");
    const std::map<std::string, std::string> earlier{{"report.json", "{\"an\":\"earlier run\"}\n"},
                                                     {"warp_0.vtk", "# vtk DataFile Version 3.0\nan earlier run\n"},
                                                     {"textile_volume.inp", "*HEADING\nan earlier run\n"},
                                                     {"notes/mine.txt", "the user's\n"}};
    for (const auto& [name, text] : earlier) std::ofstream(out / name) << text;
    const std::map<std::string, std::string> before = testing::snapshot(out);

    const std::string twill = std::string(TOWGEOM_EXAMPLE_DATA) + "/twill/";
    std::vector<std::string> args{TOWGEOM_CLI, "resolve", twill + "warp_0.stw", twill + "weft_0.stw", "--mesh-size", "0.1", "--volume",
                                  "--formats", "stl,vtk,msh,inp", "--out", out.string()};
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
    posix_spawn_file_actions_destroy(&files);
    posix_spawnattr_destroy(&attributes);

    // Ctrl-C once the volume mesh has begun (its progress line is on stderr).
    int status = 0;
    bool running = true, late = false;
    const auto start = std::chrono::steady_clock::now();
    while (running && !late && testing::slurp(err).find("meshing the tows' volumes") == std::string::npos) {
        running = waitpid(pid, &status, WNOHANG) == 0;
        late = std::chrono::steady_clock::now() - start > std::chrono::seconds(300);
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    INFO(testing::slurp(err));
    REQUIRE(running);
    if (late) ::kill(pid, SIGKILL);
    REQUIRE_FALSE(late);
    REQUIRE(::kill(pid, SIGINT) == 0);
    // The files it writes meanwhile, as temporaries next to the ones they would replace.
    std::set<std::string> temporaries;
    while (waitpid(pid, &status, WNOHANG) == 0) {
        std::error_code ec;
        for (fs::directory_iterator e(out, ec), end; !ec && e != end; e.increment(ec))
            if (e->path().filename().string().find(".tmp.") != std::string::npos) temporaries.insert(e->path().filename().string());
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    INFO(testing::slurp(err));
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 130);
    const std::string log = testing::slurp(err);
    CHECK(log.substr(log.rfind('\n', log.size() - 2) + 1) == "towgeom resolve: stopped by a signal (Ctrl-C or SIGTERM); nothing written [cancelled]\n");
    // It had written (measured: the 9 files' temporaries live for about 0.2 s) ...
    std::string seen;
    for (const std::string& t : temporaries) seen += t + " ";
    INFO("temporaries seen: " << seen);
    CHECK(temporaries.size() >= 1);
    // ... and took it all back: the directory as it was, nothing added, removed or changed.
    const std::map<std::string, std::string> after = testing::snapshot(out);
    CHECK(testing::names(after) == testing::names(before));
    CHECK(after == before);
    fs::remove_all(dir);
}
