#include "dynamics/exact/secular.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vi {
namespace {

// A relative correction below this ends the iteration of a root: the convergence is cubic, so the
// next one would be below roundoff, and the corrections of roots in clusters stall near 1e-15.
constexpr double kSettled = 1e-14;

// Newton correction P / P' of P(z) = prod_i q_i(z) g(z), q_i = z^2 + c_i z + k_i, the monic polynomial
// whose roots are the eigenvalues: one division per mode, and no division by the gap between a
// mode's poles (which vanishes at critical damping). q_i is evaluated as (z - a_i)(z - b_i): near the
// cluster of slow overdamped poles (all close to -1/beta) z^2 + c z + k would cancel 7 digits.
cd newton_ratio(const std::vector<SecularMode>& modes, double kc, double cc, cd z) {
    cd S = 0.0, Sp = 0.0, log_deriv = 0.0;
    for (const SecularMode& m : modes) {
        const cd da = z - m.pole_a, db = z - m.pole_b;
        const cd iq = 1.0 / (da * db);
        const cd qp = da + db;
        const cd t = m.s * iq;
        S += t;
        Sp -= t * qp * iq;
        log_deriv += qp * iq;
    }
    const cd g = 1.0 + (kc + cc * z) * S;
    if (g == 0.0) return 0.0;  // z is a root to the last bit
    const cd gp = cc * S + (kc + cc * z) * Sp;
    return 1.0 / (log_deriv + gp / g);
}

// The same at a real x, in real arithmetic (most roots are real: the overdamped modes' poles).
double newton_ratio(const std::vector<SecularMode>& modes, double kc, double cc, double x) {
    double S = 0.0, Sp = 0.0, log_deriv = 0.0;
    for (const SecularMode& m : modes) {
        double q = 0.0, qp = 0.0;
        if (m.pole_a.imag() != 0.0) {
            const double d = x - m.pole_a.real();
            q = d * d + m.pole_a.imag() * m.pole_a.imag();
            qp = 2.0 * d;
        } else {
            const double da = x - m.pole_a.real(), db = x - m.pole_b.real();
            q = da * db;
            qp = da + db;
        }
        const double iq = 1.0 / q;
        const double t = m.s * iq;
        S += t;
        Sp -= t * qp * iq;
        log_deriv += qp * iq;
    }
    const double g = 1.0 + (kc + cc * x) * S;
    if (g == 0.0) return 0.0;
    const double gp = cc * S + (kc + cc * x) * Sp;
    return 1.0 / (log_deriv + gp / g);
}

// The Aberth correction of real root x among the representatives (a pair w adds 2 Re 1/(x - w)).
double real_step(const std::vector<SecularMode>& modes, double kc, double cc, const ConjugateRoots& r, std::size_t k) {
    const double x = r.z[k].real();
    const double ratio = newton_ratio(modes, kc, cc, x);
    double repel = 0.0;
    for (std::size_t j = 0; j < r.z.size(); ++j) {
        if (j == k) continue;
        const double d = x - r.z[j].real();
        if (r.paired[j]) {
            repel += 2.0 * d / (d * d + r.z[j].imag() * r.z[j].imag());
        } else {
            repel += 1.0 / d;
        }
    }
    return ratio / (1.0 - ratio * repel);
}

// First-order start of the root that grows out of free pole p (its partner pole q): p - rho with
// rho the residue of g at p, held within half of |p| (beyond that the expansion means nothing).
cd start_near(const SecularMode& m, cd p, cd q, double kc, double cc) {
    cd rho = m.s * (kc + cc * p) / (q - p);
    const double cap = 0.5 * std::abs(p);
    if (std::abs(rho) > cap && cap > 0.0) rho *= cap / std::abs(rho);
    return p - rho;
}

// Aberth-Ehrlich on a conjugation-closed set held by its representatives: real roots stay real and
// each pair moves as one, so the result is exactly symmetric. Fails (false) when a pair would have
// to split into two real roots or two reals would have to merge into a pair.
bool symmetric_aberth(const std::vector<SecularMode>& modes, double kc, double cc, ConjugateRoots& r) {
    const std::size_t m = r.z.size();
    std::vector<bool> done(m, false);
    for (int it = 0; it < 100; ++it) {
        double worst = 0.0;
        for (std::size_t k = 0; k < m; ++k) {
            if (done[k]) continue;
            const cd z = r.z[k];
            cd step = 0.0;
            if (r.paired[k]) {
                const cd ratio = newton_ratio(modes, kc, cc, z);
                cd repel = 1.0 / (z - std::conj(z));
                for (std::size_t j = 0; j < m; ++j) {
                    if (j == k) continue;
                    repel += 1.0 / (z - r.z[j]);
                    if (r.paired[j]) repel += 1.0 / (z - std::conj(r.z[j]));
                }
                step = ratio / (1.0 - ratio * repel);
            } else {
                step = real_step(modes, kc, cc, r, k);
            }
            cd next = z - step;
            if (!std::isfinite(next.real()) || !std::isfinite(next.imag())) return false;
            if (!r.paired[k]) {
                next = cd(next.real(), 0.0);
            } else if (!(next.imag() > 0.0)) {
                // The pair crossed the real axis on its way: its mirror is as good an estimate. A pair
                // that should be two real roots keeps crossing and never converges (then: fallback).
                next = cd(next.real(), std::max(-next.imag(), 1e-3 * std::abs(next)));
            }
            r.z[k] = next;
            const double rel = std::sqrt(std::norm(step) / std::max(std::norm(next), std::numeric_limits<double>::min()));
            // A root whose last correction was below kSettled of its size is not moved again: most
            // roots (weakly coupled modes) settle in a few sweeps, and each sweep costs O(m) per root.
            if (rel < kSettled) done[k] = true;
            worst = std::max(worst, rel);
        }
        if (worst < kSettled) return true;
    }
    return false;
}

// Plain Aberth-Ehrlich on all 2m roots from starts pushed off the real axis, then paired: a root is
// real when its own mirror is nearer than any other root's mirror.
bool general_aberth(const std::vector<SecularMode>& modes, double kc, double cc, ConjugateRoots& out) {
    std::vector<cd> z;
    for (const SecularMode& m : modes) {
        z.push_back(start_near(m, m.pole_a, m.pole_b, kc, cc) + cd(0.0, 1e-9) * std::abs(m.pole_a));
        z.push_back(start_near(m, m.pole_b, m.pole_a, kc, cc) + cd(0.0, 1e-9) * std::abs(m.pole_b));
    }
    const std::size_t n = z.size();
    std::vector<bool> done(n, false);
    bool converged = false;
    for (int it = 0; it < 200 && !converged; ++it) {
        double worst = 0.0;
        for (std::size_t k = 0; k < n; ++k) {
            if (done[k]) continue;
            const cd ratio = newton_ratio(modes, kc, cc, z[k]);
            cd repel = 0.0;
            for (std::size_t j = 0; j < n; ++j) {
                if (j != k) repel += 1.0 / (z[k] - z[j]);
            }
            const cd step = ratio / (1.0 - ratio * repel);
            z[k] -= step;
            if (!std::isfinite(z[k].real()) || !std::isfinite(z[k].imag())) return false;
            const double rel = std::sqrt(std::norm(step) / std::max(std::norm(z[k]), std::numeric_limits<double>::min()));
            if (rel < kSettled) done[k] = true;
            worst = std::max(worst, rel);
        }
        converged = worst < kSettled;
    }
    if (!converged) return false;
    std::vector<int> partner(n, -1);
    for (std::size_t k = 0; k < n; ++k) {
        double best = 2.0 * std::abs(z[k].imag());
        int who = static_cast<int>(k);
        for (std::size_t j = 0; j < n; ++j) {
            const double d = std::abs(z[j] - std::conj(z[k]));
            if (j != k && d < best) {
                best = d;
                who = static_cast<int>(j);
            }
        }
        partner[k] = who;
    }
    out.z.clear();
    out.paired.clear();
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t p = static_cast<std::size_t>(partner[k]);
        if (partner[p] != static_cast<int>(k)) return false;
        if (p == k) {
            out.z.emplace_back(z[k].real(), 0.0);
            out.paired.push_back(false);
        } else if (z[k].imag() > z[p].imag()) {
            out.z.push_back(0.5 * (z[k] + std::conj(z[p])));
            out.paired.push_back(true);
        }
    }
    return true;
}

}  // namespace

