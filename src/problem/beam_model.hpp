#pragma once
// BeamModel: what a case describes, built once (the beam's matrices over its bending DOFs, its
// Rayleigh damping, its force elements with their names, the watched point); every analysis starts
// from it. How a transient starts (the static step, the release) is apart: dynamics/transient_start.

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "fem/rayleigh.hpp"
#include "fem/system.hpp"
#include "forces/element_family.hpp"
#include "forces/force_set.hpp"
#include "modal/eigen_solver.hpp"
#include "model/case.hpp"
#include "problem/film_elements.hpp"

namespace vi {

// The point whose motion the time history and the rebound y_max report: "tip" (a free end),
// "midspan" (a beam held at both ends) or "point" (initial.position on such a beam).
struct WatchedPoint {
    int dof = -1;                 // its v among the bending DOFs, -1 when none moves
    std::string name = "tip";
    double x_over_l = 1.0;        // where it sits, x/l
};

// A contact element of the force set with the case key it comes from; its index among the contacts
// is the index of its episodes (ContactEpisode::support) and of its columns in the time history.
struct NamedContact {
    std::string name;             // "supports[0]", "electrodes[1].dielectric"
    std::size_t element = 0;      // index in BeamModel::forces
    CaseEntry entry;              // the case entry it comes from ({"supports", 0}, {"electrodes", 1})
};

// M q'' + (alpha M + beta K) q' + K q = sum of the elements' forces, over the bending DOFs.
struct BeamModel {
    System system;                          // the beam without supports (they act as contact elements)
    Eigen::SparseMatrix<double> M;          // consistent mass over system.bending [kg]
    Eigen::SparseMatrix<double> K;          // stiffness over system.bending [N/m]
    std::vector<int> bending_position;      // each reduced DOF's place among the bending DOFs, -1 if axial
    std::vector<bool> is_v;                 // which bending DOFs are transverse (not rotations)
    ModeSet modes;                          // the lowest unsupported bending modes the case refers to
    double omega1 = 0.0;                    // first unsupported bending circular frequency [rad/s]
    RayleighCoefficients rayleigh;          // alpha, beta actually used
    ForceSet forces;                        // every force element, family by family (problem/element_families.cpp)
    std::vector<NamedContact> contacts;     // the contact elements, in the order of `forces`
    std::vector<double> contact_stiffness;  // Kc per support [N/m]; NaN for a law other than the linear one
    std::vector<double> contact_damping;    // Cc per support [N s/m] (from damping_ratio where given); NaN likewise
    std::vector<FilmRegime> films;          // each squeeze film's regime at rest, at omega1
    WatchedPoint watched;
    // The contact element of case key `name` ("supports[1]"), or nullptr.
    [[nodiscard]] const NamedContact* contact(const std::string& name) const;
};

// Builds the model of c. Throws InputError ("key: reason") when the case fails check_case or names
// what the model cannot have (a support on a fixed DOF, a mode that does not exist, Rayleigh ratios
// that damp negatively), and std::runtime_error when a numerical step fails.
BeamModel build_beam_model(const Case& c);

// The watched point's name and place for c, without building anything.
WatchedPoint watched_point_of(const Case& c);

}  // namespace vi
