// docs/validation.md sections 1-4: static deflections, frequencies, nodal points and peaks, the
// supported beam.

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <sstream>

#include "validation/closed_forms.hpp"
#include "modal/support_scan.hpp"
#include "validation/report.hpp"
#include "modal/eigen_solver.hpp"
#include "modal/modal_analysis.hpp"

namespace vi::validation_detail {
namespace {

double tip_deflection(const Case& c, double P) {
    const System s = build_system(c);
    const double l = c.beam.length;
    return transverse_displacement(s, solve_static(s, transverse_point_load(s, l, P)), l);
}

// Condition number of the diagonally scaled stiffness D K D (D = diag(K)^-1/2): the largest
// eigenvalue by power iteration, the smallest by inverse iteration (a sparse Cholesky). Two digits
// are enough to show how it grows with m.
double scaled_condition(const SparseMatrix& K) {
    const Eigen::VectorXd d = K.diagonal().cwiseSqrt().cwiseInverse();
    const SparseMatrix A = d.asDiagonal() * K * d.asDiagonal();
    Eigen::SimplicialLDLT<SparseMatrix> ldlt(A);
    Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(A.rows(), 1.0, 2.0).normalized();
    Eigen::VectorXd y = x;
    double lmax = 0.0, lmin_inv = 0.0;
    for (int it = 0; it < 300; ++it) {
        x = (A * x).normalized();
        lmax = x.dot(A * x);
        y = ldlt.solve(y).normalized();
        lmin_inv = y.dot(ldlt.solve(y));
    }
    return lmax * lmin_inv;
}

}  // namespace

std::string section_static(const ValidationOptions& o) {
    std::ostringstream s;
    s << "## 1. Static deflections\n\n"
      << "A transverse point force P = 1 uN. Cubic Hermite elements reproduce the exact Euler-Bernoulli "
         "deflection at the nodes for point loads, so any error is roundoff.\n\n";
    const double P = 1e-6;
    Table t{{"quantity (m = 50)", "computed [m]", "reference [m]", "rel. error", "test asserts"}, {}};
    {
        const Case c = paper_cantilever(50);
        const double EI = c.material.youngs_modulus * c.beam.second_moment(), l = c.beam.length;
        const double ref = P * l * l * l / (3.0 * EI);
        const double fe = tip_deflection(c, P);
        t.add({"cantilever tip, P at x = l", num(fe, 10), num(ref, 10) + " = P l^3/(3EI)", err(rel(fe, ref)),
               "< 1e-9 (FemStatic, m = 1, 7, 50)"});
    }
    {
        const Case c = clamped_clamped(50);
        const System sys = build_system(c);
        const double EI = c.material.youngs_modulus * c.beam.second_moment(), l = c.beam.length;
        const double ref = P * l * l * l / (192.0 * EI);
        const double fe =
            transverse_displacement(sys, solve_static(sys, transverse_point_load(sys, 0.5 * l, P)), 0.5 * l);
        t.add({"clamped-clamped centre, P at x = l/2", num(fe, 10), num(ref, 10) + " = P l^3/(192EI)",
               err(rel(fe, ref)), "< 1e-9 (FemStatic, m = 2, 10, 50)"});
    }
    s << t.str() << "\n";

    s << "**Roundoff grows with the mesh.** The cantilever's tip deflection (same load) on finer meshes. "
         "There is no discretisation error to lose, only roundoff, and it grows with the condition "
         "number of K. After the symmetric diagonal scaling D K D (D = diag(K)^-1/2, which removes "
         "the 1/L^2 spread between v and theta rows) the condition number grows like m^4, the ratio of "
         "the stiffest element mode (~ EI/L^3 with L = l/m) to the softest beam mode (~ EI/l^3); the "
         "column cond/m^4 shows it. The error stays below cond x eps (a worst-case bound) but rises "
         "with it: fine meshes buy nothing for statics.\n\n";
    Table r{{"m", "bending DOF", "tip rel. error", "cond(D K D) (estimate)", "cond / m^4", "test asserts"}, {}};
    for (int m : {50, 200, 400, 1000}) {
        const Case c = paper_cantilever(m);
        const double EI = c.material.youngs_modulus * c.beam.second_moment(), l = c.beam.length;
        const double ref = P * l * l * l / (3.0 * EI);
        const double fe = tip_deflection(c, P);
        const System sys = build_system(c);
        const double cond = scaled_condition(sys.K);
        r.add({std::to_string(m), std::to_string(sys.bending.size()), err(rel(fe, ref)), num(cond, 2),
               num(cond / std::pow(static_cast<double>(m), 4), 2), m == 50 ? "< 1e-9" : "-"});
    }
    report_progress(o, "section 1: static deflections");
    s << r.str() << "\n";
    return s.str();
}

std::string section_frequencies(const ValidationOptions& o) {
    std::ostringstream s;
    s << "## 2. Natural frequencies\n\n"
      << "Bending frequencies of the unsupported beam against the Euler-Bernoulli closed form "
         "omega_n = (beta_n l)^2 sqrt(EI / (rho A l^4)) with beta_n l the roots of cos x cosh x = -1 "
         "(cantilever) or +1 (clamped-clamped), found by bisection (`validation/closed_forms.hpp`). "
         "The FE value of beta_n l is sqrt(omega_n / sqrt(EI / (rho A l^4))), so its relative error is "
         "half that of the frequency. The consistent mass matrix bounds every frequency from above.\n\n";
    const std::vector<double> beta = closed_form::cantilever_beta_l(5);
    auto beta_table = [](const Case& c, const std::vector<double>& b, const std::vector<std::string>& limits) {
        const ModalResult r = analyse_modes(build_system(c), static_cast<int>(b.size()));
        const double scale = closed_omega(c, 1.0);
        Table t{{"mode", "beta_n l computed", "beta_n l closed form", "rel. error (beta l)", "f_n computed [kHz]",
                 "rel. error (f)", "test asserts (f)"},
                {}};
        for (std::size_t i = 0; i < b.size(); ++i) {
            const double w = r.bending[i].omega;
            t.add({std::to_string(i + 1), fixed(std::sqrt(w / scale), 7), fixed(b[i], 7),
                   err(rel(std::sqrt(w / scale), b[i])), num(r.bending[i].frequency_hz / 1e3, 8),
                   err(rel(w, closed_omega(c, b[i]))), limits[i]});
        }
        return t.str();
    };
    s << "**Cantilever, m = 50** (150 DOF; `ModalFrequency.CantileverMatchesEulerBernoulliAtM50`):\n\n"
      << beta_table(paper_cantilever(50), beta, {"< 1e-8", "< 1e-7", "< 1e-6", "< 3e-6", "< 1e-5"}) << "\n"
      << "**Clamped-clamped, m = 50** (`ModalFrequency.ClampedClampedMatchesEulerBernoulli`):\n\n"
      << beta_table(clamped_clamped(50), closed_form::clamped_clamped_beta_l(3), {"< 1e-7", "< 1e-6", "< 3e-6"})
      << "\n";

    // Convergence order from m = 10 and m = 20.
    const Case c10 = paper_cantilever(10), c20 = paper_cantilever(20);
    const ModalResult r10 = analyse_modes(build_system(c10), 3), r20 = analyse_modes(build_system(c20), 3);
    std::vector<double> e20(3);
    Table t{{"mode", "e(m = 10)", "e(m = 20)", "order log2(e10/e20)", "reference", "test asserts"}, {}};
    for (int i = 0; i < 3; ++i) {
        const double a = rel(r10.bending[i].omega, closed_omega(c10, beta[i]));
        e20[i] = rel(r20.bending[i].omega, closed_omega(c20, beta[i]));
        t.add({std::to_string(i + 1), err(a), err(e20[i]), fixed(std::log2(a / e20[i]), 3), "4 (h^4 for cubic elements)",
               "4 +/- 0.15 (`ConvergesWithOrderFourInM`)"});
    }
    s << "**Convergence order.** Relative frequency error e(m) of the cantilever on two meshes:\n\n" << t.str() << "\n";

    {
        const ModalResult r = analyse_modes(build_system(paper_cantilever(50)), 3);
        const double ratio = r.bending[2].omega / r.bending[0].omega;
        const double ref = std::pow(beta[2] / beta[0], 2);
        Table q{{"quantity", "computed", "reference", "rel. error", "test asserts"}, {}};
        q.add({"omega_3 / omega_1 (m = 50)", fixed(ratio, 5), fixed(ref, 5) + " = (beta_3 l / beta_1 l)^2",
               err(rel(ratio, ref)), "17.547 +/- 5e-3 (`ThirdOverFirstIs17point55`)"});
        s << "**The paper's omega_3 / omega_1 ~ 17** (its energy argument, section 4):\n\n" << q.str() << "\n";
    }

    s << "**Roundoff on fine meshes (Lanczos path).** Mode 1 of the cantilever from Spectra's shift-invert "
         "Lanczos (`lowest_modes_sparse`, the path `analyse_modes` takes above "
      << kDenseEigenLimit << " bending DOF, i.e. m > " << kDenseEigenLimit / 2
      << " for the cantilever; called directly here for every m). The column *h^4 estimate* extrapolates "
         "the discretisation error from m = 20 as e(20) (20/m)^4. Once it falls below the roundoff floor, "
         "which grows like cond(K) ~ m^4 (section 1), refining only adds error.\n\n";
    Table lz{{"m", "bending DOF", "f_1 computed [kHz]", "rel. error", "h^4 estimate", "test asserts"}, {}};
    for (int m : {50, 100, 200, 400, 1000}) {
        const Case c = paper_cantilever(m);
        const System sys = build_system(c);
        const ModeSet ms = lowest_modes_sparse(submatrix(sys.K, sys.bending), submatrix(sys.M, sys.bending), 3);
        const double e = rel(ms.omega[0], closed_omega(c, beta[0]));
        lz.add({std::to_string(m), std::to_string(sys.bending.size()), num(ms.omega[0] / (2e3 * std::numbers::pi), 10), err(e),
                err(e20[0] * std::pow(20.0 / m, 4)),
                m == 400 ? "< 1e-6 (`LargeMeshUsesLanczosAndAgreesWithDense`, modes 1-3)" : "-"});
    }
    report_progress(o, "section 2: frequencies");
    s << lz.str() << "\n";
    return s.str();
}

std::string section_shapes(const ValidationOptions& o) {
    std::ostringstream s;
    s << "## 3. Nodal points and peaks\n\n"
      << "Cantilever, m = 50. FE nodal points (zeros of v) and interior peaks of |v| are located inside "
         "the elements from their Hermite interpolation (`modal/shape_points.cpp`); the references are "
         "the zeros of the closed-form shape cosh - cos - sigma (sinh - sin) and of its slope "
         "(`closed_form::cantilever_shape_zeros`, `cantilever_slope_zeros`). Errors are absolute, in x/l.\n\n";
    const ModalResult r = analyse_modes(build_system(paper_cantilever(50)), 5);
    const std::vector<double> beta = closed_form::cantilever_beta_l(5);
    Table t{{"point", "computed x/l", "closed form x/l", "abs. error", "test asserts"}, {}};
    for (int i = 1; i < 5; ++i) {
        const std::vector<double> zeros = closed_form::cantilever_shape_zeros(beta[static_cast<std::size_t>(i)]);
        const std::vector<double>& fe = r.bending[static_cast<std::size_t>(i)].features.nodes;
        for (std::size_t k = 0; k < std::min(zeros.size(), fe.size()); ++k) {
            t.add({"nodal point y_" + std::to_string(i + 1) + std::to_string(k + 1), fixed(fe[k], 6), fixed(zeros[k], 6),
                   err(std::abs(fe[k] - zeros[k])), "< 1e-5"});
        }
        if (zeros.size() != fe.size()) {
            t.add({"mode " + std::to_string(i + 1) + " nodal point count", std::to_string(fe.size()),
                   std::to_string(zeros.size()), "MISMATCH", "equal"});
        }
    }
    for (int i = 1; i < 5; ++i) {
        const std::vector<double> zeros = closed_form::cantilever_slope_zeros(beta[static_cast<std::size_t>(i)]);
        const auto& peaks = r.bending[static_cast<std::size_t>(i)].features.peaks;
        const std::size_t interior = peaks.empty() ? 0 : peaks.size() - 1;  // the last peak is the free end
        for (std::size_t k = 0; k < std::min(zeros.size(), interior); ++k) {
            t.add({"peak of |v| Y_" + std::to_string(i + 1) + std::to_string(k + 1), fixed(peaks[k].x, 6),
                   fixed(zeros[k], 6), err(std::abs(peaks[k].x - zeros[k])), i < 4 ? "< 1e-4" : "-"});
        }
        if (zeros.size() != interior) {
            t.add({"mode " + std::to_string(i + 1) + " interior peak count", std::to_string(interior),
                   std::to_string(zeros.size()), "MISMATCH", "equal"});
        }
    }
    s << t.str() << "\n";

    const Case c = paper_cantilever(50);
    const double mass_scale = std::sqrt(c.material.density * c.beam.area() * c.beam.length);
    double worst_tip = 0.0;  // modes 1-4, as the test
    double tip5 = 0.0;
    for (const Mode& m : r.bending) {
        const double tip = std::abs(m.shape[global_dof(50, 1)]) * mass_scale;
        if (m.number <= 4) {
            worst_tip = std::max(worst_tip, std::abs(tip - 2.0));
        } else {
            tip5 = tip;
        }
    }
    const auto& p3 = r.bending[2].features.peaks;
    const double x3 = p3.size() >= 2 ? p3[1].x : std::numeric_limits<double>::quiet_NaN();
    const double x3_exact = closed_form::cantilever_slope_zeros(beta[2]).at(1);
    Table q{{"quantity", "computed", "reference", "abs. error", "test asserts"}, {}};
    q.add({"tip amplitude |v(l)| sqrt(rho A l), modes 1-4 (worst)", fixed(2.0 + worst_tip, 6), "2 (mass-normalised)",
           err(worst_tip), "< 1e-5 (`MassNormalisedTipAmplitudeIsTwo`)"});
    q.add({"tip amplitude, mode 5", fixed(tip5, 6), "2 (mass-normalised)", err(std::abs(tip5 - 2.0)), "-"});
    q.add({"mode 3 peak between its nodal points, x/l", fixed(x3, 4), fixed(x3_exact, 4) + " (closed form)",
           err(std::abs(x3 - x3_exact)), "0.6923 +/- 1e-4"});
    q.add({"the same against the paper", fixed(x3, 4), "0.67 (paper)", fixed(std::abs(x3 - 0.67), 4), "-"});
    s << q.str() << "\n"
      << "The paper's particular point 0.67 (\"the maximum amplitude point of the 3rd mode\") lies "
      << fixed(std::abs(x3 - 0.67), 3)
      << " (in x/l) below the closed-form peak " << fixed(x3_exact, 4)
      << "; the FE model agrees with the closed form, not with the paper. The paper's 0.78 and 0.87 are the "
         "nodal points "
      << fixed(r.bending[1].features.nodes.at(0), 4) << " (mode 2) and " << fixed(r.bending[2].features.nodes.at(1), 4)
      << " (mode 3) rounded.\n\n";
    report_progress(o, "section 3: nodal points and peaks");
    return s.str();
}

std::string section_supported(const ValidationOptions& o) {
    std::ostringstream s;
    s << "## 4. Supported beam\n\n"
      << "The support as a pin v(x0) = 0 (`SupportModel::pin`), m = 50 (the mesh gets a node at x0). "
         "ratio_i = omega_i(supported) / omega_i(unsupported).\n\n";
    const auto [x_star, r_star] = first_ratio_peak(50);
    const double beta1 = closed_form::cantilever_beta_l(1)[0];
    const double r_exact = std::pow(closed_form::pinned_cantilever_beta_l(x_star) / beta1, 2);
    Table t{{"quantity", "computed", "reference", "error", "test asserts"}, {}};
    t.add({"x0/l of the largest ratio_1 (golden section)", fixed(x_star, 5), "0.78 (paper)",
           fixed(std::abs(x_star - 0.78), 5) + " (abs.)", "0.78 +/- 0.01"});
    t.add({"largest ratio_1", fixed(r_star, 5), "6.27 (paper)", fixed(std::abs(r_star - 6.27), 5) + " (abs.)",
           "6.27 +/- 0.01"});
    t.add({"largest ratio_1 vs transfer determinant", fixed(r_star, 7), fixed(r_exact, 7) + " (closed form at x0*)",
           err(rel(r_star, r_exact)) + " (rel.)", "+/- 1e-6 (abs.)"});
    s << "**Where the first frequency peaks** (paper: x0/l = 0.78, ratio 6.27 read off its Fig. 8):\n\n"
      << t.str() << "\n";

    Table d{{"x0/l", "f_1 supported computed [kHz]", "closed form [kHz]", "beta l (closed form)", "rel. error",
             "test asserts"},
            {}};
    for (double x0 : {0.3, 0.7834, 0.87, 1.0}) {
        const Case c = paper_cantilever(50, x0);
        const ModalStudy st = modal_study(c, 1, SupportModel::pin);
        const double bl = closed_form::pinned_cantilever_beta_l(x0);
        const double w = closed_omega(c, bl);
        d.add({num(x0, 4), num(st.supported.bending[0].frequency_hz / 1e3, 9), num(w / (2e3 * std::numbers::pi), 9), fixed(bl, 6),
               err(rel(st.supported.bending[0].omega, w)), "< 1e-7 (`PinnedFirstFrequencyMatchesTransferDeterminant`)"});
    }
    s << "**First supported frequency against the transfer determinant** "
         "(`closed_form::pinned_cantilever_beta_l`: the 8 x 8 determinant of the two spans; at x0/l = 1 "
         "the propped cantilever, beta l = 3.9266):\n\n"
      << d.str() << "\n";

    const std::vector<double> fig8 = {0.25, 0.5, 0.67, 0.78, 0.87, 1.0};
    const auto pts = support_scan(paper_cantilever(50, 1.0), fig8, 3, SupportModel::pin);
    Table f{{"x0/l", "ratio_1", "ratio_2", "ratio_3"}, {}};
    for (const auto& p : pts) {
        std::vector<std::string> row{num(p.position, 3)};
        for (int i = 0; i < 3; ++i) {
            row.push_back(i < static_cast<int>(p.study.ratios.size()) ? fixed(p.study.ratios[static_cast<std::size_t>(i)], 4)
                                                                    : "n/a");
        }
        f.add(row);
    }
    s << "**Frequency ratios at the paper's particular points** (Fig. 8; the paper gives the curves only, "
         "so there is no reference column). The whole curve: "
         "`vibroimpact support-scan examples/paper/cantilever.toml --positions 0.02:1:50 --out out/fig8`.\n\n"
      << f.str() << "\n";
    report_progress(o, "section 4: supported beam");
    return s.str();
}

}  // namespace vi::validation_detail
