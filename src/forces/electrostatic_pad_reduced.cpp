// ElectrostaticPad on a reduced basis (ForceElement::reduced): the same Gauss points and the same
// integrand as the pad's own evaluation, with the beam's deflection at the points taken from the
// basis coordinates through the basis' values there, kept from the start.

#include <Eigen/Dense>

#include "forces/electrostatic_pad.hpp"

namespace vi {

class ReducedPad final : public ReducedElement {
public:
    ReducedPad(const ElectrostaticPad& pad, const BasisRows& rows);

    double add_force_and_power(const ReducedState& s, int mode, double* force) const override;
    void add_tangent(const ReducedState& s, int mode, double* dfdq, double* dfdv) const override;
    [[nodiscard]] double input_power(const ReducedState& s, int mode) const override;
    [[nodiscard]] double switching_function(const ReducedState& s, int mode) const override;

private:
    // g_e at every point into gap_, refusing as the pad does (the first point in the pad's order)
    // where the beam has reached the face.
    void gaps(const double* eta) const;
    [[nodiscard]] double capacitance() const;

    const ElectrostaticPad& pad_;
    // sign x the basis' deflection at each point per unit of each coordinate (Nq x r): g_e = rest -
    // values eta, and the force on the basis is values^T of the point loads along +g_e's pull.
    Eigen::MatrixXd values_;
    Eigen::VectorXd weights_;  // the points' lengths [m]
    mutable Eigen::VectorXd gap_, load_;
    mutable Eigen::MatrixXd weighted_;
};

ReducedPad::ReducedPad(const ElectrostaticPad& pad, const BasisRows& rows) : pad_(pad) {
    const Eigen::Map<const Eigen::MatrixXd> P(rows.data, static_cast<Eigen::Index>(rows.dofs),
                                              static_cast<Eigen::Index>(rows.size));
    const std::vector<PadPoint>& points = pad.points_;
    const Eigen::Index nq = static_cast<Eigen::Index>(points.size());
    values_ = Eigen::MatrixXd::Zero(nq, P.cols());
    weights_.resize(nq);
    for (Eigen::Index k = 0; k < nq; ++k) {
        const PadPoint& p = points[static_cast<std::size_t>(k)];
        for (int i = 0; i < 4; ++i) {
            if (p.local[i] >= 0) values_.row(k) += (pad.geometry_.sign * p.shape[i]) * P.row(p.local[i]);
        }
        weights_[k] = p.weight;
    }
    gap_.resize(nq);
    load_.resize(nq);
}

void ReducedPad::gaps(const double* eta) const {
    gap_.noalias() = values_ * Eigen::Map<const Eigen::VectorXd>(eta, values_.cols());
    gap_.array() = pad_.rest_gap_ - gap_.array();
    if ((gap_.array() > pad_.open_above_).all()) return;
    for (Eigen::Index k = 0; k < gap_.size(); ++k) pad_.require_open(pad_.points_[static_cast<std::size_t>(k)], gap_[k]);
}

double ReducedPad::capacitance() const {
    double c = 0.0;
    for (Eigen::Index k = 0; k < gap_.size(); ++k) c += line_capacitance(pad_.geometry_, gap_[k]).c * weights_[k];
    return c;
}

double ReducedPad::add_force_and_power(const ReducedState& s, int, double* force) const {
    const double v = pad_.voltage(s.t);
    if (v == 0.0) return 0.0;
    gaps(s.eta);
    // The pull along +g_e's decrease: V^2/2 |dc/dg_e| per length, as ElectrostaticPad::add_force.
    const double half_v2 = 0.5 * v * v;
    for (Eigen::Index k = 0; k < gap_.size(); ++k) {
        load_[k] = -half_v2 * line_capacitance(pad_.geometry_, gap_[k]).dc * weights_[k];
    }
    Eigen::Map<Eigen::VectorXd>(force, values_.cols()).noalias() += values_.transpose() * load_;
    return 0.0;
}

void ReducedPad::add_tangent(const ReducedState& s, int, double* dfdq, double*) const {
    const double v = pad_.voltage(s.t);
    if (v == 0.0) return;
    gaps(s.eta);
    const double half_v2 = 0.5 * v * v;
    for (Eigen::Index k = 0; k < gap_.size(); ++k) {
        load_[k] = half_v2 * line_capacitance(pad_.geometry_, gap_[k]).d2c * weights_[k];
    }
    weighted_.noalias() = load_.asDiagonal() * values_;
    const Eigen::Index r = values_.cols();
    // Symmetric: the row-major and column-major layouts hold the same numbers.
    Eigen::Map<Eigen::MatrixXd>(dfdq, r, r).noalias() += values_.transpose() * weighted_;
}

double ReducedPad::input_power(const ReducedState& s, int) const {
    const double v = pad_.voltage(s.t);
    const double rate = pad_.voltage_ * pad_.time_.slope(s.t);
    if (v == 0.0 || rate == 0.0) return 0.0;
    gaps(s.eta);
    return -capacitance() * v * rate;
}

double ReducedPad::switching_function(const ReducedState& s, int mode) const {
    if (mode != 0 || !(pad_.collapse_gap_ > 0.0)) return -1.0;
    gap_.noalias() = values_ * Eigen::Map<const Eigen::VectorXd>(s.eta, values_.cols());
    // The narrowest air gap as ElectrostaticPad::narrowest: the smallest g_e less the layer.
    const double least = pad_.rest_gap_ - gap_.maxCoeff();
    const PadGeometry& g = pad_.geometry_;
    return (pad_.collapse_gap_ - (least - g.dielectric_thickness / g.dielectric_permittivity)) / g.gap;
}

std::unique_ptr<const ReducedElement> ElectrostaticPad::reduced(const BasisRows& rows) const {
    return std::make_unique<ReducedPad>(*this, rows);
}

}  // namespace vi
