#include "dynamics/cvode/cvode_system.hpp"

#include "dynamics/cvode/dual_product.hpp"
#include "modal/eigen_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace vi::cvode_detail {

namespace {

using ConstVec = Eigen::Map<const Eigen::VectorXd>;

// The basis rows of the given DOFs.
Eigen::MatrixXd rows_of(const Eigen::MatrixXd& phi, const std::vector<int>& dofs) {
    Eigen::MatrixXd out(static_cast<Eigen::Index>(dofs.size()), phi.cols());
    for (std::size_t k = 0; k < dofs.size(); ++k) out.row(static_cast<Eigen::Index>(k)) = phi.row(dofs[k]);
    return out;
}

}  // namespace

ModalSystem::ModalSystem(const TransientProblem& p, ModalBasis basis)
    : p_(p), basis_(std::move(basis)), r_(basis_.size()), contacts_(contact_indices(p.forces)), t_limit_(p.t_end) {
    if (basis_.nodal) {
        nodal_ = std::make_unique<NodalLinearPart>(p.M, p.K, p.alpha, p.beta);
    } else {
        w2_ = basis_.omega.cwiseAbs2();
        d_ = (p.alpha + p.beta * w2_.array()).matrix();
        for (const ForceElementPtr& e : p.forces) rows_.push_back(rows_of(basis_.phi, e->dofs()));
    }
    for (const ForceElementPtr& e : p.forces) films_ = films_ || e->dissipation_kind() == DissipationKind::film;
    // On a full basis the union's rows cost what the element's own evaluation does; on a few modes
    // an element over many DOFs is cheaper on the basis (ForceElement::reduced).
    reduced_.resize(p.forces.size());
    for (std::size_t e = 0; e < p.forces.size() && !basis_.full; ++e) {
        const ForceElement& el = *p.forces[e];
        if (el.is_contact() || el.watch_count() > 0) continue;
        reduced_[e] = el.reduced(BasisRows{rows_[e].data(), static_cast<std::size_t>(rows_[e].rows()),
                                           static_cast<std::size_t>(r_)});
    }
    std::vector<int> all;
    for (std::size_t e = 0; e < p.forces.size(); ++e) {
        if (!reduced_[e]) all.insert(all.end(), p.forces[e]->dofs().begin(), p.forces[e]->dofs().end());
    }
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    if (!nodal_) union_rows_ = rows_of(basis_.phi, all);
    union_dofs_ = all;
    for (std::size_t e = 0; e < p.forces.size(); ++e) {
        std::vector<int> at;
        if (!reduced_[e]) {
            for (int d : p.forces[e]->dofs())
                at.push_back(static_cast<int>(std::lower_bound(all.begin(), all.end(), d) - all.begin()));
        }
        local_.push_back(std::move(at));
    }
    uf_.resize(static_cast<Eigen::Index>(all.size()));
    std::size_t largest = 0;
    for (const ForceElementPtr& e : p.forces) largest = std::max(largest, e->dofs().size());
    for (std::size_t k = 0; k < largest; ++k) identity_.push_back(static_cast<int>(k));
    if (!nodal_) watched_row_ = basis_.phi.row(p.watched_dof);
    int root = 0;
    for (const ForceElementPtr& e : p.forces) {
        switch_root_.push_back(e->modes() > 1 ? root++ : -1);
        watch_root_.push_back(root);
        root += e->watch_count();
    }
    roots_ = root + 2;
    modes_.assign(p.forces.size(), 0);
    acc_.resize(r_);
}

std::vector<int> ModalSystem::root_directions() const {
    std::vector<int> dir(static_cast<std::size_t>(roots_), 0);
    for (std::size_t e = 0; e < p_.forces.size(); ++e) {
        if (switch_root_[e] >= 0) dir[static_cast<std::size_t>(switch_root_[e])] = 1;
        const std::vector<int> wd = p_.forces[e]->watch_directions();
        for (std::size_t k = 0; k < wd.size(); ++k) dir[static_cast<std::size_t>(watch_root_[e]) + k] = wd[k];
    }
    return dir;
}

