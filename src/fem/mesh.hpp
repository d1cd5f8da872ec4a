#pragma once
// Mesh: node coordinates along the beam, a uniform grid with one node exactly at each support and at
// each boundary between two sections.

#include <vector>

#include "model/case.hpp"

namespace vi {

// Nodes along x in increasing order; element e joins nodes e and e + 1.
struct Mesh {
    std::vector<double> x;             // node coordinates [m]
    std::vector<int> support_nodes;    // node index of supports[k], in the Case's order
    [[nodiscard]] int node_count() const { return static_cast<int>(x.size()); }
    [[nodiscard]] int element_count() const { return node_count() - 1; }
    [[nodiscard]] double element_length(int e) const { return x[e + 1] - x[e]; }
};

// A support closer than this fraction of an element to a grid node shares that node: a sliver
// element that short would only spoil the conditioning, and moves the support by < 1e-9 l.
inline constexpr double kNodeMergeTolerance = 1e-9;

// A support within this fraction of an element of an interior grid node moves that node onto it
// (elements stay within 0.9..1.1 h there); farther away it gets a node of its own, inserted.
inline constexpr double kNodeMoveFraction = 0.1;

// Largest estimated condition of the bending stiffness, 5 l^4 / (L_min^3 h) (h = l/m, L_min the shortest
// element; 5 m^4 for a uniform mesh, docs/validation.md §1): beyond it K is lost to roundoff (a
// support 1e-5 l from the free end of m = 50 gives 2.5e17, and "not positive definite").
inline constexpr double kMaxMeshCondition = 1e15;

// Builds the mesh of m uniform elements and puts a node exactly at every support position. Throws
// InputError on the support whose node makes an element too short for kMaxMeshCondition.
Mesh build_mesh(const Beam& beam, const std::vector<Support>& supports);

// Index of the element holding coordinate x [m] and the local coordinate xi in [0, 1] there.
struct ElementPoint {
    int element = 0;
    double xi = 0.0;
};
ElementPoint locate(const Mesh& mesh, double x);

}  // namespace vi
