// The energy ledger of a piece in closed form: kinetic, strain and contact-spring energy at a time,
// and the Rayleigh and contact dissipation and the work of the loads integrated over the piece.

#include <cmath>
#include <limits>

#include "dynamics/exact/exact_state.hpp"

namespace vi {
namespace {

// At a sample, a mode whose term could still dissipate less than this fraction of what all terms
// together could (sum_k |a_k e_k|^2 tail_k) is left out of the O(m^2) quadratic form: by
// Cauchy-Schwarz its share of the form, cross terms included, is below 2 (2n)^1.5 1e-18 of the total
// (1e-14 at m = 50), and right after an impact and later most heavily damped modes are that small.
constexpr double kNegligibleShare = 1e-36;

// sum over k, l in the modes that matter of u_k M(k, l) u_l (M symmetric), given each mode's tail.
cd quadratic_form(const Eigen::MatrixXcd& M, const Eigen::VectorXcd& u, const std::vector<double>& tail) {
    const Eigen::Index m = u.size();
    double total = 0.0;
    for (Eigen::Index k = 0; k < m; ++k) {
        const double t = tail[static_cast<std::size_t>(k)];
        if (std::isfinite(t)) total += std::norm(u[k]) * t;
    }
    std::vector<Eigen::Index> keep;
    for (Eigen::Index k = 0; k < m; ++k) {
        const double t = tail[static_cast<std::size_t>(k)];
        if (u[k] != cd(0.0) && (!std::isfinite(t) || std::norm(u[k]) * t > kNegligibleShare * total)) keep.push_back(k);
    }
    cd sum = 0.0;
    for (const Eigen::Index k : keep) {
        cd acc = 0.0;
        for (const Eigen::Index l : keep) acc += M(l, k) * u[l];
        sum += u[k] * acc;
    }
    return sum;
}

}  // namespace

void PieceSolution::prepare_energy() const {
    if (energy_ready_) return;
    const Eigen::MatrixXcd& w = s_->rayleigh_w;
    a_wc_a_ = (a_full_.transpose() * s_->rayleigh_wc * a_full_)(0);
    const std::size_t nt = terms_full_.size();
    wC_.clear();
    for (const Term& t : terms_full_) wC_.push_back(w * t.C);
    CwC_.resize(static_cast<Eigen::Index>(nt), static_cast<Eigen::Index>(nt));
    for (std::size_t i = 0; i < nt; ++i) {
        for (std::size_t j = 0; j < nt; ++j) {
            CwC_(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = terms_full_[i].C.cwiseProduct(wC_[j]).sum();
        }
    }
    const std::size_t nc = p_->contacts.size();
    alpha_c_alpha_.assign(nc, cd(0.0));
    gC_.assign(nc, {});
    for (std::size_t c = 0; c < nc; ++c) {
        if (!active_[c] || p_->contacts[c].damping == 0.0) continue;
        const Eigen::RowVectorXcd g = s_->full_contact_vel.row(static_cast<Eigen::Index>(c));
        const Eigen::VectorXcd alpha = g.transpose().cwiseProduct(a_full_);
        alpha_c_alpha_[c] = (alpha.transpose() * s_->cauchy * alpha)(0);
        for (const Term& t : terms_full_) gC_[c].push_back((g * t.C)(0));
    }
    energy_ready_ = true;
}

// Integral over [0, tau] of c^T W c, c = a e^(lambda t) + sum_m C_m t^p e^(s t): the homogeneous part
// by the Cauchy matrix, (a e)^T (W .* cauchy) (a e) - a^T (W .* cauchy) a, the rest by moments.
double PieceSolution::rayleigh_integral(double tau, const Eigen::VectorXcd& ef) const {
    const Eigen::VectorXcd& lam = s_->full.lambda;
    const Eigen::VectorXcd ae = a_full_.cwiseProduct(ef);
    cd sum = quadratic_form(s_->rayleigh_wc, ae, s_->rayleigh_tail) - a_wc_a_;
    for (std::size_t i = 0; i < terms_full_.size(); ++i) {
        const Term& t = terms_full_[i];
        const cd es = fast_exp(t.s, tau);
        for (Eigen::Index k = 0; k < a_full_.size(); ++k) {
            sum += 2.0 * a_full_[k] * wC_[i][k] * exp_moment(lam[k] + t.s, t.power, tau, ef[k] * es);
        }
        for (std::size_t j = 0; j < terms_full_.size(); ++j) {
            const Term& u = terms_full_[j];
            sum += CwC_(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) * exp_moment(t.s + u.s, t.power + u.power, tau);
        }
    }
    return sum.real();
}

// The same for a contact damper, W = Cc g g^T: no n x n matrix is formed.
double PieceSolution::damper_integral(std::size_t c, double tau, const Eigen::VectorXcd& ef) const {
    const Eigen::VectorXcd& lam = s_->full.lambda;
    const Eigen::RowVectorXcd g = s_->full_contact_vel.row(static_cast<Eigen::Index>(c));
    const Eigen::VectorXcd alpha_e = g.transpose().cwiseProduct(a_full_).cwiseProduct(ef);
    cd sum = quadratic_form(s_->cauchy, alpha_e, s_->contact_tail[c]) - alpha_c_alpha_[c];
    for (std::size_t i = 0; i < terms_full_.size(); ++i) {
        const Term& t = terms_full_[i];
        const cd gC = gC_[c][i];
        const cd es = fast_exp(t.s, tau);
        for (Eigen::Index k = 0; k < a_full_.size(); ++k) {
            sum += 2.0 * g[k] * a_full_[k] * gC * exp_moment(lam[k] + t.s, t.power, tau, ef[k] * es);
        }
        for (std::size_t j = 0; j < terms_full_.size(); ++j) {
            const Term& u = terms_full_[j];
            sum += gC * gC_[c][j] * exp_moment(t.s + u.s, t.power + u.power, tau);
        }
    }
    return p_->contacts[c].damping * sum.real();
}

void PieceSolution::accumulate_dissipation(double tau, EnergyLedger& e) const {
    accumulate_dissipation(tau, exponentials(tau), e);
}

void PieceSolution::accumulate_dissipation(double tau, const Eigen::VectorXcd& e, EnergyLedger& ledger) const {
    if (tau <= 0.0) return;
    prepare_energy();
    const Eigen::VectorXcd ef = full_exponentials(e);
    ledger.rayleigh_dissipated += rayleigh_integral(tau, ef);
    for (std::size_t c = 0; c < p_->contacts.size(); ++c) {
        if (!active_[c] || p_->contacts[c].damping == 0.0) continue;
        ledger.contact_dissipated += damper_integral(c, tau, ef);
    }
    for (std::size_t l = 0; l < load_vel_.size(); ++l) ledger.external_work += product_integral(load_vel_[l], load_time_[l], tau);
}

EnergyLedger PieceSolution::energy_at(double tau, const EnergyLedger& start) const {
    return energy_at(tau, start, exponentials(tau));
}

EnergyLedger PieceSolution::energy_at(double tau, const EnergyLedger& start, const Eigen::VectorXcd& e) const {
    EnergyLedger out = start;
    accumulate_dissipation(tau, e, out);
    const int n = b_->n;
    const Eigen::VectorXd x = state_at(tau, e);
    out.kinetic = 0.5 * x.tail(n).squaredNorm();
    out.strain = 0.5 * x.head(n).cwiseProduct(b_->omega).squaredNorm();
    out.contact_spring = 0.0;
    for (std::size_t c = 0; c < p_->contacts.size(); ++c) {
        if (!active_[c]) continue;
        const ContactElement& ce = p_->contacts[c];
        const double d = ce.sign * (ce.surface - b_->phi.row(ce.dof).dot(x.head(n)));
        out.contact_spring += 0.5 * ce.stiffness * d * d;
    }
    return out;
}

}  // namespace vi