double ModalSystem::element_time(double t) const {
    return t < t_limit_ ? t : std::nextafter(t_limit_, -std::numeric_limits<double>::infinity());
}

void ModalSystem::gather_union(const double* y, const double* acc) const {
    // One pass over the union's rows for both (on a full basis of a fine mesh these products are
    // most of a step's work).
    const Eigen::Index u = static_cast<Eigen::Index>(union_dofs_.size());
    uqv_.resize(u, 2);
    if (nodal_) {
        if (acc) ua_.resize(u);
        for (Eigen::Index k = 0; k < u; ++k) {
            const int d = union_dofs_[static_cast<std::size_t>(k)];
            uqv_(k, 0) = y[d];
            uqv_(k, 1) = y[r_ + d];
            if (acc) ua_[k] = acc[d];
        }
        return;
    }
    dual_product(union_rows_, y, y + r_, uqv_.col(0), uqv_.col(1));
    if (acc) ua_.noalias() = union_rows_ * ConstVec(acc, r_);
}

const ElementState& ModalSystem::union_state(int e, double t, bool acc) const {
    return assembler_.gather(element(e), local_[static_cast<std::size_t>(e)], uqv_.col(0).data(), uqv_.col(1).data(),
                             acc ? ua_.data() : nullptr, t);
}

const ElementState& ModalSystem::own_state(int e, double t, const double* y) const {
    if (nodal_) return assembler_.gather(element(e), element(e).dofs(), y, y + r_, nullptr, t);
    const Eigen::MatrixXd& P = rows_[static_cast<std::size_t>(e)];
    own_q_.resize(P.rows());
    own_v_.resize(P.rows());
    own_q_.noalias() = P * ConstVec(y, r_);
    own_v_.noalias() = P * ConstVec(y + r_, r_);
    const std::span<const int> at(identity_.data(), static_cast<std::size_t>(P.rows()));
    return assembler_.gather(element(e), at, own_q_.data(), own_v_.data(), nullptr, t);
}

void ModalSystem::apply_union_forces(Eigen::Map<Eigen::VectorXd>& acc) const {
    if (!nodal_) {
        acc.noalias() += union_rows_.transpose() * uf_;
        return;
    }
    for (std::size_t k = 0; k < union_dofs_.size(); ++k) acc[union_dofs_[k]] += uf_[static_cast<Eigen::Index>(k)];
    nodal_->solve_mass(acc.data());
}

double ModalSystem::add_element_forces(double te, const double* y, Eigen::Map<Eigen::VectorXd>& acc,
                                       double* work, double* film) const {
    double dissipated = 0.0;
    gather_union(y, nullptr);
    uf_.setZero();
    const ReducedState rs{te, y, y + r_};
    for (int e = 0; e < elements(); ++e) {
        const int mode = modes_[static_cast<std::size_t>(e)];
        const ReducedElement* on_basis = reduced_[static_cast<std::size_t>(e)].get();
        double power = 0.0;
        if (on_basis) {
            power = on_basis->add_force_and_power(rs, mode, acc.data());
            if (work) *work += on_basis->input_power(rs, mode);
        } else {
            const ElementState& s = union_state(e, te, false);
            power = assembler_.force_and_power(mode);
            assembler_.scatter_force(1.0, uf_.data());
            if (work) *work += element(e).input_power(s, mode);
        }
        if (element(e).dissipation_kind() != DissipationKind::film) {
            dissipated += power;
        } else if (film) {
            *film += power;
        }
    }
    apply_union_forces(acc);
    return dissipated;
}

