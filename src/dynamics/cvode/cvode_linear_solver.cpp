#include "dynamics/cvode/cvode_linear_solver.hpp"

#include "dynamics/cvode/physical_newton.hpp"

#include <nvector/nvector_serial.h>

#include <Eigen/SparseCore>

#include <cmath>
#include <memory>
#include <new>

namespace vi::cvode_detail {
namespace {

// ---- the matrix -------------------------------------------------------------------------------

SUNMatrix_ID matrix_id(SUNMatrix) { return SUNMATRIX_CUSTOM; }

void matrix_destroy(SUNMatrix A) {
    if (!A) return;
    delete static_cast<StructuredJacobian*>(A->content);
    A->content = nullptr;
    SUNMatFreeEmpty(A);
}

int matrix_zero(SUNMatrix A) {
    StructuredJacobian& j = structured_content(A);
    j.a = 0.0;
    j.b = 0.0;
    j.tangents.reset();
    return 0;
}

int matrix_copy(SUNMatrix from, SUNMatrix to) {
    structured_content(to) = structured_content(from);
    return 0;
}

// A = c A + I.
int matrix_scale_add_identity(realtype c, SUNMatrix A) {
    StructuredJacobian& j = structured_content(A);
    j.a *= c;
    j.b = c * j.b + 1.0;
    return 0;
}

SUNMatrix matrix_clone(SUNMatrix A) {
    const StructuredJacobian& j = structured_content(A);
    return structured_matrix(*j.system, A->sunctx);
}

// ---- the solver --------------------------------------------------------------------------------

// The factorisation of one Newton matrix b I + a J. What depends on J alone (the active elements,
// their summed tangents and, for the dense form, their projections on the basis) is kept while CVODE
// reuses J with a new gamma, so such a setup costs O(r^2) plus the factorisation.
struct Factors {
    const ModalSystem* system = nullptr;
    double a = 0.0, b = 1.0;
    Eigen::VectorXd inv_delta;             // 1 / (b^2 + a^2 w^2 - a b D)
    std::shared_ptr<const ElementTangents> projected;  // the tangents the members below belong to
    std::vector<int> slot;                 // per DOF of the system's union: its row in P, or -1
    Eigen::MatrixXd P;                     // the basis rows of the active elements' DOFs, each once (s x r)
    Eigen::MatrixXd Fq, Fv;                // sums of dfdq and dfdv (s x s)
    Eigen::MatrixXd PFqP, PFvP;            // P^T Fq P and P^T Fv P (r x r), for the dense form
    Eigen::MatrixXd W;                     // -a^2 Fq + a b Fv (s x s)
    Eigen::PartialPivLU<Eigen::MatrixXd> capacitance;  // I + W P Delta^-1 P^T (s x s)
    Eigen::PartialPivLU<Eigen::MatrixXd> dense;        // the whole Delta + P^T W P (r x r) when s is large
    // A full basis solves the large-s case in the FE DOFs, where it is sparse (null: reduced basis).
    std::unique_ptr<PhysicalNewton> physical;
    bool use_dense = false;
    bool use_physical = false;  // use_dense, solved by `physical`
    long last_flag = 0;
};

Factors& factors(SUNLinearSolver S) { return *static_cast<Factors*>(S->content); }

SUNLinearSolver_Type solver_type(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }
SUNLinearSolver_ID solver_id(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }
int solver_initialize(SUNLinearSolver) { return SUNLS_SUCCESS; }
sunindextype solver_last_flag(SUNLinearSolver S) { return static_cast<sunindextype>(factors(S).last_flag); }

int solver_free(SUNLinearSolver S) {
    if (!S) return SUNLS_SUCCESS;
    delete static_cast<Factors*>(S->content);
    S->content = nullptr;
    SUNLinSolFreeEmpty(S);
    return SUNLS_SUCCESS;
}

bool nonzero(const Eigen::MatrixXd& m) { return m.size() > 0 && m.cwiseAbs().maxCoeff() > 0.0; }

// The members of f that depend on the tangents t alone.
void project(Factors& f, const std::shared_ptr<const ElementTangents>& t) {
    const ModalSystem& sys = *f.system;
    const int r = sys.basis_size();
    std::vector<int> active;
    if (t) {
        for (int e = 0; e < static_cast<int>(t->dfdq.size()); ++e) {
            const std::size_t ue = static_cast<std::size_t>(e);
            if (nonzero(t->dfdq[ue]) || nonzero(t->dfdv[ue])) active.push_back(e);
        }
    }
    // The active elements' DOFs, each once: elements that share DOFs (a pad and its film) add
    // their tangents into one block instead of stacking copies of the same basis rows.
    f.slot.assign(static_cast<std::size_t>(sys.union_rows().rows()), -1);
    int s = 0;
    for (int e : active)
        for (int u : sys.union_positions(e))
            if (f.slot[static_cast<std::size_t>(u)] < 0) f.slot[static_cast<std::size_t>(u)] = s++;
    f.P.resize(s, r);
    for (std::size_t u = 0; u < f.slot.size(); ++u)
        if (f.slot[u] >= 0) f.P.row(f.slot[u]) = sys.union_rows().row(static_cast<Eigen::Index>(u));
    f.Fq = Eigen::MatrixXd::Zero(s, s);
    f.Fv = Eigen::MatrixXd::Zero(s, s);
    for (int e : active) {
        const std::size_t ue = static_cast<std::size_t>(e);
        const std::vector<int>& at = sys.union_positions(e);
        const Eigen::Index m = t->dfdq[ue].rows();
        for (Eigen::Index a = 0; a < m; ++a) {
            const int ia = f.slot[static_cast<std::size_t>(at[static_cast<std::size_t>(a)])];
            for (Eigen::Index b = 0; b < m; ++b) {
                const int ib = f.slot[static_cast<std::size_t>(at[static_cast<std::size_t>(b)])];
                f.Fq(ia, ib) += t->dfdq[ue](a, b);
                f.Fv(ia, ib) += t->dfdv[ue](a, b);
            }
        }
    }
    // Elements on the basis give their tangents already projected: r x r, dense.
    const bool modal = t && (nonzero(t->modal_q) || nonzero(t->modal_v));
    f.use_dense = s > r / 4 || modal;
    // The FE-DOF form pays while the tangents are banded (pads and films couple the DOFs of one
    // element, at most 6 per row); a dense tangent (mid-plane stretching couples every DOF) would
    // fill its sparse factors, and the dense modal form is then the faster one.
    const Eigen::Index coupled = (f.Fq.array() != 0.0 || f.Fv.array() != 0.0).count();
    f.use_physical = f.use_dense && f.physical && coupled <= 16 * static_cast<Eigen::Index>(s);
    if (f.use_physical) {
        std::vector<int> dofs(static_cast<std::size_t>(s));
        for (std::size_t u = 0; u < f.slot.size(); ++u)
            if (f.slot[u] >= 0) dofs[static_cast<std::size_t>(f.slot[u])] = sys.union_dofs()[u];
        f.physical->set_tangents(f.Fq, f.Fv, dofs);
    } else if (f.use_dense) {
        // Fq and Fv are banded (each element couples neighbouring DOFs): the sparse product costs
        // O(nnz r) where the dense one costs O(s^2 r).
        const Eigen::SparseMatrix<double> Fqs = f.Fq.sparseView(), Fvs = f.Fv.sparseView();
        const Eigen::MatrixXd FqP = Fqs * f.P, FvP = Fvs * f.P;
        f.PFqP.noalias() = f.P.transpose() * FqP;
        f.PFvP.noalias() = f.P.transpose() * FvP;
        if (modal) {
            f.PFqP += t->modal_q;
            f.PFvP += t->modal_v;
        }
    }
    f.projected = t;
}

// On a nodal basis: the elements' summed tangents, already on the FE DOFs, for the FE-DOF
// factorisation (none: a zero tangent).
void project_nodal(Factors& f, const std::shared_ptr<const ElementTangents>& t) {
    const Eigen::Index n = f.system->problem().size();
    if (t) {
        f.physical->set_tangents(t->Fq, t->Fv);
    } else {
        f.physical->set_tangents(Eigen::SparseMatrix<double>(n, n), Eigen::SparseMatrix<double>(n, n));
    }
    f.projected = t;
}

int solver_setup(SUNLinearSolver S, SUNMatrix A) {
    try {
        Factors& f = factors(S);
        const StructuredJacobian& j = structured_content(A);
        const ModalSystem& sys = *f.system;
        f.a = j.a;
        f.b = j.b;
        if (sys.nodal()) {
            if (!j.tangents || j.tangents != f.projected) project_nodal(f, j.tangents);
            f.last_flag = f.physical->factor(f.a, f.b) ? 0 : 1;  // singular: recoverable, CVODE retries smaller
            return static_cast<int>(f.last_flag);
        }
        const Eigen::VectorXd& w = sys.basis().omega;
        const Eigen::ArrayXd delta = f.b * f.b + f.a * f.a * w.array().square() - f.a * f.b * sys.rayleigh().array();
        if (!(delta.abs() > 0.0).all()) return f.last_flag = 1, 1;  // recoverable: CVODE retries smaller
        f.inv_delta = delta.inverse().matrix();
        if (!j.tangents || j.tangents != f.projected) project(f, j.tangents);
        const Eigen::Index s = f.P.rows();
        const double cq = -f.a * f.a, cv = f.a * f.b;
        if (f.use_physical) {
            if (!f.physical->factor(f.a, f.b)) return f.last_flag = 1, 1;  // recoverable, as above
        } else if (f.use_dense) {
            Eigen::MatrixXd full = cq * f.PFqP + cv * f.PFvP;
            full.diagonal() += delta.matrix();
            f.dense.compute(full);
        } else if (s > 0) {
            f.W = cq * f.Fq + cv * f.Fv;
            const Eigen::MatrixXd G = f.P * f.inv_delta.asDiagonal() * f.P.transpose();
            f.capacitance.compute(Eigen::MatrixXd::Identity(s, s) + f.W * G);
        }
        f.last_flag = 0;
        return SUNLS_SUCCESS;
    } catch (...) {
        return -1;
    }
}

// x_v of the modal form, below.
void solve_modal(Factors& f, const Eigen::Map<const Eigen::VectorXd>& r_eta, const Eigen::Map<const Eigen::VectorXd>& r_v,
                 Eigen::VectorXd& xv) {
    const Eigen::VectorXd& w = f.system->basis().omega;
    Eigen::VectorXd t = f.b * r_v + f.a * w.cwiseAbs2().cwiseProduct(r_eta);
    if (f.P.rows() == 0 && !f.use_dense) {  // no tangent at all (elements on the basis make it dense)
        xv = f.inv_delta.cwiseProduct(t);
    } else if (f.use_physical) {
        f.physical->solve(r_eta, r_v, xv);
    } else if (f.use_dense) {
        t.noalias() -= f.a * (f.PFqP * r_eta);
        xv = f.dense.solve(t);
    } else {
        t.noalias() -= f.a * (f.P.transpose() * (f.Fq * (f.P * r_eta)));
        const Eigen::VectorXd z = f.inv_delta.cwiseProduct(t);
        const Eigen::VectorXd u = f.capacitance.solve(f.W * (f.P * z));
        xv = z - f.inv_delta.cwiseProduct(f.P.transpose() * u);
    }
}

// Rows of (b I + a J) x = rhs (on a nodal basis the same with eta = q and PhysicalNewton's system): b x_eta + a x_v = r_eta; b x_v + a (-w^2 x_eta + P^T Fq P x_eta -
// D x_v + P^T Fv P x_v) = r_v; the quadratures b x_e = r_e (their Jacobian rows are left out: they
// feed nothing back, so Newton's iteration still converges on them). With x_eta = (r_eta - a x_v) / b:
// (Delta + P^T W P) x_v = b r_v + a w^2 r_eta - a P^T Fq P r_eta.
int solver_solve(SUNLinearSolver S, SUNMatrix, N_Vector x, N_Vector rhs, realtype) {
    try {
        Factors& f = factors(S);
        const ModalSystem& sys = *f.system;
        const int r = sys.basis_size();
        const int n = sys.size();
        const double* in = N_VGetArrayPointer(rhs);
        double* out = N_VGetArrayPointer(x);
        const Eigen::Map<const Eigen::VectorXd> r_eta(in, r), r_v(in + r, r);
        Eigen::VectorXd xv;
        if (sys.nodal()) {
            f.physical->solve_nodal(r_eta, r_v, xv);
        } else {
            solve_modal(f, r_eta, r_v, xv);
        }
        Eigen::Map<Eigen::VectorXd>(out, r) = (r_eta - f.a * xv) / f.b;
        Eigen::Map<Eigen::VectorXd>(out + r, r) = xv;
        for (int k = 2 * r; k < n; ++k) out[k] = in[k] / f.b;
        f.last_flag = 0;
        return SUNLS_SUCCESS;
    } catch (...) {
        return -1;
    }
}

}  // namespace

StructuredJacobian& structured_content(SUNMatrix A) { return *static_cast<StructuredJacobian*>(A->content); }

SUNMatrix structured_matrix(const ModalSystem& system, SUNContext ctx) {
    SUNMatrix A = SUNMatNewEmpty(ctx);
    if (!A) throw std::bad_alloc();
    A->ops->getid = matrix_id;
    A->ops->clone = matrix_clone;
    A->ops->destroy = matrix_destroy;
    A->ops->zero = matrix_zero;
    A->ops->copy = matrix_copy;
    A->ops->scaleaddi = matrix_scale_add_identity;
    auto* content = new (std::nothrow) StructuredJacobian();
    if (!content) {
        SUNMatFreeEmpty(A);
        throw std::bad_alloc();
    }
    content->system = &system;
    A->content = content;
    return A;
}

SUNLinearSolver structured_solver(const ModalSystem& system, SUNContext ctx) {
    SUNLinearSolver S = SUNLinSolNewEmpty(ctx);
    if (!S) throw std::bad_alloc();
    S->ops->gettype = solver_type;
    S->ops->getid = solver_id;
    S->ops->initialize = solver_initialize;
    S->ops->setup = solver_setup;
    S->ops->solve = solver_solve;
    S->ops->lastflag = solver_last_flag;
    S->ops->free = solver_free;
    auto* f = new (std::nothrow) Factors();
    if (!f) {
        SUNLinSolFreeEmpty(S);
        throw std::bad_alloc();
    }
    f->system = &system;
    // Below about 150 vectors the dense r x r LU costs what the sparse one does (the switch example
    // at m = 50, r = 100: 0.30 s either way), and the dense form solves the modal system exactly
    // where the other leans on phi^T M phi = I.
    constexpr int kPhysicalFrom = 150;
    const bool full = system.basis().full && system.basis_size() == system.problem().size();
    if (system.nodal() || (full && system.basis_size() >= kPhysicalFrom)) {
        try {
            f->physical = std::make_unique<PhysicalNewton>(system);
        } catch (...) {
            delete f;
            SUNLinSolFreeEmpty(S);
            throw;
        }
    }
    S->content = f;
    return S;
}

}  // namespace vi::cvode_detail
