#include "report/contact_resistance.hpp"

#include <cmath>

#include "impacts/electrical_ledger.hpp"

namespace vi {

std::vector<ResistanceSeries> contact_resistances(const BeamModel& model, const TransientResult& r) {
    std::vector<ResistanceSeries> out;
    const TimeHistory& h = r.history;
    for (std::size_t k = 0; k < model.contacts.size() && k < h.contact_v.size(); ++k) {
        const ForceElement& e = *model.forces[model.contacts[k].element];
        const double probe_q = 0.0, probe_v = 0.0;
        if (std::isnan(e.contact_resistance(ElementState{0.0, &probe_q, &probe_v, nullptr}))) continue;
        ResistanceSeries s{k, model.contacts[k].name, e.on_resistance(), {}};
        s.ohm.reserve(h.t.size());
        for (std::size_t i = 0; i < h.t.size(); ++i) {
            // A closed contact pushes (F > 0); at F = 0 it is open, or touching with nothing between.
            const ElementState at{h.t[i], &h.contact_v[k][i], &h.contact_velocity[k][i], nullptr};
            s.ohm.push_back(h.contact_force[k][i] > 0.0 ? e.contact_resistance(at) : INFINITY);
        }
        out.push_back(std::move(s));
    }
    return out;
}

namespace {

nlohmann::json optional_json(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); }

// The electrical bounce ledger's keys of contact k: null without a threshold or a record.
void add_electrical(nlohmann::json& row, std::size_t k, const std::vector<ContactConduction>& conduction) {
    std::optional<ElectricalLedger> l;
    for (const ContactConduction& c : conduction) {
        if (static_cast<std::size_t>(c.contact) == k) l = electrical_ledger(c);
    }
    if (!l) {
        for (const char* key : {"first_closure_s", "electrical_bounces", "settle_time_s", "openings"}) row[key] = nullptr;
        return;
    }
    nlohmann::json openings = nlohmann::json::array();
    for (const ElectricalOpening& o : l->openings) {
        openings.push_back({{"t_s", o.t}, {"duration_s", optional_json(o.duration)},
                            {"closure_min_resistance_ohm", o.closure_min_resistance}});
    }
    row["first_closure_s"] = optional_json(l->first_closure);
    row["electrical_bounces"] = l->bounces;
    row["settle_time_s"] = optional_json(l->settle_time);
    row["openings"] = openings;
}

}  // namespace

nlohmann::json contact_resistance_json(const std::vector<ResistanceSeries>& series, const TimeHistory& h,
                                       const std::vector<ContactConduction>& conduction) {
    nlohmann::json out = nlohmann::json::array();
    for (const ResistanceSeries& s : series) {
        const double end = s.ohm.empty() ? INFINITY : s.ohm.back();
        nlohmann::json row = {{"contact", s.name},
                              {"closed_at_end", std::isfinite(end)},
                              {"resistance_end_ohm", std::isfinite(end) ? nlohmann::json(end) : nlohmann::json(nullptr)},
                              {"r_on_ohm", std::isnan(s.r_on) ? nlohmann::json(nullptr) : nlohmann::json(s.r_on)},
                              {"below_r_on_from_s", nullptr}};
        if (!std::isnan(s.r_on) && !s.ohm.empty() && s.ohm.back() < s.r_on) {
            std::size_t from = s.ohm.size() - 1;
            while (from > 0 && s.ohm[from - 1] < s.r_on) --from;
            row["below_r_on_from_s"] = h.t[from];
        }
        add_electrical(row, s.contact, conduction);
        out.push_back(row);
    }
    return out;
}

}  // namespace vi
