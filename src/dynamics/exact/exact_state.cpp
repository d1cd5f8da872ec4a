#include "dynamics/exact/exact_state.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "dynamics/exact/exact_give_up.hpp"
#include "dynamics/exact/state_memo.hpp"
#include "dynamics/signal/exp_sincos.hpp"
#include "model/run_control.hpp"

namespace vi {
namespace {

Eigen::VectorXd contact_row(const BaseModes& b, const ContactElement& c) { return b.phi.row(c.dof).transpose(); }

}  // namespace

ExpSignal derivative_signal(const ExpSignal& f) {
    ExpSignal d;
    d.lambda = f.lambda;
    d.A = f.A.cwiseProduct(*f.lambda);
    for (const ExpTerm& t : f.terms) {
        if (t.power == 0) {
            if (t.s != cd(0.0)) d.terms.push_back({t.coef * t.s, t.s, 0});
        } else {
            d.terms.push_back({t.coef, t.s, 0});
            if (t.s != cd(0.0)) d.terms.push_back({t.coef * t.s, t.s, 1});
        }
    }
    return d;
}

void negate(ExpSignal& f) {
    f.A = -f.A;
    for (ExpTerm& t : f.terms) t.coef = -t.coef;
}

// ---------------------------------------------------------------------------------------------

namespace {

template <class M>
std::size_t matrix_bytes(const M& a) {
    return static_cast<std::size_t>(a.size()) * sizeof(typename M::Scalar);
}

// The heap a decomposed state holds (its matrices; the small vectors are left out).
std::size_t state_bytes(const StateData& sd) {
    return matrix_bytes(sd.modes.vl) + matrix_bytes(sd.contact_v) + matrix_bytes(sd.contact_vel) +
           matrix_bytes(sd.load_vel) + matrix_bytes(sd.full.R) + matrix_bytes(sd.full.L) +
           matrix_bytes(sd.full_contact_vel) + matrix_bytes(sd.cauchy) + matrix_bytes(sd.rayleigh_w) +
           matrix_bytes(sd.rayleigh_wc) + sizeof(double) * sd.rayleigh_tail.size() * (1 + sd.contact_tail.size());
}

}  // namespace

ExactModel::ExactModel(const PiecewiseLinearProblem& p, bool energy, std::size_t cache_bytes)
    : p_(&p), energy_(energy), base_(base_modes(p)), memo_(&StateMemo::for_model(base_, p, energy)), cache_limit_(cache_bytes) {}

Eigen::VectorXd ExactModel::initial_state(const Eigen::VectorXd& q0, const Eigen::VectorXd& v0) const {
    Eigen::VectorXd x(2 * base_.n);
    x.head(base_.n) = base_.phi.transpose() * (p_->M * q0);
    x.tail(base_.n) = base_.phi.transpose() * (p_->M * v0);
    return x;
}

std::shared_ptr<const StateData> ExactModel::decompose(const std::vector<bool>& active) const {
    auto sd = std::make_shared<StateData>();
    // A new contact state of a fine mesh is seconds of linear algebra: the stop flag is watched
    // between its stages (and between column blocks of the largest product).
    check_run();
    sd->modes = decompose_state(base_, *p_, active);
    check_run();
    const StateModes& md = sd->modes;
    const int n = base_.n, m = md.size();
    const Eigen::VectorXcd& lam = md.lambda;
    sd->weight.resize(m);
    for (int k = 0; k < m; ++k) sd->weight[k] = md.paired[static_cast<std::size_t>(k)] ? 2.0 : 1.0;
    const int nc = static_cast<int>(p_->contacts.size());
    sd->contact_v.resize(nc, m);
    sd->contact_vel.resize(nc, m);
    for (int c = 0; c < nc; ++c) {
        const Eigen::VectorXcd v = md.project(contact_row(base_, p_->contacts[static_cast<std::size_t>(c)]));
        sd->contact_v.row(c) = v.transpose();
        sd->contact_vel.row(c) = v.cwiseProduct(lam).transpose();
    }
    const int tip = p_->watched_dof >= 0 ? p_->watched_dof : 0;
    const Eigen::VectorXcd tv = md.project(base_.phi.row(tip).transpose());
    sd->watched_v = tv.transpose();
    sd->watched_vel = tv.cwiseProduct(lam).transpose();
    sd->load_vel.resize(static_cast<Eigen::Index>(p_->loads.size()), m);
    for (std::size_t l = 0; l < p_->loads.size(); ++l) {
        const Eigen::VectorXcd v = md.project(base_.phi.transpose() * p_->loads[l].shape);
        sd->load_vel.row(static_cast<Eigen::Index>(l)) = v.cwiseProduct(lam).transpose();
    }
    if (energy_) {
        sd->full = expand(md);
        check_run();
        const Eigen::MatrixXcd& R = sd->full.R;
        const Eigen::VectorXcd& fl = sd->full.lambda;
        sd->full_contact_vel.resize(nc, 2 * n);
        for (int c = 0; c < nc; ++c) {
            const Eigen::RowVectorXcd row = contact_row(base_, p_->contacts[static_cast<std::size_t>(c)]).transpose().cast<cd>();
            sd->full_contact_vel.row(c) = row * R.bottomRows(n);
        }
        const double scale = fl.cwiseAbs().maxCoeff();
        sd->cauchy.resize(2 * n, 2 * n);
        for (int k = 0; k < 2 * n; ++k) {
            for (int l = 0; l < 2 * n; ++l) {
                const cd mu = fl[k] + fl[l];
                // mu = 0 only pairs an undamped mode with its conjugate; such a mode dissipates nothing.
                sd->cauchy(k, l) = std::abs(mu) > 1e-14 * scale ? 1.0 / mu : cd(0.0);
            }
        }
        const Eigen::VectorXd d = 2.0 * base_.zeta.cwiseProduct(base_.omega);
        const Eigen::MatrixXcd rv = R.bottomRows(n);
        const Eigen::MatrixXcd drv = d.cast<cd>().asDiagonal() * rv;
        sd->rayleigh_w.resize(2 * n, 2 * n);
        for (int c0 = 0; c0 < 2 * n; c0 += 64) {
            const int w = std::min(64, 2 * n - c0);
            sd->rayleigh_w.middleCols(c0, w).noalias() = rv.transpose() * drv.middleCols(c0, w);
            check_run();
        }
        sd->rayleigh_wc = sd->rayleigh_w.cwiseProduct(sd->cauchy);
        // What each mode's term alone could still dissipate per unit squared amplitude (exact_energy).
        auto tail = [&](int k, double weight) {
            const double decay = -fl[k].real();
            return decay > 1e-12 * std::abs(fl[k]) ? weight / (2.0 * decay) : std::numeric_limits<double>::infinity();
        };
        sd->rayleigh_tail.resize(static_cast<std::size_t>(2 * n));
        for (int k = 0; k < 2 * n; ++k) sd->rayleigh_tail[static_cast<std::size_t>(k)] = tail(k, d.dot(rv.col(k).cwiseAbs2()));
        sd->contact_tail.assign(static_cast<std::size_t>(nc), std::vector<double>(static_cast<std::size_t>(2 * n)));
        for (int c = 0; c < nc; ++c) {
            for (int k = 0; k < 2 * n; ++k) {
                sd->contact_tail[static_cast<std::size_t>(c)][static_cast<std::size_t>(k)] = tail(k, std::norm(sd->full_contact_vel(c, k)));
            }
        }
    }
    return sd;
}

ExactModel::Cached& ExactModel::cached(const std::vector<bool>& active) {
    auto it = cache_.find(active);
    if (it != cache_.end()) {
        it->second.last_use = ++uses_;
        return it->second;
    }
    const auto t0 = std::chrono::steady_clock::now();
    const StateMemoKey key = state_memo_key(*p_, active);
    const bool closed = std::find(active.begin(), active.end(), true) != active.end();
    std::shared_ptr<const StateData> sd;
    if (!(closed && GiveUpOnClosedStatesForTest::active())) sd = memo_->find(key);
    const bool decomposed = sd == nullptr;
    if (decomposed) sd = decompose(active);
    const std::size_t bytes = state_bytes(*sd);
    if (decomposed) memo_->keep(key, sd, bytes, cache_limit_);
    // Bounded memory: a long chatter over many supports meets new states for ever. The state in
    // use by the caller's previous piece may go too: that piece is replaced before it is read again.
    while (!cache_.empty() && cache_bytes_ + bytes > cache_limit_) {
        auto lru = std::min_element(cache_.begin(), cache_.end(),
                                    [](const auto& a, const auto& b) { return a.second.last_use < b.second.last_use; });
        cache_bytes_ -= lru->second.bytes;
        cache_.erase(lru);
    }
    cache_bytes_ += bytes;
    // A state taken from the memo counts as decomposed: the count says how many states this run
    // needed, the same whichever runs came before on the thread.
    ++decompositions_;
    auto [pos, inserted] = cache_.emplace(active, Cached{std::move(sd), bytes, ++uses_, {}});
    (void)inserted;
    decomposition_s_ += seconds_since(t0);
    return pos->second;
}

const PieceSolution& ExactModel::piece(const std::vector<bool>& active, const Eigen::VectorXd& x0, double t0,
                                       double t1) {
    Cached& c = cached(active);
    piece_ = std::make_unique<PieceSolution>(*p_, base_, *c.data, active, x0, t0, t1, energy_, &c.forcing);
    return *piece_;
}

// ---------------------------------------------------------------------------------------------

PieceSolution::PieceSolution(const PiecewiseLinearProblem& p, const BaseModes& b, const StateData& s,
                             const std::vector<bool>& active, const Eigen::VectorXd& x0, double t0, double t1,
                             bool energy, ForcingMemo* memo)
    : p_(&p), b_(&b), s_(&s), active_(active) {
    particular_solution(x0, t0, t1, energy, memo);
    const std::size_t nc = p.contacts.size();
    for (std::size_t c = 0; c < nc; ++c) {
        const ContactElement& ce = p.contacts[c];
        const Eigen::Index ci = static_cast<Eigen::Index>(c);
        const ExpSignal v = channel(s.contact_v.row(ci), 1.0, 0.0);
        ExpSignal vel = channel(s.contact_vel.row(ci), 1.0, 0.0);
        // d = sign (surface - v); F = Kc d + Cc dd/dt = Kc d - sign Cc v'.
        ExpSignal d = channel(s.contact_v.row(ci), -ce.sign, ce.sign * ce.surface);
        ExpSignal F = channel(s.contact_v.row(ci), -ce.sign * ce.stiffness, ce.sign * ce.stiffness * ce.surface);
        const ExpSignal fv = channel(s.contact_vel.row(ci), -ce.sign * ce.damping, 0.0);
        F.A += fv.A;
        F.terms.insert(F.terms.end(), fv.terms.begin(), fv.terms.end());
        ExpSignal ev = active[c] ? F : d;
        if (active[c]) negate(ev);
        // Open but penetrated beyond roundoff: only a positive F can close it again.
        const double d0 = d.value(0.0);
        const bool release = !active[c] && d0 > 64.0 * std::numeric_limits<double>::epsilon() * d.bound(0.0, 0.0, 0);
        if (release) ev = F;
        ExpSignal rel = d;
        negate(rel);
        release_.push_back(release);
        release_fn_.push_back(std::move(rel));
        v_.push_back(v);
        vel_.push_back(std::move(vel));
        pen_.push_back(std::move(d));
        force_.push_back(std::move(F));
        event_.push_back(std::move(ev));
    }
    watched_v_ = channel(s.watched_v, 1.0, 0.0);
    watched_vel_ = channel(s.watched_vel, 1.0, 0.0);
    if (energy) {
        const double tm = 0.5 * (t0 + t1);
        for (std::size_t l = 0; l < p.loads.size(); ++l) {
            load_vel_.push_back(channel(s.load_vel.row(static_cast<Eigen::Index>(l)), p.loads[l].amplitude, 0.0));
            // g(t0 + tau) as a terms-only signal.
            ExpSignal g;
            g.lambda = &s.modes.lambda;
            const TimeFunction& tf = p.loads[l].time;
            if (tf.kind == TimeFunction::Kind::harmonic) {
                const double w = 2.0 * std::numbers::pi * tf.frequency_hz;
                const cd k1 = std::exp(cd(0.0, w * t0 + tf.phase)) / cd(0.0, 2.0);
                g.terms.push_back({k1, cd(0.0, w), 0});
                g.terms.push_back({std::conj(k1), cd(0.0, -w), 0});
                g.terms.push_back({tf.offset, 0.0, 0});
            } else if (tf.kind == TimeFunction::Kind::table) {
                const double g1 = t1 > t0 ? (tf(t1) - tf(t0)) / (t1 - t0) : 0.0;
                g.terms.push_back({tf(tm) - g1 * (tm - t0), 0.0, 0});
                g.terms.push_back({g1, 0.0, 1});
            } else {
                g.terms.push_back({tf(tm), 0.0, 0});
            }
            load_time_.push_back(std::move(g));
        }
    }
}

namespace {

bool same_forcing(const std::vector<ForcingTerm>& a, const std::vector<ForcingTerm>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i].s != b[i].s || a[i].power != b[i].power || a[i].C.size() != b[i].C.size() || a[i].C != b[i].C) return false;
    }
    return true;
}

