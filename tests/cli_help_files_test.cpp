// `vibroimpact man` and `vibroimpact completion` are generated from the command's own help: every
// command and option appears, the page is valid roff, and the completion completes in bash.

#include <gtest/gtest.h>

#include <regex>
#include <set>
#include <string>
#include <vector>

#include "support/run_command.hpp"

namespace {

// The commands `vibroimpact --help` lists (CLI11 prints them under "Subcommands:").
std::vector<std::string> listed_commands() {
    const auto r = vi::test::run_vibroimpact({"--help"});
    std::vector<std::string> out;
    const std::size_t at = r.out.find("Subcommands:");
    if (at == std::string::npos) return out;
    const std::regex line(R"(\n  ([a-z][a-z-]*) )");
    const std::string rest = r.out.substr(at);
    for (auto it = std::sregex_iterator(rest.begin(), rest.end(), line); it != std::sregex_iterator(); ++it) {
        out.push_back((*it)[1]);
    }
    return out;
}

TEST(CliHelpFiles, ManPageHasEveryCommandAndOptionAndIsValidRoff) {
    const std::vector<std::string> commands = listed_commands();
    ASSERT_GE(commands.size(), 13u);
    const auto man = vi::test::run_vibroimpact({"man"});
    ASSERT_EQ(man.exit_code, 0) << man.err;
    EXPECT_EQ(man.out.rfind(".TH VIBROIMPACT 1", 0), 0u);
    for (const std::string& c : commands) {
        if (c == "man" || c == "completion") continue;
        std::string escaped;  // roff writes a hyphen as \-
        for (char ch : c) escaped += ch == '-' ? std::string("\\-") : std::string(1, ch);
        EXPECT_NE(man.out.find("\n.SS " + escaped + "\n"), std::string::npos) << c;
    }
    EXPECT_NE(man.out.find("\\-\\-set"), std::string::npos);           // sweep's option, escaped for roff
    EXPECT_NE(man.out.find("\\-\\-minimize"), std::string::npos);      // optimize's
    EXPECT_NE(man.out.find(".SH EXIT STATUS"), std::string::npos);
    // groff reads it without a warning (when groff is there; Debian's man-db depends on it).
    const std::string page = ::testing::TempDir() + "vibroimpact.1";
    FILE* f = std::fopen(page.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fwrite(man.out.data(), 1, man.out.size(), f);
    std::fclose(f);
    const auto groff = vi::test::run_program({"groff", "-man", "-Tutf8", "-ww", "-z", page});
    if (groff.exit_code == 127) GTEST_SKIP() << "groff not installed: the roff check is skipped";
    EXPECT_EQ(groff.exit_code, 0) << groff.err;
    EXPECT_EQ(groff.err, "");
}

// Runs the completion function in bash on the words typed so far; returns what it offers.
std::string complete(const std::string& script, const std::string& words, int cword) {
    const std::string program = script + "\nCOMP_WORDS=(" + words + "); COMP_CWORD=" + std::to_string(cword) +
                                "; _vibroimpact; printf '%s\\n' \"${COMPREPLY[@]}\"";
    const auto r = vi::test::run_program({"bash", "-c", program});
    return r.out;
}

TEST(CliHelpFiles, BashCompletionCompletesCommandsOptionsAndKinds) {
    const auto r = vi::test::run_vibroimpact({"completion"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("complete -o filenames -F _vibroimpact vibroimpact"), std::string::npos);
    EXPECT_EQ(complete(r.out, "vibroimpact sw", 1), "sweep\nswitch-report\n");
    EXPECT_EQ(complete(r.out, "vibroimpact sweep --se", 2), "--set\n");
    EXPECT_EQ(complete(r.out, "vibroimpact new bri", 2), "bridge\nbridge-switch\n");
    for (const std::string& c : listed_commands()) {
        if (c == "man" || c == "completion") continue;
        EXPECT_NE(complete(r.out, "vibroimpact " + c, 1).find(c + "\n"), std::string::npos) << c;
    }
}

}  // namespace
