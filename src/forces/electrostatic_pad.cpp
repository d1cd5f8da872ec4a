#include "forces/electrostatic_pad.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace vi {

std::vector<PointRun> point_runs(const std::vector<PadPoint>& points) {
    std::vector<PointRun> runs;
    for (std::size_t k = 0; k < points.size(); ++k) {
        if (runs.empty() || runs.back().local != points[k].local) runs.push_back({points[k].local, k, k});
        runs.back().end = k + 1;
    }
    return runs;
}

void add_fringing(const PadGeometry& g, double gap, LineCapacitance& out) {
    // eps0 (0.77 + 1.06 (w/g)^(1/4) + 1.06 (t/g)^(1/2)) and its derivatives in g.
    const double a = 1.06 * std::pow(g.width, 0.25), b = 1.06 * std::sqrt(g.beam_thickness);
    out.c += kEpsilon0 * (0.77 + a * std::pow(gap, -0.25) + b * std::pow(gap, -0.5));
    out.dc += kEpsilon0 * (-0.25 * a * std::pow(gap, -1.25) - 0.5 * b * std::pow(gap, -1.5));
    out.d2c += kEpsilon0 * (0.3125 * a * std::pow(gap, -2.25) + 0.75 * b * std::pow(gap, -2.5));
}

ElectrostaticPad::ElectrostaticPad(std::string name, std::vector<int> dofs, std::vector<PadPoint> points,
                                   PadGeometry geometry, double voltage, TimeFunction time)
    : name_(std::move(name)), dofs_(std::move(dofs)), points_(std::move(points)), geometry_(geometry),
      voltage_(voltage), time_(std::move(time)) {
    const PadGeometry& g = geometry_;
    if (points_.empty() || std::abs(g.sign) != 1.0 || !(g.gap > 0.0) || !(g.dielectric_thickness >= 0.0) ||
        !(g.dielectric_thickness < g.gap) || !(g.dielectric_permittivity >= 1.0) || !(g.width > 0.0) ||
        !std::isfinite(voltage_)) {
        throw std::invalid_argument(name_ + ": inconsistent electrostatic pad data");
    }
    for (const PadPoint& p : points_) {
        for (int l : p.local) {
            if (l >= static_cast<int>(dofs_.size())) throw std::invalid_argument(name_ + ": DOF index out of range");
        }
    }
    runs_ = point_runs(points_);
    layer_ = g.dielectric_thickness / g.dielectric_permittivity;
    rest_gap_ = (g.gap - g.dielectric_thickness) + layer_;
    // A dielectric is a contact (DielectricContact): the beam may press into it elastically, by far
    // less than its thickness; half its electrical thickness means the layer has failed. A bare
    // face stops the run where the beam reaches it.
    open_above_ = layer_ > 0.0 ? 0.5 * layer_ : 0.0;
    collapse_gap_ = layer_ > 0.0 ? 0.0 : kCollapseGapFraction * g.gap;
}

double ElectrostaticPad::switching_function(const ElementState& s, int mode) const {
    if (mode != 0 || !(collapse_gap_ > 0.0)) return -1.0;
    return (collapse_gap_ - narrowest(s.q).air_gap) / geometry_.gap;
}

int ElectrostaticPad::initial_mode(const ElementState& s) const {
    return switching_function(s, 0) >= 0.0 ? 1 : 0;
}

RunEnd ElectrostaticPad::run_end(const ElementState& s) const {
    const Narrowest n = narrowest(s.q);
    char buf[240];
    std::snprintf(buf, sizeof buf,
                  "the beam reached %s at x = %.4g um, t = %.4g us, V = %.4g V: its narrowest air gap fell to %.3g um, "
                  "%.3g of the %.3g um gap (collapse)",
                  name_.c_str(), n.x * 1e6, s.t * 1e6, voltage(s.t), n.air_gap * 1e6, n.air_gap / geometry_.gap,
                  geometry_.gap * 1e6);
    return RunEnd{"collapsed", n.x, n.air_gap, buf};
}

void ElectrostaticPad::refuse(const PadPoint& p, double ge) const {
    const double air = ge - layer_;
    if (layer_ > 0.0) {
        char buf[200];
        std::snprintf(buf, sizeof buf,
                      "the beam presses %.3g nm into the dielectric at x = %.4g um, half its electrical thickness: "
                      "raise dielectric_modulus or lower the voltage",
                      -air * 1e9, p.x * 1e6);
        throw std::domain_error(name_ + ": " + buf);
    }
    char buf[160];
    std::snprintf(buf, sizeof buf, "the beam reaches the electrode at x = %.4g um (air gap %.3g um)", p.x * 1e6, air * 1e6);
    throw std::domain_error(name_ + ": " + buf + "; a bare electrode face is not a contact: add a support that stops "
                                             "the beam before it, or a dielectric layer (docs/electrostatics.md)");
}

