#include "report/transient_output.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "io/case_writer.hpp"

namespace vi {
namespace {

nlohmann::json opt(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); }

nlohmann::json scaled(const std::optional<double>& v, double k) {
    return v ? nlohmann::json(*v * k) : nlohmann::json(nullptr);
}

// Whether some element of the model books its dissipation as a squeeze film's.
bool has_films(const BuiltProblem& b) {
    return std::any_of(b.model.forces.begin(), b.model.forces.end(),
                       [](const ForceElementPtr& e) { return e->dissipation_kind() == DissipationKind::film; });
}

// The ledger's terms; a model with squeeze films has their term too.
nlohmann::json energy_json(const EnergyLedger& e, bool films) {
    nlohmann::json j = {{"kinetic_j", e.kinetic},
                        {"strain_j", e.strain},
                        {"contact_spring_j", e.contact_spring},
                        {"electrical_j", e.electrical},
                        {"rayleigh_dissipated_j", e.rayleigh_dissipated},
                        {"contact_dissipated_j", e.contact_dissipated},
                        {"external_work_j", e.external_work}};
    if (films) j["film_dissipated_j"] = e.film_dissipated;
    return j;
}

// The damage indicators only where the run has them (the CVODE solver records the contact energy, a
// Hertz law has a pressure, a yield strength a check), so that other summaries stay as they were.
template <class Row>
nlohmann::json contact_row(const Row& e) {
    nlohmann::json j = {{"support", e.support},         {"t_on_s", e.t_on},
                        {"t_off_s", e.t_off},           {"v_in_m_s", e.v_in},
                        {"v_out_m_s", e.v_out},         {"peak_force_n", e.peak_force},
                        {"peak_penetration_m", e.peak_penetration}, {"impulse_n_s", e.impulse},
                        {"closed_at_end", e.closed_at_end}};
    if (!std::isnan(e.contact_energy)) j["contact_energy_j"] = e.contact_energy;
    if (!std::isnan(e.peak_pressure)) j["peak_pressure_pa"] = e.peak_pressure;
    if (e.yielded) j["yield_exceeded"] = *e.yielded;
    return j;
}

// The run's impacts summed (one actuation cycle): energy, peaks and the impacts past yield onset.
nlohmann::json damage_json(const ContactDamage& d) {
    nlohmann::json j = {{"impacts_contact_energy_j", d.contact_energy}, {"peak_force_n", d.peak_force}};
    j["peak_pressure_pa"] = std::isnan(d.peak_pressure) ? nlohmann::json(nullptr) : nlohmann::json(d.peak_pressure);
    j["yield_impacts"] = d.yield_known ? nlohmann::json(d.yield_impacts) : nlohmann::json(nullptr);
    return j;
}

// The case as it ran: the values the run worked out for keys left to their defaults (the horizon and
// output step it used, the grouping gap, the mean free path, an electrode's width over a beam without
// sections) written in, so that the resolved case read back as a case file runs the same.
Case case_as_run(const Case& c, const BuiltProblem& b, const ImpactSummary& s) {
    Case r = c;
    r.solver.horizon = b.problem.t_end;
    r.solver.output_step = b.problem.output_step;
    if (c.solver.grouping == SolverSettings::Grouping::flights) r.solver.group_gap = s.group_gap;
    if (r.air && !r.air->mean_free_path) r.air->mean_free_path = r.air->lambda();
    // Over a beam of sections an electrode left without a width takes the width under each of its
    // points, which no single number states: it stays unset there.
    for (Electrode& e : r.electrodes) {
        if (e.width == 0.0 && c.beam.sections.empty()) e.width = c.beam.width;
    }
    return r;
}

const char* end_name(EndCondition e) {
    switch (e) {
        case EndCondition::clamped: return "clamped";
        case EndCondition::pinned: return "pinned";
        case EndCondition::free: return "free";
    }
    return "?";
}

}  // namespace