// Forcing in x coordinates on [t0, t1]: constant part (closed contacts' surfaces and constant loads),
// ramps, and the exponentials of harmonic loads. The set of terms is closed under conjugation (the
// forcing is real), which is what lets the representatives stand for their conjugates.
std::vector<ForcingTerm> forcing_terms(const PiecewiseLinearProblem& p, const BaseModes& b, const std::vector<bool>& active,
                                       double t0, double t1) {
    const int n = b.n;
    Eigen::VectorXd f_const = Eigen::VectorXd::Zero(2 * n);
    Eigen::VectorXd f_ramp = Eigen::VectorXd::Zero(2 * n);
    for (std::size_t c = 0; c < p.contacts.size(); ++c) {
        if (!active[c]) continue;
        const ContactElement& ce = p.contacts[c];
        f_const.tail(n) += contact_row(b, ce) * (ce.stiffness * ce.surface);
    }
    std::vector<ForcingTerm> raw;
    const double tm = 0.5 * (t0 + t1);
    for (std::size_t l = 0; l < p.loads.size(); ++l) {
        const LoadTerm& ld = p.loads[l];
        const Eigen::VectorXd modal = b.phi.transpose() * ld.shape;
        Eigen::VectorXd fx = Eigen::VectorXd::Zero(2 * n);
        fx.tail(n) = modal * ld.amplitude;
        // g on [t0, t1]: g(t0 + tau) = g0 + g1 tau (+ harmonic part).
        double g0 = 0.0, g1 = 0.0;
        switch (ld.time.kind) {
            case TimeFunction::Kind::constant:
            case TimeFunction::Kind::step: g0 = ld.time(tm); break;
            case TimeFunction::Kind::table: {
                g1 = t1 > t0 ? (ld.time(t1) - ld.time(t0)) / (t1 - t0) : 0.0;
                g0 = ld.time(tm) - g1 * (tm - t0);
                break;
            }
            case TimeFunction::Kind::harmonic: {
                g0 = ld.time.offset;
                const double w = 2.0 * std::numbers::pi * ld.time.frequency_hz;
                const double th = w * t0 + ld.time.phase;
                const cd k1 = std::exp(cd(0.0, th)) / cd(0.0, 2.0);
                raw.push_back({fx.cast<cd>() * k1, cd(0.0, w), 0});
                raw.push_back({fx.cast<cd>() * std::conj(k1), cd(0.0, -w), 0});
                break;
            }
        }
        f_const += g0 * fx;
        f_ramp += g1 * fx;
    }
    if (f_const.squaredNorm() > 0.0) raw.push_back({f_const.cast<cd>(), cd(0.0), 0});
    if (f_ramp.squaredNorm() > 0.0) raw.push_back({f_ramp.cast<cd>(), cd(0.0), 1});
    return raw;
}

