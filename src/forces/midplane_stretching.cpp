#include "forces/midplane_stretching.hpp"

#include <cmath>
#include <memory>
#include <numeric>
#include <stdexcept>

namespace vi {

MidplaneStretching::MidplaneStretching(std::string name, Eigen::SparseMatrix<double> g, double axial_stiffness)
    : name_(std::move(name)), g_(std::move(g)), axial_stiffness_(axial_stiffness) {
    if (g_.rows() != g_.cols() || !(axial_stiffness_ > 0.0) || !std::isfinite(axial_stiffness_)) {
        throw std::invalid_argument(name_ + ": inconsistent mid-plane stretching data");
    }
    dofs_.resize(static_cast<std::size_t>(g_.rows()));
    std::iota(dofs_.begin(), dofs_.end(), 0);
}

Eigen::VectorXd MidplaneStretching::slope_product(const double* q) const {
    // O(nnz): G is banded (one beam element couples two nodes).
    return g_ * Eigen::Map<const Eigen::VectorXd>(q, g_.rows());
}

double MidplaneStretching::axial_force(const double* q) const {
    const Eigen::VectorXd gq = slope_product(q);
    return 0.5 * axial_stiffness_ * Eigen::Map<const Eigen::VectorXd>(q, g_.rows()).dot(gq);
}

void MidplaneStretching::add_force(const ElementState& s, int, double* f) const {
    const Eigen::VectorXd gq = slope_product(s.q);
    const double n = 0.5 * axial_stiffness_ * Eigen::Map<const Eigen::VectorXd>(s.q, g_.rows()).dot(gq);
    Eigen::Map<Eigen::VectorXd>(f, g_.rows()) -= n * gq;
}

void MidplaneStretching::add_tangent(const ElementState& s, int, double* dfdq, double*) const {
    const Eigen::Index n = g_.rows();
    const Eigen::VectorXd gq = slope_product(s.q);
    const double force = 0.5 * axial_stiffness_ * Eigen::Map<const Eigen::VectorXd>(s.q, n).dot(gq);
    // Row-major n x n: the rank-one term from the force's change, then N G on G's pattern.
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> t(dfdq, n, n);
    t.noalias() -= axial_stiffness_ * gq * gq.transpose();
    for (Eigen::Index col = 0; col < g_.outerSize(); ++col) {
        for (Eigen::SparseMatrix<double>::InnerIterator it(g_, col); it; ++it) t(it.row(), col) -= force * it.value();
    }
}

double MidplaneStretching::stored_energy(const ElementState& s, int) const {
    const double n = axial_force(s.q);
    return 0.5 * n * n / axial_stiffness_;
}

namespace {

class Stretching final : public ElementFamily {
public:
    [[nodiscard]] std::string_view name() const override { return "mid-plane stretching"; }

    [[nodiscard]] std::vector<FamilyElement> elements(const ElementSource& src) const override {
        if (!src.c.beam.stretching) return {};
        const System& s = src.system;
        // The axis's lengthening, on every bending DOF; sections in series stretch as one spring of
        // compliance sum L_e / EA_e.
        double stiffness = s.props.E * s.props.A / s.length;
        if (s.sectioned) {
            double compliance = 0.0;
            for (int e = 0; e < s.mesh.element_count(); ++e) compliance += s.mesh.element_length(e) / s.section_of(e).EA;
            stiffness = 1.0 / compliance;
        }
        return {{std::make_shared<MidplaneStretching>("beam.stretching", submatrix(s.G, s.bending), stiffness),
                 {"beam", 0}}};
    }
};

}  // namespace

const ElementFamily& beam_stretching() {
    static const Stretching family;
    return family;
}

}  // namespace vi
