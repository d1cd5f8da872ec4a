#include "statics/layer_hold.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "fem/beam_element.hpp"
#include "forces/adhesive_layer_law.hpp"
#include "model/run_control.hpp"

namespace vi {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Bisections on a position along the beam: 2^-100 of it is far below rounding.
constexpr int kBisections = 100;
// The free sections are cubics (no load on them), which Hermite elements hold exactly: a few will do.
constexpr int kSectionElements = 4;

// Release rate at a front at x of the part between the beam's end (left: x = 0, right: x = l) and x.
struct PeelSide {
    const Case& c;
    EndCondition end;
    bool left;
    double h;
    [[nodiscard]] PeelRate at(double x) const {
        if (end == EndCondition::free) return {};  // an unloaded overhang stays flat
        const double s = left ? x : c.beam.length - x;
        if (!(s > 0.0)) return {kInfinity, kInfinity, kInfinity};
        return peel_release_rate(c, end, s, h, kSectionElements, left);
    }
};

// With G decreasing in x on [a, b]: the smallest x in [a, b] with G(x) <= W (b when none).
double first_at_most(const PeelSide& side, double a, double b, double W) {
    if (side.at(a).release_rate <= W) return a;
    if (side.at(b).release_rate > W) return b;
    double lo = a, hi = b;
    for (int it = 0; it < kBisections && hi - lo > 1e-15 * (std::abs(lo) + std::abs(hi)); ++it) {
        const double mid = 0.5 * (lo + hi);
        (side.at(mid).release_rate > W ? lo : hi) = mid;
    }
    return hi;
}

// With G increasing in x: the largest x in [a, b] with G(x) <= W (a when none).
double last_at_most(const PeelSide& side, double a, double b, double W) {
    if (side.at(b).release_rate <= W) return b;
    if (side.at(a).release_rate > W) return a;
    double lo = a, hi = b;
    for (int it = 0; it < kBisections && hi - lo > 1e-15 * (std::abs(lo) + std::abs(hi)); ++it) {
        const double mid = 0.5 * (lo + hi);
        (side.at(mid).release_rate > W ? hi : lo) = mid;
    }
    return lo;
}

}  // namespace

SectionResultants electrode_section(const Case& c, std::size_t k) {
    const Electrode& e = c.electrodes.at(k);
    return beam_sections(c)[section_index_at(c.beam, 0.5 * (e.from + e.to))];
}

double layer_contact_width(const Case& c, std::size_t k) {
    const Electrode& e = c.electrodes.at(k);
    const SectionResultants under = electrode_section(c, k);
    // Release holes take their area out of the layer's contact as out of the electrode's force
    // (problem/electrode_elements.cpp).
    return (e.width > 0.0 ? e.width : under.width) * under.solid_fraction;
}

std::vector<BeamSection> part_sections(const Beam& b, double s, bool from_left) {
    std::vector<BeamSection> out;
    const double l = b.length;
    for (std::size_t i = 0; i < b.sections.size(); ++i) {
        const BeamSection& k = b.sections[from_left ? i : b.sections.size() - 1 - i];
        // Its ends as distances from the held end [m]; the far end's section goes on past the beam.
        const double near = from_left ? k.from * l : (1.0 - k.to) * l;
        const bool last = i + 1 == b.sections.size();
        const double far = last ? std::max(s, l) : (from_left ? k.to * l : (1.0 - k.from) * l);
        if (!(near < s)) break;
        BeamSection part = k;
        part.from = out.empty() ? 0.0 : out.back().to;
        part.to = far >= s ? 1.0 : far / s;
        out.push_back(std::move(part));
        if (far >= s) break;
    }
    return out;
}

