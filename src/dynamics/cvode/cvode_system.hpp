#pragma once
// ModalSystem: the first-order form CVODE integrates, in the coordinates of a ModalBasis (right-hand
// side, the pieces of the Jacobian, root functions, element readings, energy), modal or the FE DOFs
// themselves (a nodal basis). Internal to the CVODE solver (dynamics/cvode/cvode_solver.*).

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "dynamics/cvode/modal_basis.hpp"
#include "dynamics/cvode/nodal_linear_part.hpp"
#include "dynamics/transient_problem.hpp"
#include "dynamics/transient_result.hpp"
#include "forces/force_assembly.hpp"

namespace vi::cvode_detail {

// Layout of the CVODE state y, N = 2r + 3 + nc (+ 1 with squeeze films) (r basis vectors, nc contact
// elements):
//   [0, r)       eta                                   modal displacements [m sqrt(kg)]
//   [r, 2r)      eta' = d eta / dt
//   2r           integral of eta'^T D eta' dt          Rayleigh dissipation [J], D = diag(alpha + beta w^2)
//   2r + 1       integral of the elements' dissipated power but the films' [J]
//   2r + 2       integral of the elements' input power (external work) [J]
//   2r + 3 + j   integral of F_j dt while contact j is closed: its impulse [N s]
//   2r + 3 + nc  integral of the squeeze films' dissipated power [J], only where the model has a film
//                (so that a model without one integrates the same state as before the films had a
//                ledger term of their own)
// eta'' = -w^2 eta - D eta' + sum_e P_e^T f_e(P_e eta, P_e eta', t), P_e the basis rows of element
// e's DOFs. The quadratures feed nothing back.
// On a nodal basis eta = q and eta' = v over the n FE DOFs (r = n), and
// v' = M^-1 (-K q - C v + sum_e S_e^T f_e(S_e q, S_e v, t)), S_e picking element e's DOFs; the
// Rayleigh integrand is v^T C v.
//
// Root functions: per hybrid element its switching function (direction +1); per element its watch
// functions (their own directions); then the velocities of the watched point and of the first
// contact's point (direction 0: their zeros are the extremes of the displacements).
class ModalSystem {
public:
    ModalSystem(const TransientProblem& p, ModalBasis basis);

    [[nodiscard]] int basis_size() const { return r_; }
    [[nodiscard]] int size() const { return 2 * r_ + 3 + static_cast<int>(contacts_.size()) + (films_ ? 1 : 0); }
    [[nodiscard]] int elements() const { return static_cast<int>(p_.forces.size()); }
    [[nodiscard]] const ForceElement& element(int e) const { return *p_.forces[static_cast<std::size_t>(e)]; }
    [[nodiscard]] const std::vector<int>& contacts() const { return contacts_; }  // element index per contact
    [[nodiscard]] const ModalBasis& basis() const { return basis_; }
    // The linear part in the FE DOFs on a nodal basis; null on a modal one.
    [[nodiscard]] const NodalLinearPart* nodal() const { return nodal_.get(); }
    // On a modal basis only (empty on a nodal one): alpha + beta w^2 per vector, element e's basis rows.
    [[nodiscard]] const Eigen::VectorXd& rayleigh() const { return d_; }
    [[nodiscard]] const Eigen::MatrixXd& rows(int e) const { return rows_[static_cast<std::size_t>(e)]; }
    // The union of the DOFs of the elements not evaluated on the basis (elements overlap: a pad and
    // its film share every DOF): its basis rows (|U| x r; modal basis only), and the position in it
    // of each of element e's DOFs (none for an element evaluated on the basis).
    [[nodiscard]] const Eigen::MatrixXd& union_rows() const { return union_rows_; }
    [[nodiscard]] const std::vector<int>& union_positions(int e) const { return local_[static_cast<std::size_t>(e)]; }
    // The FE DOF of each row of union_rows().
    [[nodiscard]] const std::vector<int>& union_dofs() const { return union_dofs_; }
    [[nodiscard]] const TransientProblem& problem() const { return p_; }

    [[nodiscard]] int rayleigh_index() const { return 2 * r_; }
    [[nodiscard]] int dissipation_index() const { return 2 * r_ + 1; }
    [[nodiscard]] int work_index() const { return 2 * r_ + 2; }
    [[nodiscard]] int impulse_index(int j) const { return 2 * r_ + 3 + j; }
    [[nodiscard]] int film_dissipation_index() const { return 2 * r_ + 3 + static_cast<int>(contacts_.size()); }