nlohmann::json resolved_case_json(const Case& c, const BuiltProblem& b, const ImpactSummary& s) {
    nlohmann::json j;
    j["name"] = c.name;
    j["beam"] = {{"length_m", c.beam.length},       {"width_m", c.beam.width},
                 {"thickness_m", c.beam.thickness}, {"elements", c.beam.elements},
                 {"left", end_name(c.beam.left)},   {"right", end_name(c.beam.right)},
                 {"nodes", b.model.system.mesh.node_count()}, {"bending_dofs", b.problem.size()}};
    j["beam"]["mass_kg"] = beam_mass(b.model.system);
    if (b.model.system.sectioned) {
        // Each section as the model took it: the plain width and thickness are only its defaults.
        nlohmann::json parts = nlohmann::json::array();
        for (std::size_t k = 0; k < c.beam.sections.size(); ++k) {
            const SectionResultants& r = b.model.system.sections.at(k);
            parts.push_back({{"from", c.beam.sections[k].from}, {"to", c.beam.sections[k].to}, {"width_m", r.width},
                             {"thickness_m", r.thickness}, {"EI_n_m2", r.EI}, {"rho_A_kg_m", r.rho_A},
                             {"neutral_axis_m", r.neutral_axis}});
        }
        j["beam"]["sections"] = parts;
    }
    j["material"] = {{"youngs_modulus_pa", c.material.youngs_modulus},
                     {"density_kg_m3", c.material.density},
                     {"poisson_ratio", c.material.poisson_ratio},
                     {"plate_modulus", c.material.plate_modulus},
                     {"effective_modulus_pa", c.material.effective_modulus()}};
    nlohmann::json sup = nlohmann::json::array();
    for (std::size_t k = 0; k < c.supports.size(); ++k) {
        const Support& p = c.supports[k];
        sup.push_back({{"position", p.position},
                       {"side", p.side == Side::below ? "below" : "above"},
                       {"surface_m", p.surface},
                       {"stiffness_n_m", b.model.contact_stiffness.at(k)},
                       {"damping_n_s_m", b.model.contact_damping.at(k)},
                       {"damping_ratio", p.damping_ratio ? nlohmann::json(*p.damping_ratio) : nlohmann::json(nullptr)}});
    }
    j["supports"] = sup;
    j["damping"] = {{"alpha_1_s", b.model.rayleigh.alpha}, {"beta_s", b.model.rayleigh.beta},
                    {"from_ratios", c.damping.from_ratios}, {"ratios", {c.damping.ratio1, c.damping.ratio2}},
                    {"modes", {c.damping.mode1, c.damping.mode2}}};
    const char* kinds[] = {"rest", "displacement", "force"};
    const char* vkinds[] = {"none", "uniform", "mode"};
    j["initial"] = {{"kind", kinds[static_cast<int>(c.initial.kind)]},
                    {"position", c.initial.position},
                    {"y0_m", b.start.y0_m},
                    {"static_force_n", b.start.static_force_n},
                    {"velocity_shape", vkinds[static_cast<int>(c.initial.velocity_kind)]},
                    {"velocity_m_s", c.initial.velocity},
                    {"velocity_mode", c.initial.velocity_mode}};
    j["loads"] = static_cast<int>(c.loads.size());
    j["solver"] = {{"method", c.solver.method == SolverSettings::Method::exact   ? "exact"
                              : c.solver.method == SolverSettings::Method::cvode ? "cvode"
                                                                                 : "auto"},
                   {"horizon_s", b.problem.t_end},
                   {"output_step_s", b.problem.output_step},
                   {"group_gap_s", s.group_gap},
                   {"grouping", c.solver.grouping == SolverSettings::Grouping::none ? "none" : "flights"},
                   {"settle_rule", c.solver.settle_rule == SolverSettings::SettleRule::velocity ? "velocity" : "penetration"},
                   {"settle_tolerance", c.solver.settle_tolerance},
                   {"settle_velocity_m_s", c.solver.settle_velocity},
                   {"rtol", c.solver.rtol},
                   {"min_search_step", c.solver.min_search_step},
                   {"max_events", c.solver.max_events},
                   {"max_steps", c.solver.max_steps}};
    j["omega1_rad_s"] = b.model.omega1;
    // Every key of the case file in effect, in SI and in the file's layout: it reads back as a case.
    j["case"] = case_to_json(case_as_run(c, b, s));
    if (c.air) {
        nlohmann::json films = nlohmann::json::array();
        for (const FilmRegime& f : b.model.films) {
            films.push_back({{"name", f.name}, {"gap_m", f.gap}, {"knudsen", f.knudsen},
                             {"viscosity_ratio", f.viscosity_ratio}, {"squeeze_number", f.squeeze_number}});
        }
        j["air"] = {{"pressure_pa", c.air->pressure}, {"temperature_k", c.air->temperature},
                    {"viscosity_pa_s", c.air->viscosity}, {"mean_free_path_m", c.air->lambda()},
                    {"film", c.air->film}, {"films", films}};
    }
    return j;
}

