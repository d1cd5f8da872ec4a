#pragma once
// System: the assembled FE model of one case: mesh, DOF maps, sparse K and M over the free DOFs.

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <vector>

#include "fem/beam_element.hpp"
#include "fem/mesh.hpp"
#include "fem/section_properties.hpp"
#include "model/case.hpp"

namespace vi {

// How supports enter the linear model: ignored, as pins v(x0) = 0, or as their contact springs Kc.
enum class SupportModel { none, pin, spring };

// Global DOF of component comp (0 = u axial, 1 = v transverse, 2 = theta rotation) at a node.
constexpr int global_dof(int node, int comp) { return 3 * node + comp; }

using SparseMatrix = Eigen::SparseMatrix<double>;

struct System {
    Mesh mesh;
    ElementProperties props;             // the plain [beam] of [material]: the reference section
    std::vector<SectionResultants> sections;        // the beam's sections (the plain one without [[beam.sections]])
    std::vector<int> element_section;               // each element's index into `sections`
    std::vector<ElementProperties> element_props;   // each element's properties
    double length = 0.0;                 // l [m]
    EndCondition left = EndCondition::clamped;   // end conditions, as in the case
    EndCondition right = EndCondition::free;
    int total_dofs = 0;                  // 3 x nodes, constrained included
    std::vector<int> free_dofs;          // global DOF of each reduced DOF, ascending
    std::vector<int> reduced_of;         // reduced index of each global DOF, -1 if constrained
    SparseMatrix K;                      // stiffness over free DOFs, residual stress's N0 G included [N/m]
    SparseMatrix G;                      // int N_i' N_j' dx over free DOFs (bending only): K's part per unit axial force [1/m]
    double axial_force = 0.0;            // N0 = residual_stress x A (layers: held_axial_force), tension positive [N]
    SparseMatrix M;                      // consistent mass over free DOFs [kg]
    std::vector<int> bending;            // reduced indices of v and theta DOFs, ascending
    std::vector<int> axial;              // reduced indices of u DOFs, ascending
    std::vector<int> support_dof;        // reduced index of v at each support, -1 where v is fixed
    [[nodiscard]] int size() const { return static_cast<int>(free_dofs.size()); }
    // The section under element e, and the beam's width there [m].
    [[nodiscard]] const SectionResultants& section_of(int e) const {
        return sections[static_cast<std::size_t>(element_section[static_cast<std::size_t>(e)])];
    }
    bool sectioned = false;              // whether the case describes the beam by [[beam.sections]]
};

// Assembles the case's beam with its end conditions and its supports as the given model.
System build_system(const Case& c, SupportModel model = SupportModel::none);

// The rows and columns idx of a sparse matrix, in the order given.
SparseMatrix submatrix(const SparseMatrix& a, const std::vector<int>& idx);

// A reduced vector scattered to all global DOFs (zero where constrained).
Eigen::VectorXd expand_to_global(const System& s, const Eigen::VectorXd& reduced);

// Consistent nodal load vector (reduced) of a transverse point force f [N] at coordinate x [m].
Eigen::VectorXd transverse_point_load(const System& s, double x, double f);

// Transverse displacement v [m] at coordinate x [m] from a reduced DOF vector.
double transverse_displacement(const System& s, const Eigen::VectorXd& reduced, double x);

// Position of each reduced DOF of s among its bending DOFs (s.bending), -1 for axial DOFs.
std::vector<int> bending_positions(const System& s);

// A reduced vector of s restricted to its bending DOFs.
Eigen::VectorXd on_bending(const System& s, const Eigen::VectorXd& reduced);

// Consistent load vector of a unit transverse force at x/l = position, over the bending DOFs; its
// dot product with a bending vector is v at that point.
Eigen::VectorXd unit_point_load(const System& s, double position);

// The beam's mass [kg]: rho A l of the plain beam; of a beam of sections, its elements' rho A L summed
// (the scale of dimensionless mode amplitudes, v sqrt(m) and theta l sqrt(m)).
double beam_mass(const System& s);

// The section under coordinate x [m] (the later one at a boundary node).
const SectionResultants& section_at(const System& s, double x);

// Static displacement K q = f over the free DOFs; throws std::runtime_error if K is singular.
Eigen::VectorXd solve_static(const System& s, const Eigen::VectorXd& load);

}  // namespace vi