void ModalSystem::rhs(double t, const double* y, double* ydot) const {
    const ConstVec eta(y, r_), vel(y + r_, r_);
    Eigen::Map<Eigen::VectorXd>(ydot, r_) = vel;
    Eigen::Map<Eigen::VectorXd> acc(ydot + r_, r_);
    double rayleigh = 0.0;
    if (nodal_) {
        rayleigh = nodal_->linear_force(y, y + r_, acc.data());
    } else {
        acc = -w2_.cwiseProduct(eta) - d_.cwiseProduct(vel);
        rayleigh = vel.dot(d_.cwiseProduct(vel));
    }
    const double te = element_time(t);
    double work = 0.0, film = 0.0;
    const double dissipated = add_element_forces(te, y, acc, &work, &film);
    ydot[rayleigh_index()] = rayleigh;
    ydot[dissipation_index()] = dissipated;
    ydot[work_index()] = work;
    if (films_) ydot[film_dissipation_index()] = film;
    for (std::size_t j = 0; j < contacts_.size(); ++j) {
        const int e = contacts_[j];
        const ForceElement& el = element(e);
        double rate = 0.0;
        if (modes_[static_cast<std::size_t>(e)] == el.contact_mode()) rate = el.contact_force(union_state(e, te, false));
        ydot[impulse_index(static_cast<int>(j))] = rate;
    }
}

void ModalSystem::acceleration(double t, const double* y, Eigen::VectorXd& acc) const {
    acc.resize(r_);
    if (nodal_) {
        static_cast<void>(nodal_->linear_force(y, y + r_, acc.data()));
    } else {
        acc = -w2_.cwiseProduct(ConstVec(y, r_)) - d_.cwiseProduct(ConstVec(y + r_, r_));
    }
    Eigen::Map<Eigen::VectorXd> out(acc.data(), r_);
    static_cast<void>(add_element_forces(element_time(t), y, out, nullptr, nullptr));
}

bool ModalSystem::needs_acceleration(int e) const {
    const ForceElement& el = element(e);
    return el.watch_count() > 0 && el.watch_needs_acceleration(modes_[static_cast<std::size_t>(e)]);
}

bool ModalSystem::watches_need_acceleration() const {
    for (int e = 0; e < elements(); ++e) {
        if (needs_acceleration(e)) return true;
    }
    return false;
}

void ModalSystem::root_functions(double t, const double* y, double* g) const {
    const double te = element_time(t);
    // acceleration() leaves q and v on the union at y; only a is still to project.
    const bool need = watches_need_acceleration();
    if (need) {
        acceleration(t, y, acc_);
        // a only at the DOFs of the elements whose watches read it (a contact's one DOF), not on
        // the whole union: on a full basis that product is O(|U| r).
        ua_.resize(static_cast<Eigen::Index>(union_dofs_.size()));
        for (int e = 0; e < elements(); ++e) {
            if (!needs_acceleration(e)) continue;
            for (int u : local_[static_cast<std::size_t>(e)]) {
                ua_[u] = nodal_ ? acc_[union_dofs_[static_cast<std::size_t>(u)]] : union_rows_.row(u).dot(acc_);
            }
        }
    } else {
        gather_union(y, nullptr);
    }
    for (int e = 0; e < elements(); ++e) {
        const ForceElement& el = element(e);
        const std::size_t ue = static_cast<std::size_t>(e);
        if (switch_root_[ue] < 0 && el.watch_count() == 0) continue;
        if (reduced_[ue]) {
            // No watches: an element on the basis has none (ForceElement::reduced).
            g[switch_root_[ue]] = reduced_[ue]->switching_function(ReducedState{te, y, y + r_}, modes_[ue]);
            continue;
        }
        const ElementState& s = union_state(e, te, need && needs_acceleration(e));
        if (switch_root_[ue] >= 0) g[switch_root_[ue]] = el.switching_function(s, modes_[ue]);
        if (el.watch_count() > 0) el.watch_functions(s, modes_[ue], g + watch_root_[ue]);
    }
    g[extreme_root()] = watched_velocity(y);
    if (contacts_.empty()) {
        g[extreme_root() + 1] = 1.0;
    } else {
        g[extreme_root() + 1] = element(contacts_.front()).contact_point_velocity(union_state(contacts_.front(), te, false));
    }
}

