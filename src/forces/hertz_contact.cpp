#include "forces/hertz_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "fem/section_properties.hpp"
#include "forces/support_contacts.hpp"
#include "model/bisection.hpp"
#include "model/case_schema.hpp"
#include "model/input_error.hpp"
#include "model/number_format.hpp"

namespace vi {

double hertz_stiffness(double effective_modulus, double radius) {
    return 4.0 / 3.0 * effective_modulus * std::sqrt(radius);
}

double effective_modulus(double e1, double nu1, double e2, double nu2) {
    return 1.0 / ((1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2);
}

double hunt_crossley_restitution(double a) {
    constexpr double h = 1e-3;
    constexpr long kMaxSteps = 10'000'000;
    // u = 1 + a x' decays as u' = -a x^(3/2) u, so x' > -1/a throughout; once u is below roundoff
    // the force is nothing and the mass leaves at -1/a.
    const auto acc = [a](double x, double v) { return -std::pow(std::max(x, 0.0), 1.5) * (1.0 + a * v); };
    double x = 0.0, v = 1.0;
    for (long n = 0; n < kMaxSteps; ++n) {
        const double k1x = v, k1v = acc(x, v);
        const double k2x = v + 0.5 * h * k1v, k2v = acc(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
        const double k3x = v + 0.5 * h * k2v, k3v = acc(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
        const double k4x = v + h * k3v, k4v = acc(x + h * k3x, v + h * k3v);
        x += h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
        v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        // Past x = 0 the force is 0, so v at the step's end is the exit speed.
        if (x <= 0.0) return -v;
        if (a > 0.0 && 1.0 + a * v < 1e-15) return 1.0 / a;
    }
    throw std::runtime_error("the Hunt-Crossley impact with alpha v = " + significant(a, 6) + " did not end within " +
                             std::to_string(kMaxSteps) + " steps");
}

double hunt_crossley_damping(double restitution, double speed) {
    if (!(restitution > 0.0 && restitution <= 1.0) || !(speed > 0.0)) {
        throw std::invalid_argument("hunt_crossley_damping: restitution in (0, 1] and a positive speed");
    }
    if (restitution == 1.0) return 0.0;
    const double a = bisect_sign_change([restitution](double t) { return hunt_crossley_restitution(t) - restitution; },
                                        0.0, 1.0 / restitution);
    return a / speed;
}

double ContactResistance::of_radius(double a) const {
    if (!(a > 0.0)) return std::numeric_limits<double>::infinity();
    const double area = std::numbers::pi * a * a;
    double r = resistivity / (2.0 * a);
    if (mean_free_path > 0.0) {
        const double kn = mean_free_path / a;
        r = 4.0 * resistivity * mean_free_path / (3.0 * area) + (1.0 + 0.83 * kn) / (1.0 + 1.33 * kn) * r;
    }
    return r + film_resistivity / area;
}

HertzContact::HertzContact(std::string name, int dof, double sign, double surface, double x, double k, double alpha,
                           double radius, std::optional<ContactResistance> resistance, double yield_strength)
    : PointContact(std::move(name), dof, sign, surface, x), k_(k), alpha_(alpha), radius_(radius),
      resistance_(resistance), yield_strength_(yield_strength) {
    if (dof < 0 || std::abs(sign) != 1.0 || !std::isfinite(surface) || !(k > 0.0) || !std::isfinite(k) ||
        !(alpha >= 0.0) || !std::isfinite(alpha) || !(radius > 0.0) || !std::isfinite(radius)) {
        throw std::invalid_argument(name_ + ": inconsistent Hertz contact data");
    }
}

double HertzContact::force_magnitude(const ElementState& s) const {
    const double d = std::max(penetration(s), 0.0);
    return k_ * d * std::sqrt(d) * (1.0 + alpha_ * penetration_rate(s));
}

void HertzContact::add_force(const ElementState& s, int mode, double* f) const {
    if (mode == 1) f[0] += sign_ * force_magnitude(s);
}

void HertzContact::add_tangent(const ElementState& s, int mode, double* dfdq, double* dfdv) const {
    // f = sign k d^(3/2) (1 + alpha r), d = sign (surface - q), r = -sign v:
    // df/dq = -(3/2) k d^(1/2) (1 + alpha r), df/dv = -k alpha d^(3/2).
    if (mode != 1) return;
    const double d = std::max(penetration(s), 0.0);
    const double root = std::sqrt(d);
    dfdq[0] -= 1.5 * k_ * root * (1.0 + alpha_ * penetration_rate(s));
    dfdv[0] -= k_ * alpha_ * d * root;
}

double HertzContact::stored_energy(const ElementState& s, int mode) const {
    if (mode != 1) return 0.0;
    const double d = std::max(penetration(s), 0.0);
    return 0.4 * k_ * d * d * std::sqrt(d);
}

double HertzContact::dissipated_power(const ElementState& s, int mode) const {
    if (mode != 1) return 0.0;
    const double d = std::max(penetration(s), 0.0);
    const double r = penetration_rate(s);
    return k_ * alpha_ * d * std::sqrt(d) * r * r;
}

double HertzContact::switching_function(const ElementState& s, int mode) const {
    const double g = std::min(penetration(s) / radius_, 1.0 + alpha_ * penetration_rate(s));
    return mode == 1 ? -g : g;
}

std::optional<FreeMode> HertzContact::free_mode(int mode) const {
    if (mode == 1) return std::nullopt;
    // d / R = sign (surface - q) / R; 1 + alpha dd/dt = 1 - alpha sign v (switching_function's parts).
    FreeMode m;
    m.parts.push_back({{-sign_ / radius_}, {0.0}, sign_ * surface_ / radius_});
    m.parts.push_back({{0.0}, {-alpha_ * sign_}, 1.0});
    return m;
}

int HertzContact::static_mode(const ElementState& s) const {
    const double tol = 1e-12 * std::max(std::abs(surface_), std::abs(s.q[0]));
    return penetration(s) > tol ? 1 : 0;
}

int HertzContact::initial_mode(const ElementState& s) const {
    const double d = penetration(s), r = penetration_rate(s);
    if (d > 0.0 && 1.0 + alpha_ * r > 0.0) return 1;
    const double scale = std::max(std::abs(surface_), std::abs(s.q[0]));
    const bool touching = std::abs(d) <= 64.0 * std::numeric_limits<double>::epsilon() * scale;
    return touching && r > 0.0 ? 1 : 0;
}

void HertzContact::watch_functions(const ElementState& s, int mode, double* g) const {
    const double r = penetration_rate(s);
    g[0] = r;
    if (mode != 1 || s.a == nullptr) {
        g[1] = 1.0;
        return;
    }
    // dF/dt = k ((3/2) d^(1/2) r (1 + alpha r) + d^(3/2) alpha dr/dt), dr/dt = -sign a.
    const double d = std::max(penetration(s), 0.0);
    const double root = std::sqrt(d);
    g[1] = k_ * (1.5 * root * r * (1.0 + alpha_ * r) - d * root * alpha_ * sign_ * s.a[0]);
}

ContactReading HertzContact::contact_reading(const ElementState& s) const {
    return {penetration(s), force_magnitude(s), s.v[0]};
}

double HertzContact::contact_radius(double d) const {
    if (!(d > 0.0)) return 0.0;
    const double elastic = std::sqrt(radius_ * d);
    if (!resistance_ || !(resistance_->hardness > 0.0)) return elastic;
    const double plastic = std::sqrt(k_ * d * std::sqrt(d) / (std::numbers::pi * resistance_->hardness));
    return std::max(elastic, plastic);
}

double HertzContact::contact_resistance(const ElementState& s) const {
    if (!resistance_) return std::numeric_limits<double>::quiet_NaN();
    return resistance_->of_radius(contact_radius(penetration(s)));
}

double HertzContact::contact_pressure(double d) const {
    if (!(d > 0.0)) return 0.0;
    return 3.0 * k_ * std::sqrt(d) / (2.0 * std::numbers::pi * radius_);
}

double HertzContact::on_resistance() const {
    return resistance_ ? resistance_->r_on : std::numeric_limits<double>::quiet_NaN();
}

namespace {

const char* const kHertz = "hertz";

// The counter-surface's own modulus and Poisson ratio apply where E* is not given directly.
KeyCondition hertz_without_effective_modulus() {
    KeyCondition c = when_chosen("supports", "law", {kHertz});
    const auto hertz = c.holds;
    c.holds = [hertz](const Case& cs, std::size_t i) {
        return hertz(cs, i) && cs.supports[i].params.numbers.count("effective_modulus") == 0;
    };
    c.on = {"law", "effective_modulus"};
    c.file_text = "only with $.law = \"hertz\" and without $.effective_modulus";
    c.doc_text = "`law = \"hertz\"`, without `effective_modulus`";
    return c;
}

// law = "hertz" needs a solver that takes a force nonlinear in d (the exact solver's contacts are
// linear forms).
void refuse_exact_solver(std::vector<CaseProblem>& out, const Case& c, std::size_t i) {
    if (c.supports[i].linear_law() || c.solver.method != SolverSettings::Method::exact) return;
    out.push_back({"solver.method", "\"exact\" cannot take the Hertz contact of supports[" + std::to_string(i) +
                                        "].law (its force k d^(3/2) is not one of the exact solver's linear forms); "
                                        "use \"cvode\" or \"auto\""});
}

std::vector<KeySpec> hertz_keys() {
    const KeyCondition hertz = when_chosen("supports", "law", {kHertz});
    KeySpec radius = number_key("radius", Dimension::length);
    radius.require().in(positive()).only(hertz).means("R, the dimple's radius of curvature");
    radius.rule = refuse_exact_solver;
    KeySpec star = number_key("effective_modulus", Dimension::pressure);
    star.in(positive()).only(hertz).means("E* given directly, in place of the counter-surface's modulus and Poisson ratio");
    star.default_text = "from the two materials";
    KeySpec e2 = number_key("youngs_modulus", Dimension::pressure);
    e2.require().in(positive()).only(hertz_without_effective_modulus())
        .means("E2 of the counter-surface (the beam's face is the other body: [material], or the layer of its "
               "section facing the support)");
    KeySpec nu2 = number_key("poisson_ratio", Dimension::dimensionless, "-");
    nu2.require().in(interval(-1.0, true, 0.5, false)).only(hertz_without_effective_modulus())
        .means("nu2 of the counter-surface");
    KeySpec e = number_key("restitution", Dimension::dimensionless, "-");
    e.otherwise(1.0).in(interval(0.0, true, 1.0, false)).only(hertz)
        .needing("reference_speed", "needs reference_speed (the impact speed the restitution is measured at)")
        .means("coefficient of restitution e at reference_speed; sets the Hunt-Crossley alpha (1: no damping)");
    KeySpec v = number_key("reference_speed", Dimension::velocity);
    v.in(positive()).only(hertz).means("the impact speed at which restitution holds");
    v.default_text = "-";
    return {radius, star, e2, nu2, e, v};
}

// A hardness serves the plastic contact radius of a resistance or the wear estimate: alone it
// would be silently unused.
void hardness_needs_a_use(std::vector<CaseProblem>& out, const Case& c, std::size_t i) {
    const ParameterSet& p = c.supports[i].params;
    if (p.numbers.count("hardness") == 0 || p.numbers.count("resistivity") > 0 || p.numbers.count("wear_coefficient") > 0) {
        return;
    }
    out.push_back({"supports[" + std::to_string(i) + "].hardness",
                   "needs resistivity (the plastic contact radius) or wear_coefficient (the wear estimate)"});
}

// The contact resistance's keys (docs/hertz-contact.md §4): numbers in SI (no unit text).
std::vector<KeySpec> resistance_keys() {
    const KeyCondition hertz = when_chosen("supports", "law", {kHertz});
    const std::string needs = "needs resistivity (the contact metal's, which turns the resistance on)";
    KeySpec rho = number_key("resistivity", Dimension::dimensionless, "ohm m");
    rho.in(positive()).only(hertz).means("rho of the contact metal (both bodies); gives the contact's resistance");
    rho.default_text = "- (no resistance)";
    KeySpec film = number_key("film_resistivity", Dimension::dimensionless, "ohm m^2");
    film.otherwise(0.0).in(non_negative()).only(hertz).needing("resistivity", needs)
        .means("a surface film's resistance times its area: sigma_f / (pi a^2) in series");
    KeySpec hard = number_key("hardness", Dimension::pressure);
    hard.in(positive()).only(hertz)
        .means("H: the fully plastic radius sqrt(F / (pi H)) where it exceeds the elastic one (with resistivity); "
               "the wear estimate's H (with wear_coefficient)");
    hard.default_text = "- (elastic radius)";
    hard.rule = hardness_needs_a_use;
    KeySpec mfp = number_key("mean_free_path", Dimension::length);
    mfp.in(positive()).only(hertz).needing("resistivity", needs)
        .means("the electrons' mean free path: Sharvin's term by Wexler's interpolation");
    mfp.default_text = "- (Holm's term alone)";
    KeySpec on = number_key("r_on", Dimension::dimensionless, "ohm");
    on.in(positive()).only(hertz).needing("resistivity", needs)
        .means("the resistance below which the contact counts as on: the electrical bounce ledger (`simulate --r-on` sets it)");
    on.default_text = "-";
    return {rho, film, hard, mfp, on};
}

// The damage and wear keys (docs/hertz-contact.md §8, docs/cycles.md).
std::vector<KeySpec> wear_keys() {
    const KeyCondition hertz = when_chosen("supports", "law", {kHertz});
    KeySpec y = number_key("yield_strength", Dimension::pressure);
    y.in(positive()).only(hertz)
        .means("Y of the softer contact body: an impact whose Hertz peak pressure p0 passes 1.6 Y yields");
    y.default_text = "- (no yield check)";
    KeySpec k = number_key("wear_coefficient", Dimension::dimensionless, "-");
    k.in(interval(0.0, true, 1.0, false)).only(hertz)
        .needing("hardness", "needs hardness (the wear volume is K E / H)")
        .means("K: the `cycles` study's wear volume K E / H of the energy E the contact dissipates");
    k.default_text = "- (no wear estimate)";
    return {y, k};
}

// The resistance model of support entry p, where it gives a resistivity.
std::optional<ContactResistance> resistance_of(const ParameterSet& p) {
    if (p.numbers.count("resistivity") == 0) return std::nullopt;
    ContactResistance r;
    r.resistivity = p.number("resistivity");
    r.film_resistivity = p.number("film_resistivity", 0.0);
    r.hardness = p.number("hardness", 0.0);
    r.mean_free_path = p.number("mean_free_path", 0.0);
    r.r_on = p.number("r_on", std::numeric_limits<double>::quiet_NaN());
    return r;
}

class HertzContacts final : public ElementFamily {
public:
    [[nodiscard]] std::string_view name() const override { return "Hertz contacts"; }

    [[nodiscard]] std::vector<FamilyElement> elements(const ElementSource& src) const override {
        std::vector<FamilyElement> out;
        for (std::size_t k = 0; k < src.c.supports.size(); ++k) {
            if (src.c.supports[k].params.text("law") == kHertz) out.push_back({contact(src, k), {"supports", k}});
        }
        return out;
    }

    void register_case_keys() const override {
        register_option("supports", "law", kHertz,
                        "a dimple: k d^(3/2) with Hunt-Crossley damping; [hertz-contact.md](hertz-contact.md)")
            .keep();
        register_keys("supports", hertz_keys()).keep();
        register_keys("supports", resistance_keys()).keep();
        register_keys("supports", wear_keys()).keep();
    }

private:
    // The beam's face the support touches, E and nu: its section's bottom layer (a support below) or
    // top layer (above); [material] for a section without layers or a beam without sections.
    static std::pair<double, double> face_material(const Case& c, const Support& s) {
        if (!c.beam.sections.empty()) {
            const BeamSection& section = c.beam.sections[section_index_at(c.beam, s.position)];
            if (!section.layers.empty()) {
                const Layer& face = s.side == Side::below ? section.layers.front() : section.layers.back();
                for (const LayerMaterial& m : c.materials) {
                    if (m.name == face.material) return {m.youngs_modulus, m.poisson_ratio};
                }
            }
        }
        return {c.material.youngs_modulus, c.material.poisson_ratio};
    }

    static ForceElementPtr contact(const ElementSource& src, std::size_t k) {
        const ParameterSet& p = src.c.supports[k].params;
        const SupportGeometry g = support_geometry(src, k);
        const auto [e1, nu1] = face_material(src.c, src.c.supports[k]);
        const double star = p.numbers.count("effective_modulus") > 0
                                ? p.number("effective_modulus")
                                : effective_modulus(e1, nu1, p.number("youngs_modulus"), p.number("poisson_ratio"));
        const double radius = p.number("radius");
        const double e = p.number("restitution", 1.0);
        const double alpha = e < 1.0 ? hunt_crossley_damping(e, p.number("reference_speed")) : 0.0;
        return std::make_shared<HertzContact>(g.name, g.dof, g.sign, g.surface, g.x, hertz_stiffness(star, radius), alpha,
                                              radius, resistance_of(p),
                                              p.number("yield_strength", std::numeric_limits<double>::quiet_NaN()));
    }
};

}  // namespace

const ElementFamily& hertz_contacts() {
    static const HertzContacts family;
    return family;
}

}  // namespace vi
