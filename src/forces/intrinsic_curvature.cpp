#include "forces/intrinsic_curvature.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "fem/system.hpp"
#include "model/case_schema.hpp"
#include "model/number_format.hpp"

namespace vi {

IntrinsicCurvature::IntrinsicCurvature(std::string name, std::vector<int> dofs, std::vector<double> load)
    : name_(std::move(name)), dofs_(std::move(dofs)), load_(std::move(load)) {
    if (dofs_.size() != load_.size() || !std::all_of(load_.begin(), load_.end(), [](double f) { return std::isfinite(f); })) {
        throw std::invalid_argument(name_ + ": inconsistent intrinsic curvature data");
    }
}

void IntrinsicCurvature::add_force(const ElementState&, int, double* f) const {
    for (std::size_t i = 0; i < load_.size(); ++i) f[i] += load_[i];
}

double IntrinsicCurvature::stored_energy(const ElementState& s, int) const {
    double work = 0.0;
    for (std::size_t i = 0; i < load_.size(); ++i) work += load_[i] * s.q[i];
    return -work;
}

double IntrinsicCurvature::force_scale() const {
    double largest = 0.0;
    for (const double f : load_) largest = std::max(largest, std::abs(f));
    return largest;
}

std::optional<LinearForm> IntrinsicCurvature::linear_form() const {
    return LinearForm{TimeForcing{dofs_, load_, 1.0, TimeFunction{}}};
}

namespace {

const char* const kSection = "curl";
const char* const kKeys[] = {"curvature", "stress_gradient", "tip_lift"};

const ParameterSet* curl_table(const Case& c) {
    const auto it = c.sections.find(kSection);
    return it == c.sections.end() || it->second.empty() ? nullptr : &it->second.front();
}

// The key of [curl] the case gives (the one a problem with the curl names), or "" when none.
std::string given_key(const ParameterSet& p) {
    for (const char* key : kKeys) {
        if (p.numbers.count(key) > 0) return key;
    }
    return "";
}

// The released shape over x/l = s is kappa0 l^2 P(s) with P cubic: P'' = 1 where the end takes no
// moment (free, pinned), P''' = 0 at a free end (no shear), P = 0 at a held end, P' = 0 at a clamped
// one. Its coefficients p0..p3; zero when the ends do not hold the beam (refused by the checks).
Eigen::Vector4d shape_coefficients(const Beam& b) {
    Eigen::Matrix4d a = Eigen::Matrix4d::Zero();
    Eigen::Vector4d rhs = Eigen::Vector4d::Zero();
    int row = 0;
    const auto end = [&](EndCondition e, double s) {
        const Eigen::RowVector4d value(1.0, s, s * s, s * s * s), slope(0.0, 1.0, 2.0 * s, 3.0 * s * s),
            curvature(0.0, 0.0, 2.0, 6.0 * s), shear(0.0, 0.0, 0.0, 6.0);
        const bool held = e != EndCondition::free;
        a.row(row) = held ? value : curvature;
        rhs[row++] = held ? 0.0 : 1.0;
        a.row(row) = e == EndCondition::clamped ? slope : e == EndCondition::pinned ? curvature : shear;
        rhs[row++] = e == EndCondition::pinned ? 1.0 : 0.0;
    };
    end(b.left, 0.0);
    end(b.right, 1.0);
    const Eigen::FullPivLU<Eigen::Matrix4d> lu(a);
    if (!lu.isInvertible()) return Eigen::Vector4d::Zero();
    return lu.solve(rhs);
}

double shape_at(const Eigen::Vector4d& p, double s) { return p[0] + s * (p[1] + s * (p[2] + s * p[3])); }

// Where on [from, to] (x/l) the cubic P is largest in the direction `toward` (its sign): the ends
// and the interior zeros of its slope.
double farthest_toward(const Eigen::Vector4d& p, double toward, double from, double to) {
    std::vector<double> at{from, to};
    // P'(s) = p1 + 2 p2 s + 3 p3 s^2.
    const double qa = 3.0 * p[3], qb = 2.0 * p[2], qc = p[1];
    if (qa == 0.0) {
        if (qb != 0.0) at.push_back(-qc / qb);
    } else if (const double disc = qb * qb - 4.0 * qa * qc; disc >= 0.0) {
        at.push_back((-qb + std::sqrt(disc)) / (2.0 * qa));
        at.push_back((-qb - std::sqrt(disc)) / (2.0 * qa));
    }
    double best = from;
    for (const double s : at) {
        if (s >= from && s <= to && toward * shape_at(p, s) > toward * shape_at(p, best)) best = s;
    }
    return best;
}

std::string um(double v) { return significant(v * 1e6, 4) + " um"; }

// The key a layered curl's problem names: the layers of the first section whose stack carries a moment.
std::string first_layered_key(const Case& c) {
    for (std::size_t k = 0; k < c.beam.sections.size(); ++k) {
        if (!c.beam.sections[k].layers.empty()) return "beam.sections[" + std::to_string(k) + "].layers";
    }
    return "beam.sections";
}

// A surface `gap` [m] from the straight beam on side `side` over [from, to] (x/l): the problem when
// the released shape reaches it.
void check_gap(std::vector<CaseProblem>& out, const Case& c, const std::string& key, const Eigen::Vector4d& p,
               double kappa0, Side side, double from, double to, double gap, const std::string& what) {
    const double l = c.beam.length;
    const double toward = side == Side::below ? -1.0 : 1.0;
    const double s = farthest_toward(p, toward * kappa0, from, to);
    const double lift = toward * kappa0 * l * l * shape_at(p, s);
    if (!(lift > 0.0) || gap - lift > 0.0) return;
    out.push_back({key, "the released shape (kappa0 = " + significant(kappa0, 6) + " 1/m) closes " + what + " at x = " +
                            um(s * l) + " (x/l = " + significant(s, 4) + "): it moves " + um(lift) +
                            " toward a gap of " + um(gap) + ", " + um(lift - gap) +
                            " too far; a smaller curl or a larger gap is needed"});
}

// Every surface the released shape must leave open: each electrode's air gap, each film's gap and
// each support's gap (one given as a gap, not a prestress): fn(side, from, to, gap, what).
template <class Fn>
void each_gap(const Case& c, Fn fn) {
    for (std::size_t k = 0; k < c.electrodes.size(); ++k) {
        const Electrode& e = c.electrodes[k];
        fn(e.side, e.from, e.to, e.gap - e.dielectric_thickness, "the air gap of electrodes[" + std::to_string(k) + "]");
    }
    for (std::size_t k = 0; k < c.films.size(); ++k) {
        const Film& f = c.films[k];
        fn(f.side, f.from, f.to, f.gap, "the gap of films[" + std::to_string(k) + "]");
    }
    for (std::size_t k = 0; k < c.supports.size(); ++k) {
        const Support& s = c.supports[k];
        const bool as_gap = s.surface_key == "gap" || (s.surface_key.empty() && !(s.surface > 0.0));
        if (as_gap) fn(s.side, s.position, s.position, -s.surface, "the gap of supports[" + std::to_string(k) + "]");
    }
}

// Whether any section's layers carry a moment (a curl of their own).
bool layers_curl(const Case& c) {
    for (std::size_t k = 0; k < c.beam.sections.size(); ++k) {
        if (c.beam.sections[k].layers.empty()) continue;
        try {
            if (section_resultants(c, k).stress_moment != 0.0) return true;
        } catch (const std::invalid_argument&) {
            return false;  // a layer names no material: reported on its own
        }
    }
    return false;
}

// The same for a beam of sections or layered curl: the released shape from the FE model's static
// solution (no closed form once EI or kappa0 change along the beam), sampled on every element.
void check_released_gaps_fe(std::vector<CaseProblem>& out, const Case& c, const std::string& key) {
    System s;
    Eigen::VectorXd q;
    try {
        s = build_system(c, SupportModel::none);
        q = solve_static(s, curl_load(c, s));
    } catch (const std::exception&) {
        return;  // a mesh or stiffness the model refuses on its own, with its own message
    }
    const double l = c.beam.length;
    each_gap(c, [&](Side side, double from, double to, double gap, const std::string& what) {
        const double toward = side == Side::below ? -1.0 : 1.0;
        double best_x = from * l, best = toward * transverse_displacement(s, q, from * l);
        for (int e = 0; e < s.mesh.element_count(); ++e) {
            const double x0 = std::max(s.mesh.x[static_cast<std::size_t>(e)], from * l);
            const double x1 = std::min(s.mesh.x[static_cast<std::size_t>(e) + 1], to * l);
            if (x1 < x0) continue;
            for (int k = 0; k <= 16; ++k) {
                const double x = x0 + (x1 - x0) * k / 16.0;
                const double lift = toward * transverse_displacement(s, q, x);
                if (lift > best) {
                    best = lift;
                    best_x = x;
                }
            }
        }
        if (!(best > 0.0) || gap - best > 0.0) return;
        out.push_back({key, "the released shape closes " + what + " at x = " + um(best_x) + " (x/l = " +
                                significant(best_x / l, 4) + "): it moves " + um(best) + " toward a gap of " + um(gap) +
                                ", " + um(best - gap) + " too far; a smaller curl or a larger gap is needed"});
    });
}

// Gaps are measured from the straight beam: the released shape must leave every gap open.
void check_released_gaps(std::vector<CaseProblem>& out, const Case& c) {
    const ParameterSet* p = curl_table(c);
    const bool table = p != nullptr && !given_key(*p).empty();
    if (!(c.beam.length > 0.0) || (!table && !layers_curl(c))) return;
    const std::string key = table ? std::string(kSection) + "." + given_key(*p) : first_layered_key(c);
    if (!c.beam.sections.empty()) {
        check_released_gaps_fe(out, c, key);
        return;
    }
    const double kappa0 = intrinsic_curvature(c);
    if (kappa0 == 0.0 || !std::isfinite(kappa0)) return;
    const Eigen::Vector4d shape = shape_coefficients(c.beam);
    each_gap(c, [&](Side side, double from, double to, double gap, const std::string& what) {
        check_gap(out, c, key, shape, kappa0, side, from, to, gap, what);
    });
}

void check_curl(std::vector<CaseProblem>& out, const Case& c) {
    const ParameterSet* p = curl_table(c);
    if (p != nullptr && given_key(*p).empty()) {
        out.push_back({kSection, "give one of curvature, stress_gradient or tip_lift"});
        return;
    }
    check_released_gaps(out, c);
}

SectionSpec curl_section() {
    SectionSpec s;
    s.name = kSection;
    s.title = "(optional): the released curl";
    s.doc = "The stress-free curvature kappa0 of the released beam, positive when it curls up (+v, away from "
            "an electrode below): a stress gradient through the thickness, or the curvature or the tip lift "
            "measured on the device. Give exactly one key. The beam's strain energy is (1/2) EI (v'' - "
            "kappa0)^2, so the curl is a constant load, the moments EI kappa0 at each element's ends "
            "(a cantilever's free end keeps one: its released shape is kappa0 x^2 / 2, the tip lift "
            "kappa0 l^2 / 2; a beam clamped at both ends does not move). Every gap (electrodes, films, "
            "supports) is measured from the straight beam: the beam rests in its released shape, from which "
            "`simulate` starts and `pullin` traces, so a curl up widens the gap below. A curl that closes a "
            "gap at rest is refused, naming where and by how much. The small-deflection model holds while "
            "the released slope kappa0 l stays small.";
    KeySpec curvature = number_key("curvature", Dimension::dimensionless, "1/m");
    curvature.means("kappa0, the released curvature");
    curvature.default_text = "-";
    KeySpec gradient = number_key("stress_gradient", Dimension::dimensionless, "Pa/m");
    gradient.means("Gamma, the residual stress's gradient through the thickness (tension growing toward the top "
                   "is positive): kappa0 = Gamma / E, E the bending modulus of [material] (`material.plate_modulus` "
                   "applies), on a beam of sections too; a layer's own gradient is its material's `stress_gradient`");
    gradient.default_text = "-";
    KeySpec lift = number_key("tip_lift", Dimension::length);
    lift.means("delta, the tip lift of the beam released as a cantilever: kappa0 = 2 delta / l^2");
    lift.default_text = "-";
    s.keys = {curvature, gradient, lift};
    s.exclusive = {{"curvature", "stress_gradient"}, {"curvature", "tip_lift"}, {"stress_gradient", "tip_lift"}};
    s.check = check_curl;
    return s;
}

class IntrinsicCurvatures final : public ElementFamily {
public:
    [[nodiscard]] std::string_view name() const override { return "intrinsic curvature"; }