void ModalSystem::tangents(double t, const double* y, std::vector<Eigen::MatrixXd>& dfdq,
                           std::vector<Eigen::MatrixXd>& dfdv, Eigen::MatrixXd* modal_q, Eigen::MatrixXd* modal_v) const {
    const double te = element_time(t);
    dfdq.resize(p_.forces.size());
    dfdv.resize(p_.forces.size());
    gather_union(y, nullptr);
    // Row-major blocks as the elements write them; Eigen's default is column-major.
    using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    RowMajor on_basis_q, on_basis_v;
    for (int e = 0; e < elements(); ++e) {
        const std::size_t ue = static_cast<std::size_t>(e);
        if (reduced_[ue]) {
            if (!modal_q || !modal_v) throw std::logic_error("ModalSystem::tangents: an element on the basis needs the modal sums");
            if (on_basis_q.size() == 0) {
                on_basis_q = RowMajor::Zero(r_, r_);
                on_basis_v = RowMajor::Zero(r_, r_);
            }
            reduced_[ue]->add_tangent(ReducedState{te, y, y + r_}, modes_[ue], on_basis_q.data(), on_basis_v.data());
            dfdq[ue].resize(0, 0);
            dfdv[ue].resize(0, 0);
            continue;
        }
        static_cast<void>(union_state(e, te, false));
        assembler_.tangent(modes_[ue]);
        const Eigen::Index m = static_cast<Eigen::Index>(local_[ue].size());
        dfdq[ue] = Eigen::Map<const RowMajor>(assembler_.dfdq().data(), m, m);
        dfdv[ue] = Eigen::Map<const RowMajor>(assembler_.dfdv().data(), m, m);
    }
    if (modal_q) *modal_q = on_basis_q;
    if (modal_v) *modal_v = on_basis_v;
}

void ModalSystem::fe_tangents(double t, const double* y, Eigen::SparseMatrix<double>& Fq,
                              Eigen::SparseMatrix<double>& Fv) const {
    const double te = element_time(t);
    gather_union(y, nullptr);
    std::vector<Eigen::Triplet<double>> tq, tv;
    for (int e = 0; e < elements(); ++e) {
        const std::size_t ue = static_cast<std::size_t>(e);
        static_cast<void>(union_state(e, te, false));
        assembler_.tangent(modes_[ue]);
        const std::vector<int>& dofs = element(e).dofs();
        const std::size_t m = dofs.size();
        const std::vector<double>& dq = assembler_.dfdq();
        const std::vector<double>& dv = assembler_.dfdv();
        for (std::size_t a = 0; a < m; ++a) {
            for (std::size_t b = 0; b < m; ++b) {
                const double xq = dq[a * m + b], xv = dv[a * m + b];
                if (xq != 0.0) tq.emplace_back(dofs[a], dofs[b], xq);
                if (xv != 0.0) tv.emplace_back(dofs[a], dofs[b], xv);
            }
        }
    }
    Fq.resize(p_.size(), p_.size());
    Fv.resize(p_.size(), p_.size());
    Fq.setFromTriplets(tq.begin(), tq.end());
    Fv.setFromTriplets(tv.begin(), tv.end());
}

double ModalSystem::switching_function(int e, int mode, double t, const double* y) const {
    return element(e).switching_function(own_state(e, element_time(t), y), mode);
}

ContactReading ModalSystem::reading(int e, double t, const double* y) const {
    return element(e).contact_reading(own_state(e, element_time(t), y));
}

double ModalSystem::resistance(int e, double t, const double* y) const {
    return element(e).contact_resistance(own_state(e, element_time(t), y));
}

RunEnd ModalSystem::run_end(int e, double t, const double* y) const {
    return element(e).run_end(own_state(e, element_time(t), y));
}

double ModalSystem::stored_energy(int e, int mode, double t, const double* y) const {
    return element(e).stored_energy(own_state(e, element_time(t), y), mode);
}

double ModalSystem::dissipated_power(int e, int mode, double t, const double* y) const {
    return element(e).dissipated_power(own_state(e, element_time(t), y), mode);
}

