#include "statics/contact_hold.hpp"

#include <Eigen/SparseCholesky>
#include <stdexcept>
#include <string>

namespace vi {

ContactHold contact_hold(const System& s, const Case& c, std::size_t k) {
    if (k >= c.supports.size() || k >= s.support_dof.size()) {
        throw std::out_of_range("contact_hold: supports[" + std::to_string(k) + "] does not exist");
    }
    const int dof = s.support_dof[k];
    if (dof < 0) throw std::runtime_error("contact_hold: v is held by an end condition at supports[" + std::to_string(k) + "]");
    Eigen::SimplicialLDLT<SparseMatrix> ldlt(s.K);
    if (ldlt.info() != Eigen::Success) throw std::runtime_error("contact_hold: the stiffness matrix is singular");
    Eigen::VectorXd e = Eigen::VectorXd::Zero(s.K.rows());
    e[dof] = 1.0;
    const Eigen::VectorXd x = ldlt.solve(e);
    const Support& sup = c.supports[k];
    ContactHold h;
    h.point_stiffness = 1.0 / x[dof];
    // Support::surface is the height of the surface on its own side (-gap), so the surface lies
    // -surface from the rest position, toward the support, on either side.
    h.held_offset = -sup.surface;
    h.restoring_force = h.point_stiffness * h.held_offset;
    h.pull_off_force = sup.pull_off_force();
    return h;
}

}  // namespace vi
