#include "dynamics/cvode_system.hpp"

#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace vi::cvode_detail {

namespace {

using ConstVec = Eigen::Map<const Eigen::VectorXd>;

}  // namespace

CvodeSystem::CvodeSystem(const TransientProblem& p)
    : p_(p), n_(p.size()), nc_(static_cast<int>(p.contacts.size())) {
    C_ = p.alpha * p.M + p.beta * p.K;
    damped_ = p.alpha != 0.0 || p.beta != 0.0;
    const Eigen::LLT<Eigen::MatrixXd> llt(p.M);
    if (llt.info() != Eigen::Success) {
        throw std::invalid_argument("solve_cvode: the mass matrix is not symmetric positive definite");
    }
    Minv_ = llt.solve(Eigen::MatrixXd::Identity(n_, n_));
    Minv_ = 0.5 * (Minv_ + Minv_.transpose()).eval();
    MinvK_ = Minv_ * p.K;
    MinvC_ = Minv_ * C_;
    MinvE_.resize(n_, nc_);
    for (int j = 0; j < nc_; ++j) MinvE_.col(j) = Minv_.col(p.contacts[j].dof);
    MinvQ_.resize(n_, static_cast<int>(p.loads.size()));
    for (std::size_t k = 0; k < p.loads.size(); ++k) {
        MinvQ_.col(static_cast<int>(k)) = Minv_ * (p.loads[k].amplitude * p.loads[k].shape);
    }
    acc_.resize(n_);
    t_limit_ = p.t_end;
    set_active(std::vector<bool>(static_cast<std::size_t>(nc_), false));
}

void CvodeSystem::set_active(const std::vector<bool>& active) {
    active_ = active;
    A_ = MinvK_;
    B_ = MinvC_;
    c_ = Eigen::VectorXd::Zero(n_);
    for (int j = 0; j < nc_; ++j) {
        if (!active_[static_cast<std::size_t>(j)]) continue;
        const ContactElement& e = p_.contacts[static_cast<std::size_t>(j)];
        A_.col(e.dof) += e.stiffness * MinvE_.col(j);
        B_.col(e.dof) += e.damping * MinvE_.col(j);
        c_ += e.stiffness * e.surface * MinvE_.col(j);
    }
}

void CvodeSystem::set_segment_end(double t_stop) { t_limit_ = t_stop; }

double CvodeSystem::load_time(double t) const {
    return t < t_limit_ ? t : std::nextafter(t_limit_, -std::numeric_limits<double>::infinity());
}

void CvodeSystem::acceleration(double t, const double* y, Eigen::VectorXd& a) const {
    const ConstVec q(y, n_), v(y + n_, n_);
    a.noalias() = c_ - A_ * q;
    a.noalias() -= B_ * v;
    const double tl = load_time(t);
    for (std::size_t k = 0; k < p_.loads.size(); ++k) {
        a += p_.loads[k].time(tl) * MinvQ_.col(static_cast<int>(k));
    }
}

double CvodeSystem::penetration(int j, const double* y) const {
    const ContactElement& e = p_.contacts[static_cast<std::size_t>(j)];
    return e.sign * (e.surface - y[e.dof]);
}

double CvodeSystem::penetration_rate(int j, const double* y) const {
    const ContactElement& e = p_.contacts[static_cast<std::size_t>(j)];
    return -e.sign * y[n_ + e.dof];
}

double CvodeSystem::contact_velocity(int j, const double* y) const {
    return y[n_ + p_.contacts[static_cast<std::size_t>(j)].dof];
}

double CvodeSystem::force(int j, const double* y) const {
    const ContactElement& e = p_.contacts[static_cast<std::size_t>(j)];
    return e.stiffness * penetration(j, y) + e.damping * penetration_rate(j, y);
}

double CvodeSystem::closing_function(int j, const double* y) const {
    const ContactElement& e = p_.contacts[static_cast<std::size_t>(j)];
    const double s = e.stiffness > 0.0 ? e.stiffness : 1.0;
    return std::min(s * penetration(j, y), force(j, y));
}

void CvodeSystem::rhs(double t, const double* y, double* ydot) const {
    const ConstVec v(y + n_, n_);
    Eigen::Map<Eigen::VectorXd>(ydot, n_) = v;
    Eigen::Map<Eigen::VectorXd> a(ydot + n_, n_);
    a.noalias() = c_ - A_ * ConstVec(y, n_);
    a.noalias() -= B_ * v;
    const double tl = load_time(t);
    double power = 0.0;
    for (std::size_t k = 0; k < p_.loads.size(); ++k) {
        const double g = p_.loads[k].time(tl);
        a += g * MinvQ_.col(static_cast<int>(k));
        power += g * p_.loads[k].amplitude * p_.loads[k].shape.dot(v);
    }
    ydot[rayleigh_index()] = damped_ ? v.dot(C_ * v) : 0.0;
    double contact_power = 0.0;
    for (int j = 0; j < nc_; ++j) {
        double impulse_rate = 0.0;
        if (active_[static_cast<std::size_t>(j)]) {
            const double rate = penetration_rate(j, y);
            contact_power += p_.contacts[static_cast<std::size_t>(j)].damping * rate * rate;
            impulse_rate = force(j, y);
        }
        ydot[impulse_index(j)] = impulse_rate;
    }
    ydot[contact_damping_index()] = contact_power;
    ydot[work_index()] = power;
}