double ModalSystem::watched(const double* y) const {
    return nodal_ ? y[p_.watched_dof] : watched_row_.dot(ConstVec(y, r_));
}

double ModalSystem::watched_velocity(const double* y) const {
    return nodal_ ? y[r_ + p_.watched_dof] : watched_row_.dot(ConstVec(y + r_, r_));
}

double ModalSystem::contact_displacement(int j, const double* y) const {
    if (nodal_) return y[element(contacts_[static_cast<std::size_t>(j)]).dofs().front()];
    const Eigen::MatrixXd& P = rows_[static_cast<std::size_t>(contacts_[static_cast<std::size_t>(j)])];
    return P.row(0).dot(ConstVec(y, r_));
}

std::vector<int> ModalSystem::initial_modes(const double* y) const {
    std::vector<int> modes(p_.forces.size(), 0);
    for (int e = 0; e < elements(); ++e) {
        const ForceElement& el = element(e);
        const std::size_t ue = static_cast<std::size_t>(e);
        const int start = el.initial_mode(own_state(e, 0.0, y));
        modes[ue] = p_.modes0.size() == p_.forces.size() ? p_.modes0[ue] : start;
        // A contact touching at t = 0 (d = 0 to roundoff) and moving in closes at once, as the exact
        // solver's event search closes it: CVODE holds a root function that is zero at the start
        // inactive, and would let the beam pass into the support (tests/cases/starts_in_contact.toml).
        if (el.is_contact() && start == el.contact_mode()) modes[ue] = start;
        // A state the model no longer holds at t = 0 (the beam already within an electrode's
        // collapse gap) ends the run at once.
        if (el.ends_run(start)) modes[ue] = start;
    }
    return modes;
}

EnergyLedger ModalSystem::energy(double t, const double* y, double jump) const {
    const ConstVec eta(y, r_), vel(y + r_, r_);
    EnergyLedger e;
    e.kinetic = nodal_ ? nodal_->kinetic(y + r_) : 0.5 * vel.squaredNorm();
    e.strain = nodal_ ? nodal_->strain(y) : 0.5 * eta.dot(w2_.cwiseProduct(eta));
    for (int k = 0; k < elements(); ++k) {
        const double stored = stored_energy(k, modes_[static_cast<std::size_t>(k)], t, y);
        switch (element(k).stored_energy_kind()) {
            case StoredEnergyKind::contact_spring: e.contact_spring += stored; break;
            case StoredEnergyKind::electrical: e.electrical += stored; break;
            case StoredEnergyKind::strain: e.strain += stored; break;
        }
    }
    e.rayleigh_dissipated = y[rayleigh_index()];
    e.contact_dissipated = y[dissipation_index()] + jump;
    if (films_) e.film_dissipated = y[film_dissipation_index()];
    e.external_work = y[work_index()];
    return e;
}

Eigen::VectorXd ModalSystem::initial_state() const {
    Eigen::VectorXd y = Eigen::VectorXd::Zero(size());
    if (nodal_) {
        y.head(r_) = p_.q0;
        y.segment(r_, r_) = p_.v0;
        return y;
    }
    y.head(r_) = basis_.phi.transpose() * (p_.M * p_.q0);
    y.segment(r_, r_) = basis_.phi.transpose() * (p_.M * p_.v0);
    return y;
}

double ModalSystem::initial_projection_error() const {
    if (basis_.full) return 0.0;
    const double size = p_.q0.norm();
    if (!(size > 0.0)) return 0.0;
    const Eigen::VectorXd eta = basis_.phi.transpose() * (p_.M * p_.q0);
    return (p_.q0 - basis_.phi * eta).norm() / size;
}

