// The parameters the paper does not give: the values the study used and why.

#include <cmath>
#include <numbers>

#include "fem/rayleigh.hpp"
#include "study/paper/figures.hpp"
#include "study/paper/report.hpp"

namespace vi {

std::vector<std::vector<std::string>> unstated_parameters(const PaperStudy& st) {
    const PaperStudyOptions& o = st.options;
    const Case& c = o.cases.free_impact;
    const Support& sup = c.supports.front();
    const TypicalTransient& t = st.typical;
    const ImpactSummary& s = t.summary;
    const auto& modes = st.free_modes.result.bending;
    const double w1 = t.omega1;
    std::vector<std::vector<std::string>> rows;

    const double rigid = std::numbers::pi / w1 + (st.pinned_tip_omega1 > 0 ? std::numbers::pi / st.pinned_tip_omega1 : 0.0);
    rows.push_back({"contact stiffness Kc", significant(sup.stiffness, 4) + " N/m",
                    "Not fitted (the paper's fitted values are not published). The contact phase shortens as Kc grows; at " +
                        significant(sup.stiffness, 4) + " N/m the first period T = " + (s.T_first ? significant(*s.T_first * 1e6, 4) : "n/a") +
                        " us is within " + (s.T_first ? significant(100.0 * (*s.T_first / rigid - 1.0), 2) : "n/a") +
                        " % of the rigid-contact limit " + significant(rigid * 1e6, 4) + " us, while the first impact's penetration (" +
                        (s.impacts.empty() ? "n/a" : significant(s.impacts.front().peak_penetration * 1e9, 3)) +
                        " nm) stays small against the lift. docs/paper-parameters.md scans Kc from 5 to 1e5 N/m."});
    if (sup.damping_ratio) {
        const double z = *sup.damping_ratio;
        const double e = std::exp(-z * (std::numbers::pi - 2.0 * std::asin(z)) / std::sqrt(1.0 - z * z));
        rows.push_back({"contact damper Cc", "zeta_c = " + significant(z, 4) + " at the free end: Cc = " + significant(st.support_damping, 4) + " N s/m",
                        "Cc = 2 zeta_c sqrt(Kc m_eff) with m_eff the free end's first-mode effective mass (rho A l / 4); a single "
                        "mass on this contact would rebound with a coefficient of restitution " + significant(e, 3) + "."});
    } else {
        rows.push_back({"contact damper Cc", significant(st.support_damping, 4) + " N s/m", "given in the case file"});
    }
    rows.push_back({"Cc and Kc as the support moves", "held at " + significant(st.support_damping, 4) + " N s/m and " + significant(sup.stiffness, 4) + " N/m",
                    "The support is one piece of hardware wherever it sits; a damping ratio re-derived at each position would make "
                    "the damper grow as the support nears the clamp (its effective mass grows)."});
    if (c.damping.from_ratios && modes.size() >= 3) {
        std::string higher;
        for (std::size_t i = 2; i < modes.size(); ++i) {
            higher += (i > 2 ? ", " : "") + std::string("zeta_") + std::to_string(i + 1) + " = " +
                      significant(rayleigh_ratio({t.rayleigh_alpha, t.rayleigh_beta}, modes[i].omega), 3);
        }
        rows.push_back({"Rayleigh damping", "zeta = " + significant(c.damping.ratio1, 4) + ", " + significant(c.damping.ratio2, 4) + " at modes " +
                                               std::to_string(c.damping.mode1) + ", " + std::to_string(c.damping.mode2) +
                                               ": alpha = " + significant(t.rayleigh_alpha, 4) + " 1/s, beta = " + significant(t.rayleigh_beta, 4) + " s",
                        "A quality factor of " + significant(1.0 / (2.0 * c.damping.ratio1), 3) +
                            " in the two lowest modes, a material damping in vacuum (the paper models no air). The stiffness term "
                            "damps higher modes more, as the paper's argument needs: " + higher + "."});
    }
    rows.push_back({"lift y0", significant(t.y0 * 1e6, 4) + " um at the free end, released from rest",
                    "With zero gap the model is homogeneous in the lift: every displacement and force scales with y0 and no time "
                    "(T, T1, T2, T_p) changes, so z_max / (y0/l) is the lift-free result. With a prestress (Fig. 9) it is not: there "
                    "Delta / y0 matters."});
    rows.push_back({"horizon", significant(c.solver.horizon * 1e6, 4) + " us for Fig. 3, " + significant(o.position_horizon * 1e6, 4) +
                                   " us for the support-position scans, " + significant(o.cases.prestress.solver.horizon * 1e6, 4) + " us with prestress",
                    "The Fig. 3 case settles at T_p = " + (s.Tp ? significant(*s.Tp * 1e6, 4) : std::string("n/a")) +
                        " us. With the support further from the free end the bouncing decays more slowly (Cc is held at its "
                        "free-end value), so the scans run longer; T_p ends only once a smaller impact has followed the last large "
                        "one, and a short horizon can end it early. Where a run has still not settled by its horizon, T_p is left "
                        "undefined (a gap in Fig. 5), never extrapolated."});
    rows.push_back({"impact grouping (group gap)", "a quarter of the first free period, " + significant(s.group_gap * 1e6, 4) + " us",
                    "Higher modes make the contact chatter: one impact in the paper's sense (I, II, III in Fig. 10) is several "
                    "contact episodes separated by very short flights; a rebound's flight lasts about half the first period."});
    rows.push_back({"end of the transient T_p", "settle tolerance " + significant(c.solver.settle_tolerance, 4),
                    "T_p ends with the last impact whose peak penetration exceeds this fraction of the first impact's (with a "
                    "prestress: when contact is never lost again). The paper does not say how it delimits T_p."});
    rows.push_back({"support-position range", "x0/l from " + significant(o.position_min, 4) + " to 1",
                    "The paper's particular points lie in 0.6-0.9. Nearer the clamp the support is hit softly (the static lift "
                    "shape puts the support point at " + significant(100.0 * (3 * o.position_min * o.position_min - std::pow(o.position_min, 3)) / 2, 3) +
                        " % of the lift at x0/l = " + significant(o.position_min, 4) +
                        ") and the bouncing decays ever more slowly."});
    rows.push_back({"prestress range", "Delta/l from 0 to " + significant(o.prestress_max, 4),
                    "Covers the paper's point B (0.01) five times over, past the lift itself (y0/l = " +
                        significant(o.cases.prestress.initial.displacement / o.cases.prestress.beam.length, 3) + ")."});
    rows.push_back({"support in the modal figures", "a pin, v(x0) = 0",
                    "The paper's \"pin-joint support\" (Fig. 6); Kc = " + significant(sup.stiffness, 4) + " N/m is stiff against the beam "
                    "(tip stiffness 3EI/l^3 = " +
                        significant(3.0 * c.material.effective_modulus() * c.beam.second_moment() / std::pow(c.beam.length, 3), 3) + " N/m)."});
    return rows;
}

}  // namespace vi
