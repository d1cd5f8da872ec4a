// The one CSV convention (docs/architecture.md, "Output files"): awkward doubles read back bit for
// bit, the missing-value marker, RFC 4180 quoting read back by the project's reader, a row of the
// wrong width refused, the column-name rule; and every CSV file the main commands write follows it.

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/csv_names.hpp"
#include "io/csv_reader.hpp"
#include "io/csv_writer.hpp"
#include "model/input_error.hpp"
#include "study/air/air_q.hpp"
#include "sweep/case_paths.hpp"
#include "support/csv_checks.hpp"
#include "support/run_command.hpp"
#include "support/test_files.hpp"

namespace vi {
namespace {

namespace fs = std::filesystem;

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Significant digits of a decimal text ("0.00125" -> 3, "1.5e-07" -> 2, "123456789012345680" -> 17:
// the trailing zeros of a whole number only fill its places).
int significant_digits(const std::string& text) {
    std::string mantissa = text.substr(0, text.find('e'));
    if (mantissa.find('.') == std::string::npos) {
        while (mantissa.size() > 1 && mantissa.back() == '0') mantissa.pop_back();
    }
    int n = 0;
    bool leading = true;
    for (char c : mantissa) {
        if (c < '0' || c > '9') continue;
        if (leading && c == '0') continue;
        leading = false;
        ++n;
    }
    return n;
}

TEST(CsvWriter, AwkwardDoublesReadBackBitForBitFromTheirShortestText) {
    const std::vector<double> values = {0.1, 1e-320, 1e308, -0.0, 0.0, DBL_MAX, -DBL_MAX, DBL_MIN, 5e-324, -5e-324,
                                        DBL_EPSILON, 1.0 / 3.0, 2.0 / 3.0, 123456789012345678.0, 0.30000000000000004,
                                        -2.5e-7, 117e-6, 1e22, 9007199254740993.0};
    for (double v : values) {
        const std::string text = csv_number(v).text();
        const std::optional<double> back = csv_cell_number(text);
        ASSERT_TRUE(back.has_value()) << text;
        EXPECT_TRUE(same_bits(*back, v)) << text;
        // strtod (what gnuplot and C readers use) agrees.
        EXPECT_TRUE(same_bits(std::strtod(text.c_str(), nullptr), v)) << text;
        // Shortest: rounded to one significant digit less, the value no longer reads back.
        const int digits = significant_digits(text);
        if (digits > 1 && v != 0.0) {
            char fewer[40];
            std::snprintf(fewer, sizeof fewer, "%.*e", digits - 2, v);
            EXPECT_FALSE(same_bits(std::strtod(fewer, nullptr), v)) << text << " could be " << fewer;
        }
    }
    EXPECT_EQ(csv_number(0.1).text(), "0.1");
    EXPECT_EQ(csv_number(5e-324).text(), "5e-324");
    EXPECT_EQ(csv_number(1e-320).text(), "1e-320");
    EXPECT_EQ(csv_number(-0.0).text(), "-0");
    EXPECT_EQ(csv_number(DBL_MAX).text(), "1.7976931348623157e+308");
    EXPECT_EQ(csv_number(0.30000000000000004).text(), "0.30000000000000004");
    EXPECT_EQ(csv_number(3.0).text(), "3");
    EXPECT_EQ(csv_count(-42).text(), "-42");
    EXPECT_EQ(csv_count(std::numeric_limits<std::int64_t>::max()).text(), "9223372036854775807");
    EXPECT_EQ(csv_flag(true).text(), "1");
    EXPECT_EQ(csv_flag(false).text(), "0");
}

TEST(CsvWriter, OneMissingValueMarkerThatEveryReaderTakesAsNan) {
    EXPECT_EQ(std::string(kCsvMissing), "nan");
    EXPECT_EQ(csv_missing().text(), "nan");
    EXPECT_EQ(csv_number(std::numeric_limits<double>::quiet_NaN()).text(), "nan");
    EXPECT_EQ(csv_number(-std::numeric_limits<double>::quiet_NaN()).text(), "nan");  // no "-nan"
    EXPECT_EQ(csv_number(std::optional<double>()).text(), "nan");
    EXPECT_EQ(csv_number(std::optional<double>(2.5)).text(), "2.5");
    // Infinities are values, not missing.
    EXPECT_EQ(csv_number(std::numeric_limits<double>::infinity()).text(), "inf");
    EXPECT_EQ(csv_number(-std::numeric_limits<double>::infinity()).text(), "-inf");
    EXPECT_TRUE(std::isinf(*csv_cell_number("-inf")));
    // The reader: the marker and an empty cell (files from before the marker) are NaN; text is not a number.
    EXPECT_TRUE(std::isnan(*csv_cell_number("nan")));
    EXPECT_TRUE(std::isnan(*csv_cell_number("")));
    EXPECT_FALSE(csv_cell_number("settled").has_value());
    EXPECT_FALSE(csv_cell_number("1.5x").has_value());
    EXPECT_FALSE(csv_cell_number("1e999").has_value());
    EXPECT_EQ(*csv_cell_number("1e-999"), 0.0);
    EXPECT_EQ(*csv_cell_number("+2.5"), 2.5);
    EXPECT_FALSE(csv_cell_number("+-2").has_value());
}

TEST(CsvWriter, TextIsQuotedAsRfc4180AsksAndReadsBackIntact) {
    EXPECT_EQ(csv_text("settled").text(), "settled");
    EXPECT_EQ(csv_text("").text(), "");
    EXPECT_EQ(csv_text("a,b").text(), "\"a,b\"");
    EXPECT_EQ(csv_text("say \"hi\"").text(), "\"say \"\"hi\"\"\"");
    EXPECT_EQ(csv_text("two\nlines").text(), "\"two\nlines\"");
    EXPECT_EQ(csv_text(" padded").text(), "\" padded\"");
    const std::vector<std::string> texts = {"ok", "error: supports[0].position: must lie in (0, 1] (x0/l)", "say \"hi\", twice",
                                            "two\nlines", " padded ", "", "0.6 0.83"};
    CsvTable t;
    t.header = {"index", "status"};
    for (std::size_t i = 0; i < texts.size(); ++i) t.add_row({csv_count(static_cast<std::int64_t>(i)), csv_text(texts[i])});
    EXPECT_EQ(t.rows(), texts.size());
    const std::vector<CsvRow> rows = split_csv(t.str(), "t.csv");
    ASSERT_EQ(rows.size(), texts.size() + 1);
    EXPECT_EQ(rows[0].cells, (std::vector<std::string>{"index", "status"}));
    for (std::size_t i = 0; i < texts.size(); ++i) {
        ASSERT_EQ(rows[i + 1].cells.size(), 2u) << i;
        EXPECT_EQ(rows[i + 1].cells[1], texts[i]) << i;
    }
    // A quoted line break moves the following rows' line numbers on.
    EXPECT_EQ(rows[4].line, 5u);
    EXPECT_EQ(rows[5].line, 7u);
    // An unclosed quote is bad input naming file and line.
    try {
        split_csv("a,b\n1,\"open\n", "bad.csv");
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "bad.csv:2: a quoted cell is not closed");
    }
    // Comment lines only where asked for.
    EXPECT_EQ(split_csv("# note\nt_s\n1\n", "c.csv", true).size(), 2u);
    EXPECT_EQ(split_csv("# note\nt_s\n1\n", "c.csv", false).size(), 3u);
}

TEST(CsvWriter, RowOfAnotherWidthIsRefused) {
    CsvTable t;
    t.header = {"t_s", "tip_m"};
    t.add_row({0.0, 1e-6});
    EXPECT_THROW(t.add_row(std::vector<double>{0.0}), std::invalid_argument);
    EXPECT_THROW(t.add_row({0.0, 1.0, 2.0}), std::invalid_argument);
    EXPECT_THROW(t.add_row(std::vector<CsvCell>{csv_number(1.0)}), std::invalid_argument);
    EXPECT_EQ(t.rows(), 1u);
    EXPECT_EQ(t.str(), "t_s,tip_m\n0,1e-06\n");
}

TEST(CsvNames, UnitOrDimensionlessNameInEveryColumn) {
    for (const char* ok : {"t_s", "tip_m", "tip_velocity_m_s", "contact0_force_n", "impulse_n_s", "kinetic_j", "f_supported_2_hz",
                           "omega1_rad_s", "x_over_l", "x0_over_l", "voltage_v", "capacitance_f", "capacitance_ff", "t_us",
                           "tip_nm", "force_un", "f1_khz", "v_1_per_sqrt_kg", "theta_1_per_m_sqrt_kg", "z_max", "m50_z_max",
                           "m50_tau1", "tau_p", "Tp_reason", "ratio_3", "impacts", "impact2_episodes", "impact1_support", "Y_2",
                           "Phi_3_1", "status", "supports[0].gap_m", "supports[1].position_over_l", "damping.ratios[0]",
                           "material.density_kg_m3", "supports[0].work_of_adhesion_j_m2", "best_y_max_m", "low_supports[0].gap_m",
                           "data_tip_m", "residual_tip_velocity_m_s", "residual_over_sigma", "value_in_feature_unit", "critical_work_of_adhesion_j_m2", "pressure_pa",
                           "curvature_per_m", "stress_gradient_pa_per_m"}) {
        EXPECT_TRUE(csv_column_name_ok(ok)) << ok;
    }
    for (const char* bad : {"", "time [µs]", "tip_m [µm]", "voltage_V", "f1_Hz", "contact_force_N", "z_max_m50", "data", "residual",
                            "supports[0].gap", "supports[0].position", "x_low", "best_so_far", "value", "v_1", "theta_1", "_m",
                            "tip_min"}) {
        EXPECT_FALSE(csv_column_name_ok(bad)) << bad;
    }
    EXPECT_EQ(csv_column_unit("tip_velocity_m_s").unit, "m/s");
    EXPECT_EQ(csv_column_unit("tip_velocity_m_s").stem, "tip_velocity");
    EXPECT_EQ(csv_column_unit("impulse_n_s").unit, "N s");
    EXPECT_EQ(csv_column_unit("t_us").unit, "µs");
    EXPECT_EQ(csv_column_unit("z_max").unit, "");
    EXPECT_EQ(csv_column_unit("stress_gradient_pa_per_m").unit, "Pa/m");
    EXPECT_EQ(csv_column_unit("stress_gradient_pa_per_m").stem, "stress_gradient");
    EXPECT_EQ(csv_column_unit("curvature_per_m").unit, "1/m");
    EXPECT_THROW(csv_unit_suffix("furlong"), std::invalid_argument);
}

// Every value a sweep, a fit or an optimisation can vary has a column name that follows the rule.
TEST(CsvNames, EveryCasePathHasAColumnName) {
    const auto forms = case_path_form_units();
    ASSERT_GT(forms.size(), 40u);
    for (const auto& [form, unit] : forms) {
        std::string name = form;
        for (const char* index : {"[i]", "[k]"}) {
            for (auto at = name.find(index); at != std::string::npos; at = name.find(index)) name.replace(at, 3, "[0]");
        }
        std::string suffix;
        ASSERT_NO_THROW(suffix = csv_unit_suffix(unit)) << form << " [" << unit << "]";
        EXPECT_TRUE(csv_column_name_ok(name + suffix)) << name + suffix;
        // The plots read the same unit back from the name.
        if (unit != "-") {
            EXPECT_EQ(csv_column_unit(name + suffix).suffix, suffix) << name + suffix;
        }
    }
}

// air-q takes minutes; its table is checked here from made-up points.
TEST(CsvNames, AirQualityFactorTable) {
    AirQPoint p;
    p.pressure = 101325.0;
    p.maxima = 4;
    const std::string dir = test::make_temp_dir();
    test::write_text(dir + "/air_q.csv", air_q_csv({p, p}));
    test::expect_csv_convention(dir + "/air_q.csv");
    fs::remove_all(dir);
}

// The file check below can fail: each break of the convention is reported.
std::string g_bad_file;  // EXPECT_NONFATAL_FAILURE's statement may not name a local variable

TEST(CsvChecks, EachBreakOfTheConventionIsReported) {
    const std::string dir = test::make_temp_dir();
    g_bad_file = dir + "/bad.csv";
    const auto check = [](const std::string& text, const char* message) {
        test::write_text(g_bad_file, text);
        SCOPED_TRACE(text);
        EXPECT_NONFATAL_FAILURE(test::expect_csv_convention(g_bad_file), message);
    };
    check("time [us],tip_m\n0,1\n", "names no unit");
    check("t_s,voltage_V\n0,1\n", "names no unit");
    check("t_s,tip_m\n0,\n", "neither a number nor the missing marker");
    check("t_s,tip_m\n0,NaN\n", "not in its shortest form");
    check("t_s,tip_m\n0,0.10000000000000001\n", "not in its shortest form");
    check("t_s,tip_m\n0,1e-6\n", "not in its shortest form");
    check("t_s,tip_m\n0,settled\n", "neither a number nor the missing marker");
    check("t_s,tip_m\n0,1,2\n", "the header has 2");
    test::write_text(g_bad_file, "t_s,tip_m,status\n0,1e-06,\"error: a, b\"\n1,nan,ok\n");
    test::expect_csv_convention(g_bad_file);  // a good file: no failure
    fs::remove_all(dir);
}

// The main commands into a temporary folder; every CSV they write follows the convention.
class CsvFiles : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = test::make_temp_dir();
        // The paper's free-impact example at m = 10 over 40 us: a run takes milliseconds.
        std::string text = test::read_text(test::source_path("examples/paper/free_impact_tip.toml"));
        for (const auto& [from, to] : {std::pair<std::string, std::string>{"elements = 50", "elements = 10"},
                                       {"horizon = \"150 us\"", "horizon = \"40 us\""}}) {
            const auto at = text.find(from);
            ASSERT_NE(at, std::string::npos) << from;
            text.replace(at, from.size(), to);
        }
        case_ = dir_ + "/small.toml";
        test::write_text(case_, text);
    }
    void TearDown() override { fs::remove_all(dir_); }

