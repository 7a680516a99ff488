// atomic writes: a failed write never replaces an old file
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "error.hpp"
#include "output/atomic_write.hpp"
#include "output_files.hpp"

namespace fs = std::filesystem;
using namespace cairn;

using testing::read_all;
using testing::scratch_dir;

TEST_CASE("write_file_atomic replaces the file when the writer succeeds", "[output]") {
    const fs::path dir = scratch_dir("atomic_ok");
    const std::string path = (dir / "result.csv").string();
    write_text_atomic(path, "old\n");
    write_file_atomic(path, [](std::ostream& out) { out << "new\n"; });
    CHECK(read_all(path) == "new\n");
    CHECK_FALSE(fs::exists(path + ".tmp"));
}

TEST_CASE("write_file_atomic leaves the old file intact when the writer throws", "[output]") {
    const fs::path dir = scratch_dir("atomic_throw");
    const std::string path = (dir / "result.csv").string();
    write_text_atomic(path, "old\n");
    CHECK_THROWS_AS(write_file_atomic(path,
                                      [](std::ostream& out) {
                                          out << "half a fil";
                                          throw std::runtime_error("writer failed");
                                      }),
                    std::runtime_error);
    CHECK(read_all(path) == "old\n");
    CHECK_FALSE(fs::exists(path + ".tmp"));
}

TEST_CASE("write_file_atomic into a missing directory names the file", "[output]") {
    const fs::path dir = scratch_dir("atomic_missing");
    const std::string path = (dir / "no" / "such" / "result.csv").string();
    CHECK_THROWS_WITH(write_text_atomic(path, "x"), Catch::Matchers::Contains(path + ".tmp"));
}