// Per mode k of a state, c' = lambda c + G exp(s tau) (tau^p) has a particular solution in closed
// form: c1 = G / (s - lambda) (power 0), or c1 tau + c0 with c0 = -c1 / (s - lambda) (power 1).
// Appends the terms and returns their sum at tau = 0.
template <class Left>
Eigen::VectorXcd particular_terms(const std::vector<ForcingTerm>& raw, const Eigen::VectorXcd& lam, Left&& left,
                                  std::vector<ForcingTerm>& terms) {
    const double lscale = lam.cwiseAbs().maxCoeff();
    Eigen::VectorXcd p0 = Eigen::VectorXcd::Zero(lam.size());
    for (const ForcingTerm& r : raw) {
        const Eigen::VectorXcd G = left(r.C);
        Eigen::VectorXcd c1(lam.size());
        for (Eigen::Index k = 0; k < lam.size(); ++k) {
            const cd gap = r.s - lam[k];
            if (std::abs(gap) <= 1e-13 * lscale) {
                throw std::runtime_error("transient: a load excites an undamped mode exactly at resonance");
            }
            c1[k] = G[k] / gap;
        }
        if (r.power == 0) {
            terms.push_back({c1, r.s, 0});
            p0 += c1;
        } else {
            const Eigen::VectorXcd c0 = -c1.cwiseQuotient((Eigen::VectorXcd::Constant(lam.size(), r.s) - lam));
            terms.push_back({c1, r.s, 1});
            terms.push_back({c0, r.s, 0});
            p0 += c0;
        }
    }
    return p0;
}

}  // namespace