// Characteristic magnitudes (absolute tolerance = atol_scale times these):
//  - w1: the lowest basis frequency;
//  - length L: the largest of max|q0|, max|v0| / w1, each contact's penetration at q = 0 (its gap
//    or prestress) and the static deflection under each prescribed force (force_scale times the
//    flexibility sum_k phi_dk^2 / w_k^2 at its DOFs, (K^-1)_dd on a nodal basis);
//  - modal displacement: L / phi_ref, phi_ref the largest |phi| of the first five vectors at the
//    watched point and the elements' DOFs (a unit of eta moves those points by about phi_ref), or
//    |eta0_k| where larger;
//  - modal velocity: w1 times that, or |eta0'_k| where larger (one scale for every vector: weighting
//    the fast ones by their own w_k, an energy norm, saves a third of the steps at equal accuracy
//    on the paper's transient, not enough to give up the simpler rule);
//  - on a nodal basis, DOF i's displacement max(|q0_i|, L) and velocity max(|v0_i|, w1 max(|q0_i|, L)):
//    the physical scales a modal vector's tolerance is mapped from below;
//  - energies: the larger of the initial mechanical energy and 1/2 (w1 L / phi_ref)^2 (the five
//    lowest modes give w1 and phi_ref on a nodal basis);
//  - impulse of contact j: its force scale (|df/dq| L + |df/dv| w1 L, from its tangent in the
//    contact mode) over w1.
ModalSystem::ToleranceScales ModalSystem::tolerance_scales() const {
    ToleranceScales sc;
    ModeSet low;  // on a nodal basis: the five lowest modes, a modal basis's first vectors
    if (nodal_) low = lowest_modes(p_.K, p_.M, std::min(r_, 5));
    const Eigen::VectorXd& omega = nodal_ ? low.omega : basis_.omega;
    // The lowest nonzero frequency; a body held only by its contacts has none, and then the
    // contact's own frequency is the scale (its stiffness over the modal mass at its DOF).
    for (Eigen::Index k = 0; k < omega.size(); ++k) {
        if (omega[k] > 0.0) {
            sc.w1 = omega[k];
            break;
        }
    }
    if (!(sc.w1 > 0.0)) {
        for (int e : contacts_) {
            const ForceElement& el = element(e);
            assembler_.gather_rest(el);
            assembler_.tangent(el.contact_mode());
            const double flex = rows_[static_cast<std::size_t>(e)].row(0).squaredNorm();
            sc.w1 = std::max(sc.w1, std::sqrt(std::abs(assembler_.dfdq()[0]) * flex));
        }
        if (!(sc.w1 > 0.0)) sc.w1 = 1.0;
    }
    const Eigen::MatrixXd& phi = nodal_ ? low.shapes : basis_.phi;
    const Eigen::Index first = std::min<Eigen::Index>(phi.cols(), 5);
    const auto largest_row = [&](int dof) { return phi.row(dof).head(first).cwiseAbs().maxCoeff(); };
    double L = std::max(p_.q0.cwiseAbs().maxCoeff(), p_.v0.cwiseAbs().maxCoeff() / sc.w1);
    double phi_ref = largest_row(p_.watched_dof);
    for (int e = 0; e < elements(); ++e) {
        const ForceElement& el = element(e);
        for (int d : el.dofs()) phi_ref = std::max(phi_ref, largest_row(d));
        if (el.is_contact()) L = std::max(L, std::abs(el.contact_reading(assembler_.gather_rest(el)).penetration));
        if (el.force_scale() > 0.0) {
            double flex = 0.0;  // rigid-body vectors (w = 0) have no static deflection to add
            for (std::size_t i = 0; i < el.dofs().size(); ++i) {
                double sum = 0.0;
                if (nodal_) {
                    sum = nodal_->flexibility(el.dofs()[i]);
                } else {
                    const Eigen::MatrixXd& P = rows_[static_cast<std::size_t>(e)];
                    for (int k = 0; k < r_; ++k) {
                        const Eigen::Index ik = static_cast<Eigen::Index>(i);
                        if (w2_[k] > 0.0) sum += P(ik, k) * P(ik, k) / w2_[k];
                    }
                }
                flex = std::max(flex, sum);
            }
            L = std::max(L, el.force_scale() * flex);
        }
    }
    sc.L = L > 0.0 ? L : 1e-9;  // nothing moves; any small scale will do
    sc.phi_ref = phi_ref > 0.0 ? phi_ref : 1.0;
    return sc;
}

