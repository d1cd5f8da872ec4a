// Sweep grids (--set parsing, point order), CSV rows and the journal, without running the command.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "sweep/grid.hpp"
#include "sweep/identity.hpp"
#include "sweep/ranks.hpp"
#include "case_text_fixture.hpp"
#include "io/case_reader.hpp"
#include "model/input_error.hpp"
#include "io/sweep_journal.hpp"
#include "sweep/table.hpp"
#include "support/run_command.hpp"

namespace vi {
namespace {

Case support_case() {
    return read_case_text(test::kBaseCase + "[[supports]]\nposition = 1.0\nstiffness = \"100 N/m\"\n", "s.toml");
}

std::string error_of(const std::vector<std::string>& settings) {
    try {
        parse_sweep_grid(settings, support_case());
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(SweepGrid, LastAxisVariesFastest) {
    const SweepGrid g = parse_sweep_grid({"supports[0].position=0.5,1", "beam.elements=10:30:3"}, support_case());
    ASSERT_EQ(g.size(), 6u);
    const std::vector<std::vector<double>> expected = {{0.5, 10}, {0.5, 20}, {0.5, 30}, {1, 10}, {1, 20}, {1, 30}};
    for (std::size_t i = 0; i < g.size(); ++i) EXPECT_EQ(g.values_at(i), expected[i]) << i;
    const Case c = g.case_at(support_case(), 4);
    EXPECT_EQ(c.supports[0].position, 1.0);
    EXPECT_EQ(c.beam.elements, 20);
}

TEST(SweepGrid, SpecFormsExpand) {
    const Case c = support_case();
    EXPECT_EQ(parse_sweep_setting("supports[0].position=0.5,0.67,0.78", c).values, (std::vector<double>{0.5, 0.67, 0.78}));
    EXPECT_EQ(parse_sweep_setting("supports[0].position=0:1:5", c).values,
              (std::vector<double>{0, 0.25, 0.5, 0.75, 1}));
    const auto log = parse_sweep_setting("supports[0].stiffness=log:10:1000:3", c).values;
    ASSERT_EQ(log.size(), 3u);
    EXPECT_EQ(log[0], 10.0);
    EXPECT_NEAR(log[1], 100.0, 1e-12);
    EXPECT_EQ(log[2], 1000.0);
    EXPECT_EQ(parse_sweep_setting("supports[0].gap=-1e-6", c).values, (std::vector<double>{-1e-6}));
}

// Values on the command line may carry the units of case files; plain numbers stay SI.
TEST(SweepGrid, ValuesMayCarryTheUnitsOfCaseFiles) {
    const Case c = support_case();
    const auto gaps = parse_sweep_setting("supports[0].gap=0.5um:2um:4", c).values;
    ASSERT_EQ(gaps.size(), 4u);
    EXPECT_NEAR(gaps[0], 0.5e-6, 1e-20);
    EXPECT_NEAR(gaps[1], 1.0e-6, 1e-20);
    EXPECT_NEAR(gaps[3], 2.0e-6, 1e-20);
    EXPECT_EQ(parse_sweep_setting("supports[0].gap=0.5e-6,1 um", c).values, (std::vector<double>{0.5e-6, 1e-6}));
    const auto k = parse_sweep_setting("supports[0].stiffness=log:10 N/m:1 kN/m:3", c).values;
    ASSERT_EQ(k.size(), 3u);
    EXPECT_EQ(k[0], 10.0);
    EXPECT_EQ(k[2], 1000.0);
    EXPECT_EQ(parse_sweep_setting("material.youngs_modulus=200GPa", c).values, (std::vector<double>{200e9}));
    EXPECT_EQ(error_of({"supports[0].gap=1GPa:2um:3"}),
              "--set supports[0].gap=1GPa:2um:3: '1GPa': unit \"GPa\" is a pressure, expected a length: m, mm, um, µm, nm");
    // A position along the beam is x/l, a plain number: no unit makes sense there.
    EXPECT_EQ(error_of({"supports[0].position=0.5um"}), "--set supports[0].position=0.5um: '0.5um' is not a number");
}

TEST(SweepGrid, BadSettingsNameTheSettingAndTheReason) {
    const struct {
        std::vector<std::string> settings;
        const char* message;
    } cases[] = {
        {{"supports[0].position"}, "--set supports[0].position: expected PATH=SPEC"},
        {{"supports[0].foo=1"}, "--set supports[0].foo=1: unknown key 'foo'"},
        {{"supports[3].position=1"}, "--set supports[3].position=1: supports[3]: index out of range"},
        {{"supports[0].position="}, "--set supports[0].position=: empty range"},
        {{"supports[0].position=0:1:0"}, "--set supports[0].position=0:1:0: count '0' must be a whole number"},
        {{"supports[0].position=a,b"}, "--set supports[0].position=a,b: 'a' is not a number"},
        {{"supports[0].position=0.5,,1"}, "empty value in range"},
        {{"supports[0].position=1e999"}, "is not a finite number"},
        {{"supports[0].position=inf"}, "is not a finite number"},
        {{"supports[0].position=0:1"}, "a linear range is start:stop:count"},
        {{"beam.elements=10.5"}, "--set beam.elements=10.5: beam.elements takes whole numbers, got 10.5"},
        {{"beam.elements=5:10:3"}, "beam.elements takes whole numbers, got 7.5"},
        {{"beam.length=1e-4", "beam.length=2e-4"}, "--set beam.length=2e-4: beam.length is already swept by --set"},
        {{}, "--set: at least one PATH=SPEC is needed"},
    };
    for (const auto& k : cases) {
        const std::string err = error_of(k.settings);
        EXPECT_NE(err.find(k.message), std::string::npos) << err;
    }
}

// The option and the path travel beside the message, whose spec may hold ':' and '=' itself.
TEST(SweepGrid, ASettingsErrorKeepsItsOptionAndPath) {
    for (const auto& [settings, key] : std::vector<std::pair<std::vector<std::string>, std::string>>{
             {{"supports[0].position=0.5:1"}, "supports[0].position"},
             {{"supports[0].positio=0.5"}, "supports[0].positio"},
             {{"beam.length=1e-4", "beam.length=2e-4:3e-4:2"}, "beam.length"},
             {{"supports[0].position"}, "supports[0].position"}}) {
        try {
            parse_sweep_grid(settings, support_case());
            ADD_FAILURE() << settings.back() << " was taken";
        } catch (const InputError& e) {
            EXPECT_EQ(e.option(), "--set") << e.what();
            EXPECT_EQ(e.key(), key) << e.what();
            EXPECT_EQ(std::string(e.what()).rfind("--set " + settings.back() + ": ", 0), 0u) << e.what();
        }
    }
    try {
        parse_sweep_grid({}, support_case());
        ADD_FAILURE() << "no setting was taken";
    } catch (const InputError& e) {
        EXPECT_EQ(e.option(), "") << "an error of no one setting has no option apart";
    }
}

TEST(SweepGrid, TooManyPointsAreRefused) {
    const std::string err = error_of({"beam.length=1:2:10000", "beam.width=1:2:10000", "beam.thickness=1:2:10"});
    EXPECT_NE(err.find("more than 100000000 points"), std::string::npos) << err;
}

TEST(SweepGrid, RanksShareThePointsInTurn) {
    const std::vector<std::size_t> todo = {0, 2, 3, 5, 8, 9, 11};
    EXPECT_EQ(share_of_rank(todo, 0, 3), (std::vector<std::size_t>{0, 5, 11}));
    EXPECT_EQ(share_of_rank(todo, 1, 3), (std::vector<std::size_t>{2, 8}));
    EXPECT_EQ(share_of_rank(todo, 2, 3), (std::vector<std::size_t>{3, 9}));
    EXPECT_EQ(share_of_rank(todo, 0, 1), todo);
}

TEST(SweepGrid, IdentityFollowsCaseAxesAndAnalysis) {
    const Case c = support_case();
    const SweepGrid a = parse_sweep_grid({"supports[0].position=0.5:1:3"}, c);
    const SweepGrid same = parse_sweep_grid({"supports[0].position=0.5,0.75,1"}, c);
    const SweepGrid other = parse_sweep_grid({"supports[0].position=0.5:1:4"}, c);
    const SweepSettings sim;
    SweepSettings modes;
    modes.analysis = SweepAnalysis::modes;
    const auto id = [](std::string_view text, const SweepGrid& g, const SweepSettings& s) {
        return fingerprint_of(sweep_identity_text(text, g, s));
    };
    EXPECT_EQ(id("case", a, sim), id("case", same, sim));
    EXPECT_NE(id("case", a, sim), id("case", other, sim));
    EXPECT_NE(id("case", a, sim), id("case ", a, sim));
    EXPECT_NE(id("case", a, sim), id("case", a, modes));
    EXPECT_EQ(fingerprint_of("").size(), 16u);
}

TEST(SweepTable, RowsQuoteTextAndMarkMissingValues) {
    SweepPointResult r;
    r.parameters = {0.9, 10};
    r.cells = {SweepCell(), 1.5e-6, std::int64_t{3}, std::string("settled"), std::string("a,b")};
    r.status = "ok";
    EXPECT_EQ(sweep_csv_row(r, 5), "0.9,10,nan,1.5e-06,3,settled,\"a,b\",ok");
    r.cells.clear();
    r.status = "error: supports[0].position: must lie in (0, 1] (x0/l) \"quoted\"";
    const std::string row = sweep_csv_row(r, 5);
    EXPECT_EQ(row, "0.9,10,nan,nan,nan,nan,nan,\"error: supports[0].position: must lie in (0, 1] (x0/l) \"\"quoted\"\"\"");
    EXPECT_EQ(sweep_row_status(row), r.status);
    EXPECT_EQ(sweep_row_status("1,2,ok"), "ok");
    EXPECT_EQ(sweep_row_status("1,\"error: x\""), "error: x");
}

class SweepJournalFile : public ::testing::Test {
protected:
    void SetUp() override { dir_ = test::make_temp_dir(); }
    void TearDown() override { std::filesystem::remove_all(dir_); }
    [[nodiscard]] std::string path() const { return dir_ + "/sweep.journal"; }
    [[nodiscard]] std::string text() const {
        std::ifstream in(path(), std::ios::binary);
        std::ostringstream ss;
        ss << in.rdbuf();
        return ss.str();
    }
    std::string dir_;
};

TEST_F(SweepJournalFile, RowsComeBackAndATornLastLineIsCutOff) {
    {
        SweepJournal j = SweepJournal::create(path(), "abc", 5, "x,status");
        j.append(3, "0.3,ok");
        j.append(0, "0,\"error: x, y\"");
    }
    {
        std::ofstream out(path(), std::ios::app | std::ios::binary);
        out << "4,0.4,o";  // killed in the middle of a write
    }
    const JournalContents c = SweepJournal::read(path(), "abc", 5, "x,status");
    EXPECT_TRUE(c.torn_tail);
    ASSERT_EQ(c.rows.size(), 2u);
    EXPECT_EQ(c.rows.at(3), "0.3,ok");
    EXPECT_EQ(c.rows.at(0), "0,\"error: x, y\"");
    {
        SweepJournal j = SweepJournal::reopen(path(), c);
        j.append(4, "0.4,ok");
    }
    const JournalContents again = SweepJournal::read(path(), "abc", 5, "x,status");
    EXPECT_FALSE(again.torn_tail);
    EXPECT_EQ(again.rows.size(), 3u);
    EXPECT_EQ(again.rows.at(4), "0.4,ok");
    EXPECT_EQ(text().find("0.4,o4"), std::string::npos);
}

TEST_F(SweepJournalFile, AnotherSweepsJournalIsRefused) {
    { SweepJournal::create(path(), "abc", 5, "x,status"); }
    EXPECT_THROW(SweepJournal::read(path(), "abd", 5, "x,status"), InputError);
    EXPECT_THROW(SweepJournal::read(path(), "abc", 6, "x,status"), InputError);
    EXPECT_THROW(SweepJournal::read(path(), "abc", 5, "y,status"), InputError);
    EXPECT_THROW(SweepJournal::create(path(), "abc", 5, "x,status"), std::runtime_error);
    {
        std::ofstream out(path(), std::ios::app | std::ios::binary);
        out << "7,0.7,ok\n";  // index beyond the grid
    }
    try {
        SweepJournal::read(path(), "abc", 5, "x,status");
        FAIL() << "a bad line was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("sweep.journal:5: not a journal line"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace vi