// The forcing's particular solution, the homogeneous amplitudes from x0, and (constant forcing) the
// energy of the motion about the equilibrium; the state's memo spares the first when the forcing is
// the one of its last piece.
void PieceSolution::particular_solution(const Eigen::VectorXd& x0, double t0, double t1, bool energy, ForcingMemo* memo) {
    const BaseModes& b = *b_;
    std::vector<ForcingTerm> raw = forcing_terms(*p_, b, active_, t0, t1);
    const StateModes& md = s_->modes;
    const auto left = [&](const Eigen::VectorXcd& F) { return md.coordinates(F); };
    ForcingMemo local;
    ForcingMemo& fm = memo ? *memo : local;
    if (!(fm.valid && same_forcing(fm.forcing, raw))) {
        fm.valid = false;
        fm.terms.clear();
        fm.p0 = particular_terms(raw, md.lambda, left, fm.terms);
        fm.forcing = raw;
        fm.equilibrium.resize(0);
        fm.valid = true;
    }
    terms_ = fm.terms;
    a_ = md.coordinates(x0) - fm.p0;
    bool constant_forcing = true;
    for (const ForcingTerm& r : raw) constant_forcing = constant_forcing && r.s == cd(0.0) && r.power == 0;
    if (constant_forcing) {
        // x0 minus the equilibrium (the particular solution is that constant); in [eta; eta'].
        if (fm.equilibrium.size() == 0) fm.equilibrium = md.state(fm.p0);
        const Eigen::VectorXd xh = x0 - fm.equilibrium;
        const int nb = b.n;
        motion_energy_ = 0.5 * xh.tail(nb).squaredNorm() + 0.5 * xh.head(nb).cwiseProduct(b.omega).squaredNorm();
    }
    if (energy) {
        const FullModes& full = s_->full;
        const Eigen::VectorXcd pf = particular_terms(raw, full.lambda, [&](const Eigen::VectorXcd& F) { return Eigen::VectorXcd(full.L * F); },
                                                     terms_full_);
        a_full_ = full.L * x0.cast<cd>() - pf;
    }
}

