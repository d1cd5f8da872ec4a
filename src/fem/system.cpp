#include "fem/system.hpp"

#include <stdexcept>
#include <string>

namespace vi {
namespace {

std::vector<bool> constrained_dofs(const Case& c, const Mesh& mesh, SupportModel model) {
    std::vector<bool> fixed(static_cast<std::size_t>(3 * mesh.node_count()), false);
    auto apply_end = [&](int node, EndCondition ec) {
        if (ec == EndCondition::free) return;
        fixed[global_dof(node, 0)] = true;
        fixed[global_dof(node, 1)] = true;
        if (ec == EndCondition::clamped) fixed[global_dof(node, 2)] = true;
    };
    apply_end(0, c.beam.left);
    apply_end(mesh.node_count() - 1, c.beam.right);
    if (model == SupportModel::pin) {
        for (int node : mesh.support_nodes) fixed[global_dof(node, 1)] = true;
    }
    return fixed;
}

}  // namespace

System build_system(const Case& c, SupportModel model) {
    System s;
    s.mesh = build_mesh(c.beam, c.supports);
    s.length = c.beam.length;
    s.left = c.beam.left;
    s.right = c.beam.right;
    s.props = {c.material.effective_modulus(), c.beam.area(), c.beam.second_moment(), c.material.density};
    s.sections = beam_sections(c);
    s.sectioned = !c.beam.sections.empty();
    std::vector<ElementProperties> per_section;
    for (std::size_t k = 0; k < s.sections.size(); ++k) {
        const bool layered = k < c.beam.sections.size() && !c.beam.sections[k].layers.empty();
        per_section.push_back(c.beam.sections.empty() ? s.props : element_properties(c, s.sections[k], layered));
    }
    for (int e = 0; e < s.mesh.element_count(); ++e) {
        const double mid = 0.5 * (s.mesh.x[static_cast<std::size_t>(e)] + s.mesh.x[static_cast<std::size_t>(e) + 1]);
        const std::size_t k = section_index_at(c.beam, mid / c.beam.length);
        s.element_section.push_back(static_cast<int>(k));
        s.element_props.push_back(per_section[k]);
    }
    s.total_dofs = 3 * s.mesh.node_count();

    const std::vector<bool> fixed = constrained_dofs(c, s.mesh, model);
    s.reduced_of.assign(static_cast<std::size_t>(s.total_dofs), -1);
    for (int g = 0; g < s.total_dofs; ++g) {
        if (fixed[g]) continue;
        s.reduced_of[g] = static_cast<int>(s.free_dofs.size());
        s.free_dofs.push_back(g);
        (g % 3 == 0 ? s.axial : s.bending).push_back(s.reduced_of[g]);
    }

    using Triplet = Eigen::Triplet<double>;
    std::vector<Triplet> kt;
    std::vector<Triplet> mt;
    std::vector<Triplet> gt;
    kt.reserve(static_cast<std::size_t>(36 * s.mesh.element_count()));
    mt.reserve(kt.capacity());
    gt.reserve(kt.capacity());
    // The residual stress's axial force: constant along a beam whose ends hold the axis (case checks
    // refuse it otherwise), so its geometric stiffness is linear and joins K.
    s.axial_force = held_axial_force(c, s.sections);
    for (int e = 0; e < s.mesh.element_count(); ++e) {
        const double L = s.mesh.element_length(e);
        const ElementMatrix ge = element_geometric_stiffness(L);
        const ElementProperties& p = s.element_props[static_cast<std::size_t>(e)];
        const ElementMatrix ke = element_stiffness(p, L) + s.axial_force * ge;
        const ElementMatrix me = element_mass(p, L);
        for (int i = 0; i < 6; ++i) {
            const int ri = s.reduced_of[3 * e + i];
            if (ri < 0) continue;
            for (int j = 0; j < 6; ++j) {
                const int rj = s.reduced_of[3 * e + j];
                if (rj < 0) continue;
                if (ke(i, j) != 0.0) kt.emplace_back(ri, rj, ke(i, j));
                if (me(i, j) != 0.0) mt.emplace_back(ri, rj, me(i, j));
                if (ge(i, j) != 0.0) gt.emplace_back(ri, rj, ge(i, j));
            }
        }
    }
    for (std::size_t k = 0; k < s.mesh.support_nodes.size(); ++k) {
        const int r = s.reduced_of[global_dof(s.mesh.support_nodes[k], 1)];
        s.support_dof.push_back(r);
        if (model == SupportModel::spring && r >= 0) kt.emplace_back(r, r, c.supports[k].stiffness);
    }
    const int n = s.size();
    s.K.resize(n, n);
    s.M.resize(n, n);
    s.G.resize(n, n);
    s.K.setFromTriplets(kt.begin(), kt.end());
    s.M.setFromTriplets(mt.begin(), mt.end());
    s.G.setFromTriplets(gt.begin(), gt.end());
    return s;
}

SparseMatrix submatrix(const SparseMatrix& a, const std::vector<int>& idx) {
    std::vector<int> pos(static_cast<std::size_t>(a.rows()), -1);
    for (std::size_t i = 0; i < idx.size(); ++i) pos[idx[i]] = static_cast<int>(i);
    std::vector<Eigen::Triplet<double>> t;
    for (int col = 0; col < a.outerSize(); ++col) {
        if (pos[col] < 0) continue;
        for (SparseMatrix::InnerIterator it(a, col); it; ++it) {
            if (pos[it.row()] >= 0) t.emplace_back(pos[it.row()], pos[col], it.value());
        }
    }
    const auto n = static_cast<Eigen::Index>(idx.size());
    SparseMatrix out(n, n);
    out.setFromTriplets(t.begin(), t.end());
    return out;
}

Eigen::VectorXd expand_to_global(const System& s, const Eigen::VectorXd& reduced) {
    Eigen::VectorXd g = Eigen::VectorXd::Zero(s.total_dofs);
    for (int r = 0; r < s.size(); ++r) g[s.free_dofs[r]] = reduced[r];
    return g;
}

std::vector<int> bending_positions(const System& s) {
    std::vector<int> pos(static_cast<std::size_t>(s.size()), -1);
    for (std::size_t i = 0; i < s.bending.size(); ++i) pos[static_cast<std::size_t>(s.bending[i])] = static_cast<int>(i);
    return pos;
}

Eigen::VectorXd on_bending(const System& s, const Eigen::VectorXd& reduced) {
    Eigen::VectorXd out(static_cast<Eigen::Index>(s.bending.size()));
    for (std::size_t i = 0; i < s.bending.size(); ++i) out[static_cast<Eigen::Index>(i)] = reduced[s.bending[i]];
    return out;
}

Eigen::VectorXd unit_point_load(const System& s, double position) {
    return on_bending(s, transverse_point_load(s, position * s.length, 1.0));
}

Eigen::VectorXd transverse_point_load(const System& s, double x, double f) {
    const ElementPoint p = locate(s.mesh, x);
    const double L = s.mesh.element_length(p.element);
    const double xi = p.xi;
    // Work-equivalent nodal forces and moments: the Hermite shape functions at xi.
    const double n[4] = {1 - 3 * xi * xi + 2 * xi * xi * xi, L * (xi - 2 * xi * xi + xi * xi * xi),
                         3 * xi * xi - 2 * xi * xi * xi, L * (-xi * xi + xi * xi * xi)};
    const int g[4] = {global_dof(p.element, 1), global_dof(p.element, 2), global_dof(p.element + 1, 1),
                      global_dof(p.element + 1, 2)};
    Eigen::VectorXd load = Eigen::VectorXd::Zero(s.size());
    for (int i = 0; i < 4; ++i) {
        const int r = s.reduced_of[g[i]];
        if (r >= 0) load[r] += f * n[i];
    }
    return load;
}

double transverse_displacement(const System& s, const Eigen::VectorXd& reduced, double x) {
    const ElementPoint p = locate(s.mesh, x);
    auto value = [&](int node, int comp) {
        const int r = s.reduced_of[global_dof(node, comp)];
        return r >= 0 ? reduced[r] : 0.0;
    };
    const int a = p.element;
    return hermite_v(p.xi, s.mesh.element_length(a), value(a, 1), value(a, 2), value(a + 1, 1), value(a + 1, 2));
}

double beam_mass(const System& s) {
    if (!s.sectioned) return s.props.rho * s.props.A * s.length;
    double mass = 0.0;
    for (int e = 0; e < s.mesh.element_count(); ++e) mass += s.section_of(e).rho_A * s.mesh.element_length(e);
    return mass;
}

const SectionResultants& section_at(const System& s, double x) {
    return s.section_of(locate(s.mesh, x).element);
}

Eigen::VectorXd solve_static(const System& s, const Eigen::VectorXd& load) {
    Eigen::SimplicialLDLT<SparseMatrix> ldlt(s.K);
    if (ldlt.info() != Eigen::Success) throw std::runtime_error("static solve: stiffness matrix is singular");
    // Pivots compared with their own diagonal entries: u, v and theta rows differ by many decades.
    const Eigen::VectorXd diag = ldlt.permutationP() * Eigen::VectorXd(s.K.diagonal());
    const Eigen::VectorXd d = ldlt.vectorD();
    for (Eigen::Index i = 0; i < d.size(); ++i) {
        if (!(d[i] > 1e-12 * diag[i])) {
            throw std::runtime_error("static solve: stiffness matrix is singular (the structure is a mechanism)");
        }
    }
    return ldlt.solve(load);
}

}  // namespace vi
