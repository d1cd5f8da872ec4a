#pragma once
// Pieces of the exact solution: one contact state from one initial state, as modal exponentials.

#include <Eigen/Dense>
#include <map>
#include <memory>
#include <vector>

#include "dynamics/exact/state_memo.hpp"
#include "dynamics/signal/exp_signal.hpp"
#include "dynamics/exact/state_modes.hpp"
#include "dynamics/piecewise_linear_problem.hpp"
#include "dynamics/transient_result.hpp"

namespace vi {

// Per contact state: its decomposition and everything derived from it once. Outputs are read per
// representative mode (m of them); the energy ledger works on all 2n modes written out.
struct StateData {
    StateModes modes;
    Eigen::VectorXd weight;         // 2 for a mode standing for a conjugate pair, else 1
    Eigen::MatrixXcd contact_v;     // nc x m: v at each contact point per mode
    Eigen::MatrixXcd contact_vel;   // nc x m
    Eigen::RowVectorXcd watched_v, watched_vel;
    Eigen::MatrixXcd load_vel;      // loads x m: shape^T q_dot per mode
    // Energy ledger only (2n modes):
    FullModes full;
    Eigen::MatrixXcd full_contact_vel;  // nc x 2n
    Eigen::MatrixXcd cauchy;        // 1 / (lambda_k + lambda_l), 0 where that sum vanishes
    Eigen::MatrixXcd rayleigh_w;    // Rv^T diag(2 zeta omega) Rv
    Eigen::MatrixXcd rayleigh_wc;   // rayleigh_w .* cauchy
    // Per mode, the dissipation its term alone could still do from a sample on, per unit squared
    // amplitude: |Rv_k|_D^2 / (2 |Re lambda_k|), and |g_k|^2 / (2 |Re lambda_k|) for each contact's
    // velocity row g (infinite for an undamped mode).
    std::vector<double> rayleigh_tail;
    std::vector<std::vector<double>> contact_tail;
};

// A term G exp(s tau) tau^power of a forcing or of a particular solution (G in state coordinates or
// per mode).
struct ForcingTerm {
    Eigen::VectorXcd C;
    cd s;
    int power;
};

// The forcing of a state's last piece and what follows from it alone: its particular terms per mode
// and, for a constant forcing, the equilibrium in x coordinates. The pieces of a state whose forcing
// is unchanged (contact surfaces, constant loads) take them instead of solving again.
struct ForcingMemo {
    std::vector<ForcingTerm> forcing;  // x coordinates
    std::vector<ForcingTerm> terms;    // per representative mode
    Eigen::VectorXcd p0;               // the particular solution at tau = 0
    Eigen::VectorXd equilibrium;       // x at p0 (empty until a constant forcing asks for it)
    bool valid = false;
};

// The solution from x0 at t0 in one state with the loads of [t0, t1]: c(tau) = a exp(lambda tau) + P(tau).
class PieceSolution {
public:
    // memo: the state's forcing memo (null: none).
    PieceSolution(const PiecewiseLinearProblem& p, const BaseModes& b, const StateData& s, const std::vector<bool>& active,
                  const Eigen::VectorXd& x0, double t0, double t1, bool energy, ForcingMemo* memo = nullptr);
    // Penetration d (open contact) or -F (closed one): its upward zero crossing is the next event.
    [[nodiscard]] const ExpSignal& event_function(int c) const { return event_[static_cast<std::size_t>(c)]; }
    // An open contact still inside its support (d > 0 after a damped separation) waits for F to turn
    // positive instead of d; the crossing of this release function (-d) ends that wait.
    [[nodiscard]] bool waits_for_release(int c) const { return release_[static_cast<std::size_t>(c)]; }
    [[nodiscard]] const ExpSignal& release_function(int c) const { return release_fn_[static_cast<std::size_t>(c)]; }
    [[nodiscard]] const ExpSignal& contact_force(int c) const { return force_[static_cast<std::size_t>(c)]; }
    [[nodiscard]] const ExpSignal& penetration(int c) const { return pen_[static_cast<std::size_t>(c)]; }
    [[nodiscard]] const ExpSignal& contact_velocity(int c) const { return vel_[static_cast<std::size_t>(c)]; }
    [[nodiscard]] const ExpSignal& watched_displacement() const { return watched_v_; }
    [[nodiscard]] const ExpSignal& contact_displacement(int c) const { return v_[static_cast<std::size_t>(c)]; }
    [[nodiscard]] Eigen::VectorXd state_at(double tau) const;
    // The representatives' exponentials at tau (exp_sincos: within 4 ulps, 0 below exp(-707)), and the
    // state from them (the same as state_at(tau)).
    [[nodiscard]] Eigen::VectorXcd exponentials(double tau) const;
    [[nodiscard]] Eigen::VectorXd state_at(double tau, const Eigen::VectorXcd& e) const;
    // With a constant forcing (no load ramps or harmonics in the piece), the mechanical energy of the
    // motion about the piece's own equilibrium at its start [J]: what is left to move; -1 otherwise.
    [[nodiscard]] double motion_energy() const { return motion_energy_; }
    // Energy terms at tau, with `start` the ledger's integrals at the start of the piece.
    [[nodiscard]] EnergyLedger energy_at(double tau, const EnergyLedger& start) const;
    // Adds the dissipated energies and external work of [0, tau] to the ledger.
    void accumulate_dissipation(double tau, EnergyLedger& ledger) const;
    void sample(double tau, double t_abs, const std::vector<bool>& active, TimeHistory& h, bool energy,
                const EnergyLedger& start) const;
    // sample() at count samples in time order (tau[i] in the piece, t_abs[i] absolute), without the
    // energy ledger: the same values to the last bit, each run of samples that follow an anchor
    // by the recurrence computed together (dynamics/exact/piece_samples.cpp).
    void sample_many(const double* tau, const double* t_abs, int count, const std::vector<bool>& active,
                     TimeHistory& h) const;

private:
    using Term = ForcingTerm;
    ExpSignal channel(const Eigen::RowVectorXcd& row, double scale, double offset) const;
    // All 2n modes' exponentials from the representatives' (the conjugates are conjugate).
    [[nodiscard]] Eigen::VectorXcd full_exponentials(const Eigen::VectorXcd& e) const;
    [[nodiscard]] Eigen::VectorXcd coords_at(double tau, const Eigen::VectorXcd& e) const;
    // With e the representatives' exponentials at tau:
    [[nodiscard]] EnergyLedger energy_at(double tau, const EnergyLedger& start, const Eigen::VectorXcd& e) const;
    void accumulate_dissipation(double tau, const Eigen::VectorXcd& e, EnergyLedger& ledger) const;
    // Integral over [0, tau] of c^T W c for the Rayleigh W, and of kappa (g^T c)^2 for a contact damper.
    [[nodiscard]] double rayleigh_integral(double tau, const Eigen::VectorXcd& ef) const;
    [[nodiscard]] double damper_integral(std::size_t c, double tau, const Eigen::VectorXcd& ef) const;
    void prepare_energy() const;  // the piece's constant parts of the dissipation integrals

