// OutputFiles (all-or-nothing output): a commit that fails at its last rename leaves the
// directory exactly as it was, older files included; a successful one leaves no backup or
// temporary file; directories made for output that is never committed are removed again.
#include <catch2/catch.hpp>

#include <towgeom/error.hpp>

#include <filesystem>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

#include "cli_runner.hpp"
#include "io/output_files.hpp"

namespace fs = std::filesystem;
using towgeom::Error;
using towgeom::ErrorCode;
using towgeom::detail::OutputFiles;
using towgeom::testing::snapshot;

namespace {

fs::path scratch(const std::string& name)
{
    const fs::path p = fs::temp_directory_path() / ("towgeom_output_files_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(p);
    fs::create_directories(p);
    return p;
}

void put(const fs::path& p, const std::string& bytes) { std::ofstream(p, std::ios::binary) << bytes; }

ino_t inode(const fs::path& p)
{
    struct stat s {};
    REQUIRE(::lstat(p.c_str(), &s) == 0);
    return s.st_ino;
}

}  // namespace

TEST_CASE("a commit failing at its last rename restores every replaced file and removes the new ones", "[io][output]")
{
    const fs::path dir = scratch("fail");
    put(dir / "a.txt", "old a\n");
    put(dir / "b.txt", "old b\n");
    put(dir / "keep.txt", "not ours\n");
    fs::create_directory(dir / "last");  // the last target: a directory that is not empty
    put(dir / "last" / "inside", "x");
    fs::create_symlink("a.txt", dir / "link");
    const auto before = snapshot(dir);
    const ino_t aInode = inode(dir / "a.txt");
    {
        OutputFiles files;
        files.open((dir / "a.txt").string()) << "new a\n";
        files.open((dir / "new.txt").string()) << "new\n";
        files.open((dir / "b.txt").string()) << "new b\n";
        files.open((dir / "link").string()) << "replaces the link\n";
        files.open((dir / "last").string()) << "cannot go over a directory\n";
        try {
            files.commit();
            FAIL("commit over a non-empty directory succeeded");
        } catch (const Error& e) {
            CHECK(e.code() == ErrorCode::WriteFailed);
            CHECK(e.file() == (dir / "last").string());
            CHECK(e.message().rfind("cannot rename into place: ", 0) == 0);
            CHECK(e.message().find("could not") == std::string::npos);  // everything restored
        }
        // Before the destructor: nothing but the temporaries of the files not renamed.
        auto now = snapshot(dir);
        std::size_t temporaries = 0;
        for (auto it = now.begin(); it != now.end();)
            if (it->first.find(".tmp.") != std::string::npos) {
                ++temporaries;
                it = now.erase(it);
            } else {
                ++it;
            }
        CHECK(temporaries == 1);  // last's
        CHECK(now == before);
    }
    const auto after = snapshot(dir);
    INFO("before: " << towgeom::testing::names(before) << "\nafter: " << towgeom::testing::names(after));
    CHECK(after == before);
    CHECK(after.at("a.txt") == "old a\n");
    CHECK(after.at("b.txt") == "old b\n");
    CHECK(after.at("link") == "<link>a.txt");
    CHECK(inode(dir / "a.txt") == aInode);  // the very file, not a copy
    fs::remove_all(dir);
}

TEST_CASE("a successful commit replaces older files and leaves no backup or temporary", "[io][output]")
{
    const fs::path dir = scratch("ok");
    put(dir / "a.txt", "old a\n");
    put(dir / "keep.txt", "not ours\n");
    {
        OutputFiles files;
        files.open((dir / "a.txt").string()) << "new a\n";
        files.open((dir / "new.txt").string()) << "new\n";
        files.commit();
    }
    const std::map<std::string, std::string> expected{{"a.txt", "new a\n"}, {"keep.txt", "not ours\n"}, {"new.txt", "new\n"}};
    CHECK(snapshot(dir) == expected);
    fs::remove_all(dir);
}

TEST_CASE("output directories are removed again when the output is not committed", "[io][output]")
{
    const fs::path dir = scratch("dirs");
    const fs::path nested = dir / "made" / "for" / "output";
    {
        OutputFiles files;
        files.makeDirectory(nested.string());
        CHECK(fs::is_directory(nested));
        files.open((nested / "f.txt").string()) << "never committed\n";
    }
    CHECK(snapshot(dir).empty());
    {
        // A directory that existed stays, as do those of a committed output.
        fs::create_directory(dir / "made");
        OutputFiles files;
        files.makeDirectory((nested.string() + "/"));
        files.open((nested / "f.txt").string()) << "committed\n";
        files.commit();
    }
    const std::map<std::string, std::string> expected{
        {"made", "<dir>"}, {"made/for", "<dir>"}, {"made/for/output", "<dir>"}, {"made/for/output/f.txt", "committed\n"}};
    CHECK(snapshot(dir) == expected);
    {
        OutputFiles files;
        files.makeDirectory((dir / "made" / "again").string());
    }
    CHECK(snapshot(dir) == expected);
    put(dir / "file", "x");
    OutputFiles files;
    CHECK_THROWS_MATCHES(files.makeDirectory((dir / "file" / "sub").string()), Error,
                         Catch::Matchers::Predicate<Error>([](const Error& e) { return e.code() == ErrorCode::WriteFailed; }));
    fs::remove_all(dir);
}
