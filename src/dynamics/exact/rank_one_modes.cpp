#include "dynamics/exact/rank_one_modes.hpp"

#include <algorithm>
#include <cmath>

#include "dynamics/exact/secular.hpp"

namespace vi {
namespace {

// prod num / prod den without overflow (the factors span ~1e-3 to 1e13 1/s): each product keeps
// a separate power of two.
cd product_ratio(const std::vector<cd>& num, const std::vector<cd>& den) {
    auto product = [](const std::vector<cd>& f, int& exponent) {
        cd prod = 1.0;
        exponent = 0;
        for (const cd x : f) {
            prod *= x;
            const double size = std::max(std::abs(prod.real()), std::abs(prod.imag()));
            if (size > 0x1p500 || size < 0x1p-500) {
                int e = 0;
                std::frexp(size, &e);
                prod = cd(std::ldexp(prod.real(), -e), std::ldexp(prod.imag(), -e));
                exponent += e;
            }
        }
        return prod;
    };
    int en = 0, ed = 0;
    const cd q = product(num, en) / product(den, ed);
    return cd(std::ldexp(q.real(), en - ed), std::ldexp(q.imag(), en - ed));
}

}  // namespace

// Right vectors v = (z^2 + z C + Omega^2)^-1 phi_c on the modes the contact couples (z a root of the
// secular equation; modes with a node at the contact keep their free poles and unit vectors). Left
// vectors in the free diagonal coordinates y are w_j / (z - p_j) / N for the poles p_j; with the
// residues rho_j = u_j w_j of the original problem, computed roots inside a cluster of poles (the
// slow poles of the overdamped modes all lie near -1/beta) would make them lose biorthogonality.
// The residues are instead recomputed from the roots, rho_j = prod_k (p_j - z_k) / prod_l (p_j - p_l)
// (Loewner; Gu & Eisenstat 1994): the roots are then exact for this rank-one problem, L R = I holds
// to roundoff, and the right vectors (which only need u) stay those of the original problem. How far
// the residues moved is the decomposition's backward error, and is checked.
bool rank_one_roots(const BaseModes& b, const ContactElement& ce, RankOneRoots& r) {
    const int n = b.n;
    const Eigen::VectorXd phi = b.phi.row(ce.dof).transpose();
    const double kc = ce.stiffness, cc = ce.damping;
    // Residues of g at a mode's poles, rho_a = -phi^2 (kc + cc a) / (b - a) and likewise at b: the
    // first-order shifts of the poles. A mode counts as uncoupled when they are below 1e-15 of the
    // largest, or each below 1e-14 of its own pole (a node at the contact, or a shift under roundoff
    // of the pole: a root would coincide with the pole in floating point).
    auto residue = [&](int i, cd p, cd q) { return -phi[i] * phi[i] * (kc + cc * p) / (q - p); };
    std::vector<double> shift(static_cast<std::size_t>(n));
    double scale = 0.0;
    for (int i = 0; i < n; ++i) {
        const std::size_t iu = static_cast<std::size_t>(i);
        shift[iu] = std::max(std::abs(residue(i, b.pole_a[i], b.pole_b[i])), std::abs(residue(i, b.pole_b[i], b.pole_a[i])));
        scale = std::max(scale, shift[iu]);
    }
    std::vector<SecularMode>& modes = r.modes;
    std::vector<int>& coupled = r.coupled;
    std::vector<RankOneRoots::Candidate>& cand = r.cand;
    modes.clear();
    coupled.clear();
    cand.clear();
    for (int i = 0; i < n; ++i) {
        const cd a = b.pole_a[i], bb = b.pole_b[i];
        const bool visible = std::abs(residue(i, a, bb)) > 1e-14 * std::abs(a) || std::abs(residue(i, bb, a)) > 1e-14 * std::abs(bb);
        if (shift[static_cast<std::size_t>(i)] > 1e-15 * scale && visible) {
            modes.push_back({phi[i] * phi[i], 2.0 * (b.zeta[i] * b.omega[i]), b.omega[i] * b.omega[i], a, bb});
            coupled.push_back(i);
        } else {
            const bool pair = a.imag() != 0.0;
            cand.push_back({a, pair, i, bb});
            if (!pair) cand.push_back({bb, false, i, a});
        }
    }
    ConjugateRoots roots;
    if (!secular_roots(modes, kc, cc, roots)) return false;
    // Every root and pole written out (conjugates included), in matching order so that each factor
    // of the products stays near 1.
    std::vector<cd> zall;
    std::vector<cd>& pall = r.pall;
    pall.clear();
    for (std::size_t k = 0; k < roots.z.size(); ++k) {
        zall.push_back(roots.z[k]);
        if (roots.paired[k]) zall.push_back(std::conj(roots.z[k]));
        cand.push_back({roots.z[k], roots.paired[k], -1, 0.0});
    }
    for (const SecularMode& md : modes) {
        pall.push_back(md.pole_a);
        pall.push_back(md.pole_b);
    }
    const std::size_t np = pall.size();
    std::vector<cd>& rho_hat = r.rho_hat;
    rho_hat.assign(np, 0.0);
    std::vector<cd> num(np), den;
    double worst = 0.0;
    for (std::size_t j = 0; j < np; ++j) {
        den.clear();
        for (std::size_t t = 0; t < np; ++t) {
            num[t] = pall[j] - zall[t];
            if (t != j) den.push_back(pall[j] - pall[t]);
        }
        rho_hat[j] = product_ratio(num, den);
        if (pall[j].imag() == 0.0) rho_hat[j] = rho_hat[j].real();
        // Roots that are not those of the contact's own equation show up as residues far from it: a
        // relative change of 1e-8, or 1e-12 of the pole itself (a weakly coupled mode), is allowed.
        const cd rho = residue(coupled[j / 2], pall[j], pall[j ^ 1]);
        worst = std::max(worst, std::abs(rho_hat[j] - rho) / (1e-8 * std::abs(rho) + 1e-12 * std::abs(pall[j])));
    }
    if (!(worst <= 1.0)) return false;
    // Conjugate poles get exactly conjugate residues.
    for (std::size_t j = 0; j < np; j += 2) {
        if (pall[j].imag() != 0.0) rho_hat[j + 1] = std::conj(rho_hat[j]);
    }
    return true;
}

bool rank_one_modes(const BaseModes& b, const ContactElement& ce, const RankOneRoots& roots, LeftRows left, StateModes& s) {
    const int n = b.n;
    const Eigen::VectorXd phi = b.phi.row(ce.dof).transpose();
    const double kc = ce.stiffness, cc = ce.damping;
    const std::vector<SecularMode>& modes = roots.modes;
    const std::vector<int>& coupled = roots.coupled;
    const std::vector<RankOneRoots::Candidate>& cand = roots.cand;
    const std::vector<cd>& pall = roots.pall;
    const std::vector<cd>& rho_hat = roots.rho_hat;
    const std::size_t np = pall.size();
    std::vector<cd> zs;
    for (const RankOneRoots::Candidate& c : cand) zs.push_back(c.z);
    const std::vector<int> order = order_by_magnitude(zs);
    const int m = static_cast<int>(cand.size());
    s.lambda.resize(m);
    s.paired.assign(static_cast<std::size_t>(m), false);
    // Written column by column (no zero fill first: these are the largest arrays of a transient).
    s.vl.resize(6 * n, m);
    // V(r, k) and L^T(r, k) = v into the real and imaginary blocks of s.vl.
    auto put_v = [&](int r, int k, cd v) {
        s.vl(r, k) = v.real();
        s.vl(n + r, k) = v.imag();
    };
    auto put_l = [&](int r, int k, cd v) {
        s.vl(2 * n + r, k) = v.real();
        s.vl(4 * n + r, k) = v.imag();
    };
    std::vector<bool> is_coupled(static_cast<std::size_t>(n), false);
    for (const int i : coupled) is_coupled[static_cast<std::size_t>(i)] = true;
    std::vector<cd> d(np);
    for (int k = 0; k < m; ++k) {
        const RankOneRoots::Candidate& c = cand[static_cast<std::size_t>(order[static_cast<std::size_t>(k)])];
        const cd z = c.z;
        s.lambda[k] = z;
        s.paired[static_cast<std::size_t>(k)] = c.paired;
        if (c.free_mode >= 0) {
            const int i = c.free_mode;
            s.vl.col(k).setZero();
            put_v(i, k, 1.0);
            put_l(i, k, c.partner / (c.partner - z));
            put_l(n + i, k, -1.0 / (c.partner - z));
            continue;
        }
        for (std::size_t j = 0; j < np; ++j) d[j] = 1.0 / (z - pall[j]);
        for (int i = 0; i < n; ++i) {
            if (is_coupled[static_cast<std::size_t>(i)]) continue;
            put_v(i, k, 0.0);
            put_l(i, k, 0.0);
            put_l(n + i, k, 0.0);
        }
        if (left == LeftRows::direct) {
            // y^T = w^T (z - A0)^-1 in x = [eta; eta_dot]: per mode (kc (z + D) - cc Omega^2, kc + cc z)
            // phi / Q(z), Q = (z - a)(z - b), normalised by y^T r. Formed directly, not as l L0 with
            // L0's rows ~1/(b - a): that product cancels by |z| / |b - a|, which a contact root far
            // above a slow free pole (a single mass on a soft spring: 1e7) turns into lost digits.
            cd N = 0.0;
            for (std::size_t j = 0; j < modes.size(); ++j) {
                const SecularMode& md = modes[j];
                const cd q = d[2 * j] * d[2 * j + 1];
                N += md.s * (kc * (2.0 * z + md.c) + cc * (z * z - md.k)) * q * q;
            }
            if (!(std::abs(N) > 0.0) || !std::isfinite(std::abs(N))) return false;
            const cd inv_n = 1.0 / N;
            for (std::size_t j = 0; j < modes.size(); ++j) {
                const int i = coupled[j];
                const SecularMode& md = modes[j];
                const cd v = phi[i] * d[2 * j] * d[2 * j + 1];
                put_v(i, k, v);
                put_l(i, k, (kc * (z + md.c) - cc * md.k) * v * inv_n);
                put_l(n + i, k, (kc + cc * z) * v * inv_n);
            }
            continue;
        }
        cd N = 0.0;
        for (std::size_t j = 0; j < np; ++j) N += rho_hat[j] * d[j] * d[j];
        if (!(std::abs(N) > 0.0) || !std::isfinite(std::abs(N))) return false;
        const cd inv_n = 1.0 / N;
        for (std::size_t j = 0; j < modes.size(); ++j) {
            const int i = coupled[j];
            const cd ra = rho_hat[2 * j] * d[2 * j], rb = rho_hat[2 * j + 1] * d[2 * j + 1];
            const cd scaled = inv_n / phi[i];
            put_v(i, k, phi[i] * d[2 * j] * d[2 * j + 1]);
            // l L0 with L0's rows [b, -1] / (b - a) and [-a, 1] / (b - a) for this mode's (eta, eta_dot).
            put_l(i, k, -(ra * modes[j].pole_b + rb * modes[j].pole_a) * scaled);
            put_l(n + i, k, (ra + rb) * scaled);
        }
    }
    return true;
}

}  // namespace vi