PeelRate peel_release_rate(const Case& c, EndCondition end, double s, double offset, int elements, bool from_left) {
    if (end == EndCondition::free) throw std::invalid_argument("peel_release_rate: a free end holds nothing");
    Case span = c;
    span.beam.sections = part_sections(c.beam, s, from_left);
    span.beam.length = s;
    span.beam.elements = elements;
    span.beam.left = end;
    span.beam.right = EndCondition::free;
    span.beam.residual_stress = 0.0;
    span.beam.stretching = false;
    span.supports.clear();
    span.electrodes.clear();
    span.loads.clear();
    span.films.clear();
    const System sys = build_system(span, SupportModel::none);
    const Eigen::MatrixXd K(sys.K);
    const int last = sys.mesh.node_count() - 1;
    const int rv = sys.reduced_of[static_cast<std::size_t>(global_dof(last, 1))];
    const int rt = sys.reduced_of[static_cast<std::size_t>(global_dof(last, 2))];
    const Eigen::Index n = K.rows();
    // The free DOFs are all but the held end's v and theta: K_ff q_f = -K_fp q_p.
    std::vector<Eigen::Index> free;
    for (Eigen::Index i = 0; i < n; ++i) {
        if (i != rv && i != rt) free.push_back(i);
    }
    const auto m = static_cast<Eigen::Index>(free.size());
    Eigen::MatrixXd Kff(m, m);
    Eigen::VectorXd rhs(m);
    for (Eigen::Index a = 0; a < m; ++a) {
        rhs[a] = K(free[static_cast<std::size_t>(a)], rv) * offset;  // -K_fp q_p with q_p = (-offset, 0)
        for (Eigen::Index b = 0; b < m; ++b) Kff(a, b) = K(free[static_cast<std::size_t>(a)], free[static_cast<std::size_t>(b)]);
    }
    const Eigen::VectorXd qf = Kff.ldlt().solve(rhs);
    Eigen::VectorXd q = Eigen::VectorXd::Zero(n);
    for (Eigen::Index a = 0; a < m; ++a) q[free[static_cast<std::size_t>(a)]] = qf[a];
    q[rv] = -offset;
    PeelRate r;
    r.moment = K.row(rt).dot(q);
    r.shear = K.row(rv).dot(q);
    r.release_rate = r.moment * r.moment / (2.0 * sys.section_of(sys.mesh.element_count() - 1).EI);
    return r;
}

LayerHold layer_hold(const Case& c, std::size_t k) {
    if (k >= c.electrodes.size() || !c.electrodes[k].work_of_adhesion || !(c.electrodes[k].dielectric_thickness > 0.0)) {
        throw std::invalid_argument("layer_hold: electrodes[" + std::to_string(k) + "] has no adhesive layer");
    }
    const Electrode& e = c.electrodes[k];
    const double l = c.beam.length;
    const SectionResultants under = electrode_section(c, k);
    const double contact_width = layer_contact_width(c, k);
    LayerHold h;
    h.electrode = k;
    h.air_gap = e.gap - e.dielectric_thickness;
    h.adhesion_energy = *e.work_of_adhesion * contact_width;
    const double EI = under.EI;
    h.holding_moment = std::sqrt(2.0 * EI * h.adhesion_energy);
    h.span_from = e.from * l;
    h.span_to = e.to * l;
    const PeelSide left{c, c.beam.left, true, h.air_gap};
    const PeelSide right{c, c.beam.right, false, h.air_gap};
    const double a = h.span_from, b = h.span_to, W = h.adhesion_energy;
    h.release_from = left.at(a).release_rate;
    h.release_to = right.at(b).release_rate;
    // Each edge peels while it releases more than W: G_left falls as its front moves right (a longer
    // free part), G_right rises.
    h.contact_from = first_at_most(left, a, b, W);
    h.contact_to = last_at_most(right, a, b, W);
    h.sticks = h.contact_from < h.contact_to && left.at(h.contact_from).release_rate <= W &&
               right.at(h.contact_to).release_rate <= W;
    const double x0 = h.sticks ? h.contact_from : a, x1 = h.sticks ? h.contact_to : b;
    h.restoring_force = std::abs(left.at(x0).shear) + std::abs(right.at(x1).shear);
    if (!h.sticks) h.contact_from = h.contact_to = 0.0;
    const double stiffness = e.dielectric_modulus * contact_width / e.dielectric_thickness;
    const AdhesiveLayerLaw law(stiffness, W, e.adhesion_range);
    h.even_pull_off_force = h.sticks ? law.largest_pull() * (h.contact_to - h.contact_from) : 0.0;
    // Some contact stays exactly when an x in [a, b] has both G_left(x) and G_right(x) <= W: the least
    // W for which one does is the least over x of max(G_left, G_right), where the falling G_left meets
    // the rising G_right (or at an end of the span).
    double lo = a, hi = b;
    const auto gap_at = [&](double x) { return left.at(x).release_rate - right.at(x).release_rate; };
    if (gap_at(b) > 0.0) {
        lo = hi = b;
    } else if (gap_at(a) <= 0.0) {
        lo = hi = a;
    } else {
        for (int it = 0; it < kBisections && hi - lo > 1e-15 * (std::abs(lo) + std::abs(hi)); ++it) {
            check_run();
            const double mid = 0.5 * (lo + hi);
            (gap_at(mid) > 0.0 ? lo : hi) = mid;
        }
    }
    const double x = 0.5 * (lo + hi);
    h.critical_work_of_adhesion = std::max(left.at(x).release_rate, right.at(x).release_rate) / contact_width;
    return h;
}

