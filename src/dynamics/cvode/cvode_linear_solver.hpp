#pragma once
// The Newton matrix of the modal first-order form and its solver, as a SUNDIALS SUNMatrix and
// SUNLinearSolver of their own. The Jacobian is kept in pieces: the diagonal linear part (w^2 and
// the Rayleigh D of each basis vector) and each element's small tangent blocks on its DOFs. Solving
// (b I + a J) x = r eliminates the displacements, leaving (Delta + P^T W P) x_v = ..., a diagonal
// Delta plus a low-rank term from the elements, solved by Sherman-Morrison-Woodbury in O(r s^2) for
// s element DOFs (or densely when s is large). On a nodal basis (the state in the FE DOFs) the
// tangents are summed on the FE DOFs and the banded Newton matrix is factorised there
// (physical_newton.hpp). Internal to the CVODE solver.

#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "dynamics/cvode/cvode_system.hpp"

namespace vi::cvode_detail {

// The elements' tangents at one state: d f_e / d q_e and d f_e / d v_e per element (row-major
// |D_e| x |D_e|; empty or zero: no tangent).
struct ElementTangents {
    std::vector<Eigen::MatrixXd> dfdq, dfdv;
    // The projected tangents of the elements evaluated on the basis, summed (r x r; empty: none).
    Eigen::MatrixXd modal_q, modal_v;
    // On a nodal basis instead: their sums on the FE DOFs (n x n).
    Eigen::SparseMatrix<double> Fq, Fv;
};

// The matrix a J + b I. J is filled by the Jacobian callback (a = 1, b = 0 then); CVODE forms
// I - gamma J from it with SUNMatCopy and SUNMatScaleAddI. The tangents are shared, never changed
// once made: a copy costs a pointer, and the solver knows a Jacobian it has already projected.
struct StructuredJacobian {
    const ModalSystem* system = nullptr;
    double a = 0.0;
    double b = 0.0;
    std::shared_ptr<const ElementTangents> tangents;  // null: J has no element part
};

// A new SUNMatrix holding a StructuredJacobian of `system` (zero).
SUNMatrix structured_matrix(const ModalSystem& system, SUNContext ctx);
// The matrix's content.
StructuredJacobian& structured_content(SUNMatrix A);
// A direct SUNLinearSolver for such matrices.
SUNLinearSolver structured_solver(const ModalSystem& system, SUNContext ctx);

}  // namespace vi::cvode_detail
