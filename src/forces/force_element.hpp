#pragma once
// ForceElement: one physical force acting on a few DOFs of the beam (a contact support, plain or
// adhesive, a point load, an electrostatic pad, a dielectric layer, a squeeze film, mid-plane
// stretching). Solvers, the statics and the energy ledger see forces only through this interface
// (docs/architecture.md).

#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "forces/linear_form.hpp"
#include "forces/reduced_element.hpp"
#include "model/time_function.hpp"

namespace vi {

// What an element sees at one instant: the time [s] and the displacements [m, rad] and velocities
// [m/s, rad/s] of its own DOFs, in the order of dofs(). `a` (accelerations) is given only where a
// solver has it (watch functions); it may be null.
struct ElementState {
    double t = 0.0;
    const double* q = nullptr;
    const double* v = nullptr;
    const double* a = nullptr;
};

// A contact's reading for the episode ledger: penetration d [m] (> 0 inside the surface), the
// force magnitude F = what the surface pushes with [N] (whether or not it is closed), and the
// velocity of the beam at the contact point [m/s] (dv/dt, positive up).
struct ContactReading {
    double penetration = 0.0;
    double force = 0.0;
    double point_velocity = 0.0;
};

// A linear function of an element's state, wq . q + wv . v + offset over its DOFs (the units of the
// switching function it is part of).
struct LinearPart {
    std::vector<double> wq, wv;  // weights over dofs()
    double offset = 0.0;
};

// An element that exerts no force in some mode (an open contact): there its switching function is
// the smallest of `parts`, so its mode ends where they are all positive; no parts: it never switches.
struct FreeMode {
    std::vector<LinearPart> parts;
};

// What a terminal mode (ForceElement::ends_run) answers, read where the element entered it: a
// one-word outcome ("collapsed"), the place along the beam [m] (negative when none), the value that
// decided it (for an electrode, the narrowest air gap [m]) and one sentence saying what happened.
struct RunEnd {
    std::string outcome;
    double x = -1.0;
    double value = 0.0;
    std::string text;
};

// Which term of the energy ledger an element's stored energy belongs to: a contact's spring, the
// electrical co-energy of an electrode (-C V^2/2), or strain energy (mid-plane stretching).
enum class StoredEnergyKind { contact_spring, electrical, strain };

// Which term of the energy ledger an element's dissipated power belongs to: a contact's damper (and
// what a contact loses when it switches), or a squeeze film's viscous flow.
enum class DissipationKind { contact, film };

// A force element. Forces are generalised nodal forces on dofs() [N, N m], positive along the DOF.
//
// Modes: an element may be hybrid (a contact is open or closed). Mode 0 is the first; modes() says
// how many. In a mode the force is smooth in (q, v, t). The element switches when its switching
// function, evaluated in the current mode, crosses zero upward; then mode_after_switch() holds.
// A smooth element has one mode and never switches.
//
// Contract (checked for every element by the tests): add_tangent is the derivative of add_force
// (central differences), and in every mode the stored energy's gradient is minus the conservative
// part of the force.
class ForceElement {
public:
    virtual ~ForceElement() = default;

    // The case key it comes from, for messages ("supports[0]", "loads[1]").
    [[nodiscard]] virtual const std::string& name() const = 0;
    // What it is, for messages ("Kelvin-Voigt contact").
    [[nodiscard]] virtual std::string kind() const = 0;
    // The problem DOFs it acts on (fixed for the life of the element).
    [[nodiscard]] virtual const std::vector<int>& dofs() const = 0;

    [[nodiscard]] virtual int modes() const { return 1; }
    // Adds the force in `mode` to f (|dofs| entries).
    virtual void add_force(const ElementState& s, int mode, double* f) const = 0;
    // Adds d f_i / d q_j to dfdq and d f_i / d v_j to dfdv (row-major |dofs| x |dofs|).
    virtual void add_tangent(const ElementState& s, int mode, double* dfdq, double* dfdv) const = 0;
    // Energy stored in the element [J] (a contact spring's 1/2 Kc d^2).
    [[nodiscard]] virtual double stored_energy(const ElementState& s, int mode) const = 0;
    // The ledger term stored_energy goes to.
    [[nodiscard]] virtual StoredEnergyKind stored_energy_kind() const { return StoredEnergyKind::contact_spring; }
    // Power it dissipates [W], >= 0 (a contact damper's Cc (dd/dt)^2).
    [[nodiscard]] virtual double dissipated_power(const ElementState& s, int mode) const = 0;
    // The ledger term dissipated_power goes to.
    [[nodiscard]] virtual DissipationKind dissipation_kind() const { return DissipationKind::contact; }
    // add_force and dissipated_power in one call, returning the power: a solver's right-hand side
    // needs both at every evaluation, and an element whose power shares costly work with its force
    // (a squeeze film's gap law at every quadrature point) overrides it to do that work once.
    virtual double add_force_and_power(const ElementState& s, int mode, double* f) const {
        add_force(s, mode, f);
        return dissipated_power(s, mode);
    }
    // Power an external source delivers through it [W] (a load's Q(t) v).
    [[nodiscard]] virtual double input_power(const ElementState& s, int mode) const = 0;

    // Hybrid behaviour. The switching function of `mode`: its upward zero crossing ends the mode.
    [[nodiscard]] virtual double switching_function(const ElementState& /*s*/, int /*mode*/) const { return -1.0; }
    [[nodiscard]] virtual int mode_after_switch(int mode) const { return mode; }
    // The mode a static state (v = 0) is in, e.g. a contact is closed where it penetrates.
    [[nodiscard]] virtual int static_mode(const ElementState& /*s*/) const { return 0; }
    // The mode at the start of a transient from state s: static_mode, except where a solver must
    // take a contact that touches and moves in (d = 0, dd/dt > 0) as closed.
    [[nodiscard]] virtual int initial_mode(const ElementState& s) const { return static_mode(s); }