Eigen::VectorXd held_flat(const System& s, const SparseMatrix& K_b, double from, double to, double height) {
    const auto n = static_cast<Eigen::Index>(s.bending.size());
    std::vector<int> position(static_cast<std::size_t>(s.size()), -1);
    for (std::size_t i = 0; i < s.bending.size(); ++i) position[static_cast<std::size_t>(s.bending[i])] = static_cast<int>(i);
    Eigen::VectorXd q = Eigen::VectorXd::Zero(n);
    std::vector<bool> held(static_cast<std::size_t>(n), false);
    for (int node = 0; node < s.mesh.node_count(); ++node) {
        const double x = s.mesh.x[static_cast<std::size_t>(node)];
        if (x < from || x > to) continue;
        for (int comp = 1; comp <= 2; ++comp) {
            const int r = s.reduced_of[static_cast<std::size_t>(global_dof(node, comp))];
            if (r < 0) continue;
            const int b = position[static_cast<std::size_t>(r)];
            held[static_cast<std::size_t>(b)] = true;
            q[b] = comp == 1 ? height : 0.0;
        }
    }
    std::vector<int> free;
    for (Eigen::Index i = 0; i < n; ++i) {
        if (!held[static_cast<std::size_t>(i)]) free.push_back(static_cast<int>(i));
    }
    if (free.empty()) return q;
    const SparseMatrix Kff = submatrix(K_b, free);
    Eigen::VectorXd rhs = -(K_b * q);
    Eigen::VectorXd rf(static_cast<Eigen::Index>(free.size()));
    for (std::size_t i = 0; i < free.size(); ++i) rf[static_cast<Eigen::Index>(i)] = rhs[free[i]];
    Eigen::SimplicialLDLT<SparseMatrix> ldlt(Kff);
    if (ldlt.info() != Eigen::Success) throw std::runtime_error("held_flat: the beam's free part is a mechanism");
    const Eigen::VectorXd qf = ldlt.solve(rf);
    for (std::size_t i = 0; i < free.size(); ++i) q[free[i]] = qf[static_cast<Eigen::Index>(i)];
    return q;
}

std::optional<std::pair<double, double>> layer_contact(const Case& c, std::size_t k, const System& s,
                                                       const Eigen::VectorXd& q) {
    const Electrode& e = c.electrodes.at(k);
    const double sign = e.side == Side::above ? 1.0 : -1.0;
    const double face = e.gap - e.dielectric_thickness;
    const double from = e.from * s.length, to = e.to * s.length;
    Eigen::VectorXd reduced = Eigen::VectorXd::Zero(s.size());
    for (std::size_t i = 0; i < s.bending.size(); ++i) reduced[s.bending[i]] = q[static_cast<Eigen::Index>(i)];
    const auto d = [&](double x) { return sign * transverse_displacement(s, reduced, x) - face; };
    // Sample each element's part of the span finely enough that a contact of a few elements' width is
    // seen, then bisect the sign change next to the first and last touching sample.
    constexpr int kSamples = 64;
    std::vector<double> xs;
    for (int el = 0; el < s.mesh.element_count(); ++el) {
        const double x0 = std::max(from, s.mesh.x[static_cast<std::size_t>(el)]);
        const double x1 = std::min(to, s.mesh.x[static_cast<std::size_t>(el) + 1]);
        if (!(x1 > x0)) continue;
        for (int i = 0; i < kSamples; ++i) xs.push_back(x0 + (x1 - x0) * i / kSamples);
    }
    xs.push_back(to);
    std::optional<std::size_t> first, last;
    for (std::size_t i = 0; i < xs.size(); ++i) {
        if (d(xs[i]) >= 0.0) {
            if (!first) first = i;
            last = i;
        }
    }
    if (!first) return std::nullopt;
    const auto edge = [&](double out, double in) {  // d(out) < 0 <= d(in)
        for (int it = 0; it < kBisections && std::abs(in - out) > 1e-15 * s.length; ++it) {
            const double mid = 0.5 * (out + in);
            (d(mid) >= 0.0 ? in : out) = mid;
        }
        return in;
    };
    const double x0 = *first == 0 ? xs.front() : edge(xs[*first - 1], xs[*first]);
    const double x1 = *last + 1 == xs.size() ? xs.back() : edge(xs[*last + 1], xs[*last]);
    return std::make_pair(x0, x1);
}

}  // namespace vi
