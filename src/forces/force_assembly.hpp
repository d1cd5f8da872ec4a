#pragma once
// One assembly of the force elements' terms: an element's state gathered from vectors of the beam
// (or of the DOFs several elements share), its force, tangent or stored energy evaluated in its own
// DOF order, and the result scattered back: the force added into a vector, the tangent as
// triplets. The static solutions, pull-in, the CVODE right-hand side and the ledgers all use it.

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <span>
#include <vector>

#include "forces/force_set.hpp"

namespace vi {

// Evaluates one element at a time. Its buffers are kept between elements and calls, so that a Newton
// step over an electrode's dense block, or a right-hand side of CVODE, allocates nothing.
class ElementAssembler {
public:
    // Element e's state at time t read from vectors indexed by `at` (the places of e's DOFs in them,
    // e.dofs() for vectors of the beam's DOFs): displacements q [m, rad], velocities v [m/s, rad/s]
    // (0 where null) and accelerations a (left null where null). `at` must outlive the scatters.
    const ElementState& gather(const ForceElement& e, std::span<const int> at, const double* q,
                               const double* v = nullptr, const double* a = nullptr, double t = 0.0);
    // The static state (v = 0, t = 0) of e from displacements q over the beam's DOFs.
    const ElementState& gather(const ForceElement& e, const Eigen::VectorXd& q) {
        return gather(e, e.dofs(), q.data());
    }
    // The state at rest at q = 0 (a contact's gap, a tangent at rest).
    const ElementState& gather_rest(const ForceElement& e);
    [[nodiscard]] const ElementState& state() const { return state_; }

    // The gathered element's force in `mode` [N, N m], in its DOF order.
    const std::vector<double>& force(int mode);
    // The same, and the power the element dissipates [W] (ForceElement::add_force_and_power).
    double force_and_power(int mode);
    // Its tangent in `mode`: d f / d q and d f / d v, row-major |dofs| x |dofs|.
    void tangent(int mode);
    [[nodiscard]] const std::vector<double>& dfdq() const { return dfdq_; }
    [[nodiscard]] const std::vector<double>& dfdv() const { return dfdv_; }
    // Sum of the entries of the last force: the net push of a point element.
    [[nodiscard]] double force_sum() const;

    // Adds factor x the last force into f at the gathered places.
    void scatter_force(double factor, double* f) const;
    void scatter_force(double factor, Eigen::VectorXd& f) const { scatter_force(factor, f.data()); }
    // Adds |factor x the last force| into m (the magnitudes of the terms a sum of forces rounds).
    void scatter_magnitude(double factor, Eigen::VectorXd& m) const;
    // Appends -factor x d f / d q's nonzero entries (what the element adds to the stiffness K) at the
    // gathered places.
    void scatter_stiffness(double factor, std::vector<Eigen::Triplet<double>>& triplets) const;

private:
    const ForceElement* element_ = nullptr;
    std::span<const int> at_;
    std::vector<double> q_, v_, a_, force_, dfdq_, dfdv_;
    ElementState state_;
};

// What the elements of a set add up to at one static state of the beam (v = 0, t = 0).
struct StaticSums {
    Eigen::VectorXd force;      // sum of the elements' forces [N, N m]
    Eigen::VectorXd magnitude;  // sum of the magnitudes of their terms per DOF, the roundoff scale of `force`
    std::vector<Eigen::Triplet<double>> stiffness;  // -d force / d q, the elements' share of the stiffness [N/m]
    double energy = 0.0;            // sum of the stored energies [J]
    double energy_magnitude = 0.0;  // sum of their magnitudes [J]
};

// The terms a static assembly computes besides the force.
struct StaticTerms {
    bool stiffness = false;
    bool energy = false;
};

// Every element of `forces` that acts in the static state (ForceElement::in_static_state), element i
// in modes[i], at displacements q.
StaticSums sum_static(const ForceSet& forces, const std::vector<int>& modes, const Eigen::VectorXd& q,
                      StaticTerms terms = {});

// Each element's static mode at q (ForceElement::static_mode); an element that does not act in the
// static state keeps current[i].
std::vector<int> static_modes(const ForceSet& forces, const Eigen::VectorXd& q, std::vector<int> current);

// K + the stiffness triplets, n x n.
Eigen::SparseMatrix<double> with_stiffness(const Eigen::SparseMatrix<double>& K,
                                           const std::vector<Eigen::Triplet<double>>& triplets);

}  // namespace vi
