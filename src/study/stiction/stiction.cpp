#include "study/stiction/stiction.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "statics/contact_hold.hpp"
#include "statics/layer_hold.hpp"
#include "fem/system.hpp"
#include "model/case_checks.hpp"
#include "model/input_error.hpp"
#include "model/run_control.hpp"

namespace vi {
namespace {

// The energy release rate -dU/ds [J/m] of the beam section of c over [0, s], clamped at x = 0 and
// held at v = -gap, theta = 0 at x = s (flat on the substrate from there on), on `elements` elements
// (statics/layer_hold.hpp). A difference quotient of U would lose digits (the FE energy's rounding
// grows with the mesh's condition and is divided by the step).
double release_rate(const Case& c, double s, double gap, int elements) {
    return peel_release_rate(c, EndCondition::clamped, s, gap, elements).release_rate;
}

std::string law_name(Adhesion a) { return a == Adhesion::dmt ? "DMT" : "JKR"; }

}  // namespace

double detached_length_closed_form(double youngs_modulus, double thickness, double gap, double work_of_adhesion) {
    return std::pow(1.5 * youngs_modulus * thickness * thickness * thickness * gap * gap / work_of_adhesion, 0.25);
}

double detached_length_of_section(double bending_stiffness, double width, double gap, double work_of_adhesion) {
    return std::pow(18.0 * bending_stiffness * gap * gap / (width * work_of_adhesion), 0.25);
}

double detached_length_on_layer(double bending_stiffness, double gap, double adhesion_energy, double line_stiffness) {
    const double d0 = std::sqrt(2.0 * adhesion_energy / line_stiffness);
    const double beta = std::pow(line_stiffness / (4.0 * bending_stiffness), 0.25);
    const double target = gap / d0;
    // z^2 (z + 3) / (3 (z + 1)) rises from 0 with z and exceeds z^2 / 3, so sqrt(3 target) bounds the root.
    const auto f = [](double z) { return z * z * (z + 3.0) / (3.0 * (z + 1.0)); };
    double lo = 0.0, hi = std::sqrt(3.0 * target);
    for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
        const double mid = 0.5 * (lo + hi);
        (f(mid) < target ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi) / beta;
}

double detached_length_fe(const Case& c, double gap, double work_of_adhesion, int elements) {
    // gamma w [J/m], w the width at the front (the tip's past the tip).
    const auto line_energy = [&](double s) {
        if (c.beam.sections.empty()) return work_of_adhesion * c.beam.width;
        const BeamSection& at = c.beam.sections[section_index_at(c.beam, std::min(s / c.beam.length, 1.0))];
        return work_of_adhesion * at.width.value_or(c.beam.width);
    };
    // Energy balance: the free span grows while the strain energy it releases, -dU/ds, exceeds gamma w.
    const auto excess = [&](double s) { return release_rate(c, s, gap, elements) - line_energy(s); };
    double lo = c.beam.length, hi = c.beam.length;
    constexpr int kBracket = 200;  // factors of 2 each way: far beyond any physical l_d
    int k = 0;
    for (; k < kBracket && excess(lo) <= 0.0; ++k) lo *= 0.5;
    for (; k < kBracket && excess(hi) > 0.0; ++k) hi *= 2.0;
    if (k >= kBracket) throw std::runtime_error("detached_length_fe: no detached length within 2^200 of beam.length");
    for (int it = 0; it < 200 && hi - lo > 1e-13 * hi; ++it) {
        check_run();
        const double mid = 0.5 * (lo + hi);
        (excess(mid) > 0.0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

StictionResult stiction_check(const Case& c) {
    if (const std::vector<CaseProblem> problems = check_case(c); !problems.empty()) {
        throw InputError(problems.front().key + ": " + problems.front().message);
    }
    StictionResult r;
    const System sys = build_system(c, SupportModel::none);
    for (std::size_t k = 0; k < c.supports.size(); ++k) {
        const Support& s = c.supports[k];
        if (s.adhesion == Adhesion::none) continue;
        const ContactHold h = contact_hold(sys, c, k);
        SupportStiction st;
        st.support = static_cast<int>(k);
        st.law = law_name(s.adhesion);
        st.restoring_force = h.restoring_force;
        st.point_stiffness = h.point_stiffness;
        st.held_offset = h.held_offset;
        st.pull_off_force = h.pull_off_force;
        st.sticks = h.sticks();
        // F_po is linear in w: it equals the restoring force at w_c = w R_f / F_po.
        if (h.restoring_force > 0.0) st.critical_work_of_adhesion = s.work_of_adhesion * h.restoring_force / h.pull_off_force;
        r.supports.push_back(st);
    }
    r.layers = layer_stiction(c);
    if (r.supports.empty() && r.layers.empty()) {
        throw InputError("supports: no support has adhesion and no electrode's dielectric adheres (give a support "
                         "adhesion = \"dmt\" or \"jkr\" with its work_of_adhesion and contact_radius, or an electrode "
                         "with a dielectric_thickness its work_of_adhesion)");
    }
    if (r.supports.empty()) return r;
    const bool cantilever = (c.beam.left == EndCondition::free) != (c.beam.right == EndCondition::free);
    if (!cantilever) {
        r.note = "the detached length is for a cantilever (one end free); this beam has none or two";
        return r;
    }
    for (const SupportStiction& st : r.supports) {
        const Support& s = c.supports[static_cast<std::size_t>(st.support)];
        if (!(s.surface < 0.0)) continue;  // a prestressed support has no gap to bridge
        DetachedLength d;
        d.support = st.support;
        d.gap = -s.surface;
        d.work_of_adhesion = s.work_of_adhesion;
        if (c.beam.sections.empty()) {
            d.closed_form = detached_length_closed_form(c.material.effective_modulus(), c.beam.thickness, d.gap,
                                                        d.work_of_adhesion);
        } else {
            const SectionResultants& under = sys.sections[section_index_at(c.beam, s.position)];
            d.closed_form = detached_length_of_section(under.EI, under.width, d.gap, d.work_of_adhesion);
        }
        d.finite_element = detached_length_fe(c, d.gap, d.work_of_adhesion, c.beam.elements);
        d.beam_longer = c.beam.length > d.closed_form;
        r.detached.push_back(d);
    }
    if (r.detached.empty()) r.note = "no adhesive support has a gap (prestressed supports bridge none)";
    return r;
}

}  // namespace vi
