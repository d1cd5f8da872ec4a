#include "validation/reference_problems.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "fem/system.hpp"
#include "forces/kelvin_voigt_contact.hpp"
#include "modal/modal_analysis.hpp"
#include "model/golden_section.hpp"

namespace vi {

Case paper_cantilever(int elements, double support_at) {
    Case c;
    c.name = "paper-cantilever";
    c.beam = {117e-6, 30e-6, 2e-6, elements, EndCondition::clamped, EndCondition::free};
    c.material = {207e9, 8902.0, 0.31, false};
    if (support_at > 0.0) {
        Support s;
        s.position = support_at;
        s.stiffness = 50.0;
        c.supports.push_back(s);
    }
    return c;
}

Case clamped_clamped(int elements) {
    Case c = paper_cantilever(elements);
    c.beam.right = EndCondition::clamped;
    return c;
}

TransientProblem cantilever_drop(int m, double Kc, double Cc, double y0, double alpha, double beta, double t_end) {
    const Case c = paper_cantilever(m, 1.0);
    const System s = build_system(c);
    TransientProblem p;
    p.M = submatrix(s.M, s.bending);
    p.K = submatrix(s.K, s.bending);
    p.alpha = alpha;
    p.beta = beta;
    const int tip_reduced = s.reduced_of[static_cast<std::size_t>(global_dof(s.mesh.node_count() - 1, 1))];
    int tip = -1;
    for (std::size_t i = 0; i < s.bending.size(); ++i) {
        if (s.bending[i] == tip_reduced) tip = static_cast<int>(i);
    }
    Eigen::VectorXd f = Eigen::VectorXd::Zero(p.K.rows());
    f[tip] = 1.0;
    Eigen::VectorXd q = Eigen::MatrixXd(p.K).ldlt().solve(f);
    q *= y0 / q[tip];
    p.forces.push_back(std::make_shared<KelvinVoigtContact>("supports[0]", tip, 1.0, 0.0, Kc, Cc, c.beam.length));
    p.q0 = q;
    p.v0 = Eigen::VectorXd::Zero(q.size());
    p.modes0 = {0};
    p.watched_dof = tip;
    p.t_end = t_end;
    p.output_step = t_end / 500;
    return p;
}

TransientProblem single_dof_drop(double m, double Kc, double Cc, double h, double v, double t_end) {
    TransientProblem p;
    p.M = Eigen::MatrixXd::Constant(1, 1, m).sparseView();
    // The free state needs a positive stiffness; 1e-14 Kc changes the closed forms by O(1e-14).
    p.K = Eigen::MatrixXd::Constant(1, 1, 1e-14 * Kc).sparseView();
    p.forces.push_back(std::make_shared<KelvinVoigtContact>("supports[0]", 0, 1.0, 0.0, Kc, Cc, 0.0));
    p.q0 = Eigen::VectorXd::Constant(1, h);
    p.v0 = Eigen::VectorXd::Constant(1, -v);
    p.modes0 = {0};
    p.watched_dof = 0;
    p.t_end = t_end;
    p.output_step = t_end / 100;
    return p;
}

std::pair<double, double> first_ratio_peak(int elements) {
    auto ratio = [&](double x0) { return modal_study(paper_cantilever(elements, x0), 1, SupportModel::pin).ratios.at(0); };
    double best = 0.02;
    for (double x = 0.02; x <= 1.0 + 1e-12; x += 0.02) {
        if (ratio(x) > ratio(best)) best = x;
    }
    const GoldenSectionPeak p = golden_section_max(ratio, best - 0.02, std::min(1.0, best + 0.02), 1e-10);
    return {p.x, p.value};
}

}  // namespace vi