// A real output row^T eta (or eta_dot) per representative; a paired mode carries its conjugate's
// share too: Re(z) + Re(conj z) = 2 Re(z).
ExpSignal PieceSolution::channel(const Eigen::RowVectorXcd& row, double scale, double offset) const {
    ExpSignal f;
    f.lambda = &s_->modes.lambda;
    const Eigen::VectorXcd wrow = scale * row.transpose().cwiseProduct(s_->weight.cast<cd>());
    f.A = wrow.cwiseProduct(a_);
    for (const Term& t : terms_) f.terms.push_back({wrow.cwiseProduct(t.C).sum(), t.s, t.power});
    if (offset != 0.0) f.terms.push_back({offset, 0.0, 0});
    return f;
}

Eigen::VectorXcd PieceSolution::exponentials(double tau) const {
    Eigen::VectorXcd e(s_->modes.lambda.size());
    exponentials_into(tau, nullptr, e);
    return e;
}

void PieceSolution::exponentials_into(double tau, const std::vector<int>* modes, Eigen::VectorXcd& e) const {
    const Eigen::VectorXcd& lam = s_->modes.lambda;
    const std::size_t n = modes ? modes->size() : static_cast<std::size_t>(lam.size());
    const int* idx = modes ? modes->data() : nullptr;
    auto mode = [idx](std::size_t i) { return static_cast<Eigen::Index>(idx ? idx[i] : static_cast<int>(i)); };
    if (tau == 0.0) {
        for (std::size_t i = 0; i < n; ++i) e[mode(i)] = 1.0;
        return;
    }
    // In the scans' vectorised pass (the same values they use: each lane rounds alike), and 0 below
    // exp(-707) as fast_exp.
    thread_local std::vector<double> scratch;
    if (scratch.size() < 5 * n) scratch.resize(5 * n);
    double* x = scratch.data();
    double* y = x + n;
    for (std::size_t i = 0; i < n; ++i) {
        x[i] = lam[mode(i)].real() * tau;
        y[i] = lam[mode(i)].imag() * tau;
    }
    double* ex = y + n;
    double* co = ex + n;
    double* si = co + n;
    exp_sincos(x, y, ex, co, si, static_cast<int>(n));
    for (std::size_t i = 0; i < n; ++i) {
        const double g = x[i] < -707.0 ? 0.0 : ex[i];
        e[mode(i)] = cd(g * co[i], g * si[i]);
    }
}