Eigen::VectorXd ModalSystem::absolute_tolerances(double atol_scale) const {
    const Eigen::VectorXd y0 = initial_state();
    const ToleranceScales sc = tolerance_scales();
    const double w1 = sc.w1, L = sc.L;
    const double eta_L = L / sc.phi_ref;

    Eigen::VectorXd scale(size());
    // Each vector's tolerance is the one its error would meet in the physical DOFs: the RMS over the
    // DOFs of phi_ik / s_i, s_i = max(|q0_i|, L) (rotations too: a fast vector bends the element
    // ends, and it is their rotation that keeps its error small). A nodal basis has the s_i
    // themselves.
    const Eigen::VectorXd s_phys = p_.q0.cwiseAbs().cwiseMax(L);
    const double n = static_cast<double>(p_.size());
    double e0 = 0.0;
    if (nodal_) {
        scale.head(r_) = s_phys;
        scale.segment(r_, r_) = p_.v0.cwiseAbs().cwiseMax(w1 * s_phys);
        e0 = nodal_->kinetic(y0.data() + r_) + nodal_->strain(y0.data());
    } else {
        for (int k = 0; k < r_; ++k) {
            const double rms = std::sqrt(basis_.phi.col(k).cwiseQuotient(s_phys).squaredNorm() / n);
            const double eta_k = rms > 0.0 ? 1.0 / rms : eta_L;
            scale[k] = std::max(std::abs(y0[k]), eta_k);
            scale[r_ + k] = std::max(std::abs(y0[r_ + k]), w1 * eta_k);
        }
        e0 = 0.5 * y0.segment(r_, r_).squaredNorm() + 0.5 * y0.head(r_).dot(w2_.cwiseProduct(y0.head(r_)));
    }
    const double energy = std::max(e0, 0.5 * (w1 * eta_L) * (w1 * eta_L));
    scale[rayleigh_index()] = energy;
    scale[dissipation_index()] = energy;
    scale[work_index()] = energy;
    if (films_) scale[film_dissipation_index()] = energy;
    for (std::size_t j = 0; j < contacts_.size(); ++j) {
        const int e = contacts_[j];
        const ForceElement& el = element(e);
        assembler_.gather_rest(el);
        assembler_.tangent(el.contact_mode());
        double kq = 0.0, kv = 0.0;
        for (double x : assembler_.dfdq()) kq = std::max(kq, std::abs(x));
        for (double x : assembler_.dfdv()) kv = std::max(kv, std::abs(x));
        const double f = kq * L + kv * w1 * L;
        scale[impulse_index(static_cast<int>(j))] = f > 0.0 ? f / w1 : energy / (w1 * L);
    }
    return atol_scale * scale;
}

void validate(const TransientProblem& p) {
    const int n = p.size();
    auto bad = [](const std::string& what) { throw std::invalid_argument("solve_cvode: " + what); };
    if (n <= 0 || p.M.cols() != n || p.K.rows() != n || p.K.cols() != n) bad("M and K must be n x n, n > 0");
    if (p.q0.size() != n || p.v0.size() != n) bad("q0 and v0 must have one entry per DOF");
    if (!p.q0.allFinite() || !p.v0.allFinite()) bad("non-finite initial state");
    if (!p.modes0.empty() && p.modes0.size() != p.forces.size()) bad("modes0 must have one entry per force element");
    for (const ForceElementPtr& e : p.forces) {
        for (int d : e->dofs()) {
            if (d < 0 || d >= n) bad(e->name() + ": DOF out of range");
        }
    }
    if (p.watched_dof < 0 || p.watched_dof >= n) bad("watched_dof out of range");
    if (!(p.t_end > 0.0) || !std::isfinite(p.t_end)) bad("t_end must be positive");
    if (!std::isfinite(p.output_step)) bad("output_step must be finite");
}

}  // namespace vi::cvode_detail
