// A .stw file of 10^7 lines (1,250,000 sections of 7 points, ~190 MB), written at test time:
//   1. readStackFile() reads and validates it, in a child process whose peak RSS must stay
//      below 2 GB (the reader streams: memory grows with the points, not the file);
//   2. its last line is broken in place ("x" for a digit) and `towgeom fit FILE GOOD --out DIR`
//      must exit 2 with one stderr line naming FILE:10000000 and [non_numeric], write nothing,
//      and stay below 2 GB too.
// Usage: towgeom_ten_million_lines CLI GOOD.stw WORKDIR. Prints times and peak RSS; the file is
// removed afterwards, also when the test fails.
#include <towgeom/towgeom.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

constexpr long kLines = 10'000'000;
constexpr long kPoints = 7;
constexpr long kSections = kLines / (kPoints + 1);  // with 1 comment line and a blank line between sections
constexpr long kMaxRssKiB = 2L * 1024 * 1024;

fs::path bigFile;  // removed on failure too: ~190 MB

[[noreturn]] void fail(const std::string& why)
{
    std::cerr << "FAILED: " << why << "\n";
    if (!bigFile.empty()) fs::remove(bigFile);
    std::exit(1);
}

double since(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Writes the file; returns the length of its last line (without the newline).
std::size_t writeLongStack(const fs::path& path)
{
    static_assert(1 + kSections * kPoints + (kSections - 1) == kLines, "exactly 10^7 lines");
    std::ofstream out(path, std::ios::binary);
    std::vector<char> buffer(1 << 20);
    out.rdbuf()->pubsetbuf(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    out << "# 10^7 lines: " << kSections << " sections of " << kPoints << " points\n";
    char around[kPoints][32];
    for (long j = 0; j < kPoints; ++j) {
        const double a = 2 * 3.14159265358979323846 * static_cast<double>(j) / kPoints;
        std::snprintf(around[j], sizeof around[j], " %.4f %.4f\n", 0.5 * std::cos(a), 0.5 * std::sin(a));
    }
    std::string last;
    for (long i = 0; i < kSections; ++i) {
        if (i) out << '\n';
        const std::string x = std::to_string(i);
        for (long j = 0; j < kPoints; ++j) {
            out << x << around[j];
            if (i + 1 == kSections && j + 1 == kPoints) last = x + around[j];
        }
    }
    out.close();
    if (!out) fail("cannot write " + path.string());
    return last.size() - 1;
}

struct Child {
    int status = -1;
    long maxRssKiB = 0;
    double seconds = 0;
};

/// Runs @p body in a child process (its exit status is body's return value) and measures it.
template <class F>
Child inChild(F&& body)
{
    const auto t0 = std::chrono::steady_clock::now();
    std::cout.flush();
    const pid_t pid = ::fork();
    if (pid < 0) fail("fork failed");
    if (pid == 0) _exit(body());
    int raw = 0;
    rusage usage{};
    if (::wait4(pid, &raw, 0, &usage) != pid) fail("wait4 failed");
    Child c;
    c.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
    c.maxRssKiB = usage.ru_maxrss;
    c.seconds = since(t0);
    return c;
}

std::string slurp(const fs::path& p)
{
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc != 4) fail("usage: towgeom_ten_million_lines CLI GOOD.stw WORKDIR");
    const std::string cli = argv[1], good = argv[2];
    const fs::path work = argv[3];
    fs::remove_all(work);
    fs::create_directories(work);
    const fs::path file = work / "ten_million.stw";
    bigFile = file;

    auto t0 = std::chrono::steady_clock::now();
    const std::size_t lastLength = writeLongStack(file);
    std::cout << "wrote " << file << ": " << kLines << " lines, " << fs::file_size(file) / 1e6 << " MB in "
              << since(t0) << " s\n";

    // 1. The library reads the valid file.
    const Child read = inChild([&] {
        try {
            const towgeom::TowStack s = towgeom::readStackFile(file.string());
            const bool ok = s.sectionCount() == static_cast<std::size_t>(kSections) &&
                            s.pointsPerSection() == static_cast<std::size_t>(kPoints) &&
                            s.lineOf(kSections - 1, kPoints - 1) == static_cast<std::size_t>(kLines);
            if (!ok) std::cerr << "read " << s.sectionCount() << " x " << s.pointsPerSection() << " points\n";
            return ok ? 0 : 3;
        } catch (const std::exception& e) {
            std::cerr << e.what() << "\n";
            return 4;
        }
    });
    std::cout << "readStackFile: status " << read.status << ", " << read.seconds << " s, peak RSS "
              << read.maxRssKiB / 1024 << " MiB\n";
    if (read.status != 0) fail("readStackFile did not read the valid 10^7-line file");
    if (read.maxRssKiB >= kMaxRssKiB) fail("readStackFile needed 2 GB or more");

    // 2. Break the last line in place and give it to the command line, after a good file.
    {
        std::fstream io(file, std::ios::in | std::ios::out | std::ios::binary);
        io.seekp(-static_cast<std::streamoff>(lastLength + 1), std::ios::end);  // the last line's start
        io.put('x');
        if (!io) fail("cannot edit the last line");
    }
    const fs::path out = work / "out", stdoutFile = work / "stdout", stderrFile = work / "stderr";
    const Child run = inChild([&] {
        const int o = ::open(stdoutFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int e = ::open(stderrFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (o < 0 || e < 0 || ::dup2(o, 1) < 0 || ::dup2(e, 2) < 0) return 5;
        ::execl(cli.c_str(), cli.c_str(), "fit", good.c_str(), file.c_str(), "--out", out.c_str(), "--quiet",
                static_cast<char*>(nullptr));
        return 6;
    });
    const std::string err = slurp(stderrFile);
    std::cout << "towgeom fit: exit " << run.status << ", " << run.seconds << " s, peak RSS " << run.maxRssKiB / 1024
              << " MiB, stderr: " << err;
    const std::string where = file.string() + ":" + std::to_string(kLines) + ": ";
    if (run.status != 2) fail("expected exit status 2");
    if (err.find(where) == std::string::npos || err.find("[non_numeric]") == std::string::npos ||
        std::count(err.begin(), err.end(), '\n') != 1)
        fail("stderr should be one line naming '" + where + "' and [non_numeric]");
    if (!slurp(stdoutFile).empty()) fail("expected nothing on stdout");
    if (fs::exists(out) && !fs::is_empty(out)) fail("output left in " + out.string());
    if (run.maxRssKiB >= kMaxRssKiB) fail("towgeom fit needed 2 GB or more");

    fs::remove_all(work);
    std::cout << "ok\n";
    return 0;
}
