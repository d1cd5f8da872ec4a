#include "study/cycles/cycles_output.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>

#include "model/number_format.hpp"

namespace vi {
namespace {

nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json opt(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); }

nlohmann::json trend_json(const CycleTrend& t) {
    return {{"slope_per_cycle", t.slope}, {"intercept", t.intercept}, {"first", t.first}, {"last", t.last}};
}

nlohmann::json cycle_json(const CycleRecord& c, double cumulative) {
    return {{"cycle", c.index},
            {"t_start_s", c.t_start},
            {"closing_time_s", opt(c.switching.closing_time)},
            {"bounces", c.switching.bounces},
            {"grouped_bounces", c.switching.grouped_bounces},
            {"switching_state", c.switching.state},
            {"impacts", c.impacts.size()},
            {"contact_energy_j", number_or_null(c.damage.contact_energy)},
            {"peak_force_n", c.damage.peak_force},
            {"peak_pressure_pa", number_or_null(c.damage.peak_pressure)},
            {"yield_impacts", c.damage.yield_known ? nlohmann::json(c.damage.yield_impacts) : nlohmann::json(nullptr)},
            {"electrical_bounces", c.electrical_bounces >= 0 ? nlohmann::json(c.electrical_bounces) : nlohmann::json(nullptr)},
            {"wear_volume_m3", number_or_null(c.wear_volume)},
            {"cumulative_wear_m3", number_or_null(cumulative)}};
}

}  // namespace

CsvTable cycles_csv(const CyclesResult& r) {
    CsvTable t;
    t.header = {"cycle", "t_start_s", "closing_time_s", "bounces", "grouped_bounces", "switching_state", "impacts",
                "contact_energy_j", "peak_force_n", "peak_pressure_pa", "yield_impacts", "electrical_bounces",
                "wear_volume_m3", "cumulative_wear_m3"};
    double cumulative = 0.0;
    for (const CycleRecord& c : r.cycles) {
        cumulative += c.wear_volume;
        t.add_row(std::vector<CsvCell>{
            csv_count(c.index), csv_number(c.t_start), csv_number(c.switching.closing_time),
            csv_count(c.switching.bounces), csv_count(c.switching.grouped_bounces), csv_text(c.switching.state),
            csv_count(static_cast<std::int64_t>(c.impacts.size())), csv_number(c.damage.contact_energy),
            csv_number(c.damage.peak_force), csv_number(c.damage.peak_pressure),
            c.damage.yield_known ? csv_count(c.damage.yield_impacts) : csv_missing(),
            c.electrical_bounces >= 0 ? csv_count(c.electrical_bounces) : csv_missing(), csv_number(c.wear_volume),
            csv_number(cumulative)});
    }
    return t;
}

nlohmann::json cycles_json(const CyclesResult& r) {
    nlohmann::json j;
    j["cycles"] = r.settings.cycles;
    j["period_s"] = r.settings.period;
    j["total_contact_energy_j"] = number_or_null(r.total_contact_energy);
    j["total_wear_volume_m3"] = number_or_null(r.total_wear_volume);
    j["wear_law"] = r.wear ? nlohmann::json("V = K E / H per support (docs/cycles.md)") : nlohmann::json(nullptr);
    j["yield_impacts"] = r.yield_known ? nlohmann::json(r.yield_impacts) : nlohmann::json(nullptr);
    j["trend"] = {{"contact_energy_j", trend_json(r.energy_trend)},
                  {"bounces", trend_json(r.bounce_trend)},
                  {"peak_force_n", trend_json(r.peak_force_trend)}};
    nlohmann::json rows = nlohmann::json::array();
    double cumulative = 0.0;
    for (const CycleRecord& c : r.cycles) {
        cumulative += c.wear_volume;
        rows.push_back(cycle_json(c, cumulative));
    }
    j["per_cycle"] = rows;
    j["solver"] = {{"method", r.method}, {"steps", r.steps}};
    return j;
}

std::string cycles_text(const CyclesResult& r) {
    std::string s;
    char buf[400];
    std::snprintf(buf, sizeof buf, "%d cycles of %s us (%s, %d steps)\n", r.settings.cycles,
                  significant(r.settings.period * 1e6, 6).c_str(), r.method.c_str(), r.steps);
    s += buf;
    std::snprintf(buf, sizeof buf, "  contact energy %.4g J in all; per cycle %.4g J first, %.4g J last, trend %+.3g J/cycle\n",
                  r.total_contact_energy, r.energy_trend.first, r.energy_trend.last, r.energy_trend.slope);
    s += buf;
    std::snprintf(buf, sizeof buf, "  bounces per cycle %g first, %g last, trend %+.3g per cycle\n", r.bounce_trend.first,
                  r.bounce_trend.last, r.bounce_trend.slope);
    s += buf;
    std::snprintf(buf, sizeof buf, "  peak force per cycle %.4g N first, %.4g N last\n", r.peak_force_trend.first,
                  r.peak_force_trend.last);
    s += buf;
    if (r.yield_known) {
        std::snprintf(buf, sizeof buf, "  impacts past yield onset (p0 > 1.6 Y): %d\n", r.yield_impacts);
        s += buf;
    }
    if (r.wear) {
        std::snprintf(buf, sizeof buf, "  wear volume (K E / H) %.4g m^3 after %d cycles\n", r.total_wear_volume,
                      r.settings.cycles);
        s += buf;
    }
    return s;
}

OutputFiles cycles_files(const CyclesResult& r) {
    return {{"cycles.csv", cycles_csv(r).str()}, {"cycles.json", cycles_json(r).dump(2) + "\n"}};
}

}  // namespace vi
