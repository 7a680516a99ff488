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

TEST_CASE("a run's worst metric reads value vs reference and the tolerance, for every kind of check", "[report]") {
    validation::CaseRun r;
    r.outcome = Outcome::completed;
    r.analysed = true;
    SECTION("absolute: the reference appears once, after vs") {
        r.analysis.metrics = {metrics::absolute("slip while held", "m", 4.2e-6, 0.0, 1.26e-7, "")};
        CHECK(worst_metric_text(r) == "slip while held 4.2e-06 m vs 0 m (± 1.26e-07 m)");
    }
    SECTION("an upper bound") {
        r.analysis.metrics = {metrics::at_most("drift", "m", 2.0, 1.0, 0.5, "")};
        CHECK(worst_metric_text(r) == "drift 2 m vs 1 m (≤ ref + 0.5 m)");
    }
    SECTION("relative") {
        r.analysis.metrics = {metrics::relative("period", "s", 1.01, 1.0, 0.02, "")};
        CHECK(worst_metric_text(r) == "period 1.01 s vs 1 (+1.000 %, tol 2 %)");
    }
}
