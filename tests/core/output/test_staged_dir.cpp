// a result directory written as a set: staged beside DIR, swapped in whole, or not at all
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "error.hpp"
#include "output/staged_dir.hpp"
#include "output_files.hpp"

using namespace cairn;
namespace fs = std::filesystem;
using Catch::Matchers::Contains;

namespace {

fs::path scratch(const std::string& name) { return testing::scratch_dir("staged_dir/" + name); }

void put(const fs::path& p, const std::string& text) {
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
}

std::string get(const fs::path& p) { return testing::read_all(p); }

/// the names in `dir`, sorted
std::vector<std::string> names(const fs::path& dir) {
    std::vector<std::string> v;
    for (const auto& e : fs::directory_iterator(dir)) v.push_back(e.path().filename().string());
    std::sort(v.begin(), v.end());
    return v;
}

}  // namespace

TEST_CASE("a staged directory appears only on commit", "[output]") {
    const fs::path root = scratch("new");
    const fs::path dir = root / "sub" / "run";   // missing parents are created
    {
        StagedDir s(dir.string(), false);
        CHECK(s.path().parent_path() == fs::absolute(dir).parent_path());
        CHECK(s.path().filename().string() == "run.cairn-tmp-" + std::to_string(::getpid()));
        put(s.path() / "a.txt", "new\n");
        CHECK_FALSE(fs::exists(dir));
        s.commit();
    }
    CHECK(get(dir / "a.txt") == "new\n");
    CHECK(names(root / "sub") == std::vector<std::string>{"run"});
}

TEST_CASE("a commit swaps the whole set, without it the old set stays", "[output]") {
    const fs::path root = scratch("replace");
    const fs::path dir = root / "run";
    put(dir / "a.txt", "old a\n");
    put(dir / "b.txt", "old b\n");
    {
        StagedDir s(dir.string(), true);
        put(s.path() / "a.txt", "new a\n");
        // not committed: discarded on scope exit
    }
    CHECK(get(dir / "a.txt") == "old a\n");
    CHECK(names(root) == std::vector<std::string>{"run"});
    {
        StagedDir s(dir.string(), true);
        put(s.path() / "a.txt", "new a\n");
        s.commit();
    }
    CHECK(get(dir / "a.txt") == "new a\n");
    CHECK_FALSE(fs::exists(dir / "b.txt"));   // the old set is gone, not merged
    CHECK(names(root) == std::vector<std::string>{"run"});
}

TEST_CASE("a staged directory refuses before any work what it cannot replace", "[output]") {
    const fs::path root = scratch("refuse");
    put(root / "run" / "a.txt", "old\n");
    CHECK_THROWS_WITH(StagedDir((root / "run").string(), false), Contains("not empty") && Contains("--force"));
    put(root / "file", "x");
    CHECK_THROWS_WITH(StagedDir((root / "file").string(), true), Contains("not a directory"));
    // a parent that is a file: the staging directory cannot be created
    CHECK_THROWS_AS(StagedDir((root / "file" / "run").string(), true), Error);
    CHECK(names(root) == std::vector<std::string>{"file", "run"});
    // an empty directory is not a result: replaced without force
    fs::create_directories(root / "empty");
    StagedDir s((root / "empty").string(), false);
    s.commit();
}

TEST_CASE("carry_over keeps the entries a command does not own", "[output]") {
    const fs::path root = scratch("carry");
    const fs::path dir = root / "validation";
    put(dir / "report.md", "old report\n");
    put(dir / "runs" / "x" / "trajectory.csv", "old\n");
    put(dir / "study" / "inertia.md", "study\n");
    put(dir / "bench.cairn-tmp-99999999" / "junk", "a staging leftover\n");
    StagedDir s(dir.string(), true);
    s.carry_over({"report.md", "runs"}, StagedDir::Carry::copy);
    put(s.path() / "report.md", "new report\n");
    s.commit();
    CHECK(get(dir / "report.md") == "new report\n");
    CHECK(get(dir / "study" / "inertia.md") == "study\n");
    CHECK(names(dir) == std::vector<std::string>{"report.md", "study"});
}

