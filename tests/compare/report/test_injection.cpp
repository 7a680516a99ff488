// a scene whose text carries every gnuplot and shell metacharacter, validated into an output
// directory whose path carries quotes, spaces and $( ): nothing of it runs, the figures still render
#include <algorithm>
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "report/spawn.hpp"

namespace fs = std::filesystem;

namespace {

/// `s` as a TOML basic string
std::string toml_string(const std::string& s) {
    std::string o = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') o += std::string("\\") + c;
        else if (c == '\n') o += "\\n";
        else o += c;
    }
    return o + "\"";
}

/// every file under `dir` named SENTINEL_<something> (what the `touch` commands would create;
/// cairn's own files carry the whole scene name, never these names alone)
std::vector<std::string> sentinels(const fs::path& dir) {
    std::vector<std::string> found;
    for (const auto& e : fs::recursive_directory_iterator(dir)) {
        const std::string f = e.path().filename().string();
        if (f.rfind("SENTINEL_", 0) == 0 && f.find_first_of(" .'\"") == std::string::npos)
            found.push_back(e.path().string());
    }
    return found;
}

}  // namespace

TEST_CASE("validate draws the figures of a scene full of metacharacters and runs none of them", "[report][security]") {
    const fs::path dir = fs::path(CAIRN_BINARY_DIR) / "test_scratch" / "report" / "injection";
    fs::remove_all(dir);
    fs::create_directories(dir);
    // shell: $( ), backquotes, ; and quotes; gnuplot: quotes, backslash, backquote, @ macro,
    // system(), # comments, a newline ending the command, '<' and '|' pipes
    const std::string evil = "\" ' \\ `touch SENTINEL_bq` $(touch SENTINEL_dollar) ; # @m "
                             "system('touch SENTINEL_sys') system(\"touch SENTINEL_sys2\") '< touch SENTINEL_pipe'";
    const std::string description = "x\"; system 'touch SENTINEL_desc' #\n" + evil + "\nlast line \\";
    // names: everything but ',', '"' and a newline (names must stay usable as CSV columns)
    std::string name_evil = evil;
    name_evil.erase(std::remove(name_evil.begin(), name_evil.end(), '"'), name_evil.end());
    const std::string block = "A" + name_evil;
    const std::string probe = "p" + name_evil;
    const std::string scene_name = "scene '\"`touch SENTINEL_file`$(touch SENTINEL_file2);#@m system('touch SENTINEL_f') \\.toml";
    std::ofstream(dir / scene_name)
        << "description = " << toml_string(description) << "\n"
        << "[run]\nduration = 0.15\nsettle = false\n"
        << "[materials.stone]\ndensity = 2600\nyoung = 30e9\npoisson = 0.2\n"
        << "[contact]\nkn = 3e7\nks = 3e7\nfriction = 0.6\n"
        << "[blocks." << toml_string(block) << "]\nsize = [1.0, 1.0, 1.0]\nposition = [0.0, 0.0, 0.5]\n"
        << "material = \"stone\"\n"
        << "[blocks." << toml_string(block) << ".mesh]\ndivisions = [1, 1, 1]\nmass = \"consistent\"\n"
        << "[blocks.B]\nsize = [1.0, 1.0, 1.0]\nposition = [0.0, 0.0, -0.5]\nmaterial = \"stone\"\nfixed = true\n"
        << "[probes." << toml_string(probe) << "]\nblock = " << toml_string(block) << "\ncorner = 6\n"
        << "[reference]\nkind = \"rest\"\nblock = " << toml_string(block) << "\n";
    const fs::path out = dir / "out \"dq\" 'sq' $(touch SENTINEL_out) `touch SENTINEL_out2` ;#@m";
    const std::string cairn = std::string(CAIRN_BINARY_DIR) + "/app/cairn";
    const int code = cairn::report::run_program(
        {cairn, "validate", "--cases", (dir / scene_name).string(), "--backends", "dem", "-q", "--out", out.string()},
        dir.string(), "log.txt");
    std::ifstream log(dir / "log.txt");
    std::stringstream ss;
    ss << log.rdbuf();
    INFO(ss.str());
    REQUIRE(code == 0);
    CHECK(sentinels(dir) == std::vector<std::string>{});
    CHECK_FALSE(fs::exists("SENTINEL_dollar"));   // nor where the test runs
    // the case's figure rendered, and the title reached gnuplot as one string
    const std::string case_name = fs::path(scene_name).filename().string();
    CHECK(fs::file_size(out / "figures" / (case_name + ".png")) > 1000);
    std::ifstream glog(out / "figures" / (case_name + ".gp.log"));
    std::stringstream gs;
    gs << glog.rdbuf();
    CHECK(gs.str().empty());   // gnuplot said nothing: no warning, no error
}
