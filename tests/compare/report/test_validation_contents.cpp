// the validation report opens with a table of contents linking to its sections and cases
#include <catch2/catch.hpp>

#include "report/document.hpp"
#include "report/validation_report.hpp"

using namespace cairn;
using namespace cairn::report;

TEST_CASE("the validation report has a table of contents with links to its sections and cases", "[report]") {
    validation::CaseResult c;
    c.name = "rocking";
    const Document d = build_report({c}, FigureSet{}, ReportContext{});
    const std::string md = to_markdown(d), html = to_html(d);
    // the contents come before the verdict grid they link to
    const auto toc = md.find("- [Verdict](#verdict)");
    REQUIRE(toc != std::string::npos);
    CHECK(toc < md.find("## Verdict"));
    CHECK(html.find("<nav><ul class=\"toc\">") != std::string::npos);
    CHECK(html.find("<a href=\"#verdict\">Verdict</a>") != std::string::npos);
    CHECK(html.find("id=\"verdict\"") != std::string::npos);
}