    [[nodiscard]] std::vector<FamilyElement> elements(const ElementSource& src) const override {
        if (curl_table(src.c) == nullptr && !layers_curl(src.c)) return {};
        const System& sys = src.system;
        const Eigen::VectorXd f = curl_load(src.c, sys);
        std::vector<double> on_bending(sys.bending.size(), 0.0);
        for (int r = 0; r < sys.size(); ++r) {
            const int b = src.bending_position[static_cast<std::size_t>(r)];
            if (b >= 0) on_bending[static_cast<std::size_t>(b)] += f[r];
        }
        std::vector<int> dofs;
        std::vector<double> load;
        for (std::size_t i = 0; i < on_bending.size(); ++i) {
            if (on_bending[i] == 0.0) continue;
            dofs.push_back(static_cast<int>(i));
            load.push_back(on_bending[i]);
        }
        if (dofs.empty()) return {};  // both ends clamped: the curl moves nothing
        return {{std::make_shared<IntrinsicCurvature>(kSection, std::move(dofs), std::move(load)), {kSection, 0}}};
    }

    void register_case_keys() const override { register_section(curl_section()).keep(); }

    [[nodiscard]] std::string validation() const override {
        return "**Released curl** (`tests/intrinsic_curvature_test.cpp`; docs/case-files.md, `[curl]`): a beam "
               "with stress-free curvature kappa0 (strain energy (1/2) EI (w'' - kappa0)^2) against the closed "
               "forms of the uniform Euler-Bernoulli beam, which the cubic Hermite elements hold exactly: the "
               "cantilever's arc kappa0 x^2 / 2 and slope kappa0 x at every node to 1e-10 (tip lift kappa0 l^2 / 2), "
               "pinned-pinned kappa0 (x^2 - l x) / 2, clamped-pinned kappa0 l^2 (s^3 - s^2) / 4, no motion clamped "
               "at both ends; a single layer with a linear stress gradient Gamma, kappa0 = Gamma / E and tip lift "
               "Gamma l^2 / (2 E) (the released moment Gamma I over EI; S. Timoshenko, *J. Opt. Soc. Am.* 11 (1925) "
               "233, the bimetal strip's curvature from a strain varying through the thickness; W. Fang and "
               "J. A. Wickert, *J. Micromech. Microeng.* 6 (1996) 301, the curl of released cantilevers); the "
               "switch example's pull-in voltage curled up lying between those of the straight switch with its "
               "electrode's gap widened uniformly by the released shape's least and largest lift over the electrode; "
               "the energy ledger through the curled switch's bounces.";
    }
};

}  // namespace

Eigen::VectorXd curl_load(const Case& c, const System& s) {
    const double kappa0 = intrinsic_curvature(c);
    // Each element e takes its released moment M_e = EI_e kappa0 + M_r (the [curl] curvature and its
    // section's layers): f = M_e int N''^T dx, -M_e on its first rotation, +M_e on its last; between
    // two elements of one section the two cancel.
    std::vector<double> moment;
    for (const SectionResultants& r : s.sections) moment.push_back(r.EI * kappa0 + r.stress_moment);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(s.size());
    const auto add = [&](int node, double m) {
        const int reduced = s.reduced_of[static_cast<std::size_t>(global_dof(node, 2))];
        if (reduced >= 0) f[reduced] += m;
    };
    for (int e = 0; e < s.mesh.element_count(); ++e) {
        const double m = moment[static_cast<std::size_t>(s.element_section[static_cast<std::size_t>(e)])];
        add(e, -m);
        add(e + 1, m);
    }
    return f;
}

double intrinsic_curvature(const Case& c) {
    const ParameterSet* p = curl_table(c);
    if (p == nullptr) return 0.0;
    if (p->numbers.count("curvature") > 0) return p->number("curvature");
    if (p->numbers.count("stress_gradient") > 0) return p->number("stress_gradient") / c.material.effective_modulus();
    if (p->numbers.count("tip_lift") > 0) return 2.0 * p->number("tip_lift") / (c.beam.length * c.beam.length);
    return 0.0;
}

double released_shape(const Case& c, double kappa0, double x) {
    const double l = c.beam.length;
    return kappa0 * l * l * shape_at(shape_coefficients(c.beam), x / l);
}

const ElementFamily& intrinsic_curvatures() {
    static const IntrinsicCurvatures family;
    return family;
}

}  // namespace vi