    [[nodiscard]] int roots() const { return roots_; }
    [[nodiscard]] int switch_root(int e) const { return switch_root_[static_cast<std::size_t>(e)]; }  // -1: none
    [[nodiscard]] int watch_root(int e) const { return watch_root_[static_cast<std::size_t>(e)]; }    // first one
    [[nodiscard]] int extreme_root() const { return roots_ - 2; }
    [[nodiscard]] std::vector<int> root_directions() const;

    // The elements' modes of the current piece.
    void set_modes(const std::vector<int>& modes) { modes_ = modes; }
    [[nodiscard]] const std::vector<int>& modes() const { return modes_; }
    // Element forces are evaluated at min(t, the left limit of t_stop): a jump at a stop belongs to
    // the next segment, which starts after a reinit there.
    void set_segment_end(double t_stop) { t_limit_ = t_stop; }

    // CVODE callbacks on raw arrays of length size().
    void rhs(double t, const double* y, double* ydot) const;
    void root_functions(double t, const double* y, double* g) const;
    // d f_e / d q_e and d f_e / d v_e of every element at y (row-major |D_e| x |D_e| each; 0 x 0 for an
    // element evaluated on the basis, reduced(e)), and where some are, the sums of their projected
    // tangents P_e^T (d f_e / d q_e) P_e and P_e^T (d f_e / d v_e) P_e (r x r; else left empty).
    void tangents(double t, const double* y, std::vector<Eigen::MatrixXd>& dfdq, std::vector<Eigen::MatrixXd>& dfdv,
                  Eigen::MatrixXd* modal_q = nullptr, Eigen::MatrixXd* modal_v = nullptr) const;
    // Whether element e is evaluated directly on the basis (ForceElement::reduced): on a reduced
    // basis, for an element that offers it. Its DOFs are then not in the union unless another
    // element's are.
    [[nodiscard]] bool reduced(int e) const { return reduced_[static_cast<std::size_t>(e)] != nullptr; }

    // The same summed over the elements onto their FE DOFs, as n x n sparse matrices (nodal basis:
    // the element blocks are dense in storage but banded in content, so only their nonzeros move).
    void fe_tangents(double t, const double* y, Eigen::SparseMatrix<double>& Fq, Eigen::SparseMatrix<double>& Fv) const;

    // Element e at y in mode `mode`: switching function, contact reading, stored energy.
    [[nodiscard]] double switching_function(int e, int mode, double t, const double* y) const;
    [[nodiscard]] ContactReading reading(int e, double t, const double* y) const;
    // Element e's contact resistance at y taken as closed [ohm] (ForceElement::contact_resistance).
    [[nodiscard]] double resistance(int e, double t, const double* y) const;
    [[nodiscard]] RunEnd run_end(int e, double t, const double* y) const;
    [[nodiscard]] double stored_energy(int e, int mode, double t, const double* y) const;
    // Element e's dissipated power at y in mode `mode` [W].
    [[nodiscard]] double dissipated_power(int e, int mode, double t, const double* y) const;
    // The mode each element starts in at y: the problem's modes0, turned to the contact mode where a
    // contact's initial_mode says it touches and moves in.
    [[nodiscard]] std::vector<int> initial_modes(const double* y) const;

    // Displacement and velocity of the watched point and of a contact's point [m], [m/s].
    [[nodiscard]] double watched(const double* y) const;
    [[nodiscard]] double watched_velocity(const double* y) const;
    [[nodiscard]] double contact_displacement(int j, const double* y) const;
    // The basis rows of the watched point's and of contact j's displacement (1 x r; modal basis only).
    [[nodiscard]] const Eigen::RowVectorXd& watched_row() const { return watched_row_; }
    [[nodiscard]] Eigen::RowVectorXd contact_row(int j) const {
        return rows_[static_cast<std::size_t>(contacts_[static_cast<std::size_t>(j)])].row(0);
    }

    // kinetic, strain, the elements' stored energy and the dissipation and work integrals from y;
    // `jump` is added to the contacts' dissipated energy (what a massless element loses when it
    // switches; cvode_solver.cpp).
    [[nodiscard]] EnergyLedger energy(double t, const double* y, double jump) const;