TEST_CASE("staging directories of processes that died are removed by the next one", "[output]") {
    const fs::path root = scratch("stale");
    const pid_t child = ::fork();
    if (child == 0) ::_exit(0);
    ::waitpid(child, nullptr, 0);   // a pid that no longer exists
    put(root / ("run.cairn-tmp-" + std::to_string(child)) / "trajectory.csv", "half\n");
    put(root / ("run.cairn-tmp-" + std::to_string(::getppid())) / "x", "a live process's\n");
    StagedDir s((root / "run").string(), false);
    CHECK_FALSE(fs::exists(root / ("run.cairn-tmp-" + std::to_string(child))));
    CHECK(fs::exists(root / ("run.cairn-tmp-" + std::to_string(::getppid()))));
}

TEST_CASE("carry_over by hard links brings a directory's other files without copying them", "[output]") {
    const fs::path root = scratch("carry_link");
    const fs::path dir = root / "run";
    put(dir / "trajectory.csv", "old\n");
    put(dir / "notes.txt", "mine\n");
    put(dir / "sub" / "data.bin", "more\n");
    fs::permissions(dir, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec);
    StagedDir s(dir.string(), true);
    s.carry_over({"trajectory.csv"}, StagedDir::Carry::link);
    CHECK(fs::hard_link_count(s.path() / "notes.txt") == 2);   // one file, two names
    CHECK(fs::hard_link_count(s.path() / "sub" / "data.bin") == 2);
    CHECK(fs::status(s.path()).permissions() == fs::status(dir).permissions());
    put(s.path() / "trajectory.csv", "new\n");
    s.commit();
    CHECK(names(dir) == std::vector<std::string>{"notes.txt", "sub", "trajectory.csv"});
    CHECK(get(dir / "notes.txt") == "mine\n");
    CHECK(fs::hard_link_count(dir / "notes.txt") == 1);   // the old name went with the old directory
    CHECK(get(dir / "trajectory.csv") == "new\n");
}

TEST_CASE("a staged directory given as a symbolic link replaces the directory it points to", "[output]") {
    const fs::path root = scratch("symlink");
    put(root / "real" / "a.txt", "old\n");
    fs::create_directory_symlink("real", root / "link");
    StagedDir s((root / "link").string(), true);
    put(s.path() / "a.txt", "new\n");
    s.commit();
    CHECK(fs::is_symlink(root / "link"));
    CHECK(get(root / "real" / "a.txt") == "new\n");
    CHECK(names(root) == std::vector<std::string>{"link", "real"});
}

TEST_CASE("a directory being written by another process is refused at once, then free when it ends", "[output]") {
    const fs::path dir = scratch("locked") / "run";
    int ready[2], release[2];
    REQUIRE(::pipe(ready) == 0);
    REQUIRE(::pipe(release) == 0);
    const pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) {   // the other writer: holds DIR until told to end
        char c = 0;
        try {
            StagedDir s(dir.string(), true);
            (void)!::write(ready[1], "y", 1);
            (void)!::read(release[0], &c, 1);
        } catch (...) {
            (void)!::write(ready[1], "n", 1);
        }
        ::_exit(0);
    }
    char c = 0;
    REQUIRE(::read(ready[0], &c, 1) == 1);
    REQUIRE(c == 'y');
    CHECK_THROWS_WITH(StagedDir(dir.string(), true),
                      Contains("being written by another cairn process") && Contains("pid " + std::to_string(child)));
    REQUIRE(::write(release[1], "x", 1) == 1);
    int status = 0;
    REQUIRE(::waitpid(child, &status, 0) == child);
    for (int fd : {ready[0], ready[1], release[0], release[1]}) ::close(fd);
    StagedDir s(dir.string(), true);   // the kernel dropped the lock with the process
    put(s.path() / "a.txt", "mine\n");
    s.commit();
    CHECK(get(dir / "a.txt") == "mine\n");
}

TEST_CASE("one command cannot write one directory twice at once", "[output]") {
    const fs::path dir = scratch("twice") / "run";
    StagedDir first(dir.string(), true);
    CHECK_THROWS_WITH(StagedDir(dir.string(), true), Contains("already being written by this command"));
    const fs::path other = scratch("twice") / "other";
    CHECK_NOTHROW(StagedDir(other.string(), true));   // another directory is free
}
