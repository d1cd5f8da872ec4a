#pragma once
// CvodeSystem: the first-order form of a TransientProblem for CVODE (right-hand side, analytic
// Jacobian, event functions, contact quantities, energy). Internal to the CVODE solver.

#include <sundials/sundials_matrix.h>
#include <sundials/sundials_nvector.h>

#include <Eigen/Dense>
#include <vector>

#include "dynamics/transient_problem.hpp"
#include "dynamics/transient_result.hpp"

namespace vi::cvode_detail {

// Layout of the CVODE state y, N = 2n + 3 + nc (n DOFs, nc contacts):
//   [0, n)       q                                   displacements [m, rad]
//   [n, 2n)      v = dq/dt                           velocities [m/s, rad/s]
//   2n           integral of v^T C v dt              Rayleigh dissipation [J]
//   2n + 1       integral of sum_active Cc (dd/dt)^2 contact-damper dissipation [J]
//   2n + 2       integral of Q(t)^T v dt             external work [J]
//   2n + 3 + j   integral of F_j dt while j closed   impulse of contact j [N s]
// The quadratures feed nothing back, so they only add rows to the Jacobian; keeping them in y makes
// one CVODE run integrate them to the same tolerance as the motion.
//
// Event functions, three per contact j (index 3j + k), all evaluated from the state:
//   k = 0  switching: open:   min(s d, F)  (s = Kc, or 1 if Kc = 0), direction +1: the contact
//                             closes when d > 0 and F > 0 become both true (d crossing 0 upward,
//                             or F crossing 0 upward while d > 0);
//                     closed: -F, direction +1: the contact opens when F falls through 0.
//   k = 1  dd/dt, direction -1: local maxima of d. Closed: peak penetration. Open: a guard against
//          an engagement CVODE stepped over (d up through 0 and back within one step).
//   k = 2  closed: dF/dt, direction -1: local maxima of F (peak force). Open: constant 1 (unused).
class CvodeSystem {
public:
    explicit CvodeSystem(const TransientProblem& p);

    [[nodiscard]] int dofs() const { return n_; }
    [[nodiscard]] int size() const { return 2 * n_ + 3 + nc_; }
    [[nodiscard]] int contacts() const { return nc_; }
    // 3 per contact, then 2 for the extremes: the watched point's velocity and contact 0's
    // velocity (zero crossings in either direction are its local maxima and minima).
    [[nodiscard]] int roots() const { return 3 * nc_ + 2; }
    [[nodiscard]] int extreme_root() const { return 3 * nc_; }
    [[nodiscard]] int rayleigh_index() const { return 2 * n_; }
    [[nodiscard]] int contact_damping_index() const { return 2 * n_ + 1; }
    [[nodiscard]] int work_index() const { return 2 * n_ + 2; }
    [[nodiscard]] int impulse_index(int j) const { return 2 * n_ + 3 + j; }

    // Sets the closed contacts; rebuilds the linear operator of the current piece.
    void set_active(const std::vector<bool>& active);
    [[nodiscard]] const std::vector<bool>& active() const { return active_; }
    // Loads are evaluated at min(t, left limit of t_stop): a jump at the stop time belongs to the
    // next segment, which starts after a reinit there.
    void set_segment_end(double t_stop);

    // CVODE callbacks on raw arrays of length size() (J: column-major size() x size()).
    void rhs(double t, const double* y, double* ydot) const;
    void jacobian(double t, const double* y, double* jac) const;
    void events(double t, const double* y, double* g) const;

    // Contact j from the state: penetration d, its rate, the force magnitude F = Kc d + Cc dd/dt
    // (whether or not the contact is closed), and the switching function (event 0) for open j.
    [[nodiscard]] double penetration(int j, const double* y) const;
    [[nodiscard]] double penetration_rate(int j, const double* y) const;
    [[nodiscard]] double force(int j, const double* y) const;
    [[nodiscard]] double closing_function(int j, const double* y) const;
    [[nodiscard]] double contact_velocity(int j, const double* y) const;

    // kinetic, strain, contact_spring (closed contacts) and the three integrals from y; the
    // contact_dissipated entry gets `jump` added (see cvode_solver.cpp for what that holds).
    [[nodiscard]] EnergyLedger energy(const double* y, double jump) const;

    // Absolute tolerance of each component: atol_scale times a characteristic magnitude.
    [[nodiscard]] Eigen::VectorXd absolute_tolerances(double atol_scale) const;

    [[nodiscard]] Eigen::VectorXd initial_state() const;

private:
    [[nodiscard]] double load_time(double t) const;
    void acceleration(double t, const double* y, Eigen::VectorXd& a) const;

    const TransientProblem& p_;
    int n_ = 0;
    int nc_ = 0;
    Eigen::MatrixXd C_;              // alpha M + beta K
    Eigen::MatrixXd Minv_;           // M^-1 (from the Cholesky factor of M)
    Eigen::MatrixXd MinvK_, MinvC_;  // M^-1 K, M^-1 C
    Eigen::MatrixXd MinvE_;          // column j: M^-1 e_dof(j)
    Eigen::MatrixXd MinvQ_;          // column k: M^-1 amplitude_k shape_k
    bool damped_ = false;
    // Current piece: v' = -A q - B v + c + sum_k g_k(t) MinvQ_k.
    std::vector<bool> active_;
    Eigen::MatrixXd A_, B_;
    Eigen::VectorXd c_;
    double t_limit_ = 0.0;
    mutable Eigen::VectorXd acc_;    // scratch for events()
};

// Throws std::invalid_argument when p is inconsistent (sizes, DOF indices, signs, horizon).
void validate(const TransientProblem& p);

// CVODE callbacks; user_data is the CvodeSystem. They never let an exception into the C library:
// one becomes an unrecoverable error (-1) and CVODE fails.
int rhs_fn(realtype t, N_Vector y, N_Vector ydot, void* user_data);
int jac_fn(realtype t, N_Vector y, N_Vector fy, SUNMatrix J, void* user_data, N_Vector, N_Vector, N_Vector);
int root_fn(realtype t, N_Vector y, realtype* g, void* user_data);

}  // namespace vi::cvode_detail
