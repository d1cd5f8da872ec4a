#include "report/pullin_output.hpp"

#include <cstdio>

#include "io/csv_names.hpp"
#include "io/csv_writer.hpp"

namespace vi {
namespace {

nlohmann::json point_json(const PullinPoint& p) {
    return {{"voltage_V", p.voltage},
            {"mean_travel_m", p.travel},
            {"watched_travel_m", p.watched_travel},
            {"capacitance_F", p.capacitance},
            {"contact_force_N", p.contact_force},
            {"contact", p.contact},
            {"stable", p.stable}};
}

std::string line(const char* format, double a, double b = 0.0, double c = 0.0) {
    char buf[240];
    std::snprintf(buf, sizeof buf, format, a, b, c);
    return buf;
}

}  // namespace

nlohmann::json pullin_json(const PullinResult& r) {
    nlohmann::json j;
    j["pullin"] = r.pullin ? point_json(*r.pullin) : nlohmann::json(nullptr);
    j["touchdown"] = r.touchdown ? point_json(*r.touchdown) : nlohmann::json(nullptr);
    j["collapse"] = r.collapse ? point_json(*r.collapse) : nlohmann::json(nullptr);
    j["release_voltage_V"] = r.release_voltage ? nlohmann::json(*r.release_voltage) : nlohmann::json(nullptr);
    j["watched_x_over_l"] = r.watched_x;
    j["end"] = r.end;
    j["branch_points"] = r.branch.size();
    j["newton_iterations"] = r.newton_iterations;
    nlohmann::json f = nlohmann::json::array();
    for (const PullinFrequencies& x : r.frequencies) f.push_back({{"voltage_V", x.voltage}, {"frequency_Hz", x.frequency_hz}});
    j["frequencies"] = f;
    return j;
}

std::string pullin_text(const PullinResult& r) {
    std::string out;
    if (r.pullin) {
        const PullinPoint& p = *r.pullin;
        out += line("Pull-in voltage V_PI = %.6g V\n", p.voltage);
        out += line("  at pull-in: mean travel over electrodes[0] %.6g um, watched point (x/l = %.4g) %.6g um\n",
                    p.travel * 1e6, r.watched_x, p.watched_travel * 1e6);
        out += line("  capacitance %.6g fF\n", p.capacitance * 1e15);
    } else {
        out += "No pull-in instability before the beam closes on a support\n";
    }
    if (r.touchdown) {
        out += line("Touch-down on a contact (a support or a dielectric) at V = %.6g V (mean travel %.6g um)\n", r.touchdown->voltage,
                    r.touchdown->travel * 1e6);
    } else {
        out += "No support closes on the traced branch\n";
    }
    if (r.release_voltage) {
        out += line("Release (pull-out) voltage %.6g V: below it the closed switch opens\n", *r.release_voltage);
    } else if (r.touchdown) {
        out += "No stable closed state on the traced branch: after touch-down the beam collapses further\n";
    }
    if (r.collapse) {
        out += line("Closed, the beam snaps further toward the electrode (the closed branch folds) above V = %.6g V (mean travel %.6g um)\n",
                    r.collapse->voltage, r.collapse->travel * 1e6);
    }
    if (!r.frequencies.empty()) {
        const PullinFrequencies& a = r.frequencies.front();
        const PullinFrequencies& b = r.frequencies.back();
        if (!a.frequency_hz.empty() && !b.frequency_hz.empty()) {
            out += line("f1 %.6g kHz at 0 V, %.6g kHz at %.6g V\n", a.frequency_hz[0] * 1e-3, b.frequency_hz[0] * 1e-3,
                        b.voltage);
        }
    }
    out += "Branch ends: " + r.end + "\n";
    return out;
}

OutputFiles pullin_files(const PullinResult& r) {
    CsvTable branch;
    branch.header = {"voltage_v", "mean_travel_m", "watched_travel_m", "capacitance_f", "contact_force_n", "contact",
                     "stable"};
    for (const PullinPoint& p : r.branch) {
        branch.add_row({p.voltage, p.travel, p.watched_travel, p.capacitance, p.contact_force, p.contact ? 1.0 : 0.0,
                        p.stable ? 1.0 : 0.0});
    }
    CsvTable freq;
    std::size_t count = 0;
    for (const PullinFrequencies& f : r.frequencies) count = std::max(count, f.frequency_hz.size());
    freq.header = {"voltage_v"};
    for (std::string& name : numbered_columns("f", count, "_hz")) freq.header.push_back(std::move(name));
    for (const PullinFrequencies& f : r.frequencies) {
        std::vector<double> row{f.voltage};
        for (std::size_t k = 0; k < count; ++k) row.push_back(k < f.frequency_hz.size() ? f.frequency_hz[k] : std::nan(""));
        freq.add_row(row);
    }
    return {{"pullin.json", pullin_json(r).dump(2) + "\n"},
            {"pullin_branch.csv", branch.str()},
            {"pullin_frequencies.csv", freq.str()}};
}

nlohmann::json dynamic_pullin_json(const DynamicPullinResult& r) {
    nlohmann::json trials = nlohmann::json::array();
    for (const StepTrial& t : r.trials) {
        trials.push_back({{"voltage_V", t.voltage},
                          {"pulls_in", t.closes},
                          {"how", t.how},
                          {"reduced_modes", t.reduced_modes},
                          {"seconds", t.seconds},
                          {"closing_time_s", t.closing_time ? nlohmann::json(*t.closing_time) : nlohmann::json(nullptr)}});
    }
    return {{"voltage_V", r.voltage},
            {"ratio_to_static", r.voltage / r.static_voltage},
            {"static_voltage_V", r.static_voltage},
            {"lower_V", r.lower},
            {"upper_V", r.upper},
            {"upper_closing_time_s",
             r.upper_closing_time ? nlohmann::json(*r.upper_closing_time) : nlohmann::json(nullptr)},
            {"criterion", r.criterion == PullinCriterion::close ? "close" : "electrode"},
            {"model_reduced_modes", r.model},
            {"confirmed_on_reduced_modes", r.confirmed_on >= 0 ? nlohmann::json(r.confirmed_on) : nlohmann::json(nullptr)},
            {"model", dynamic_pullin_model_text(r)},
            {"horizon_s", r.horizon},
            {"trials", trials}};
}

std::string dynamic_pullin_model_text(const DynamicPullinResult& r) {
    const auto name = [](int modes) {
        return modes > 0 ? "the reduced model of " + std::to_string(modes) + " modes" : std::string("the full model");
    };
    std::string out = "bracket of " + name(r.model);
    if (r.model != r.bisected_on) out += " (" + name(r.bisected_on) + " parted from it first)";
    if (r.confirmed_on >= 0) out += "; " + name(r.confirmed_on) + " agrees at both ends";
    if (r.model > 0 && r.reduced_modes == r.model) out += " (solver.reduced_modes)";
    return out;
}

std::string dynamic_pullin_text(const DynamicPullinResult& r) {
    std::string out = line("Dynamic pull-in V_DPI = %.6g V (= %.4f of static)\n", r.voltage, r.voltage / r.static_voltage);
    out += line("  step bracket %.6g .. %.6g V", r.lower, r.upper);
    out += line(", %.0f transients of at most %.4g us", static_cast<double>(r.trials.size()), r.horizon * 1e6);
    out += r.criterion == PullinCriterion::close ? ", criterion: a support closes or the beam reaches the electrode\n"
                                                 : ", criterion: the beam reaches the electrode (supports removed)\n";
    out += "  " + dynamic_pullin_model_text(r) + "\n";
    return out;
}

}  // namespace vi
