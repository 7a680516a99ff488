// limits checked before toml++ sees the text, --set text, and names that become CSV columns:
// each refused with a cairn::Error naming the file (or --set), the key and the value
#include <catch2/catch.hpp>

#include "scene/scene_limits.hpp"
#include "scene_fixture.hpp"

using namespace cairn;
using Catch::Matchers::Contains;
using test::error_of;
using test::kBaseScene;
using test::with_extra;
using test::with_line;

namespace {
// "a.a.a...a" of n parts
std::string dotted(int n) {
    std::string s = "a";
    for (int i = 1; i < n; ++i) s += ".a";
    return s;
}
}  // namespace

TEST_CASE("a dotted key of 30000 parts is refused before the parser (it overflowed its stack)", "[scene][limits]") {
    const std::string msg = error_of(with_extra(dotted(30000) + " = 1\n"));
    CHECK_THAT(msg, Contains("bad.toml:20: a.a.a.a") && Contains("more than 32 parts"));
    CHECK_THAT(error_of(with_extra("[" + dotted(30000) + "]\n")), Contains("bad.toml:20:") && Contains("more than 32 parts"));
    CHECK_THAT(error_of(with_extra("\"a\". \"b\" ." + dotted(40) + " = 1\n")), Contains("more than 32 parts"));
}

TEST_CASE("a key of 32 parts passes the pre-scan (and is then an unknown key)", "[scene][limits]") {
    CHECK_THAT(error_of(with_extra(dotted(32) + " = 1\n")), Contains("bad.toml:20: blocks.B.a = (table): unknown key"));
}

TEST_CASE("arrays and inline tables nested beyond 32 levels are refused", "[scene][limits]") {
    const std::string arrays = "x = " + std::string(10000, '[') + std::string(10000, ']') + "\n";
    CHECK_THAT(error_of(with_extra(arrays)), Contains("bad.toml:20: x = [[[[") && Contains("nested deeper than 32"));
    std::string tables = "x = ";
    for (int i = 0; i < 40; ++i) tables += "{a = ";
    tables += "1" + std::string(40, '}') + "\n";
    CHECK_THAT(error_of(with_extra(tables)), Contains("nested deeper than 32"));
}

TEST_CASE("dots and brackets inside strings and comments do not count", "[scene][limits]") {
    const std::string text = with_line(1, "name = \"t\"  # " + dotted(100) + std::string(100, '[')) +
                             "[loads.push]\nblock = \"A\"\nforce = [1.5, 2.5, 3.5]\n";
    std::string desc = "description = '''" + dotted(100) + "\n" + std::string(50, '{') + "'''\n";
    CHECK(error_of(desc + text).empty());
    CHECK(error_of("description = \"" + dotted(100) + "\\\"" + std::string(50, '[') + "\"\n" + text).empty());
}

TEST_CASE("a scene beyond 16 MiB is refused before parsing", "[scene][limits]") {
    const std::string big = kBaseScene + "# " + std::string(kMaxSceneBytes, 'x') + "\n";
    CHECK_THAT(error_of(big), Contains("bad.toml: ") && Contains("bytes, beyond the limit of 16777216 bytes"));
}

TEST_CASE("overrides: control characters and invalid UTF-8 are refused naming the key", "[scene][limits][override]") {
    CHECK_THAT(error_of(kBaseScene, {{"description", "a\x01z"}}),
               Contains("--set description = a\\x01z: the value contains a control character (0x01)"));
    CHECK_THAT(error_of(kBaseScene, {{"description", "line\nbreak"}}),
               Contains("--set description = line\\x0abreak: the value contains a control character (0x0a)"));
    CHECK_THAT(error_of(kBaseScene, {{"description", "a\xff"}}),
               Contains("--set description = a\\xff: the value contains invalid UTF-8 at byte 1 (0xff)"));
    CHECK_THAT(error_of(kBaseScene, {{"blocks.A\x02.size", "1"}}),
               Contains("--set blocks.A\\x02.size: the key contains a control character (0x02)"));
    // a tab and multi-byte UTF-8 are fine
    CHECK(error_of(kBaseScene, {{"description", "a\tb \xc3\xa9 \xe7\x9f\xb3"}}).empty());
}

TEST_CASE("overrides: too many key parts, nesting or size are refused naming the key", "[scene][limits][override]") {
    CHECK_THAT(error_of(kBaseScene, {{dotted(33), "1"}}), Contains("--set a.a.a") && Contains("a key of 33 parts"));
    CHECK_THAT(error_of(kBaseScene, {{"description", std::string(100, '[') + std::string(100, ']')}}),
               Contains("--set description:1: [[[[") && Contains("nested deeper than 32"));
}

TEST_CASE("block and probe names that would break the CSV header are refused", "[scene][limits][names]") {
    auto renamed = [](const std::string& header) { return with_line(11, header); };
    CHECK_THAT(error_of(renamed("[blocks.\"A,B\"]")),
               Contains("bad.toml:11: blocks.A,B = (table): a name must not contain ','"));
    CHECK_THAT(error_of(renamed("[blocks.'say\"hi']")),
               Contains("bad.toml:11: blocks.say\"hi = (table): a name must not contain '\"'"));
    CHECK_THAT(error_of(renamed("[blocks.\"A\\nB\"]")),
               Contains("bad.toml:11: blocks.A\\x0aB = (table): a name must not contain a control character (0x0a)"));
    CHECK_THAT(error_of(renamed("[blocks.\"A\\u0007\"]")),
               Contains("blocks.A\\x07 = (table): a name must not contain a control character (0x07)"));
    CHECK_THAT(error_of(renamed("[blocks.\"\"]")), Contains("bad.toml:11: blocks. = (table): a name must not be empty"));
    CHECK_THAT(error_of(with_extra("[probes.\"p,q\"]\nblock = \"A\"\npoint = [0, 0, 0]\n")),
               Contains("bad.toml:20: probes.p,q = (table): a name must not contain ','"));
    // a probe named through --set with an invalid byte never reaches the CSV
    CHECK_THAT(error_of(kBaseScene, {{"probes.p\xff.block", "A"}}), Contains("--set probes.p\\xff.block: the key contains invalid UTF-8"));
    // non-ASCII names are fine
    CHECK(error_of(renamed("[blocks.\"pierre_\xc3\xa9\"]"), {}).find("name") == std::string::npos);
}

TEST_CASE("text_problem accepts UTF-8 and refuses overlong forms, surrogates and stray bytes", "[scene][limits]") {
    CHECK(text_problem("caf\xc3\xa9 \xf0\x9f\xa7\xb1", false).empty());
    CHECK_THAT(text_problem("\xc0\xaf", false), Contains("invalid UTF-8 at byte 0"));       // overlong '/'
    CHECK_THAT(text_problem("\xed\xa0\x80", false), Contains("invalid UTF-8 at byte 0"));   // U+D800
    CHECK_THAT(text_problem("ab\xe7\x9f", false), Contains("invalid UTF-8 at byte 2"));    // cut short
    CHECK_THAT(text_problem("a\x7f", false), Contains("control character (0x7f)"));
    CHECK(text_problem("a\tb", true).empty());
    CHECK_THAT(text_problem("a\tb", false), Contains("control character (0x09)"));
}
