#include "study/stiction/stiction.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "dynamics/contact_hold.hpp"
#include "fem/system.hpp"
#include "model/case_checks.hpp"
#include "model/input_error.hpp"
#include "model/run_control.hpp"

namespace vi {
namespace {

// The energy release rate -dU/ds [J/m] of the beam section of c over [0, s], clamped at x = 0 and
// held at v = -gap, theta = 0 at x = s (flat on the substrate from there on), on `elements` elements:
// M^2 / (2 E I), M the FE reaction moment at x = s. The span's bending moment jumps from M to 0 where
// it meets the substrate, and moving that front by ds releases the strain energy M^2 / (2 E I) ds
// (the J-integral of a peeled beam). A difference quotient of U would lose digits (the FE energy's
// rounding grows with the mesh's condition and is divided by the step).
double release_rate(const Case& c, double s, double gap, int elements) {
    Case span = c;
    span.beam.length = s;
    span.beam.elements = elements;
    span.beam.left = EndCondition::clamped;
    span.beam.right = EndCondition::free;
    span.beam.residual_stress = 0.0;
    span.beam.stretching = false;
    span.supports.clear();
    span.electrodes.clear();
    span.loads.clear();
    const System sys = build_system(span, SupportModel::none);
    const Eigen::MatrixXd K(sys.K);
    const int last = sys.mesh.node_count() - 1;
    const int rv = sys.reduced_of[static_cast<std::size_t>(global_dof(last, 1))];
    const int rt = sys.reduced_of[static_cast<std::size_t>(global_dof(last, 2))];
    const Eigen::Index n = K.rows();
    // The free DOFs are all but the held end's v and theta: K_ff q_f = -K_fp q_p.
    std::vector<Eigen::Index> free;
    for (Eigen::Index i = 0; i < n; ++i) {
        if (i != rv && i != rt) free.push_back(i);
    }
    Eigen::MatrixXd Kff(free.size(), free.size());
    Eigen::VectorXd rhs(free.size());
    for (std::size_t a = 0; a < free.size(); ++a) {
        rhs[static_cast<Eigen::Index>(a)] = K(free[a], rv) * gap;  // -K_fp q_p with q_p = (-gap, 0)
        for (std::size_t b = 0; b < free.size(); ++b) Kff(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b)) = K(free[a], free[b]);
    }
    const Eigen::VectorXd qf = Kff.ldlt().solve(rhs);
    Eigen::VectorXd q = Eigen::VectorXd::Zero(n);
    for (std::size_t a = 0; a < free.size(); ++a) q[free[a]] = qf[static_cast<Eigen::Index>(a)];
    q[rv] = -gap;
    const double moment = K.row(rt).dot(q);
    return moment * moment / (2.0 * sys.props.E * sys.props.I);
}

std::string law_name(Adhesion a) { return a == Adhesion::dmt ? "DMT" : "JKR"; }

}  // namespace

double detached_length_closed_form(double youngs_modulus, double thickness, double gap, double work_of_adhesion) {
    return std::pow(1.5 * youngs_modulus * thickness * thickness * thickness * gap * gap / work_of_adhesion, 0.25);
}

double detached_length_fe(const Case& c, double gap, double work_of_adhesion, int elements) {
    const double line_energy = work_of_adhesion * c.beam.width;  // gamma w [J/m]
    // Energy balance: the free span grows while the strain energy it releases, -dU/ds, exceeds gamma w.
    const auto excess = [&](double s) { return release_rate(c, s, gap, elements) - line_energy; };
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
    if (r.supports.empty()) {
        throw InputError("supports: no support has adhesion (give one adhesion = \"dmt\" or \"jkr\" with its "
                         "work_of_adhesion and contact_radius)");
    }
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
        d.closed_form = detached_length_closed_form(c.material.effective_modulus(), c.beam.thickness, d.gap,
                                                    d.work_of_adhesion);
        d.finite_element = detached_length_fe(c, d.gap, d.work_of_adhesion, c.beam.elements);
        d.beam_longer = c.beam.length > d.closed_form;
        r.detached.push_back(d);
    }
    if (r.detached.empty()) r.note = "no adhesive support has a gap (prestressed supports bridge none)";
    return r;
}

}  // namespace vi