    // A terminal mode: entering it ends a transient, because the model stops holding there and the
    // state reached is itself the answer (the beam collapsing onto a bare electrode's face: its force
    // grows without bound, and following it further only creeps toward a singularity). The solver
    // locates the switch into it as any other and ends the run there with run_end's reading.
    [[nodiscard]] virtual bool ends_run(int /*mode*/) const { return false; }
    [[nodiscard]] virtual RunEnd run_end(const ElementState& /*s*/) const { return {}; }

    // Watch functions: smooth functions whose zero crossings a solver locates because something is
    // reported there (a contact's peak force and penetration) or because a switch could hide between
    // two steps (the maximum of d of an open contact). `directions` like CVODE's root directions.
    [[nodiscard]] virtual int watch_count() const { return 0; }
    virtual void watch_functions(const ElementState& /*s*/, int /*mode*/, double* /*g*/) const {}
    [[nodiscard]] virtual std::vector<int> watch_directions() const { return {}; }
    // Whether a watch function in `mode` needs the accelerations (ElementState::a): a solver then
    // evaluates its whole right-hand side for the watch, so an element asks only in the modes that
    // use them (a contact's peak-force watch, when closed).
    [[nodiscard]] virtual bool watch_needs_acceleration(int /*mode*/) const { return false; }

    // Generalised load patterns over dofs() whose static responses a reduced-order model adds to its
    // modes (modal truncation augmentation, docs/model.md §13): by default a unit force at each DOF;
    // an element spread over many DOFs gives the few shapes its own load takes instead, or the
    // reduced model would keep every DOF it touches.
    [[nodiscard]] virtual std::vector<std::vector<double>> load_patterns() const {
        std::vector<std::vector<double>> unit(dofs().size(), std::vector<double>(dofs().size(), 0.0));
        for (std::size_t i = 0; i < unit.size(); ++i) unit[i][i] = 1.0;
        return unit;
    }

    // The largest magnitude of a force it prescribes [N] (a load's amplitude times max |g|), for the
    // scales of solver tolerances; 0 when its force follows from the motion alone.
    [[nodiscard]] virtual double force_scale() const { return 0.0; }

    // Whether it acts in the static state a transient starts from (a prescribed load Q(t) acts only
    // from t = 0 on, so it does not).
    [[nodiscard]] virtual bool in_static_state() const { return true; }

    // Times in (t0, t1) where an integrator must stop for its prescribed force (a step's jump, a
    // table's corners: TimeFunction::stops), ascending.
    [[nodiscard]] virtual std::vector<double> time_stops(double /*t0*/, double /*t1*/) const { return {}; }

    // The element evaluated directly on the basis rows P of its DOFs (forces/reduced_element.hpp), or
    // null: a reduced-order model then projects the element's own force and tangent. Worth offering
    // where the element's work grows with its DOFs while the model has few coordinates (an electrode
    // over a fine mesh); only for an element that is not a contact and has no watch functions.
    [[nodiscard]] virtual std::unique_ptr<const ReducedElement> reduced(const BasisRows& /*rows*/) const {
        return nullptr;
    }

    // The element as the exact solver needs it, or nullopt when its force is not piecewise linear.
    [[nodiscard]] virtual std::optional<LinearForm> linear_form() const { return std::nullopt; }

    // In `mode`: where the element neither acts nor stores or dissipates energy there, its switching
    // function as linear parts (a solver may then carry the beam's free motion in closed form up to
    // the switch); nullopt where it acts or its switching function is not of that form.
    [[nodiscard]] virtual std::optional<FreeMode> free_mode(int /*mode*/) const { return std::nullopt; }

    // Contacts report episodes: which mode is "in contact", and the reading.
    [[nodiscard]] virtual bool is_contact() const { return false; }
    [[nodiscard]] virtual int contact_mode() const { return 1; }
    [[nodiscard]] virtual ContactReading contact_reading(const ElementState& /*s*/) const { return {}; }
    // The reading's force alone [N] and its point's velocity alone [m/s], each the same number as in
    // contact_reading: a contact over many points gives either without the other's pass over them.
    [[nodiscard]] virtual double contact_force(const ElementState& s) const { return contact_reading(s).force; }
    [[nodiscard]] virtual double contact_point_velocity(const ElementState& s) const {
        return contact_reading(s).point_velocity;
    }
    // Position along the beam [m] where it acts (for output), or a negative number.
    [[nodiscard]] virtual double position() const { return -1.0; }
    // A contact's electrical resistance at state s, taken as closed [ohm] (+inf where the surfaces do
    // not touch); NaN for an element without a resistance model.
    [[nodiscard]] virtual double contact_resistance(const ElementState& /*s*/) const {
        return std::numeric_limits<double>::quiet_NaN();
    }
    // The resistance below which such a contact counts as on [ohm]; NaN when none is set.
    [[nodiscard]] virtual double on_resistance() const { return std::numeric_limits<double>::quiet_NaN(); }
    // A contact's peak surface pressure at penetration d [m], taken as closed [Pa] (Hertz's p0); NaN
    // for a law that has no contact area.
    [[nodiscard]] virtual double contact_pressure(double /*d*/) const { return std::numeric_limits<double>::quiet_NaN(); }
    // The peak pressure at which the softer body starts to yield [Pa]; NaN when no yield strength is given.
    [[nodiscard]] virtual double yield_onset_pressure() const { return std::numeric_limits<double>::quiet_NaN(); }
};

using ForceElementPtr = std::shared_ptr<const ForceElement>;

}  // namespace vi
