// Reading a run folder's CSV back (study/run_plots/run_table): quoted cells, text columns, and
// errors that name the file and the line; and the units plot reads from column names.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "model/input_error.hpp"
#include "study/run_plots/plot_style.hpp"
#include "study/run_plots/run_table.hpp"
#include "support/run_command.hpp"
#include "support/test_files.hpp"

namespace vi {
namespace {

std::string error_of(const std::string& path, bool numbers_only) {
    try {
        read_run_table(path, numbers_only);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(RunTable, QuotedCellsAndTextColumns) {
    const std::string dir = test::make_temp_dir();
    const std::string path = dir + "/sweep.csv";
    test::write_text(path, "x,T_s,status\r\n0.5,1e-6,ok\n\n0.75,,\"error: a, b \"\"c\"\"\"\n1,nan,ok\n");
    const RunTable t = read_run_table(path, false);
    ASSERT_EQ(t.rows, 3u);
    EXPECT_EQ(t.find("T_s"), 1);
    EXPECT_EQ(t.find("y"), -1);
    EXPECT_FALSE(t.text[0]);
    EXPECT_FALSE(t.text[1]);
    EXPECT_TRUE(t.text[2]);
    EXPECT_DOUBLE_EQ(t.columns[0][1], 0.75);
    EXPECT_DOUBLE_EQ(t.columns[1][0], 1e-6);
    EXPECT_TRUE(std::isnan(t.columns[1][1]));
    EXPECT_TRUE(std::isnan(t.columns[1][2]));
    // numbers_only refuses the status column at its first row, line 2.
    EXPECT_EQ(error_of(path, true), path + ":2: status: 'ok' is not a number");
    std::filesystem::remove_all(dir);
}

TEST(RunTable, ErrorsNameFileAndLine) {
    const std::string dir = test::make_temp_dir();
    const std::string path = dir + "/history.csv";
    test::write_text(path, "t_s,tip_m\n0,1\n\n1,2,3\n");
    EXPECT_EQ(error_of(path, true), path + ":4: expected 2 comma-separated cells as in the header, got 3");
    test::write_text(path, "t_s,t_s\n0,1\n");
    EXPECT_EQ(error_of(path, true), path + ":1: column t_s appears twice in the header");
    test::write_text(path, "t_s,tip_m\n0,\"1\n");
    EXPECT_EQ(error_of(path, true), path + ":2: a quoted cell is not closed");
    test::write_text(path, "\n\n");
    EXPECT_EQ(error_of(path, true), path + ":1: empty; expected a header row and data rows");
    EXPECT_NE(error_of(dir + "/none.csv", true).find(dir + "/none.csv: cannot read"), std::string::npos);
    std::filesystem::remove_all(dir);
}

TEST(RunPlotStyle, UnitsFromColumnNamesAndPrefixes) {
    EXPECT_EQ(column_unit("tip_velocity_m_s").quantity, "tip velocity");
    EXPECT_EQ(column_unit("tip_velocity_m_s").unit, "m/s");
    EXPECT_EQ(column_unit("contact0_force_n").unit, "N");
    EXPECT_EQ(column_unit("omega1_rad_s").unit, "rad/s");
    EXPECT_EQ(column_unit("x_over_l").unit, "x/l");
    EXPECT_EQ(column_unit("z_max").unit, "");
    EXPECT_EQ(column_unit("z_max").quantity, "z max");
    EXPECT_EQ(display_unit("m", 9.9999999e-7).text, "µm");  // a rounded 1 µm stays in µm
    EXPECT_DOUBLE_EQ(display_unit("m", 9.9999999e-7).factor, 1e6);
    EXPECT_EQ(display_unit("s", 1.5e-4).text, "µs");
    EXPECT_EQ(display_unit("J", 3.9e-12).text, "pJ");
    EXPECT_EQ(display_unit("Hz", 6.5e6).text, "MHz");
    EXPECT_EQ(display_unit("N/m", 1e4).text, "N/m");  // stiffness keeps its plain unit
    EXPECT_EQ(display_unit("-", 3.0).text, "");
    EXPECT_EQ(safe_name("supports[0].gap"), "supports_0_gap");
}

TEST(RunPlotStyle, ThinnedRowsKeepEveryPeak) {
    // A spike one row wide in a long flat history survives thinning.
    std::vector<double> v(100000, 0.0);
    v[54321] = 5.0;
    v[77777] = -3.0;
    const auto rows = rows_to_draw({&v}, v.size(), 1000);
    EXPECT_LT(rows.size(), 2000u);
    EXPECT_NE(std::find(rows.begin(), rows.end(), 54321u), rows.end());
    EXPECT_NE(std::find(rows.begin(), rows.end(), 77777u), rows.end());
    EXPECT_EQ(rows.front(), 0u);
    EXPECT_EQ(rows.back(), v.size() - 1);
    EXPECT_TRUE(std::is_sorted(rows.begin(), rows.end()));
}

}  // namespace
}  // namespace vi