    void run(const std::vector<std::string>& args) const {
        const test::CommandResult r = test::run_vibroimpact(args);
        EXPECT_EQ(r.exit_code, 0) << args.front() << ": " << r.err;
    }

    std::string dir_, case_;
};

TEST_F(CsvFiles, EveryFileOfTheMainCommandsFollowsTheConvention) {
    const std::string out = dir_ + "/out";
    const std::string sw = test::source_path("examples/switch/cantilever_switch.toml");
    run({"simulate", case_, "--out", out + "/simulate"});
    run({"modes", case_, "--count", "3", "--out", out + "/modes"});
    run({"support-scan", case_, "--positions", "0.5,0.8", "--count", "3", "--out", out + "/support_scan"});
    // Two axes, a failing point (x0/l = 1.5) and values the run leaves undefined (second impacts, the
    // switching ledger without electrodes).
    run({"sweep", case_, "--set", "supports[0].position=0.6,1.5", "--set", "supports[0].stiffness=500,1000", "--threads", "2",
         "--out", out + "/sweep"});
    run({"sweep", case_, "--analysis", "modes", "--modes", "1", "--set", "supports[0].position=0.5,1", "--set",
         "supports[0].stiffness=500,1000", "--out", out + "/sweep_modes"});
    run({"pullin", sw, "--steps", "60", "--out", out + "/pullin"});
    run({"sweep", sw, "--analysis", "pullin", "--set", "beam.thickness=1.9um,2um", "--out", out + "/sweep_pullin"});
    run({"sweep", test::source_path("examples/switch/cantilever_stiction.toml"), "--analysis", "stiction", "--set",
         "supports[0].work_of_adhesion=0.2,0.5", "--out", out + "/sweep_stiction"});
    // uq: samples.csv and the figures' data (a histogram, a Sobol chart).
    run({"uq", test::source_path("tests/cases/full_electrode_cantilever.toml"), "--analysis", "pullin", "--vary",
         "beam.thickness=lognormal:2um:0.03", "--samples", "32", "--sensitivity", "--spec", "pullin_voltage_v<=60",
         "--out", out + "/uq"});
    run({"switch-report", sw, "--out", out + "/switch"});
    run({"stiction", test::source_path("examples/switch/cantilever_stiction.toml"), "--out", out + "/stiction"});
    run({"plot", out + "/simulate", "--out", out + "/plot_simulate"});
    run({"plot", out + "/modes", "--out", out + "/plot_modes"});
    // A heat map per quantity; the modes sweep has few (the transient one takes seconds to draw).
    run({"plot", out + "/sweep_modes", "--out", out + "/plot_sweep"});
    // fit: data made from the simulate history (noise-free: one parameter, a few simulations).
    test::write_text(dir_ + "/data.csv", test::read_text(out + "/simulate/history.csv"));
    run({"fit", case_, "--data", dir_ + "/data.csv", "--fit", "supports[0].stiffness", "--out", out + "/fit"});
    // fit --features: one row per feature, the unit in the feature's name.
    test::write_text(dir_ + "/features.csv", "name,value,sigma\nf1_hz,115000,500\nq1,50,5\n");
    run({"fit", case_, "--features", dir_ + "/features.csv", "--fit", "material.youngs_modulus", "--out", out + "/fit_features"});
    run({"optimize", case_, "--vary", "supports[0].position=0.6:1", "--minimize", "y_max_m", "--max-evals", "6", "--out",
         out + "/optimize"});
    const std::size_t files = test::expect_csv_convention_in(out);
    EXPECT_GE(files, 30u);
    std::printf("checked %zu CSV files\n", files);

    // The failed point's results are the missing marker, its status quoted as it holds commas.
    const std::vector<CsvRow> rows = split_csv(test::read_text(out + "/sweep/sweep.csv"), "sweep.csv");
    ASSERT_EQ(rows.size(), 5u);
    EXPECT_EQ(rows[0].cells[0], "supports[0].position_over_l");
    EXPECT_EQ(rows[0].cells[1], "supports[0].stiffness_n_m");
    const std::vector<std::string>& bad = rows[3].cells;
    EXPECT_EQ(bad[0], "1.5");
    EXPECT_EQ(bad.back(), "error: supports[0].position: must lie in (0, 1] (x0/l)");
    for (std::size_t k = 2; k + 1 < bad.size(); ++k) EXPECT_EQ(bad[k], "nan") << rows[0].cells[k];
}

}  // namespace
}  // namespace vi