nlohmann::json switching_json(const SwitchingLedger& l) {
    nlohmann::json contacts = nlohmann::json::array();
    for (const SwitchingContact& k : l.contacts) {
        contacts.push_back({{"support", k.support},
                            {"t_on_s", k.t_on},
                            {"t_off_s", k.t_off},
                            {"impact_velocity_m_s", k.impact_velocity},
                            {"peak_force_n", k.peak_force},
                            {"closed_at_end", k.closed_at_end}});
    }
    nlohmann::json stuck = nullptr;
    if (l.stuck) {
        stuck = {{"support", l.stuck->support},
                 {"restoring_force_n", l.stuck->restoring_force},
                 {"pull_off_force_n", l.stuck->pull_off_force},
                 {"contact_force_n", l.stuck->contact_force}};
        // A layer's peel balance (docs/adhesion.md §10); a support's object stays as it was.
        if (const auto& h = l.stuck->layer) {
            stuck["contact"] = l.stuck->contact;
            stuck["adhesion_energy_j_m"] = h->adhesion_energy;
            stuck["release_rate_j_m"] = std::max(h->release_from, h->release_to);
            stuck["statically_stuck"] = h->sticks;
            stuck["contact_from_m"] = h->sticks ? nlohmann::json(h->contact_from) : nlohmann::json(nullptr);
            stuck["contact_to_m"] = h->sticks ? nlohmann::json(h->contact_to) : nlohmann::json(nullptr);
            stuck["critical_work_of_adhesion_j_m2"] = h->critical_work_of_adhesion;
        }
    }
    nlohmann::json j = {{"voltage_on_s", opt(l.voltage.on)},
            {"voltage_off_s", opt(l.voltage.off)},
            {"closing_time_s", opt(l.closing_time)},
            {"bounces", l.bounces},
            {"bounces_count", "every separation, chatter included"},
            {"grouped_bounces", l.grouped_bounces},
            {"group_gap_s", l.group_gap},
            {"stable_contact_s", opt(l.stable_contact)},
            {"peak_force_n", l.contacts.empty() ? nlohmann::json(nullptr) : nlohmann::json(l.peak_force)},
            {"release_time_s", opt(l.release_time)},
            {"state", l.state},
            {"reason", l.reason},
            {"contacts", contacts}};
    // Only where a support has adhesion, so that the summaries of other cases stay as they were.
    if (l.stuck) j["stuck"] = stuck;
    if (const auto& c = l.collapse) {
        j["collapse"] = {{"electrode", c->electrode}, {"time_s", c->time}, {"x_m", c->x},
                         {"voltage_v", c->voltage}, {"air_gap_m", c->air_gap}};
    }
    return j;
}

nlohmann::json transient_summary_json(const Case& c, const BuiltProblem& b, const TransientResult& r,
                                      const ImpactSummary& s, const SwitchingLedger* switching) {
    const double w1 = b.model.omega1;
    nlohmann::json j;
    j["omega1_rad_s"] = w1;
    nlohmann::json impacts = nlohmann::json::array();
    for (const Impact& im : s.impacts) {
        nlohmann::json row = contact_row(im);
        row["episodes"] = im.episodes;
        impacts.push_back(row);
    }
    j["impacts"] = impacts;
    const ContactDamage damage = contact_damage(s.impacts);
    if (!s.impacts.empty() && !std::isnan(damage.contact_energy)) j["contact_damage"] = damage_json(damage);
    nlohmann::json eps = nlohmann::json::array();
    for (const ContactEpisode& e : r.episodes) eps.push_back(contact_row(e));
    j["episodes"] = eps;
    j["T_s"] = opt(s.T_first);
    j["T1_s"] = opt(s.T1_first);
    j["T2_s"] = opt(s.T2_first);
    j["Tp_s"] = opt(s.Tp);
    j["Tp_reason"] = s.Tp_reason;
    j["tau"] = scaled(s.T_first, w1);
    j["tau1"] = scaled(s.T1_first, w1);
    j["tau2"] = scaled(s.T2_first, w1);
    j["tau_p"] = scaled(s.Tp, w1);
    j["cycles"] = {{"support", s.cycle_support}, {"T_s", s.T}, {"T1_s", s.T1}, {"T2_s", s.T2}};
    // y_max, z_max and watched_min are of this point (the free end, or mid-span of a bridge).
    j["watched_point"] = {{"name", b.model.watched.name}, {"x_over_l", b.model.watched.x_over_l}};
    j["y_max_m"] = opt(s.y_max);
    j["z_max"] = opt(s.z_max);
    j["y_max_contact_m"] = opt(s.y_max_contact);
    j["tip_min_m"] = opt(s.watched_min);
    const bool films = has_films(b);
    j["energy"] = {{"initial", energy_json(r.initial_energy, films)}, {"final", energy_json(r.final_energy, films)}};
    j["solver"] = {{"method", r.stats.method},
                   {"decompositions", r.stats.decompositions},
                   {"events", r.stats.events},
                   {"steps", r.stats.steps}};
    if (r.stats.method == "exact") {
        j["solver"]["unproven_steps"] = r.stats.unproven_steps;
        j["solver"]["unproven_excess"] = r.stats.unproven_excess;
        j["solver"]["tangencies"] = r.stats.tangencies;
        if (r.stats.at_rest_from >= 0.0) j["solver"]["at_rest_from_s"] = r.stats.at_rest_from;
    } else {
        // Which coordinates CVODE integrated: the answers of the two agree to its tolerance, not bit for bit.
        j["solver"]["state"] = r.stats.nodal_state ? "fe_dofs" : "modal";
        j["solver"]["basis_vectors"] = r.stats.basis_vectors;
        j["solver"]["basis_modes"] = r.stats.basis_modes;
        j["solver"]["initial_projection_error"] = r.stats.initial_projection_error;
        // Only where flights were carried in closed form, so that other summaries stay as they were.
        if (r.stats.free_flights > 0) j["solver"]["free_flights"] = r.stats.free_flights;
    }
    if (!r.stats.fallback_reason.empty()) j["solver"]["fallback_reason"] = r.stats.fallback_reason;
    if (switching) {
        j["switching"] = switching_json(*switching);
        if (switching->collapse) j["switching"]["collapse"]["x_over_l"] = switching->collapse->x / c.beam.length;
    }
    // Only where a contact has a resistance model, so that the summaries of other cases stay as they were.
    const std::vector<ResistanceSeries> resistances = contact_resistances(b.model, r);
    if (!resistances.empty()) j["contact_resistance"] = contact_resistance_json(resistances, r.history, r.conduction);
    j["resolved"] = resolved_case_json(c, b, s);
    return j;
}