Eigen::VectorXcd PieceSolution::full_exponentials(const Eigen::VectorXcd& e) const {
    // The conjugate modes follow the representatives in expand()'s order: their exponentials are
    // the conjugates.
    const std::vector<bool>& paired = s_->modes.paired;
    Eigen::VectorXcd f(s_->full.lambda.size());
    f.head(e.size()) = e;
    Eigen::Index j = e.size();
    for (Eigen::Index k = 0; k < e.size(); ++k) {
        if (paired[static_cast<std::size_t>(k)]) f[j++] = std::conj(e[k]);
    }
    return f;
}

Eigen::VectorXcd PieceSolution::coords_at(double tau, const Eigen::VectorXcd& e) const {
    Eigen::VectorXcd c = a_.cwiseProduct(e);
    for (const Term& t : terms_) c += t.C * (fast_exp(t.s, tau) * (t.power == 1 ? tau : 1.0));
    return c;
}

Eigen::VectorXd PieceSolution::state_at(double tau) const { return s_->modes.state(coords_at(tau, exponentials(tau))); }

Eigen::VectorXd PieceSolution::state_at(double tau, const Eigen::VectorXcd& e) const {
    return s_->modes.state(coords_at(tau, e));
}

const Eigen::VectorXcd& PieceSolution::sample_exponentials(double tau, double t_abs, bool all_modes) const {
    const double dt = tau - sample_tau_;
    // Sample times are k times the output step: their differences are exact to a few ulps of t_abs.
    const bool same_step = sample_tau_ >= 0.0 && dt > 0.0 &&
                           std::abs(dt - sample_dt_) <= 8.0 * std::numeric_limits<double>::epsilon() * t_abs;
    if (same_step && sample_run_ < kSampleAnchor) {
        for (int k : sample_live_) sample_e_[k] *= sample_step_[k];
        ++sample_run_;
    } else {
        const Eigen::Index m = s_->modes.lambda.size();
        if (sample_decaying_ < 0) sample_decaying_ = s_->modes.lambda.real().maxCoeff() <= 0.0 ? 1 : 0;
        // After the piece's first sample, a mode found dead stays dead (|exp(lambda tau)| does not
        // grow when no exponent has a positive real part): only the live ones are formed and tested.
        const bool narrowed = !all_modes && sample_tau_ >= 0.0 && sample_decaying_ == 1;
        if (sample_tau_ >= 0.0 && dt > 0.0 && !same_step) {
            sample_dt_ = dt;
            if (narrowed) {
                if (sample_step_.size() != m) sample_step_.setOnes(m);
                exponentials_into(dt, &sample_live_, sample_step_);
            } else {
                sample_step_ = exponentials(dt);
            }
        }
        if (narrowed) {
            exponentials_into(tau, &sample_live_, sample_e_);
        } else {
            sample_e_ = exponentials(tau);
        }
        sample_run_ = 0;
        select_live_modes(all_modes, narrowed);
    }
    sample_tau_ = tau;
    return sample_e_;
}

