#include "study/stiction/stiction_output.hpp"

#include <cstdio>

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
    return {{"supports", supports}, {"detached", detached}, {"note", r.note}};
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
    return {{"stiction.json", stiction_json(r).dump(2) + "\n"}, {"stiction.csv", t.str()}};
}

}  // namespace vi
