#include "impacts/settled_stop.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <exception>
#include <vector>

#include "dynamics/piecewise_linear_form.hpp"
#include "impacts/impact_summary.hpp"
#include "impacts/simulation.hpp"

namespace vi {
namespace {

// A bound must clear the value it protects by this much, so that roundoff in the solver's own
// maxima cannot make a later one count.
constexpr double kMargin = 1e-6;

struct SettleBounds {
    ImpactSettings settings;
    int impacts = 3;
    double watched_compliance = 0.0;           // (K^-1)_ww [m/N]
    std::vector<double> contact_compliance;    // (K^-1)_cc per contact [m/N]
    std::vector<double> contact_penetration;   // penetration at the free equilibrium (q = 0) [m]
};

// Each of the first n impacts has a later one of its own support: no episode can join it.
bool first_impacts_closed(const std::vector<Impact>& impacts, int n) {
    if (static_cast<int>(impacts.size()) < n) return false;
    for (int i = 0; i < n; ++i) {
        bool later = false;
        for (std::size_t j = static_cast<std::size_t>(i) + 1; j < impacts.size() && !later; ++j) {
            later = impacts[j].support == impacts[static_cast<std::size_t>(i)].support;
        }
        if (!later) return false;
    }
    return true;
}

bool settled(const SettleBounds& k, const RunSoFar& r) {
    if (!r.all_open || !(r.motion_energy >= 0.0) || !r.extremes.valid || r.episodes.empty()) return false;
    const double two_e = 2.0 * r.motion_energy;
    const double w = std::sqrt(two_e * k.watched_compliance) * (1.0 + kMargin);
    if (!(w < r.extremes.watched_max && -w > r.extremes.watched_min)) return false;
    const double c0 = std::sqrt(two_e * k.contact_compliance.front()) * (1.0 + kMargin);
    if (!(c0 < r.extremes.contact_max)) return false;
    double deepest = 0.0;  // deepest penetration any later impact can reach
    for (std::size_t c = 0; c < k.contact_compliance.size(); ++c) {
        deepest = std::max(deepest, k.contact_penetration[c] + std::sqrt(two_e * k.contact_compliance[c]) * (1.0 + kMargin));
    }
    // The first impact's peak is at most the deepest episode's: a cheap test before grouping.
    double peak = 0.0;
    for (const ContactEpisode& e : r.episodes) peak = std::max(peak, e.peak_penetration);
    if (deepest > k.settings.settle_tolerance * peak) return false;
    TransientResult so_far;
    so_far.episodes = r.episodes;
    so_far.extremes = r.extremes;
    const ImpactSummary s = summarize_impacts(so_far, k.settings);
    if (s.Tp_reason != "settled" || !first_impacts_closed(s.impacts, k.impacts)) return false;
    return deepest <= k.settings.settle_tolerance * s.impacts.front().peak_penetration;
}

}  // namespace

std::function<bool(const RunSoFar&)> settled_stop(const Case& c, const BuiltProblem& b, int impacts) {
    if (c.solver.settle_rule == SolverSettings::SettleRule::velocity || b.problem.watched_dof < 0) return {};
    PiecewiseLinearProblem p;
    try {
        p = piecewise_linear_form(b.problem);
    } catch (const std::exception&) {
        return {};  // an element that is not a Kelvin-Voigt support: no energy bound
    }
    if (!p.loads.empty() || p.contacts.empty()) return {};
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(b.problem.K);
    if (ldlt.info() != Eigen::Success) return {};
    const auto compliance = [&](int dof) {
        Eigen::VectorXd e = Eigen::VectorXd::Zero(b.problem.size());
        e[dof] = 1.0;
        return ldlt.solve(e)[dof];
    };
    SettleBounds k;
    k.settings = impact_settings(c, b);
    k.impacts = impacts;
    k.watched_compliance = compliance(p.watched_dof);
    for (const ContactElement& e : p.contacts) {
        k.contact_compliance.push_back(compliance(e.dof));
        k.contact_penetration.push_back(e.sign * e.surface);
    }
    for (double x : k.contact_compliance) {
        if (!(x > 0.0)) return {};  // K not positive definite: no bound
    }
    if (!(k.watched_compliance > 0.0)) return {};
    return [k](const RunSoFar& r) { return settled(k, r); };
}

}  // namespace vi
