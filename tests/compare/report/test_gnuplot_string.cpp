// quoting text for gnuplot scripts: what goes in comes back out of gnuplot unchanged, and nothing runs
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "report/gnuplot.hpp"
#include "report/spawn.hpp"

namespace fs = std::filesystem;
using cairn::report::gnuplot_file;
using cairn::report::gnuplot_string;

TEST_CASE("gnuplot_string doubles single quotes and turns control characters into spaces", "[report][gnuplot]") {
    CHECK(gnuplot_string("plain") == "'plain'");
    CHECK(gnuplot_string("it's") == "'it''s'");
    CHECK(gnuplot_string("a\nb\rc\td") == "'a b c d'");
    CHECK(gnuplot_string("back\\slash \" `x` @m $(y)") == "'back\\slash \" `x` @m $(y)'");
    CHECK(gnuplot_string("") == "''");
    CHECK(gnuplot_string("é") == "'é'");   // UTF-8 bytes pass through
}

TEST_CASE("gnuplot_file prefixes ./ so that no name is read as a pipe or a special file", "[report][gnuplot]") {
    CHECK(gnuplot_file("< touch x") == "'./< touch x'");
    CHECK(gnuplot_file("|cmd") == "'./|cmd'");
    CHECK(gnuplot_file("-") == "'./-'");
}

TEST_CASE("gnuplot reads gnuplot_string back verbatim and runs none of it", "[report][gnuplot]") {
    const std::string gp = cairn::report::find_on_path("gnuplot");
    if (gp.empty()) {
        WARN("gnuplot is not installed: the round trip through gnuplot is not checked");
        return;
    }
    const fs::path dir = fs::path(CAIRN_BINARY_DIR) / "test_scratch" / "report" / "gnuplot_string";
    fs::remove_all(dir);
    fs::create_directories(dir);
    // every metacharacter of gnuplot and of the shell; newline and a trailing backslash too
    const std::string evil = "q\"uote' back\\slash `touch BQ` $(touch DOLLAR) ; # @m system('touch SYS') "
                             "system(\"touch SYS2\") \\\nnext '< touch PIPE' |touch OUT\\";
    std::ofstream(dir / "t.gp") << "m = 'touch MACRO'\nset print " << gnuplot_file("printed.txt") << "\n"
                                << "print " << gnuplot_string(evil) << "\n";
    REQUIRE(cairn::report::run_program({gp, "./t.gp"}, dir.string(), "t.log") == 0);
    std::ifstream in(dir / "printed.txt");
    std::string back;
    std::getline(in, back);
    std::string expected = evil;
    for (char& c : expected)
        if (c == '\n') c = ' ';
    CHECK(back == expected);
    for (const char* f : {"BQ", "DOLLAR", "SYS", "SYS2", "MACRO", "PIPE", "OUT"}) {
        INFO(f);
        CHECK_FALSE(fs::exists(dir / f));
    }
}

TEST_CASE("run_program passes arguments verbatim, sets the directory and reports the exit status", "[report][spawn]") {
    const fs::path dir = fs::path(CAIRN_BINARY_DIR) / "test_scratch" / "report" / "spawn dir $(touch X) 'q'";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string pf = cairn::report::find_on_path("printf");
    REQUIRE_FALSE(pf.empty());
    CHECK(cairn::report::run_program({pf, "%s|", "a b", "$(touch Y)", "'"}, dir.string(), "out.txt") == 0);
    std::ifstream in(dir / "out.txt");
    std::string got;
    std::getline(in, got);
    CHECK(got == "a b|$(touch Y)|'|");
    CHECK_FALSE(fs::exists(dir / "X"));
    CHECK_FALSE(fs::exists(dir / "Y"));
    CHECK(cairn::report::run_program({cairn::report::find_on_path("false")}, dir.string(), "") == 1);
    CHECK(cairn::report::run_program({"/nonexistent/program"}, dir.string(), "") == -1);
    CHECK(cairn::report::run_program({pf, "x"}, (dir / "missing").string(), "") == -1);
    CHECK(cairn::report::find_on_path("no-such-program-here").empty());
}