    void particular_solution(const Eigen::VectorXd& x0, double t0, double t1, bool energy, ForcingMemo* memo);

    const PiecewiseLinearProblem* p_;
    const BaseModes* b_;
    const StateData* s_;
    std::vector<bool> active_;
    Eigen::VectorXcd a_;          // homogeneous amplitudes of the representatives
    double motion_energy_ = -1.0;
    std::vector<Term> terms_;     // particular terms of the representatives
    Eigen::VectorXcd a_full_;     // the same over all 2n modes (energy ledger only)
    std::vector<Term> terms_full_;
    std::vector<ExpSignal> event_, force_, pen_, v_, vel_, release_fn_;
    std::vector<bool> release_;
    ExpSignal watched_v_, watched_vel_;
    std::vector<ExpSignal> load_vel_, load_time_;
    // Samples at an even step: the exponentials at tau + dt are those at tau times exp(lambda dt), one
    // complex product per mode instead of an exp and a sincos (sample()). Anchored afresh from the
    // exact exponentials every kSampleAnchor samples, so the recurrence's rounding (a few ulps per
    // product) never grows past about 1e-14 of a term.
    static constexpr int kSampleAnchor = 64;
    // Without the energy ledger, only the modes still alive in some sampled channel are carried: at
    // each anchor, those whose largest channel amplitude times |exp(lambda tau)| is above 1e-18 of
    // the channels' summed amplitudes (a heavily damped mode soon after a switch is not), compared
    // in squares.
    [[nodiscard]] const Eigen::VectorXcd& sample_exponentials(double tau, double t_abs, bool all_modes) const;
    // exponentials(tau) into e for the listed modes only (all when `modes` is null); the others untouched.
    void exponentials_into(double tau, const std::vector<int>* modes, Eigen::VectorXcd& e) const;
    // sample_live_ at an anchor: every mode, or those above the threshold (narrowed: of those live so far).
    void select_live_modes(bool all_modes, bool narrowed) const;
    // The channels fs at the sample tau (after sample_exponentials), into out; the same channels at
    // every sample of the piece.
    void sampled_values(const std::vector<const ExpSignal*>& fs, double tau, std::vector<double>& out) const;
    // The sampled channels (watched v and velocity, then per contact v, velocity and, if `active`
    // closes it, F at index force_at[c]; -1 for an open one), and their amplitudes packed per mode
    // (sample_pack_) once per piece.
    void sampled_channels(const std::vector<bool>& active, std::vector<const ExpSignal*>& out,
                          std::vector<int>& force_at) const;
    void pack_channels(const std::vector<const ExpSignal*>& fs) const;
    mutable double sample_tau_ = -1.0, sample_dt_ = -1.0;
    mutable int sample_run_ = 0;
    mutable Eigen::VectorXcd sample_e_, sample_step_;
    mutable Eigen::VectorXd sample_weight_;  // per mode: the largest |A_k|^2 of the sampled channels
    mutable double sample_floor2_ = 0.0;     // (1e-18 of the sum of the largest |A_k|)^2
    mutable Eigen::VectorXd sample_pack_;  // per mode: the sampled channels' Re A_k, then Im A_k
    mutable std::vector<const ExpSignal*> sample_pack_of_;  // the channels packed there
    mutable std::vector<int> sample_live_;
    mutable int sample_decaying_ = -1;  // 1: no exponent with a positive real part; -1: not yet known
    mutable bool energy_ready_ = false;
    mutable cd a_wc_a_;                        // a^T (W .* cauchy) a
    mutable std::vector<Eigen::VectorXcd> wC_; // W C_m per particular term
    mutable Eigen::MatrixXcd CwC_;             // C_m^T W C_l
    mutable std::vector<cd> alpha_c_alpha_;    // per contact: alpha^T cauchy alpha, alpha = g .* a
    mutable std::vector<std::vector<cd>> gC_;  // per contact: g^T C_m
};

// Appends one sample at t to h: the watched point's v and velocity, then per contact v, velocity and
// F (0 when force_at[c] < 0: open), reading the sampled channels in that order through value(j).
template <class Value>
void record_sample(TimeHistory& h, double t, const std::vector<int>& force_at, const Value& value) {
    h.t.push_back(t);
    h.watched_v.push_back(value(0));
    h.watched_velocity.push_back(value(1));
    int j = 2;
    for (std::size_t c = 0; c < force_at.size(); ++c) {
        h.contact_v[c].push_back(value(j++));
        h.contact_velocity[c].push_back(value(j++));
        h.contact_force[c].push_back(force_at[c] >= 0 ? value(j++) : 0.0);
    }
}

// The model shared by all pieces: base modes and a cache of decomposed contact states.
class ExactModel {
public:
    // Decomposed states are kept for reuse up to cache_bytes (ExactOptions::state_cache_bytes).
    ExactModel(const PiecewiseLinearProblem& p, bool energy, std::size_t cache_bytes);
    [[nodiscard]] const BaseModes& base() const { return base_; }
    // x = [Phi^T M q0; Phi^T M v0].
    [[nodiscard]] Eigen::VectorXd initial_state(const Eigen::VectorXd& q0, const Eigen::VectorXd& v0) const;
    // Builds the piece (decomposing its state on first use); valid until the next call.
    const PieceSolution& piece(const std::vector<bool>& active, const Eigen::VectorXd& x0, double t0, double t1);
    // Contact states decomposed so far (a state evicted and decomposed again counts twice; one taken
    // from this thread's memo of earlier runs counts too).
    [[nodiscard]] int decompositions() const { return decompositions_; }

    // Wall time spent decomposing states and deriving their per-state data [s].
    [[nodiscard]] double decomposition_seconds() const { return decomposition_s_; }

private:
    [[nodiscard]] std::shared_ptr<const StateData> decompose(const std::vector<bool>& active) const;
    const PiecewiseLinearProblem* p_;
    bool energy_;
    BaseModes base_;
    StateMemo* memo_;  // this thread's states of earlier runs of the same model
    struct Cached {
        std::shared_ptr<const StateData> data;
        std::size_t bytes = 0;
        long last_use = 0;
        ForcingMemo forcing;
    };
    Cached& cached(const std::vector<bool>& active);
    std::map<std::vector<bool>, Cached> cache_;
    std::size_t cache_limit_;
    std::size_t cache_bytes_ = 0;
    long uses_ = 0;
    std::unique_ptr<PieceSolution> piece_;
    double decomposition_s_ = 0.0;
    int decompositions_ = 0;
};

// f' as a signal of the same piece.
ExpSignal derivative_signal(const ExpSignal& f);
// f -> -f.
void negate(ExpSignal& f);

}  // namespace vi