void ElectrostaticPad::add_force(const ElementState& s, int, double* f) const {
    const double v = voltage(s.t);
    if (v == 0.0) return;
    // f_i = dW*/dq_i, W* = V^2/2 int c(g_e) dx, dg_e/dq_i = -sign N_i.
    const double half_v2 = 0.5 * v * v;
    for (const PointRun& r : runs_) {
        const std::array<double, 4> qe = run_dofs(r, s.q);
        std::array<double, 4> fe{};
        for (std::size_t k = r.begin; k < r.end; ++k) {
            const PadPoint& p = points_[k];
            const double ge = run_gap(p, qe);
            require_open(p, ge);
            const double load = -half_v2 * line_capacitance(geometry_, ge).dc * geometry_.sign * p.weight;
            for (int i = 0; i < 4; ++i) fe[i] += load * p.shape[i];
        }
        for (int i = 0; i < 4; ++i) {
            if (r.local[i] >= 0) f[r.local[i]] += fe[i];
        }
    }
}

void ElectrostaticPad::add_tangent(const ElementState& s, int, double* dfdq, double*) const {
    const double v = voltage(s.t);
    if (v == 0.0) return;
    const std::size_t n = dofs_.size();
    const double half_v2 = 0.5 * v * v;
    for (const PadPoint& p : points_) {
        const double ge = electrical_gap(p, s.q);
        require_open(p, ge);
        // d f_i / d q_j = V^2/2 c''(g_e) N_i N_j (sign^2 = 1): a negative stiffness.
        add_point_stiffness(p, half_v2 * line_capacitance(geometry_, ge).d2c * p.weight, n, dfdq);
    }
}

double ElectrostaticPad::capacitance(const double* q) const {
    double c = 0.0;
    for (const PointRun& r : runs_) {
        const std::array<double, 4> qe = run_dofs(r, q);
        for (std::size_t k = r.begin; k < r.end; ++k) {
            const PadPoint& p = points_[k];
            const double ge = run_gap(p, qe);
            require_open(p, ge);
            c += line_capacitance(geometry_, ge).c * p.weight;
        }
    }
    return c;
}

double ElectrostaticPad::stored_energy(const ElementState& s, int) const {
    const double v = voltage(s.t);
    return v == 0.0 ? 0.0 : -0.5 * v * v * capacitance(s.q);
}

double ElectrostaticPad::input_power(const ElementState& s, int) const {
    const double v = voltage(s.t);
    const double rate = voltage_ * time_.slope(s.t);
    return v == 0.0 || rate == 0.0 ? 0.0 : -capacitance(s.q) * v * rate;
}

double ElectrostaticPad::force_scale() const {
    const double v = voltage_ * time_.max_abs();
    double f = 0.0;
    const PadGeometry& g = geometry_;
    const double ge = g.gap - g.dielectric_thickness + g.dielectric_thickness / g.dielectric_permittivity;
    for (const PadPoint& p : points_) f += -0.5 * v * v * line_capacitance(g, ge).dc * p.weight;
    return f;
}

ElectrostaticPad::Narrowest ElectrostaticPad::narrowest(const double* q) const {
    // The smallest g_e, then its air gap (subtracting the layer keeps the order).
    double least = std::numeric_limits<double>::infinity();
    double x = 0.0;
    for (const PointRun& r : runs_) {
        const std::array<double, 4> qe = run_dofs(r, q);
        for (std::size_t k = r.begin; k < r.end; ++k) {
            const double ge = run_gap(points_[k], qe);
            if (ge < least) least = ge, x = points_[k].x;
        }
    }
    const PadGeometry& g = geometry_;
    return {least - g.dielectric_thickness / g.dielectric_permittivity, x};
}

std::vector<double> ElectrostaticPad::mean_travel_row() const {
    std::vector<double> r(dofs_.size(), 0.0);
    const double length = geometry_.to - geometry_.from;
    for (const PadPoint& p : points_) {
        for (int i = 0; i < 4; ++i) {
            if (p.local[i] >= 0) r[static_cast<std::size_t>(p.local[i])] += geometry_.sign * p.weight * p.shape[i] / length;
        }
    }
    return r;
}

std::vector<std::vector<double>> line_load_patterns(const std::vector<PadPoint>& points, const PadGeometry& g,
                                                    std::size_t n) {
    return line_load_patterns(points, g.from, g.to, n);
}

std::vector<std::vector<double>> line_load_patterns(const std::vector<PadPoint>& points, double from, double to,
                                                    std::size_t n) {
    const double centre = 0.5 * (from + to);
    const double half = 0.5 * (to - from);
    std::vector<std::vector<double>> patterns(3, std::vector<double>(n, 0.0));
    for (const PadPoint& p : points) {
        const double xi = half > 0.0 ? (p.x - centre) / half : 0.0;
        const double moment[3] = {1.0, xi, xi * xi};
        for (std::size_t k = 0; k < 3; ++k) {
            for (int i = 0; i < 4; ++i) {
                if (p.local[i] >= 0) patterns[k][static_cast<std::size_t>(p.local[i])] += moment[k] * p.weight * p.shape[i];
            }
        }
    }
    return patterns;
}

std::vector<std::vector<double>> ElectrostaticPad::load_patterns() const {
    return line_load_patterns(points_, geometry_, dofs_.size());
}

}  // namespace vi