void PieceSolution::select_live_modes(bool all_modes, bool narrowed) const {
    const Eigen::Index m = sample_e_.size();
    if (all_modes) {
        sample_live_.clear();
        for (Eigen::Index k = 0; k < m; ++k) sample_live_.push_back(static_cast<int>(k));
        return;
    }
    if (sample_weight_.size() != m) {
        // Squared magnitudes (no hypot): only compared with a threshold far below roundoff.
        sample_weight_ = watched_v_.A.cwiseAbs2().cwiseMax(watched_vel_.A.cwiseAbs2());
        for (std::size_t c = 0; c < v_.size(); ++c) {
            sample_weight_ = sample_weight_.cwiseMax(v_[c].A.cwiseAbs2())
                                 .cwiseMax(vel_[c].A.cwiseAbs2())
                                 .cwiseMax(force_[c].A.cwiseAbs2());
        }
        const double floor = 1e-18 * sample_weight_.cwiseSqrt().sum();
        sample_floor2_ = floor * floor;
    }
    auto live = [&](int k) { return sample_weight_[k] * std::norm(sample_e_[k]) > sample_floor2_; };
    if (narrowed) {
        std::erase_if(sample_live_, [&](int k) { return !live(k); });
        return;
    }
    sample_live_.clear();
    for (Eigen::Index k = 0; k < m; ++k) {
        if (live(static_cast<int>(k))) sample_live_.push_back(static_cast<int>(k));
    }
}

namespace {

// acc[j] += Re(A_jk e_k) over the live modes k, from the packed amplitudes (per mode: the channels'
// Re A, then Im A). NF > 0: that many channels, summed in registers; NF = 0: nf of them in memory.
template <std::size_t NF>
void accumulate_channels(const double* pack, const double* ep, const std::vector<int>& live, double* acc,
                         std::size_t nf = NF) {
    if constexpr (NF > 0) {
        double sum[NF] = {};
        for (int k : live) {
            const double er = ep[2 * k], ei = ep[2 * k + 1];
            const double* ar = pack + 2 * NF * static_cast<std::size_t>(k);
            const double* ai = ar + NF;
            for (std::size_t j = 0; j < NF; ++j) sum[j] += ar[j] * er - ai[j] * ei;
        }
        for (std::size_t j = 0; j < NF; ++j) acc[j] = sum[j];
    } else {
        for (int k : live) {
            const double er = ep[2 * k], ei = ep[2 * k + 1];
            const double* ar = pack + 2 * nf * static_cast<std::size_t>(k);
            const double* ai = ar + nf;
            for (std::size_t j = 0; j < nf; ++j) acc[j] += ar[j] * er - ai[j] * ei;
        }
    }
}

}  // namespace

