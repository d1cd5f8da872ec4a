// `vibroimpact validate`: the quick document has every section and no NaN; --help works.

#include <gtest/gtest.h>

#include <string>

#include "support/run_command.hpp"
#include "support/text_checks.hpp"

namespace vi {
namespace {

using test::run_vibroimpact;

TEST(ValidateCommand, QuickReportHasEverySectionAndNoNan) {
    const auto r = run_vibroimpact(
        {"validate", "--quick", "--quiet", "--case", test::source_path("examples/paper/free_impact_tip.toml"),
         "--switch-case", test::source_path("examples/switch/cantilever_switch.toml")});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out.find("# Validation"), 0u);
    EXPECT_NE(r.out.find("validate --out docs/validation.md"), std::string::npos) << "says how to regenerate";
    for (const char* heading :
         {"## 1. Static deflections", "## 2. Natural frequencies", "## 3. Nodal points and peaks",
          "## 4. Supported beam", "## 5. Single-DOF Kelvin-Voigt impact", "## 6. Energy conservation",
          "## 7. Exact vs CVODE on the default example", "## 8. Mesh convergence of the default example",
          "## 9. Time-dependent loads", "## 10. Electrostatic pull-in",
          "## 11. A closed switch collapsing onto its electrode", "## 12. Validated in the test suite"}) {
        EXPECT_NE(r.out.find(heading), std::string::npos) << heading;
    }
    // printf spells a NaN "nan" or "-nan" and an infinity "inf"; as words, not inside "dominant".
    const std::string bad = test::find_word_ignoring_case(r.out, {"nan", "inf"});
    EXPECT_TRUE(bad.empty()) << "found \"" << bad << "\"";
    EXPECT_EQ(r.out.find("MISMATCH"), std::string::npos);
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