void CvodeSystem::jacobian(double t, const double* y, double* jac) const {
    const int N = size();
    Eigen::Map<Eigen::MatrixXd> J(jac, N, N);
    J.setZero();
    const ConstVec v(y + n_, n_);
    J.block(0, n_, n_, n_).diagonal().setOnes();
    J.block(n_, 0, n_, n_) = -A_;
    J.block(n_, n_, n_, n_) = -B_;
    if (damped_) J.block(rayleigh_index(), n_, 1, n_) = 2.0 * (C_ * v).transpose();
    const double tl = load_time(t);
    for (const LoadTerm& load : p_.loads) {
        J.block(work_index(), n_, 1, n_) += (load.time(tl) * load.amplitude) * load.shape.transpose();
    }
    for (int j = 0; j < nc_; ++j) {
        if (!active_[static_cast<std::size_t>(j)]) continue;
        const ContactElement& e = p_.contacts[static_cast<std::size_t>(j)];
        // d/dv_k of Cc (dd/dt)^2 = Cc v_k^2 ; d/d(q_k, v_k) of F = Kc s (surface - q_k) - Cc s v_k.
        J(contact_damping_index(), n_ + e.dof) += 2.0 * e.damping * v[e.dof];
        J(impulse_index(j), e.dof) += -e.sign * e.stiffness;
        J(impulse_index(j), n_ + e.dof) += -e.sign * e.damping;
    }
}

void CvodeSystem::events(double t, const double* y, double* g) const {
    const bool any_active = std::find(active_.begin(), active_.end(), true) != active_.end();
    if (any_active) acceleration(t, y, acc_);
    for (int j = 0; j < nc_; ++j) {
        const ContactElement& e = p_.contacts[static_cast<std::size_t>(j)];
        double* gj = g + 3 * j;
        gj[1] = penetration_rate(j, y);
        if (active_[static_cast<std::size_t>(j)]) {
            gj[0] = -force(j, y);
            // dF/dt = Kc dd/dt + Cc d2d/dt2, d2d/dt2 = -sign v'.
            gj[2] = e.stiffness * gj[1] - e.damping * e.sign * acc_[e.dof];
        } else {
            gj[0] = closing_function(j, y);
            gj[2] = 1.0;
        }
    }
    g[3 * nc_] = y[n_ + p_.tip_dof];
    g[3 * nc_ + 1] = nc_ > 0 ? y[n_ + p_.contacts.front().dof] : 1.0;
}

EnergyLedger CvodeSystem::energy(const double* y, double jump) const {
    const ConstVec q(y, n_), v(y + n_, n_);
    EnergyLedger e;
    e.kinetic = 0.5 * v.dot(p_.M * v);
    e.strain = 0.5 * q.dot(p_.K * q);
    for (int j = 0; j < nc_; ++j) {
        if (!active_[static_cast<std::size_t>(j)]) continue;
        const double d = penetration(j, y);
        e.contact_spring += 0.5 * p_.contacts[static_cast<std::size_t>(j)].stiffness * d * d;
    }
    e.rayleigh_dissipated = y[rayleigh_index()];
    e.contact_dissipated = y[contact_damping_index()] + jump;
    e.external_work = y[work_index()];
    return e;
}

Eigen::VectorXd CvodeSystem::initial_state() const {
    Eigen::VectorXd y = Eigen::VectorXd::Zero(size());
    y.head(n_) = p_.q0;
    y.segment(n_, n_) = p_.v0;
    return y;
}