void PieceSolution::pack_channels(const std::vector<const ExpSignal*>& fs) const {
    if (sample_pack_of_ == fs) return;
    const std::size_t nf = fs.size();
    const std::size_t m = static_cast<std::size_t>(sample_e_.size());
    // The channels' amplitudes per mode side by side (real parts, then imaginary), once per piece
    // (every entry written: no zeroing first).
    sample_pack_.resize(static_cast<Eigen::Index>(2 * nf * m));
    double* pack = sample_pack_.data();
    for (std::size_t k = 0; k < m; ++k) {
        for (std::size_t j = 0; j < nf; ++j) {
            const cd a = fs[j]->A[static_cast<Eigen::Index>(k)];
            pack[2 * nf * k + j] = a.real();
            pack[2 * nf * k + nf + j] = a.imag();
        }
    }
    sample_pack_of_ = fs;
}

void PieceSolution::sampled_channels(const std::vector<bool>& active, std::vector<const ExpSignal*>& out,
                                     std::vector<int>& force_at) const {
    out.assign({&watched_v_, &watched_vel_});
    force_at.assign(v_.size(), -1);
    for (std::size_t c = 0; c < v_.size(); ++c) {
        out.push_back(&v_[c]);
        out.push_back(&vel_[c]);
        // An open contact's force is recorded as 0: its channel is not summed.
        if (c < active.size() && active[c]) {
            force_at[c] = static_cast<int>(out.size());
            out.push_back(&force_[c]);
        }
    }
}

void PieceSolution::sampled_values(const std::vector<const ExpSignal*>& fs, double tau, std::vector<double>& out) const {
    const std::size_t nf = fs.size();
    pack_channels(fs);
    // All channels in one pass over the live modes, real parts only: Re sum A_k e_k summed in the
    // same order as the complex sum, the same value to the last bit.
    out.assign(nf, 0.0);
    const double* ep = reinterpret_cast<const double*>(sample_e_.data());
    const double* pack = sample_pack_.data();
    switch (nf) {  // a fixed count keeps the sums in registers (one or two contacts, open or closed)
        case 4: accumulate_channels<4>(pack, ep, sample_live_, out.data()); break;
        case 5: accumulate_channels<5>(pack, ep, sample_live_, out.data()); break;
        case 6: accumulate_channels<6>(pack, ep, sample_live_, out.data()); break;
        case 7: accumulate_channels<7>(pack, ep, sample_live_, out.data()); break;
        case 8: accumulate_channels<8>(pack, ep, sample_live_, out.data()); break;
        default: accumulate_channels<0>(pack, ep, sample_live_, out.data(), nf); break;
    }
    for (std::size_t j = 0; j < nf; ++j) {
        for (const ExpTerm& t : fs[j]->terms) out[j] += term_derivative(t, tau, 0).real();
    }
}

void PieceSolution::sample(double tau, double t_abs, const std::vector<bool>& active, TimeHistory& h, bool energy,
                           const EnergyLedger& start) const {
    const std::size_t nc = p_->contacts.size();
    if (h.contact_v.size() != nc) {
        h.contact_v.resize(nc);
        h.contact_velocity.resize(nc);
        h.contact_force.resize(nc);
    }
    // One set of exponentials serves every channel, the state and the energy terms.
    const Eigen::VectorXcd& e = sample_exponentials(tau, t_abs, energy);
    thread_local std::vector<const ExpSignal*> channels;
    thread_local std::vector<int> force_at;
    thread_local std::vector<double> values;
    sampled_channels(active, channels, force_at);
    sampled_values(channels, tau, values);
    record_sample(h, t_abs, force_at, [&](int j) { return values[static_cast<std::size_t>(j)]; });
    if (energy) h.energy.push_back(energy_at(tau, start, e));
}

}  // namespace vi