CsvTable history_csv(const TransientResult& r, const std::string& watched, bool films,
                     const std::vector<ResistanceSeries>& resistances) {
    const TimeHistory& h = r.history;
    CsvTable t;
    t.header = {"t_s", watched + "_m", watched + "_velocity_m_s"};
    for (std::size_t k = 0; k < h.contact_v.size(); ++k) {
        const std::string p = "contact" + std::to_string(k);
        t.header.insert(t.header.end(), {p + "_m", p + "_velocity_m_s", p + "_force_n"});
    }
    const bool energy = h.energy.size() == h.t.size();
    if (energy) {
        t.header.insert(t.header.end(), {"kinetic_j", "strain_j", "contact_spring_j", "electrical_j",
                                         "rayleigh_dissipated_j", "contact_dissipated_j", "external_work_j"});
        if (films) t.header.push_back("film_dissipated_j");
    }
    for (const ResistanceSeries& s : resistances) t.header.push_back("contact" + std::to_string(s.contact) + "_resistance_ohm");
    for (std::size_t i = 0; i < h.t.size(); ++i) {
        std::vector<double> row{h.t[i], h.watched_v[i], h.watched_velocity[i]};
        for (std::size_t k = 0; k < h.contact_v.size(); ++k) {
            row.insert(row.end(), {h.contact_v[k][i], h.contact_velocity[k][i], h.contact_force[k][i]});
        }
        if (energy) {
            const EnergyLedger& e = h.energy[i];
            row.insert(row.end(), {e.kinetic, e.strain, e.contact_spring, e.electrical, e.rayleigh_dissipated,
                                   e.contact_dissipated, e.external_work});
            if (films) row.push_back(e.film_dissipated);
        }
        for (const ResistanceSeries& s : resistances) row.push_back(s.ohm[i]);
        t.add_row(std::move(row));
    }
    return t;
}

CsvTable events_csv(const TransientResult& r, const ImpactSummary& s) {
    CsvTable t;
    t.header = {"episode", "impact", "support", "t_on_s", "t_off_s", "v_in_m_s", "v_out_m_s",
                "peak_force_n", "peak_penetration_m", "impulse_n_s", "closed_at_end"};
    for (std::size_t i = 0; i < r.episodes.size(); ++i) {
        const ContactEpisode& e = r.episodes[i];
        double impact = std::numeric_limits<double>::quiet_NaN();  // in no impact: the missing marker
        for (std::size_t k = 0; k < s.impacts.size(); ++k) {
            const Impact& im = s.impacts[k];
            if (im.support == e.support && e.t_on >= im.t_on && e.t_on <= im.t_off) impact = static_cast<double>(k);
        }
        t.add_row({static_cast<double>(i), impact, static_cast<double>(e.support), e.t_on, e.t_off, e.v_in, e.v_out,
                   e.peak_force, e.peak_penetration, e.impulse, e.closed_at_end ? 1.0 : 0.0});
    }
    return t;
}

OutputFiles transient_files(const Case& c, const BuiltProblem& b, const TransientResult& r, const ImpactSummary& s,
                            const SwitchingLedger* switching) {
    return {{"history.csv", history_csv(r, b.model.watched.name, has_films(b), contact_resistances(b.model, r)).str()},
            {"events.csv", events_csv(r, s).str()},
            {"summary.json", transient_summary_json(c, b, r, s, switching).dump(2) + "\n"}};
}

}  // namespace vi
