#include "study/stiction/stiction_output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "io/csv_writer.hpp"

namespace vi {
namespace {

const DetachedLength* detached_of(const StictionResult& r, int support) {
    for (const DetachedLength& d : r.detached) {
        if (d.support == support) return &d;
    }
    return nullptr;
}

const char* verdict(const SupportStiction& s) { return s.sticks ? "sticks" : "releases"; }

}  // namespace

nlohmann::json stiction_json(const StictionResult& r) {
    nlohmann::json supports = nlohmann::json::array();
    for (const SupportStiction& s : r.supports) {
        supports.push_back({{"support", s.support},
                            {"law", s.law},
                            {"restoring_force_n", s.restoring_force},
                            {"point_stiffness_n_m", s.point_stiffness},
                            {"held_offset_m", s.held_offset},
                            {"pull_off_force_n", s.pull_off_force},
                            {"verdict", verdict(s)},
                            {"critical_work_of_adhesion_j_m2", s.critical_work_of_adhesion
                                                                   ? nlohmann::json(*s.critical_work_of_adhesion)
                                                                   : nlohmann::json(nullptr)}});
    }
    nlohmann::json detached = nlohmann::json::array();
    for (const DetachedLength& d : r.detached) {
        detached.push_back({{"support", d.support},
                            {"gap_m", d.gap},
                            {"work_of_adhesion_j_m2", d.work_of_adhesion},
                            {"detached_length_m", d.closed_form},
                            {"detached_length_fe_m", d.finite_element},
                            {"beam_longer", d.beam_longer}});
    }
    nlohmann::json j = {{"supports", supports}, {"detached", detached}, {"note", r.note}};
    // Only with an adhesive layer, so that the checks of supports read as they did.
    if (!r.layers.empty()) {
        nlohmann::json layers = nlohmann::json::array();
        const auto opt = [](const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); };
        const auto finite = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
        for (const LayerStiction& l : r.layers) {
            const LayerHold& h = l.hold;
            layers.push_back({{"electrode", h.electrode},
                              {"contact", "electrodes[" + std::to_string(h.electrode) + "].dielectric"},
                              {"air_gap_m", h.air_gap},
                              {"adhesion_energy_j_m", h.adhesion_energy},
                              {"holding_moment_n_m", h.holding_moment},
                              {"span_from_m", h.span_from},
                              {"span_to_m", h.span_to},
                              {"release_rate_from_j_m", finite(h.release_from)},
                              {"release_rate_to_j_m", finite(h.release_to)},
                              {"verdict", h.sticks ? "sticks" : "releases"},
                              {"contact_from_m", h.sticks ? nlohmann::json(h.contact_from) : nlohmann::json(nullptr)},
                              {"contact_to_m", h.sticks ? nlohmann::json(h.contact_to) : nlohmann::json(nullptr)},
                              {"restoring_force_n", h.restoring_force},
                              {"even_pull_off_force_n", h.even_pull_off_force},
                              {"critical_work_of_adhesion_j_m2", h.critical_work_of_adhesion},
                              {"settled",
                               {{"stuck", l.settled_stuck},
                                {"contact_from_m", l.settled_stuck ? nlohmann::json(l.settled_from) : nlohmann::json(nullptr)},
                                {"contact_to_m", l.settled_stuck ? nlohmann::json(l.settled_to) : nlohmann::json(nullptr)}}},
                              {"detached_length_m", opt(l.detached_closed_form)},
                              {"detached_length_on_layer_m", opt(l.detached_on_layer)},
                              {"detached_length_fe_m", opt(l.detached_settled)}});
        }
        j["layers"] = layers;
    }
    return j;
}

