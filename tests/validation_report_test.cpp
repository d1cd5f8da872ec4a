// `vibroimpact validate`: the quick document has every section and no NaN; --json gives its sections
// and tables; --help works.

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "support/run_command.hpp"
#include "support/test_files.hpp"
#include "support/text_checks.hpp"

namespace vi {
namespace {

using test::run_vibroimpact;

// One run for both: the Markdown document written with --out, and --json on stdout.
TEST(ValidateCommand, QuickReportHasEverySectionAndNoNanAndItsJsonTheSameTables) {
    const std::string dir = test::make_temp_dir();
    const std::string md = dir + "/validation.md";
    const auto r = run_vibroimpact({"validate", "--quick", "--quiet", "--json", "--out", md, "--case",
                                    test::source_path("examples/paper/free_impact_tip.toml"), "--switch-case",
                                    test::source_path("examples/switch/cantilever_switch.toml")});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string text = test::read_text(md);
    EXPECT_EQ(text.find("# Validation"), 0u);
    EXPECT_NE(text.find("validate --out docs/validation.md"), std::string::npos) << "says how to regenerate";
    for (const char* heading :
         {"## 1. Static deflections", "## 2. Natural frequencies", "## 3. Nodal points and peaks",
          "## 4. Supported beam", "## 5. Single-DOF Kelvin-Voigt impact", "## 6. Energy conservation",
          "## 7. Exact vs CVODE on the default example", "## 8. Mesh convergence of the default example",
          "## 9. Time-dependent loads", "## 10. Electrostatic pull-in",
          "## 11. A closed switch collapsing onto its electrode", "## 12. Validated in the test suite"}) {
        EXPECT_NE(text.find(heading), std::string::npos) << heading;
    }
    // printf spells a NaN "nan" or "-nan" and an infinity "inf"; as words, not inside "dominant".
    const std::string bad = test::find_word_ignoring_case(text, {"nan", "inf"});
    EXPECT_TRUE(bad.empty()) << "found \"" << bad << "\"";
    EXPECT_EQ(text.find("MISMATCH"), std::string::npos);

    const auto j = nlohmann::json::parse(r.out);  // stdout is the JSON alone
    EXPECT_EQ(j["document"], "validation");
    EXPECT_EQ(j["quick"], true);
    EXPECT_EQ(j["title"], "Validation of the FE model and the transient solvers");
    ASSERT_EQ(j["sections"].size(), 12u);
    for (std::size_t i = 0; i < 11; ++i) EXPECT_EQ(j["sections"][i]["number"], i + 1);
    EXPECT_EQ(j["sections"][0]["title"], "Static deflections");
    // As many tables as the Markdown has header rules, each row as wide as its header.
    std::size_t rules = 0, tables = 0;
    for (std::size_t at = text.find("\n|---|"); at != std::string::npos; at = text.find("\n|---|", at + 1)) ++rules;
    for (const auto& section : j["sections"]) {
        for (const auto& table : section["tables"]) {
            ++tables;
            for (const auto& row : table["rows"]) EXPECT_EQ(row.size(), table["columns"].size()) << section["title"];
        }
    }
    EXPECT_GT(rules, 10u);
    EXPECT_EQ(tables, rules);
    // The first row of section 1 as the Markdown writes it: text stays text, a number is a number
    // that reads back the document's digits.
    const auto& first = j["sections"][0]["tables"][0];
    EXPECT_EQ(first["columns"][0], "quantity (m = 50)");
    const auto& row = first["rows"][0];
    EXPECT_EQ(row[0], "cantilever tip, P at x = l");
    ASSERT_TRUE(row[1].is_number()) << row;
    std::ostringstream cells;
    cells.precision(10);
    cells << "| " << row[0].get<std::string>() << " | " << row[1].get<double>() << " | ";
    EXPECT_NE(text.find(cells.str()), std::string::npos) << cells.str();
    std::filesystem::remove_all(dir);
}

TEST(ValidateCommand, HelpExitsZero) {
    const auto r = run_vibroimpact({"validate", "--help"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("--paper-parameters"), std::string::npos);
    EXPECT_NE(r.out.find("--quick"), std::string::npos);
}

TEST(ValidateCommand, MissingCaseIsBadInput) {
    const auto r = run_vibroimpact({"validate", "--quick", "--case", "no/such/case.toml", "--switch-case",
                                    test::source_path("examples/switch/cantilever_switch.toml")});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("no/such/case.toml"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace vi