bool secular_roots(const std::vector<SecularMode>& modes, double kc, double cc, ConjugateRoots& out) {
    out.z.clear();
    out.paired.clear();
    for (const SecularMode& m : modes) {
        if (m.pole_a.imag() != 0.0) {
            const cd p = m.pole_a.imag() > 0.0 ? m.pole_a : m.pole_b;
            const cd q = std::conj(p);
            cd z = start_near(m, p, q, kc, cc);
            if (!(z.imag() > 0.0)) z = cd(z.real(), 0.5 * p.imag());
            out.z.push_back(z);
            out.paired.push_back(true);
        } else {
            out.z.emplace_back(start_near(m, m.pole_a, m.pole_b, kc, cc).real(), 0.0);
            out.z.emplace_back(start_near(m, m.pole_b, m.pole_a, kc, cc).real(), 0.0);
            out.paired.push_back(false);
            out.paired.push_back(false);
        }
    }
    if (!symmetric_aberth(modes, kc, cc, out) && !general_aberth(modes, kc, cc, out)) return false;
    std::size_t count = 0;
    for (bool p : out.paired) count += p ? 2 : 1;
    if (count != 2 * modes.size()) return false;
    const bool undamped = cc == 0.0 && std::all_of(modes.begin(), modes.end(), [](const SecularMode& m) { return m.c == 0.0; });
    if (undamped) {
        // g depends on z^2 only: every root is +-i w with w real (K~ positive definite).
        for (std::size_t k = 0; k < out.z.size(); ++k) {
            if (!out.paired[k]) return false;
            out.z[k] = cd(0.0, out.z[k].imag());
        }
    }
    return true;
}

}  // namespace vi