std::string stiction_text(const StictionResult& r) {
    std::string out;
    char buf[256];
    for (const SupportStiction& s : r.supports) {
        std::snprintf(buf, sizeof buf,
                      "supports[%d] (%s): %s: restoring force %.4g N (k_p %.4g N/m x %.4g um) vs pull-off force %.4g N\n",
                      s.support, s.law.c_str(), verdict(s), s.restoring_force, s.point_stiffness, s.held_offset * 1e6,
                      s.pull_off_force);
        out += buf;
        if (s.critical_work_of_adhesion) {
            std::snprintf(buf, sizeof buf, "  it sticks for a work of adhesion above %.4g J/m^2\n", *s.critical_work_of_adhesion);
        } else {
            std::snprintf(buf, sizeof buf, "  the beam presses on it unloaded: it stays closed whatever the adhesion\n");
        }
        out += buf;
    }
    for (const DetachedLength& d : r.detached) {
        std::snprintf(buf, sizeof buf,
                      "S-shaped stuck cantilever on supports[%d]'s gap %.4g um, gamma %.4g J/m^2: detached length "
                      "%.4g um (FE %.4g um); the beam is %s\n",
                      d.support, d.gap * 1e6, d.work_of_adhesion, d.closed_form * 1e6, d.finite_element * 1e6,
                      d.beam_longer ? "longer: it can stay stuck lying on the substrate" : "shorter: it cannot lie stuck in the S-shape");
        out += buf;
    }
    if (!r.note.empty()) out.append("Detached length: ").append(r.note).append("\n");
    for (const LayerStiction& l : r.layers) {
        const LayerHold& h = l.hold;
        const double released = std::max(h.release_from, h.release_to);
        std::snprintf(buf, sizeof buf,
                      "electrodes[%zu].dielectric: %s: held flat on its layer (x = %.4g to %.4g um, %.4g um below the "
                      "beam) it releases at most %.4g J/m per unit length peeled, vs the adhesion energy w w_e %.4g J/m\n",
                      h.electrode, h.sticks ? "sticks" : "releases", h.span_from * 1e6, h.span_to * 1e6, h.air_gap * 1e6,
                      released, h.adhesion_energy);
        out += buf;
        if (h.sticks) {
            std::snprintf(buf, sizeof buf,
                          "  peeled to balance it lies on x = %.4g to %.4g um; restoring force %.4g N (that contact lifted "
                          "evenly would hold %.4g N)\n",
                          h.contact_from * 1e6, h.contact_to * 1e6, h.restoring_force, h.even_pull_off_force);
            out += buf;
        }
        std::snprintf(buf, sizeof buf, "  it sticks for a work of adhesion above %.4g J/m^2\n", h.critical_work_of_adhesion);
        out += buf;
        if (l.settled_stuck) {
            std::snprintf(buf, sizeof buf, "  FE beam laid on it and settled (full law): stuck, touching x = %.4g to %.4g um\n",
                          l.settled_from * 1e6, l.settled_to * 1e6);
        } else {
            std::snprintf(buf, sizeof buf, "  FE beam laid on it and settled (full law): released\n");
        }
        out += buf;
        if (l.detached_closed_form) {
            char fe[48] = "none (released)";
            if (l.detached_settled) std::snprintf(fe, sizeof fe, "%.4g um", *l.detached_settled * 1e6);
            std::snprintf(buf, sizeof buf,
                          "  S-shaped stuck cantilever: detached length %.4g um (rigid layer), %.4g um on this layer, "
                          "settled FE %s\n",
                          *l.detached_closed_form * 1e6, *l.detached_on_layer * 1e6, fe);
            out += buf;
        }
    }
    return out;
}

OutputFiles stiction_files(const StictionResult& r) {
    CsvTable t;
    t.header = {"support", "law", "restoring_force_n", "pull_off_force_n", "verdict", "critical_work_of_adhesion_j_m2",
                "detached_length_m", "detached_length_fe_m"};
    for (const SupportStiction& s : r.supports) {
        const DetachedLength* d = detached_of(r, s.support);
        t.add_row({csv_count(s.support), csv_text(s.law), csv_number(s.restoring_force), csv_number(s.pull_off_force),
                   csv_text(verdict(s)), csv_number(s.critical_work_of_adhesion), d ? csv_number(d->closed_form) : csv_missing(),
                   d ? csv_number(d->finite_element) : csv_missing()});
    }
    // A layer's row: its contact name for the support, "layer" for the law, the settled FE front as
    // the FE detached length.
    for (const LayerStiction& l : r.layers) {
        const LayerHold& h = l.hold;
        t.add_row({csv_text("electrodes[" + std::to_string(h.electrode) + "].dielectric"), csv_text("layer"),
                   csv_number(h.restoring_force), csv_number(h.even_pull_off_force), csv_text(h.sticks ? "sticks" : "releases"),
                   csv_number(h.critical_work_of_adhesion), csv_number(l.detached_closed_form),
                   csv_number(l.detached_settled)});
    }
    return {{"stiction.json", stiction_json(r).dump(2) + "\n"}, {"stiction.csv", t.str()}};
}

}  // namespace vi
