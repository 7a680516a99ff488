// The resume log: kept jobs read back, a line cut by an interruption left out, text hashes
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "run/resume_log.hpp"

using namespace cairn;
namespace fs = std::filesystem;

TEST_CASE("resume log keeps whole lines and leaves out one cut by an interruption", "[run][resume]") {
    const fs::path dir = fs::path(CAIRN_BINARY_DIR) / "test_scratch" / "resume_log";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string path = (dir / "jobs.resume").string();
    {
        ResumeLog log(path);
        CHECK(log.find("a") == nullptr);
        log.keep("a", {"completed", "1.5,2\tx\ny"});   // tabs and newlines in a record become spaces
        log.keep("b", {"unstable", ""});
    }
    std::ofstream(path, std::ios::app) << "c\tcompleted\tcut here";   // no newline: interrupted
    ResumeLog again(path);
    REQUIRE(again.find("a") != nullptr);
    CHECK(again.find("a")->outcome == "completed");
    CHECK(again.find("a")->record == "1.5,2 x y");
    REQUIRE(again.find("b") != nullptr);
    CHECK(again.find("b")->record.empty());
    CHECK(again.find("c") == nullptr);
    again.keep("d", {"refused", "r"});
    ResumeLog third(path);
    REQUIRE(third.find("d") != nullptr);   // written on a line of its own after the cut one
    CHECK(third.find("d")->record == "r");
    CHECK(third.find("c") == nullptr);
}

TEST_CASE("text hash is FNV-1a 64", "[run][resume]") {
    CHECK(text_hash("") == "cbf29ce484222325");   // the FNV-1a offset basis
    CHECK(text_hash("a") == "af63dc4c8601ec8c");  // published FNV-1a 64 test vector
    CHECK(text_hash("a") != text_hash("b"));
}