    // y at t = 0: eta = phi^T M q0, eta' = phi^T M v0 (q0, v0 on a nodal basis).
    [[nodiscard]] Eigen::VectorXd initial_state() const;
    // How far the basis is from the initial displacement: |q0 - phi eta0| / |q0| (0 for a full basis).
    [[nodiscard]] double initial_projection_error() const;
    // Absolute tolerance of each component: atol_scale times a characteristic magnitude.
    [[nodiscard]] Eigen::VectorXd absolute_tolerances(double atol_scale) const;

private:
    // q, v (and a) at every DOF of the union once: each shared DOF is projected once per call
    // instead of once per element.
    void gather_union(const double* y, const double* acc) const;
    // Element e's state at time t from the union's q, v (and a where `acc`), after gather_union.
    const ElementState& union_state(int e, double t, bool acc) const;
    // Element e's state at time t from y, through its own basis rows (as the union's, without
    // projecting the other elements' DOFs).
    const ElementState& own_state(int e, double t, const double* y) const;
    [[nodiscard]] double element_time(double t) const;
    // The modal accelerations at y without the ledger's integrals.
    void acceleration(double t, const double* y, Eigen::VectorXd& acc) const;
    // Adds the elements' generalised forces at y to acc and returns the power they dissipate but the
    // films' (and adds the films' dissipated power to *film and the power the elements take in to
    // *work, unless null); leaves q and v on the union at y.
    double add_element_forces(double te, const double* y, Eigen::Map<Eigen::VectorXd>& acc, double* work,
                              double* film) const;
    // Whether a watch function needs the accelerations in the elements' current modes.
    [[nodiscard]] bool watches_need_acceleration() const;
    // Whether element e's watch functions read the accelerations in its current mode.
    [[nodiscard]] bool needs_acceleration(int e) const;
    // absolute_tolerances' lowest frequency w1 [rad/s], length L [m] and largest basis row phi_ref
    // at the watched point and the elements' DOFs over the five lowest vectors [1/sqrt(kg)].
    struct ToleranceScales {
        double w1 = 0.0, L = 0.0, phi_ref = 1.0;
    };
    [[nodiscard]] ToleranceScales tolerance_scales() const;
    // Accelerations from the summed forces: the linear part's force in `acc` on a nodal basis
    // (-K q - C v) gets uf_ spread on the union's DOFs and is solved with M; a modal one adds P^T uf_.
    void apply_union_forces(Eigen::Map<Eigen::VectorXd>& acc) const;

    const TransientProblem& p_;
    ModalBasis basis_;
    std::unique_ptr<NodalLinearPart> nodal_;
    int r_ = 0;
    Eigen::VectorXd w2_, d_;                 // omega^2, alpha + beta omega^2
    std::vector<Eigen::MatrixXd> rows_;      // per element: basis rows of its DOFs (|D_e| x r)
    std::vector<std::unique_ptr<const ReducedElement>> reduced_;  // per element: on the basis, or null
    Eigen::MatrixXd union_rows_;             // basis rows of the union of the elements' DOFs (|U| x r)
    std::vector<int> union_dofs_;            // the union's DOFs, ascending
    std::vector<std::vector<int>> local_;    // per element: positions of its DOFs in the union
    Eigen::RowVectorXd watched_row_;
    std::vector<int> contacts_;
    bool films_ = false;  // some element books its dissipation as a film's (DissipationKind::film)
    std::vector<int> modes_;
    std::vector<int> switch_root_, watch_root_;
    int roots_ = 0;
    double t_limit_ = 0.0;
    std::vector<int> identity_;                  // 0, 1, ..., the largest element's DOF count - 1
    mutable ElementAssembler assembler_;
    mutable Eigen::VectorXd own_q_, own_v_;      // one element's q and v through its own rows
    mutable Eigen::MatrixXd uqv_;                // on the union: q and v (two columns)
    mutable Eigen::VectorXd ua_, uf_;            // on the union: a, summed element forces
    mutable Eigen::VectorXd acc_;
};

// Throws std::invalid_argument when p is inconsistent (sizes, DOF indices, horizon).
void validate(const TransientProblem& p);

}  // namespace vi::cvode_detail
