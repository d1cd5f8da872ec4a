// Every analysis as a sweep point: the columns of pullin, stiction and air-q against the physics
// they report, their documentation (one list, the docs' tables generated from it), the refusals of
// a case that cannot have the analysis, and pullin as an optimisation's objective.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "calibration/feature_fit.hpp"
#include "io/case_reader.hpp"
#include "io/measured_features.hpp"
#include "io/csv_names.hpp"
#include "model/input_error.hpp"
#include "study/analyses/sweep_analyses.hpp"
#include "support/run_command.hpp"
#include "support/test_files.hpp"
#include "sweep/column_docs.hpp"
#include "sweep/grid.hpp"
#include "sweep/runner.hpp"

namespace vi {
namespace {

namespace fs = std::filesystem;
using test::run_vibroimpact;

const std::string kSrc = VI_SOURCE_DIR;
const std::string kFullElectrode = kSrc + "/tests/cases/full_electrode_cantilever.toml";
const std::string kSwitch = kSrc + "/examples/switch/cantilever_switch.toml";
const std::string kStiction = kSrc + "/examples/switch/cantilever_stiction.toml";
const std::string kSwitchAir = kSrc + "/examples/switch/cantilever_switch_air.toml";

// Column `name` of a finished point.
double cell(const std::vector<SweepColumn>& cols, const SweepPointResult& r, const std::string& name) {
    for (std::size_t k = 0; k < cols.size(); ++k) {
        if (cols[k].name == name) {
            const std::optional<double> v = numeric_cell(r.cells.at(k));
            return v ? *v : std::nan("");
        }
    }
    ADD_FAILURE() << "no column " << name;
    return std::nan("");
}

// Every point of a sweep of `base` over the settings, computed in order on one thread.
std::vector<SweepPointResult> sweep_points(const Case& base, const std::vector<std::string>& sets, SweepAnalysis a) {
    const SweepGrid grid = parse_sweep_grid(sets, base);
    SweepSettings s;
    s.analysis = a;
    s = with_study_analyses(s);
    check_sweep_analysis(base, s);
    std::vector<SweepPointResult> out;
    for (std::size_t i = 0; i < grid.size(); ++i) out.push_back(run_sweep_point(base, grid, i, s));
    return out;
}

TEST(SweepColumnDocs, EveryColumnOfEveryAnalysisIsDocumentedAndEveryEntryNamesAColumn) {
    for (SweepAnalysis a : kSweepAnalyses) {
        SCOPED_TRACE(sweep_analysis_name(a));
        const std::vector<SweepColumn> cols = sweep_result_columns(a, 3, 2);
        std::set<const SweepColumnDoc*> used;
        for (const SweepColumn& c : cols) {
            const SweepColumnDoc* d = sweep_column_doc(a, c.name);
            EXPECT_NE(d, nullptr) << c.name << " has no entry in src/sweep/column_docs.cpp";
            EXPECT_TRUE(csv_column_name_ok(c.name)) << c.name << ": not a column name of io/csv_names.cpp";
            used.insert(d);
        }
        for (const SweepColumnDoc& d : sweep_column_docs(a)) {
            EXPECT_TRUE(used.count(&d)) << d.names.front() << " is documented but no column has that name";
        }
        EXPECT_FALSE(sweep_analysis_summary(a).empty());
    }
    // A pattern's <k> stands for digits only.
    EXPECT_NE(sweep_column_doc(SweepAnalysis::simulate, "impact12_t_on_s"), nullptr);
    EXPECT_EQ(sweep_column_doc(SweepAnalysis::simulate, "impact_t_on_s"), nullptr);
    EXPECT_EQ(sweep_column_doc(SweepAnalysis::simulate, "impactx_t_on_s"), nullptr);
}

TEST(SweepColumnDocs, TablesOfSweepsMdAreGeneratedFromTheList) {
    const std::string path = kSrc + "/docs/sweeps.md";
    const std::string page = test::read_text(path);
    ASSERT_FALSE(page.empty()) << path;
    for (SweepAnalysis a : kSweepAnalyses) {
        EXPECT_NE(page.find(std::string("<!-- sweep-columns:") + sweep_analysis_name(a) + " -->"), std::string::npos)
            << sweep_analysis_name(a) << " has no column table in docs/sweeps.md";
    }
    const std::string fresh = with_sweep_column_tables(page);
    if (fresh == page) return;
    if (std::getenv("VI_UPDATE_DOCS") != nullptr) {
        std::ofstream(path, std::ios::binary) << fresh;
        GTEST_SKIP() << "rewrote the column tables of " << path;
    }
    ADD_FAILURE() << "the column tables of docs/sweeps.md differ from src/sweep/column_docs.cpp; regenerate them "
                     "with: VI_UPDATE_DOCS=1 ./build/tests/vi_tests --gtest_filter='SweepColumnDocs.*'";
}

// Bending stiffness ~ E t^3, the parallel-plate force ~ V^2 / g^2 and the travel ~ g make the
// full-length electrode's V_PI exactly proportional to t^1.5 g^1.5: the FE trace keeps it to its
// fold bracket's width.
TEST(SweepAnalyses, PullinVoltageScalesAsThicknessAndGapToTheThreeHalves) {
    const Case base = read_case_file(kFullElectrode);
    const std::vector<SweepPointResult> r =
        sweep_points(base, {"beam.thickness=1.5um,2um,2.7um", "electrodes[0].gap=1um,2um,3.3um"}, SweepAnalysis::pullin);
    const std::vector<SweepColumn> cols = sweep_result_columns(SweepAnalysis::pullin, 0);
    ASSERT_EQ(r.size(), 9u);
    const double v0 = cell(cols, r[4], "pullin_voltage_v");  // t = 2 um, g = 2 um
    EXPECT_GT(v0, 10.0);
    for (const SweepPointResult& p : r) {
        ASSERT_TRUE(p.ok()) << p.status;
        const double t = p.parameters[0] / 2e-6, g = p.parameters[1] / 2e-6;
        EXPECT_NEAR(cell(cols, p, "pullin_voltage_v") / (v0 * std::pow(t * g, 1.5)), 1.0, 1e-9);
        // The travel at pull-in scales with the gap alone; no contact, so no touch-down or release.
        EXPECT_NEAR(cell(cols, p, "pullin_travel_m") / (cell(cols, r[4], "pullin_travel_m") * g), 1.0, 1e-6);
        EXPECT_TRUE(std::isnan(cell(cols, p, "touchdown_voltage_v")));
        EXPECT_TRUE(std::isnan(cell(cols, p, "hysteresis_v")));
    }
}

// The switch example's numbers as its case file states them (pullin: 58.4 V, release below 53.4 V,
// collapse above 98.8 V), and the hysteresis as their difference.
TEST(SweepAnalyses, PullinColumnsOfTheSwitchExample) {
    const Case base = read_case_file(kSwitch);
    const std::vector<SweepPointResult> r = sweep_points(base, {"beam.thickness=2um"}, SweepAnalysis::pullin);
    const std::vector<SweepColumn> cols = sweep_result_columns(SweepAnalysis::pullin, 0);
    ASSERT_TRUE(r.at(0).ok()) << r[0].status;
    EXPECT_NEAR(cell(cols, r[0], "pullin_voltage_v"), 58.4, 0.05);
    EXPECT_NEAR(cell(cols, r[0], "release_voltage_v"), 53.4, 0.05);
    EXPECT_NEAR(cell(cols, r[0], "collapse_voltage_v"), 98.8, 0.05);
    EXPECT_DOUBLE_EQ(cell(cols, r[0], "hysteresis_v"),
                     cell(cols, r[0], "pullin_voltage_v") - cell(cols, r[0], "release_voltage_v"));
    // The capacitance grows as the beam closes.
    EXPECT_LT(cell(cols, r[0], "rest_capacitance_f"), cell(cols, r[0], "pullin_capacitance_f"));
    EXPECT_LT(cell(cols, r[0], "pullin_capacitance_f"), cell(cols, r[0], "collapse_capacitance_f"));
    // The beam is on the stop when it releases: its travel there is past the pull-in travel.
    EXPECT_GT(cell(cols, r[0], "release_travel_m"), cell(cols, r[0], "pullin_travel_m"));
}

// F_po = 2 pi R w is linear in w: the support sticks exactly above the critical work of adhesion the
// check reports, and the margins change sign there.
TEST(SweepAnalyses, StictionFlipsAtTheCriticalWorkOfAdhesion) {
    const Case base = read_case_file(kStiction);
    const StictionResult check = stiction_check(base);
    ASSERT_EQ(check.supports.size(), 1u);
    const double wc = *check.supports[0].critical_work_of_adhesion;
    const std::string set = "supports[0].work_of_adhesion=" + std::to_string(0.9 * wc) + "," + std::to_string(1.1 * wc);
    const std::vector<SweepPointResult> r = sweep_points(base, {set}, SweepAnalysis::stiction);
    const std::vector<SweepColumn> cols = sweep_result_columns(SweepAnalysis::stiction, 0);
    ASSERT_TRUE(r.at(0).ok() && r.at(1).ok());
    EXPECT_EQ(cell(cols, r[0], "stuck"), 0.0);
    EXPECT_EQ(cell(cols, r[1], "stuck"), 1.0);
    EXPECT_GT(cell(cols, r[0], "force_margin_n"), 0.0);
    EXPECT_LT(cell(cols, r[1], "force_margin_n"), 0.0);
    EXPECT_NEAR(cell(cols, r[0], "adhesion_margin_j_m2"), wc - r[0].parameters[0], 1e-12 * wc);
    EXPECT_NEAR(cell(cols, r[1], "adhesion_margin_j_m2"), wc - r[1].parameters[0], 1e-12 * wc);
    // l_d = (3 E t^3 h^2 / (2 gamma))^(1/4): the larger work of adhesion gives the shorter span.
    EXPECT_NEAR(cell(cols, r[0], "detached_length_m") / cell(cols, r[1], "detached_length_m"), std::pow(1.1 / 0.9, 0.25),
                1e-6);
}

// Q at the case's own pressure: the modal estimate and the ring-down agree (docs/squeeze-film.md
// §5), and the film damps less as the gas thins.
TEST(SweepAnalyses, AirQAtTheCasePressure) {
    const Case base = read_case_file(kSwitchAir);
    const std::vector<SweepPointResult> r = sweep_points(base, {"beam.elements=16", "air.pressure=100,1000"}, SweepAnalysis::air_q);
    const std::vector<SweepColumn> cols = sweep_result_columns(SweepAnalysis::air_q, 0);
    for (const SweepPointResult& p : r) {
        ASSERT_TRUE(p.ok()) << p.status;
        EXPECT_EQ(cell(cols, p, "pressure_pa"), p.parameters[1]);
        EXPECT_NEAR(cell(cols, p, "q_ringdown") / cell(cols, p, "q_modal"), 1.0, 0.01);
    }
    EXPECT_GT(cell(cols, r[0], "q_modal"), 5.0 * cell(cols, r[1], "q_modal"));
    EXPECT_GT(cell(cols, r[0], "knudsen"), cell(cols, r[1], "knudsen"));
}

TEST(SweepAnalyses, ACaseWithoutTheAnalysisIsRefusedBeforeAnyPoint) {
    const std::string paper = kSrc + "/examples/paper/free_impact_tip.toml";
    for (const char* analysis : {"pullin", "stiction", "air-q"}) {
        const test::CommandResult r = run_vibroimpact({"sweep", paper, "--analysis", analysis, "--set", "beam.thickness=2um"});
        EXPECT_EQ(r.exit_code, 2) << analysis << ": " << r.err;
        EXPECT_NE(r.err.find(std::string("--analysis ") + analysis + ": the case has"), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_TRUE(r.out.empty());
    }
}

TEST(SweepAnalyses, ListColumnsPrintsTheDocumentedColumns) {
    for (SweepAnalysis a : kSweepAnalyses) {
        const test::CommandResult r = run_vibroimpact({"sweep", "--list-columns", sweep_analysis_name(a)});
        ASSERT_EQ(r.exit_code, 0) << r.err;
        for (const SweepColumnDoc& d : sweep_column_docs(a)) {
            for (const std::string& n : d.names) EXPECT_NE(r.out.find(n), std::string::npos) << n;
        }
    }
    const test::CommandResult bad = run_vibroimpact({"sweep", "--list-columns", "nonsense"});
    EXPECT_EQ(bad.exit_code, 2);
}

// The pull-in voltage as an objective: it rises with the thickness, so its minimum over a box of
// thicknesses is at the lower bound, with V_PI = V0 (t / t0)^1.5 there.
TEST(SweepAnalyses, PullinVoltageIsAnOptimisationObjective) {
    const fs::path out = fs::temp_directory_path() / "vi_optimize_pullin";
    fs::remove_all(out);
    const test::CommandResult r = run_vibroimpact({"optimize", kFullElectrode, "--analysis", "pullin", "--vary",
                                                   "beam.thickness=1.8um:2.2um", "--minimize", "pullin_voltage_v",
                                                   "--constraint", "pullin_travel_m<=1e-6", "--max-evals", "12",
                                                   "--json", "--out", out.string(), "--threads", "1"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Case base = read_case_file(kFullElectrode);
    const std::vector<SweepPointResult> at = sweep_points(base, {"beam.thickness=2um"}, SweepAnalysis::pullin);
    const double v0 = cell(sweep_result_columns(SweepAnalysis::pullin, 0), at[0], "pullin_voltage_v");
    const auto j = nlohmann::json::parse(r.out);
    const double best_t = j["best"]["x"]["beam.thickness"].get<double>();
    EXPECT_NEAR(best_t, 1.8e-6, 0.02e-6) << r.out;
    EXPECT_NEAR(j["best"]["objective"].get<double>(), v0 * std::pow(best_t / 2e-6, 1.5), 1e-6 * v0);
    fs::remove_all(out);
}

// Every numeric column of a pullin sweep is a feature of fit --features.
TEST(SweepAnalyses, PullinColumnsAreFitFeatures) {
    const std::vector<std::string>& names = feature_names();
    for (const SweepColumn& c : sweep_result_columns(SweepAnalysis::pullin, 0)) {
        if (c.name == "end_reason") continue;
        EXPECT_NE(std::find(names.begin(), names.end(), c.name), names.end()) << c.name;
    }
}

// The travel at pull-in fixes the gap (travel ~ g), then V_PI ~ t^1.5 g^1.5 the thickness: both are
// recovered from the two features of a thicker beam over a wider gap, starting from the nominal case.
TEST(SweepAnalyses, ThicknessAndGapFittedToPullinVoltageAndTravel) {
    const Case start = read_case_file(kFullElectrode);
    Case truth = start;
    truth.beam.thickness = 1.9e-6;
    truth.electrodes[0].gap = 2.2e-6;
    MeasuredFeatures data;
    data.file = "synthetic";
    data.features = {{"pullin_voltage_v", 0.0, 0.01, 2}, {"pullin_travel_m", 0.0, 1e-10, 3}};
    const std::vector<double> exact = model_features(truth, {}, {}, data);
    for (std::size_t k = 0; k < exact.size(); ++k) data.features[k].value = exact[k];
    const std::vector<FitParameter> params = {parse_fit_parameter("beam.thickness", start),
                                              parse_fit_parameter("electrodes[0].gap", start)};
    const FitResult r = fit_features(start, params, data);
    ASSERT_TRUE(r.converged) << r.message;
    EXPECT_NEAR(r.estimate[0], 1.9e-6, 1e-6 * 1.9e-6);
    EXPECT_NEAR(r.estimate[1], 2.2e-6, 1e-6 * 2.2e-6);
}

}  // namespace
}  // namespace vi