// Characteristic magnitudes (absolute tolerance = atol_scale times these):
//  - reference frequency w: the first natural frequency of (K, M); if K has no positive eigenvalue
//    (free body), that of K with every contact spring closed;
//  - displacement scale L: the largest of max|q0|, max|surface|, max|v0| / w and the static
//    deflection max|K_all^-1 Q| under the load amplitudes (K_all: K with every contact spring);
//    DOF i uses max(|q0_i|, L), so a rotation DOF with a larger initial value keeps its own scale;
//  - velocity of DOF i: max(|v0_i|, w * displacement scale of DOF i);
//  - energies and external work: the larger of the initial mechanical energy and the kinetic
//    energy at the velocity scales;
//  - impulse of contact j: (Kc L + Cc w L) / w, a contact force scale times a contact time scale.
Eigen::VectorXd CvodeSystem::absolute_tolerances(double atol_scale) const {
    Eigen::MatrixXd K_all = p_.K;
    for (const ContactElement& e : p_.contacts) K_all(e.dof, e.dof) += e.stiffness;
    auto first_frequency = [&](const Eigen::MatrixXd& K) {
        const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(
            K, p_.M, Eigen::EigenvaluesOnly);
        if (es.info() != Eigen::Success) return 0.0;
        const Eigen::VectorXd& lam = es.eigenvalues();
        const double cut = 1e-10 * std::max(lam.cwiseAbs().maxCoeff(), 0.0);
        for (int i = 0; i < lam.size(); ++i) {
            if (lam[i] > cut && lam[i] > 0.0) return std::sqrt(lam[i]);
        }
        return 0.0;
    };
    double w = first_frequency(p_.K);
    if (w <= 0.0) w = first_frequency(K_all);
    if (w <= 0.0) w = 1.0;

    double L = std::max(p_.q0.cwiseAbs().maxCoeff(), p_.v0.cwiseAbs().maxCoeff() / w);
    for (const ContactElement& e : p_.contacts) L = std::max(L, std::abs(e.surface));
    if (!p_.loads.empty()) {
        Eigen::VectorXd Q = Eigen::VectorXd::Zero(n_);
        for (const LoadTerm& load : p_.loads) Q += std::abs(load.amplitude) * load.shape;
        const Eigen::LDLT<Eigen::MatrixXd> ldlt(K_all);
        if (ldlt.info() == Eigen::Success) {
            const Eigen::VectorXd u = ldlt.solve(Q);
            if (u.allFinite()) L = std::max(L, u.cwiseAbs().maxCoeff());
        }
    }
    if (!(L > 0.0)) L = 1e-9;  // nothing moves; any small scale will do

    Eigen::VectorXd scale(size());
    for (int i = 0; i < n_; ++i) {
        scale[i] = std::max(std::abs(p_.q0[i]), L);
        scale[n_ + i] = std::max(std::abs(p_.v0[i]), w * scale[i]);
    }
    const Eigen::VectorXd vs = scale.segment(n_, n_);
    double energy = 0.5 * vs.dot(p_.M * vs);
    energy = std::max(energy, 0.5 * p_.v0.dot(p_.M * p_.v0) + 0.5 * p_.q0.dot(p_.K * p_.q0));
    scale[rayleigh_index()] = energy;
    scale[contact_damping_index()] = energy;
    scale[work_index()] = energy;
    for (int j = 0; j < nc_; ++j) {
        const ContactElement& e = p_.contacts[static_cast<std::size_t>(j)];
        const double f = e.stiffness * L + e.damping * w * L;
        scale[impulse_index(j)] = f > 0.0 ? f / w : energy / (w * L);
    }
    return atol_scale * scale;
}

void validate(const TransientProblem& p) {
    const int n = p.size();
    auto bad = [](const std::string& what) { throw std::invalid_argument("solve_cvode: " + what); };
    if (n <= 0 || p.M.cols() != n || p.K.rows() != n || p.K.cols() != n) bad("M and K must be n x n, n > 0");
    if (p.q0.size() != n || p.v0.size() != n) bad("q0 and v0 must have one entry per DOF");
    if (!p.M.allFinite() || !p.K.allFinite() || !p.q0.allFinite() || !p.v0.allFinite()) bad("non-finite input");
    if (!p.active0.empty() && p.active0.size() != p.contacts.size()) bad("active0 must have one entry per contact");
    for (const ContactElement& c : p.contacts) {
        if (c.dof < 0 || c.dof >= n) bad("contact DOF out of range");
        if (std::abs(c.sign) != 1.0) bad("contact sign must be +1 or -1");
        if (!(c.stiffness >= 0.0) || !(c.damping >= 0.0) || !std::isfinite(c.surface)) bad("contact data");
    }
    for (const LoadTerm& l : p.loads) {
        if (l.shape.size() != n || !std::isfinite(l.amplitude)) bad("load shape size or amplitude");
    }
    if (p.tip_dof < 0 || p.tip_dof >= n) bad("tip_dof out of range");
    if (!(p.t_end > 0.0) || !std::isfinite(p.t_end)) bad("t_end must be positive");
    if (!std::isfinite(p.output_step)) bad("output_step must be finite");
}

int rhs_fn(realtype t, N_Vector y, N_Vector ydot, void* ud) {
    try {
        static_cast<const CvodeSystem*>(ud)->rhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
        return 0;
    } catch (...) { return -1; }
}

int jac_fn(realtype t, N_Vector y, N_Vector /*fy*/, SUNMatrix J, void* ud, N_Vector, N_Vector, N_Vector) {
    try {
        static_cast<const CvodeSystem*>(ud)->jacobian(t, N_VGetArrayPointer(y), SUNDenseMatrix_Data(J));
        return 0;
    } catch (...) { return -1; }
}

int root_fn(realtype t, N_Vector y, realtype* g, void* ud) {
    try {
        static_cast<const CvodeSystem*>(ud)->events(t, N_VGetArrayPointer(y), g);
        return 0;
    } catch (...) { return -1; }
}

}  // namespace vi::cvode_detail
